// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_lane_deal (make formal, docs/formal.md). Included at the
// end of the module's body when SGM_FORMAL is defined (tests/formal/lane_deal_*.sby: yosys
// read -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed: the first cycle is in reset; width_i (2 .. MAX_WIDTH) and height_i change only in
// the cycle of a frame's first slot (en_i and sof_i); a frame has fewer than F_MAX slots.
// en_i, sof_i, the raster positions and the payload are free.
// Asserted, the slot order of the module's header and docs/lanes.md written from the slot
// count n since the frame's first slot (n = 0 at sof_i), not from the module's lane states:
// slot n belongs to lane k = n mod K; lane k's slots before its start are the first
// k SKEW of its own (it starts SKEW x K slots after lane k - 1); its p-th slot after its
// start is the raster position p of its rows: column p mod W, row k - LANE_LEAD +
// K (p div W) (rows < 0 wrap in YW bits). One slot later col_o / row_o are the slot's
// position (column 0 and row k - LANE_LEAD before the start), active_o whether the lane
// has started, valid_o = active_o and 0 <= row < height. Outputs change only on a slot.
// The invariant that closes the induction: every lane's state is the one that formula
// gives after n slots. The payload (the ring's read after write, before overwrite) is the
// simulation's (tests/rtl/test_sgm_lane_deal.cpp).
// Covered: the last lane starting, a lane wrapping from a row's last column to its next
// row, a slot after a stall, a new frame restarting the lanes mid-frame.

  localparam int F_NW  = 9;                 // bits of the slot count
  localparam int F_MAX = (1 << F_NW) - 2;   // a frame's slots stay below this (assumed)

  logic [1:0] f_t = 2'd0;
  always @(posedge clk_i) if (f_t != 2'd3) f_t <= f_t + 2'd1;
  wire f_past_valid = f_t != 2'd0;

  logic [F_NW-1:0] f_n;       // slots since the frame's first slot (since reset before one)
  logic [XW-1:0]   f_w;       // width_i of the cycle before
  always @(posedge clk_i) begin
    if (!rst_ni) f_n <= '0;
    else if (en_i) f_n <= sof_i ? F_NW'(1) : f_n + 1'b1;
    f_w <= width_i;
  end

  always @(*) begin
    if (!f_past_valid) assume (!rst_ni);
    assume (32'(width_i) >= 2 && 32'(width_i) <= MAX_WIDTH);
    if (en_i && !sof_i) assume (32'(f_n) < F_MAX);
  end
  always @(posedge clk_i) begin
    if (f_past_valid && !(en_i && sof_i)) assume (width_i == $past(width_i) && height_i == $past(height_i));
  end

  // Lane k's state after n slots of its frame (before slot n): {started flag, start
  // countdown, column, row}, as the header defines it.
  function automatic logic [LSW-1:0] f_state(input logic [F_NW-1:0] k, input logic [F_NW-1:0] n,
                                              input logic [XW-1:0] w);
    logic [F_NW-1:0] m, s, p, q, qk;
    logic            started_flag;
    logic [WW-1:0]   countdown;
    logic [XW-1:0]   col;
    logic [YW-1:0]   row;
    m   = n > k ? (n - 1'b1 - k) / F_NW'(LANES) + 1'b1 : '0;  // lane k's slots among 0 .. n - 1
    s   = k * F_NW'(SKEW);
    p   = m - s;
    q   = p / F_NW'(w);
    qk  = q * F_NW'(LANES);
    row = k[YW-1:0] - LANE_LEAD[YW-1:0];
    col = '0;
    countdown = '0;
    started_flag = m > s;
    if (m > s) begin
      col = XW'(p % F_NW'(w));
      row = row + qk[YW-1:0];
    end else begin
      countdown = WW'(s - m);
    end
    f_state = {started_flag, countdown, col, row};
  endfunction

  // The lane of the next slot is f_n mod K; st_q[j] holds lane (f_n + j) mod K.
  logic [LANES*LSW-1:0] f_expect;
  for (genvar j = 0; j < LANES; j++) begin : g_f_lane
    assign f_expect[j*LSW +: LSW] = f_state((f_n % F_NW'(LANES) + F_NW'(j)) % F_NW'(LANES), f_n, f_w);
  end
  always @(*) if (f_past_valid) assert (st_q == f_expect);
  always @(*) if (f_past_valid) assert (wm1_q == f_w - 1'b1);

  // The slot of this cycle: its lane's state before the slot.
  wire [F_NW-1:0] f_slot_n  = sof_i ? '0 : f_n;
  wire [LSW-1:0]  f_slot_st = f_state(f_slot_n % F_NW'(LANES), f_slot_n, f_w);
  wire            f_started = f_slot_st[LSW-1] || f_slot_st[XW + YW +: WW] == '0;
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni) begin
      if ($past(en_i)) begin
        assert (col_o == $past(f_slot_st[YW +: XW]) && row_o == $past(f_slot_st[0 +: YW]));
        assert (active_o == $past(f_started));
        assert (valid_o == $past(f_started && f_slot_st[0 +: YW] < height_i));
      end else begin
        assert (col_o == $past(col_o) && row_o == $past(row_o) && active_o == $past(active_o) &&
                valid_o == $past(valid_o) && data_o == $past(data_o));
      end
    end
  end

  // ------------------------------------------------------------ covers
  always @(posedge clk_i) begin
    if (f_past_valid && rst_ni && $past(rst_ni)) begin
      cover ($past(en_i) && active_o && row_o == YW'(LANES - 1 - LANE_LEAD) && col_o == '0 &&
             $past(f_n % F_NW'(LANES)) == F_NW'(LANES - 1));
      cover ($past(en_i) && active_o && col_o == '0 && $past(f_slot_st[LSW-1]) && row_o != YW'(LANES - 1 - LANE_LEAD) &&
             $past(f_n % F_NW'(LANES)) == F_NW'(LANES - 1));
      cover ($past(en_i) && !$past(en_i, 2) && $past(en_i, 3) && active_o);
      cover ($past(en_i && sof_i) && $past(f_n) > F_NW'(LANES));
    end
  end
