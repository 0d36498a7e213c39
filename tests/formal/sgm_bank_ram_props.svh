// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_bank_ram (make formal, docs/formal.md). Included at the
// end of the module when SGM_FORMAL is defined (tests/formal/bank_ram_*.sby: yosys read
// -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed: addresses below DEPTH; en_i, we_i, the addresses and the data free in every
// cycle. One address f_addr is chosen freely and held.
// Asserted (the module's contract, its header): a read of f_addr gives, two enabled clocks
// later, the word last written there before the read's clock (the old word when written
// in the same clock), whichever bank holds it. The invariants that close the induction:
// the memory word of f_addr (in its bank) is that word, and so is the read register of a
// read in flight (the bank select pointing at f_addr's bank).
// Covered: a read returning a word written earlier, in each bank; a read and a write of
// f_addr in one clock (the old word returned).

  (* anyconst *) logic [AW-1:0] f_addr;
  logic f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;
  always @(*) begin
    assume (32'(f_addr) < DEPTH);
    assume (32'(waddr_i) < DEPTH);
    assume (32'(raddr_i) < DEPTH);
  end

  // The word last written at f_addr (f_written: there was one), and the reads of f_addr in
  // flight: f_rd1 after the memory read, f_rd2 on rdata_o.
  logic             f_written = 1'b0, f_rd1 = 1'b0, f_rd2 = 1'b0;
  logic [WIDTH-1:0] f_word, f_rd1_word, f_rd2_word;
  always @(posedge clk_i) begin
    if (en_i) begin
      if (we_i && waddr_i == f_addr) begin
        f_written <= 1'b1;
        f_word    <= wdata_i;
      end
      f_rd1      <= f_written && raddr_i == f_addr;
      f_rd1_word <= f_word;
      f_rd2      <= f_rd1;
      f_rd2_word <= f_rd1_word;
    end
  end

  wire f_lo = 32'(f_addr) >= HI_DEPTH;
  always @(*) if (!f_init && f_rd2) assert (rdata_o == f_rd2_word);
  if (BANKED == 0) begin : g_f_one
    always @(*) begin
      if (!f_init && f_written) assert (g_one.mem[f_addr] == f_word);
      if (!f_init && f_rd1) assert (g_one.rd_q == f_rd1_word);
    end
  end else begin : g_f_banks
    always @(*) begin
      if (!f_init && f_written && !f_lo) assert (g_banks.mem_hi[f_addr[g_banks.HI_AW-1:0]] == f_word);
      if (!f_init && f_written && f_lo) assert (g_banks.mem_lo[f_addr[g_banks.LO_AW-1:0]] == f_word);
      if (!f_init && f_rd1) assert (g_banks.sel_lo_q == f_lo);
      if (!f_init && f_rd1) assert ((f_lo ? g_banks.rd_lo_q : g_banks.rd_hi_q) == f_rd1_word);
    end
  end

  always @(posedge clk_i) begin
    if (!f_init && f_rd2 && en_i && !f_lo) cover (rdata_o != '0);
    if (!f_init && f_rd2 && en_i && f_lo) cover (rdata_o != '0);
    if (!f_init && f_written && en_i && we_i && waddr_i == f_addr && raddr_i == f_addr && wdata_i != f_word)
      cover (1'b1);
  end
