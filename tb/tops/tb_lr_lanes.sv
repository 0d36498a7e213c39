`default_nettype none
// tb_lr_lanes: test wrapper for tests/rtl/test_tb_lr_lanes.cpp: sgm_lr_check
// built with LANES and ROW_BANKS, the S and WTA sides in lane order and the
// read side in raster order (docs/reschedule.md). A plain pass-through: the
// test file is named after its top, and sgm_lr_check's own fixture is the
// one-lane test.
module tb_lr_lanes #(
  parameter int D         /*verilator public*/ = 16,
  parameter int SW        /*verilator public*/ = 13,
  parameter int DW        /*verilator public*/ = $clog2(D) + 4,
  parameter int MAX_WIDTH /*verilator public*/ = 128,
  parameter int CW        /*verilator public*/ = $clog2(MAX_WIDTH + 1),
  parameter int RW        /*verilator public*/ = 8,
  parameter int LANES     /*verilator public*/ = 2,
  parameter int ROW_BANKS /*verilator public*/ = 8,
  localparam int LD       = $clog2(D)
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [CW-1:0]    width_i,
  input  wire  [RW-1:0]    height_i,
  input  wire  [2:0]       tol_i,
  input  wire              check_en_i,
  input  wire  [D*SW-1:0]  s_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire              valid_i,
  input  wire  [LD-1:0]    d_i,
  input  wire  [DW-1:0]    disp_i,
  input  wire  [CW-1:0]    wta_col_i,
  input  wire  [RW-1:0]    wta_row_i,
  input  wire              wta_valid_i,
  input  wire  [CW-1:0]    rd_col_i,
  input  wire  [RW-1:0]    rd_row_i,
  output logic [DW-1:0]    disp_o,
  output logic             valid_o,
  output logic [CW-1:0]    col_o,
  output logic [RW-1:0]    row_o,
  output logic             out_valid_o
);

  // Mirror of sgm_lr_check::LATENCY (the test's slot arithmetic; the one-lane
  // fixture reads the module's own).
  localparam int LATENCY /*verilator public*/ = 4;

  sgm_lr_check #(
    .D(D), .SW(SW), .DW(DW), .MAX_WIDTH(MAX_WIDTH), .CW(CW), .RW(RW), .LANES(LANES), .ROW_BANKS(ROW_BANKS)
  ) u_lr (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en_i),
    .width_i     (width_i),
    .height_i    (height_i),
    .tol_i       (tol_i),
    .check_en_i  (check_en_i),
    .s_i         (s_i),
    .col_i       (col_i),
    .row_i       (row_i),
    .valid_i     (valid_i),
    .d_i         (d_i),
    .disp_i      (disp_i),
    .wta_col_i   (wta_col_i),
    .wta_row_i   (wta_row_i),
    .wta_valid_i (wta_valid_i),
    .rd_col_i    (rd_col_i),
    .rd_row_i    (rd_row_i),
    .disp_o      (disp_o),
    .valid_o     (valid_o),
    .col_o       (col_o),
    .row_o       (row_o),
    .out_valid_o (out_valid_o)
  );

endmodule
`default_nettype wire
