// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// tb_cost_front: test wrapper for tests/rtl/test_tb_cost_front.cpp. Two
// sgm_census_unit (left, right) on one step stream feed sgm_cost_volume, as in
// the core: gray pair in, the full cost volume out in raster order.
//
// mode_i and the AD term's ad_weight_i / ad_cap_i are the frame's settings at
// the input slot; they are delayed by the census latency so that they reach the
// cost volume with the same slot (with the census units' centre grays).
// Outputs: the left and right census units' census/rank (left also col/row/valid,
// latency CENSUS_LATENCY) and the cost volume (latency
// CENSUS_LATENCY + COST_LATENCY). AD_TERM = 0: the volume without the AD term
// (its weight and cap inputs ignored).
module tb_cost_front #(
  parameter int D         /*verilator public*/ = 16,
  parameter int MAX_WIDTH /*verilator public*/ = 128,
  parameter int CW        = 8,
  parameter int RW        = 8,
  parameter int AD_TERM   /*verilator public*/ = 1  // sgm_cost_volume's: 0 builds no AD term
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [1:0]       mode_i,
  input  wire  [3:0]       ad_weight_i,
  input  wire  [7:0]       ad_cap_i,
  input  wire  [7:0]       lpix_i,
  input  wire  [7:0]       rpix_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire  [CW-1:0]    width_i,
  input  wire  [RW-1:0]    height_i,
  output logic [43:0]      lcensus_o,
  output logic [5:0]       lrank_o,
  output logic [CW-1:0]    lcol_o,
  output logic [RW-1:0]    lrow_o,
  output logic             lvalid_o,
  output logic [43:0]      rcensus_o,
  output logic [5:0]       rrank_o,
  output logic [D*7-1:0]   cost_o,
  output logic [CW-1:0]    col_o,
  output logic             valid_o
);

  // Mirrors of sgm_census_unit::LATENCY and sgm_cost_volume::LATENCY (checked by the test).
  localparam int CENSUS_LATENCY /*verilator public*/ = 5;
  localparam int COST_LATENCY   /*verilator public*/ = 4;

  logic [7:0]    l_centre, r_centre;
  logic [31:0]   l_nbr, r_nbr;
  logic [CW-1:0] r_col;
  logic [RW-1:0] r_row;
  logic          r_valid;
  wire           unused_right = ^{l_nbr, r_nbr, r_col, r_row, r_valid};

  sgm_census_unit #(
    .MAX_WIDTH (MAX_WIDTH),
    .CW        (CW),
    .RW        (RW)
  ) u_left (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .en_i     (en_i),
    .active_i (1'b1),
    .pix_i    (lpix_i),
    .col_i    (col_i),
    .row_i    (row_i),
    .width_i  (width_i),
    .height_i (height_i),
    .census_o (lcensus_o),
    .rank_o   (lrank_o),
    .centre_o (l_centre),
    .nbr_o    (l_nbr),
    .col_o    (lcol_o),
    .row_o    (lrow_o),
    .valid_o  (lvalid_o)
  );

  sgm_census_unit #(
    .MAX_WIDTH (MAX_WIDTH),
    .CW        (CW),
    .RW        (RW)
  ) u_right (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .en_i     (en_i),
    .active_i (1'b1),
    .pix_i    (rpix_i),
    .col_i    (col_i),
    .row_i    (row_i),
    .width_i  (width_i),
    .height_i (height_i),
    .census_o (rcensus_o),
    .rank_o   (rrank_o),
    .centre_o (r_centre),
    .nbr_o    (r_nbr),
    .col_o    (r_col),
    .row_o    (r_row),
    .valid_o  (r_valid)
  );

  // The frame's mode, delayed to the census outputs' slot.
  localparam int SETW = 2 + 4 + 8;  // {mode, AD weight, AD cap}
  logic [CENSUS_LATENCY*SETW-1:0] set_q;
  always_ff @(posedge clk_i) begin
    if (en_i) set_q <= {set_q[(CENSUS_LATENCY-1)*SETW-1:0], mode_i, ad_weight_i, ad_cap_i};
  end
  wire [1:0] mode_c;
  wire [3:0] adw_c;
  wire [7:0] adt_c;
  assign {mode_c, adw_c, adt_c} = set_q[(CENSUS_LATENCY-1)*SETW +: SETW];

  sgm_cost_volume #(
    .D      (D),
    .CW     (CW),
    .AD_TERM(AD_TERM)
  ) u_cost (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .en_i      (en_i),
    .mode_i    (mode_c),
    .dmin_i    (8'd0),  // the minimum disparity: whole-core tests (MIN_DISPARITY builds)
    .ad_weight_i(adw_c),
    .ad_cap_i  (adt_c),
    .lgray_i   (l_centre),
    .rgray_i   (r_centre),
    .lcensus_i (lcensus_o),
    .lrank_i   (lrank_o),
    .col_i     (lcol_o),
    .rcensus_i (rcensus_o),
    .rrank_i   (rrank_o),
    .valid_i   (lvalid_o),
    .cost_o    (cost_o),
    .col_o     (col_o),
    .valid_o   (valid_o)
  );

endmodule
`default_nettype wire
