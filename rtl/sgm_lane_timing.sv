`default_nettype none
// sgm_lane_timing: the two frame-relative positions sgm_top needs with K > 1
// row lanes (docs/reschedule.md, docs/rtl.md "Lanes: the slot schedule"):
//
//   sof_o        the census output is the frame's first centre: the frame's
//                first slot (col_i, row_i) = (0, 0) delayed by CENSUS_LATENCY
//                slots (sgm_lane_deal restarts its lanes there).
//   rd_col_o /   the LR check's read position: the census output position
//   rd_row_o     (cen_col_i, cen_row_i) LR_LAG rows back, registered, with
//                LR_LAG = 2K - 3 + ceil(LR_WAIT / W) for the frame's width W,
//                taken at the frame's first centre (slots of the frame before,
//                still in flight, keep the previous value).
//
// ceil(LR_WAIT / W) = 1 + #{m >= 1 : m W < LR_WAIT}, and m W < LR_WAIT iff
// W <= (LR_WAIT - 1) / m: one constant comparison per m, for the m with
// m x MIN_FRAME_WIDTH < LR_WAIT (no other can hold).
//
// Parameters: LANES (K >= 2), LR_WAIT and LR_LAG_MAX (sgm_top derives them),
// MIN_FRAME_WIDTH (the narrowest frame), CENSUS_LATENCY (sgm_census_unit's),
// XW column bits, RW row bits.
// Latency: sof_o CENSUS_LATENCY slots after its (0, 0); rd_col_o / rd_row_o one
// slot after the census position. Throughput: one slot per en_i.
module sgm_lane_timing #(
  parameter int LANES           = 2,
  parameter int LR_WAIT         = 35,
  parameter int LR_LAG_MAX      = 4,
  parameter int MIN_FRAME_WIDTH = 16,
  parameter int CENSUS_LATENCY  = 5,
  parameter int XW              = 8,
  parameter int RW              = 8
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  input  wire  [XW-1:0] width_i,    // the frame's width (sgm_stream_ctrl)
  input  wire  [XW-1:0] col_i,      // the slot's position at the stream control
  input  wire  [RW-1:0] row_i,
  input  wire  [XW-1:0] cen_col_i,  // the slot's position at the census output
  input  wire  [RW-1:0] cen_row_i,
  output logic          sof_o,
  output logic [XW-1:0] rd_col_o,
  output logic [RW-1:0] rd_row_o
);

  localparam int LAGW      = $clog2(LR_LAG_MAX + 1);
  localparam int LAG_TERMS = (LR_WAIT - 1) / MIN_FRAME_WIDTH;

  // ------------------------------------------------------------ frame start
  wire sof0 = col_i == '0 && row_i == '0;
  sgm_delay #(.WIDTH(1), .DEPTH(CENSUS_LATENCY)) u_sof_delay (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (sof0),
    .q_o   (sof_o)
  );

  // ------------------------------------------------------------ LR_LAG
  logic [LAG_TERMS-1:0] narrow;  // bit m - 1: m W < LR_WAIT
  for (genvar m = 1; m <= LAG_TERMS; m++) begin : g_lag_term
    assign narrow[m-1] = {{(32 - XW){1'b0}}, width_i} <= 32'((LR_WAIT - 1) / m);
  end

  logic [LAGW-1:0] lag_d, lag_q;
  always_comb begin
    lag_d = LAGW'(2 * LANES - 2);
    for (int m = 0; m < LAG_TERMS; m++) lag_d = lag_d + LAGW'(narrow[m]);
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      lag_q <= LAGW'(LR_LAG_MAX);
    end else if (en_i && sof_o) begin
      lag_q <= lag_d;
    end
  end

  // ------------------------------------------------------------ read position
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_col_o <= cen_col_i;
      rd_row_o <= cen_row_i - RW'(lag_q);
    end
  end

endmodule
`default_nettype wire
