// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_delay_ram's memory form (make formal, docs/formal.md).
// Included in its g_ram block when SGM_FORMAL is defined (tests/formal/delay_ram_*.sby:
// yosys read -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed: the first cycle is in reset. en_i and d_i are free in every cycle.
// Asserted (the module's contract, its header): once DEPTH slots have passed since reset,
// q_o is the d_i of the slot DEPTH slots before, and q_o changes only on a slot. The
// invariant that closes the induction: the word at i slots behind the pointer holds the
// input of the slot i + 1 slots ago, once that slot has passed since reset.
// Covered: DEPTH slots passed with a stall (en_i low) between two of them, and q_o
// carrying a value after a full pass.

  localparam int F_CW = $clog2(DEPTH + 1);
  logic [F_CW-1:0] f_t = '0;  // cycles since the start, saturating at DEPTH
  always @(posedge clk_i) if (32'(f_t) != DEPTH) f_t <= f_t + 1'b1;
  wire f_past_valid = f_t != '0;
  always @(*) if (!f_past_valid) assume (!rst_ni);

  // The inputs of the last DEPTH slots, the newest at [0], and how many slots have passed
  // since the last reset (saturating at DEPTH).
  logic [WIDTH-1:0] f_hist [0:DEPTH-1];
  logic [F_CW-1:0]  f_slots;
  always @(posedge clk_i) begin
    if (en_i) begin
      f_hist[0] <= d_i;
      for (int i = 1; i < DEPTH; i++) f_hist[i] <= f_hist[i - 1];
    end
    if (!rst_ni) f_slots <= '0;
    else if (en_i && 32'(f_slots) != DEPTH) f_slots <= f_slots + 1'b1;
  end

  always @(*) begin
    if (f_past_valid && 32'(f_slots) == DEPTH) assert (q_o == f_hist[DEPTH-1]);
    if (f_past_valid) assert (32'(ptr_q) < WORDS);
  end
  for (genvar i = 0; i < WORDS; i++) begin : g_f_word
    wire [PTRW-1:0] f_at = 32'(ptr_q) >= i + 1 ? PTRW'(32'(ptr_q) - (i + 1)) : PTRW'(32'(ptr_q) + WORDS - (i + 1));
    always @(*) if (f_past_valid && 32'(f_slots) > i) assert (mem[f_at] == f_hist[i]);
  end
  always @(posedge clk_i) begin
    if (f_past_valid && !$past(en_i)) assert (q_o == $past(q_o));
    if (f_past_valid && 32'(f_slots) == DEPTH && $past(32'(f_slots) == DEPTH - 1) && $past(!en_i, 2))
      cover (1'b1);
    if (f_past_valid && 32'(f_slots) == DEPTH) cover (q_o != '0 && $past(q_o) != q_o);
  end
