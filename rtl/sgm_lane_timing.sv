// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_lane_timing: the frame-relative positions sgm_top needs with K > 1 row
// lanes (docs/lanes.md, docs/rtl.md "Lanes: the slot schedule"):
//
//   rd_col_o /   the LR check's read position: the raster census position (the
//   rd_row_o     centre a census unit in raster order would output for this
//                slot, CENSUS_LATENCY slots later: (x - 4, y - RY), or
//                (W + x - 4, y - RY - 1) for x < 4) LR_LAG rows back,
//                registered, with LR_LAG = 2K - 3 + ceil(LR_WAIT / W) for the
//                frame's width W, taken at the frame's first centre (slots of
//                the frame before, still in flight, keep the previous value).
//
// ceil(LR_WAIT / W) = 1 + #{m >= 1 : m W < LR_WAIT}, and m W < LR_WAIT iff
// W <= (LR_WAIT - 1) / m: one constant comparison per m, for the m with
// m x MIN_FRAME_WIDTH < LR_WAIT (no other can hold).
//
// Parameters: LANES (K >= 2), LR_WAIT and LR_LAG_MAX (sgm_top derives them),
// MIN_FRAME_WIDTH (the narrowest frame), CENSUS_LATENCY (sgm_census_unit's),
// CENSUS_RY (the census window's rows above the centre), XW column bits, RW
// row bits.
// Inputs per slot (en_i): the slot's position and sof_i, the slot is the frame's
// first, (col_i, row_i) = (0, 0) (sgm_stream_ctrl's flag).
// Latency: rd_col_o / rd_row_o CENSUS_LATENCY + 1 slots after the slot's
// position. Throughput: one slot per en_i.
module sgm_lane_timing #(
  parameter int LANES           = 2,
  parameter int LR_WAIT         = 35,
  parameter int LR_LAG_MAX      = 4,
  parameter int MIN_FRAME_WIDTH = 16,
  parameter int CENSUS_LATENCY  = 5,
  parameter int CENSUS_RY       = 2,
  parameter int XW              = 8,
  parameter int RW              = 8
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  input  wire  [XW-1:0] width_i,    // the frame's width (sgm_stream_ctrl)
  input  wire  [XW-1:0] col_i,      // the slot's position at the stream control
  input  wire  [RW-1:0] row_i,
  input  wire           sof_i,
  output logic [XW-1:0] rd_col_o,
  output logic [RW-1:0] rd_row_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(LANES >= 2)) begin : g_bad_lanes
    $error("sgm_lane_timing: LANES = %0d: LANES must be at least 2 (one lane has no lane timing)", LANES);
  end
  if (!(LR_WAIT >= 1)) begin : g_bad_lr_wait
    $error("sgm_lane_timing: LR_WAIT = %0d: LR_WAIT must be at least 1", LR_WAIT);
  end
  if (!(LR_LAG_MAX >= 0)) begin : g_bad_lr_lag_max
    $error("sgm_lane_timing: LR_LAG_MAX = %0d: LR_LAG_MAX must be at least 0", LR_LAG_MAX);
  end
  if (!(MIN_FRAME_WIDTH >= 16)) begin : g_bad_min_frame_width
    $error("sgm_lane_timing: MIN_FRAME_WIDTH = %0d: MIN_FRAME_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MIN_FRAME_WIDTH);
  end
  if (!(CENSUS_LATENCY >= 1)) begin : g_bad_census_latency
    $error("sgm_lane_timing: CENSUS_LATENCY = %0d: CENSUS_LATENCY must be at least 1", CENSUS_LATENCY);
  end
  if (!(CENSUS_RY >= 0)) begin : g_bad_census_ry
    $error("sgm_lane_timing: CENSUS_RY = %0d: CENSUS_RY must be at least 0", CENSUS_RY);
  end
  if (!(XW >= $clog2(MIN_FRAME_WIDTH + 1))) begin : g_bad_xw
    $error("sgm_lane_timing: XW = %0d: XW must hold MIN_FRAME_WIDTH = %0d", XW, MIN_FRAME_WIDTH);
  end
  if (!(RW >= 2)) begin : g_bad_rw
    $error("sgm_lane_timing: RW = %0d: RW must be at least 2", RW);
  end
`endif

  localparam int LAGW      = $clog2(LR_LAG_MAX + 1);
  localparam int LAG_TERMS = (LR_WAIT - 1) / MIN_FRAME_WIDTH;

  // ------------------------------------------------------------ frame start
  // sof_cen: the raster census's first centre.
  logic sof_cen;
  sgm_delay #(.WIDTH(1), .DEPTH(CENSUS_LATENCY)) u_sof_delay (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (sof_i),
    .q_o   (sof_cen)
  );

  // ------------------------------------------------------------ raster census position
  // width - 4 registered, a cycle behind width_i (sgm_stream_ctrl changes the
  // width only while idle, cycles before a frame's first slot), so that one
  // adder sits in front of the delay.
  logic [XW-1:0] wm4_q;
  always_ff @(posedge clk_i) wm4_q <= width_i - XW'(4);
  wire          wrap   = col_i < XW'(4);
  wire [XW-1:0] cx     = wrap ? wm4_q + col_i : col_i - XW'(4);
  wire [RW-1:0] cy     = row_i - (wrap ? RW'(CENSUS_RY + 1) : RW'(CENSUS_RY));
  logic [XW-1:0] cen_col;
  logic [RW-1:0] cen_row;
  sgm_delay #(.WIDTH(XW + RW), .DEPTH(CENSUS_LATENCY)) u_cen_delay (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   ({cx, cy}),
    .q_o   ({cen_col, cen_row})
  );

  // ------------------------------------------------------------ LR_LAG
  // With MIN_FRAME_WIDTH >= LR_WAIT no m can hold (LR_LAG = 2K - 2 for every frame):
  // one constant 0 bit.
  localparam int NARROW_W = LAG_TERMS > 0 ? LAG_TERMS : 1;
  logic [NARROW_W-1:0] narrow;  // bit m - 1: m W < LR_WAIT
  if (LAG_TERMS == 0) begin : g_no_lag_term
    assign narrow = 1'b0;
  end
  for (genvar m = 1; m <= LAG_TERMS; m++) begin : g_lag_term
    assign narrow[m-1] = {{(32 - XW){1'b0}}, width_i} <= 32'((LR_WAIT - 1) / m);
  end

  logic [LAGW-1:0] lag_d, lag_q;
  always_comb begin
    lag_d = LAGW'(2 * LANES - 2);
    for (int m = 0; m < NARROW_W; m++) lag_d = lag_d + LAGW'(narrow[m]);
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      lag_q <= LAGW'(LR_LAG_MAX);
    end else if (en_i && sof_cen) begin
      lag_q <= lag_d;
    end
  end

  // ------------------------------------------------------------ read position
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_col_o <= cen_col;
      rd_row_o <= cen_row - RW'(lag_q);
    end
  end

endmodule
`default_nettype wire
