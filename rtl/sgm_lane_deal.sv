// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_lane_deal: deals a raster slot stream to K row lanes (docs/lanes.md).
// Every slot writes its payload into a ring of ROWS rows (bank = row mod ROWS,
// address = column) and reads one back for the lane of the slot: slot K n + k
// belongs to lane k, lane k holds the rows y with (y + LANE_LEAD) mod K == k in
// order, each a raster of its own, and lane k starts SKEW x K slots after lane
// k - 1 (SKEW columns behind it). sof_i restarts the raster and the lanes: at
// that slot lane 0 is at column 0 of row -LANE_LEAD, lane k at row k -
// LANE_LEAD, each idle (valid_o = 0, column 0) until its start. LANE_LEAD must
// be large enough that a position is read after the raster wrote it, and ROWS
// that it is read before the raster overwrites it (tests/rtl/test_tb_lane_deal.cpp
// checks both for its builds; docs/lanes.md derives them).
//
// Inputs per slot (en_i): the raster position col_i / row_i (rows < 0 wrap in
// YW bits, consecutive slots are consecutive positions within a frame) and its
// payload. Outputs, one slot later: the lane slot's position, payload,
// valid_o (0 <= row < height_i, the lane started) and active_o (the lane
// started: its slots are positions of its raster, whatever the row).
// width_i is taken a cycle late (width - 1 is registered, so that no subtraction
// sits in front of the last-column comparison): it may change with sof_i,
// because no frame's column 0 is its last (width >= 2).
//
// Parameters: WIDTH payload bits, LANES (K >= 1), SKEW columns, LANE_LEAD rows,
// ROWS ring rows (a power of two), MAX_WIDTH, XW column bits, YW row bits.
// Latency: 1 slot (the ring's registered read). Throughput: one slot per en_i.
module sgm_lane_deal #(
  parameter int WIDTH     = 16,
  parameter int LANES     /*verilator public*/ = 2,
  parameter int SKEW      /*verilator public*/ = 3,
  parameter int LANE_LEAD /*verilator public*/ = 4,
  parameter int ROWS      /*verilator public*/ = 8,
  parameter int MAX_WIDTH = 128,
  parameter int XW        = 8,
  parameter int YW        = 8
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [XW-1:0]    width_i,
  input  wire  [YW-1:0]    height_i,
  // Raster side.
  input  wire              sof_i,
  input  wire  [WIDTH-1:0] data_i,
  input  wire  [XW-1:0]    col_i,
  input  wire  [YW-1:0]    row_i,
  // Lane side, one slot later.
  output logic [WIDTH-1:0] data_o,
  output logic [XW-1:0]    col_o,
  output logic [YW-1:0]    row_o,
  output logic             valid_o,
  output logic             active_o   // the lane has started (any row)
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(WIDTH >= 1)) begin : g_bad_width
    $error("sgm_lane_deal: WIDTH = %0d: WIDTH must be at least 1", WIDTH);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_lane_deal: LANES = %0d: LANES must be at least 1", LANES);
  end
  if (!(SKEW >= 1)) begin : g_bad_skew
    $error("sgm_lane_deal: SKEW = %0d: SKEW must be at least 1", SKEW);
  end
  if (!(LANE_LEAD >= 1 && LANE_LEAD >= LANES - 1)) begin : g_bad_lane_lead
    $error("sgm_lane_deal: LANE_LEAD = %0d: LANE_LEAD must be at least max(1, LANES - 1) (LANES = %0d)", LANE_LEAD, LANES);
  end
  if (!(ROWS >= 2 && ROWS >= 2 * LANES - 2 && (ROWS & (ROWS - 1)) == 0)) begin : g_bad_rows
    $error("sgm_lane_deal: ROWS = %0d: ROWS must be a power of two >= max(2, 2 LANES - 2) (LANES = %0d)", ROWS, LANES);
  end
  if (!(MAX_WIDTH >= 2)) begin : g_bad_max_width
    $error("sgm_lane_deal: MAX_WIDTH = %0d: MAX_WIDTH must be at least 2 (no frame's column 0 is its last)", MAX_WIDTH);
  end
  if (!(XW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_xw
    $error("sgm_lane_deal: XW = %0d: XW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", XW, MAX_WIDTH);
  end
  if (!(YW >= 2)) begin : g_bad_yw
    $error("sgm_lane_deal: YW = %0d: YW must be at least 2", YW);
  end
`endif

  localparam int BW  = $clog2(ROWS);
  localparam int AW  = $clog2(ROWS * MAX_WIDTH);
  localparam int WW  = $clog2(LANES * SKEW + 1);  // start countdown (rounds)
  localparam int LSW = 1 + WW + XW + YW;          // lane state {active, wait, col, row}

  // Column-major, {col, bank}: no multiplier in front of the ring's addresses (the
  // LFE5U-45F five-lane build's critical path ran from sof_i through bank x MAX_WIDTH +
  // col to the block RAM address).
  function automatic logic [AW-1:0] ring_addr(input logic [BW-1:0] bank, input logic [XW-1:0] col);
    ring_addr = AW'({col, bank});
  endfunction

  // ------------------------------------------------------------ raster side
  logic [WIDTH-1:0] ring [0:ROWS*MAX_WIDTH-1];
  always_ff @(posedge clk_i) begin
    if (en_i) ring[ring_addr(row_i[BW-1:0], col_i)] <= data_i;
  end

  // ------------------------------------------------------------ lane side
  // The lane states rotate through K registers: st_q[0] is the state of the
  // lane of this slot; after the slot it goes to the back, advanced.
  logic [LANES*LSW-1:0] st_q;

  // The state of lane k at the frame's first slot.
  function automatic logic [LSW-1:0] lane_init(input integer k);
    lane_init = {1'b0, WW'(k * SKEW), XW'(0), YW'(k - LANE_LEAD)};
  endfunction

  logic [LANES*LSW-1:0] st_init;
  for (genvar k = 0; k < LANES; k++) begin : g_init
    assign st_init[k*LSW +: LSW] = lane_init(k);
  end
  // A lane has started: its flag, or its start countdown at 0.
  function automatic logic started(input logic [LSW-1:0] st);
    started = st[LSW-1] || st[XW + YW +: WW] == '0;
  endfunction

  // The state after the lane's slot (last: the slot is its row's last column).
  function automatic logic [LSW-1:0] advance(input logic [LSW-1:0] st, input logic last);
    logic [WW-1:0] wait_n;
    logic [XW-1:0] col;
    logic [YW-1:0] row;
    {wait_n, col, row} = st[0 +: WW + XW + YW];
    advance = !started(st) ? {1'b0, wait_n - 1'b1, col, row} :
              last ? {1'b1, WW'(0), XW'(0), row + YW'(LANES)} :
                     {1'b1, WW'(0), col + 1'b1, row};
  endfunction

  // sof_i selects between the two results, each from registers or constants
  // (the state after the frame's first slot is a constant: lane 0 at column 0,
  // never its row's last, width >= 2), so that it is the last step in front of
  // the lane states rather than the first (a critical path of the five-lane
  // core on the LFE5U-85F ran from sof_i through the state update).
  logic [XW-1:0] wm1_q;  // width - 1, a cycle behind width_i
  always_ff @(posedge clk_i) wm1_q <= width_i - 1'b1;
  wire [LSW-1:0] cur_q    = st_q[0 +: LSW];
  wire [LSW-1:0] adv_q    = advance(cur_q, cur_q[YW +: XW] == wm1_q);
  wire [LSW-1:0] adv_init = advance(st_init[0 +: LSW], 1'b0);

  logic [LANES*LSW-1:0] st_d;
  if (LANES > 1) begin : g_rotate
    assign st_d = sof_i ? {adv_init, st_init[LANES*LSW-1:LSW]} : {adv_q, st_q[LANES*LSW-1:LSW]};
  end else begin : g_single
    assign st_d = sof_i ? adv_init : adv_q;
  end

  // The slot's lane state (its position, whether it started).
  wire [LSW-1:0] cur        = sof_i ? st_init[0 +: LSW] : cur_q;
  wire           cur_active = started(cur);
  wire [XW-1:0]  cur_col    = cur[YW +: XW];
  wire [YW-1:0]  cur_row    = cur[0 +: YW];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      st_q <= st_init;
    end else if (en_i) begin
      st_q <= st_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      data_o <= ring[ring_addr(cur_row[BW-1:0], cur_col)];
      col_o  <= cur_col;
      row_o  <= cur_row;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_o  <= 1'b0;
      active_o <= 1'b0;
    end else if (en_i) begin
      valid_o  <= cur_active && cur_row < height_i;
      active_o <= cur_active;
    end
  end

`ifdef SGM_FORMAL
  // The formal property set (tests/formal/sgm_lane_deal_props.svh; make formal, docs/formal.md).
`include "sgm_lane_deal_props.svh"
`endif

endmodule
`default_nettype wire
