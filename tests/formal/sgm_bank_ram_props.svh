// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_bank_ram (make formal, docs/formal.md). Included at the
// end of the module when SGM_FORMAL is defined (tests/formal/bank_ram_*.sby: yosys read
// -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed: addresses below DEPTH; en_i, we_i, the addresses and the data free in every
// cycle. One address f_addr is chosen freely and held.
// Asserted (the module's contract, its header): a read of f_addr gives, three enabled
// clocks later, the word last written there before the read's clock (the old word when
// written in the same clock), whichever bank holds it. The invariants that close the
// induction: the word of f_addr in its bank is that word; a read in flight has its bank
// number in the select registers and its word in the bank's read and hold registers.
// Covered: a read returning a word written earlier, from the first bank and from the
// last (shorter) one; a read and a write of f_addr in one clock (the old word returned).

  (* anyconst *) logic [AW-1:0] f_addr;
  logic f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;
  always @(*) begin
    assume (32'(f_addr) < DEPTH);
    assume (32'(waddr_i) < DEPTH);
    assume (32'(raddr_i) < DEPTH);
  end

  // The word last written at f_addr (f_written: there was one), and the reads of f_addr in
  // flight: f_rd[0] after the block RAM's read, f_rd[1] in the bank register, f_rd[2] on
  // rdata_o.
  logic             f_written = 1'b0;
  logic [2:0]       f_rd = '0;
  logic [WIDTH-1:0] f_word, f_rd_word [0:2];
  always @(posedge clk_i) begin
    if (en_i) begin
      if (we_i && waddr_i == f_addr) begin
        f_written <= 1'b1;
        f_word    <= wdata_i;
      end
      f_rd         <= {f_rd[1:0], f_written && raddr_i == f_addr};
      f_rd_word[0] <= f_word;
      f_rd_word[1] <= f_rd_word[0];
      f_rd_word[2] <= f_rd_word[1];
    end
  end

  wire [SELW-1:0] f_bank = bank_of(f_addr);
  always @(*) if (!f_init && f_rd[2]) assert (rdata_o == f_rd_word[2]);
  always @(*) if (!f_init && f_rd[0]) assert (sel_q == f_bank);
  always @(*) if (!f_init && f_rd[1]) assert (sel_bank_q == f_bank);
  for (genvar b = 0; b < NBANK; b++) begin : g_f_bank
    wire [g_bank[b].WAW-1:0] f_word_addr = f_addr[g_bank[b].WAW-1:0];
    always @(*) begin
      if (!f_init && f_written && f_bank == SELW'(b)) assert (g_bank[b].mem[f_word_addr] == f_word);
      if (!f_init && f_rd[0] && f_bank == SELW'(b)) assert (g_bank[b].rd_q == f_rd_word[0]);
      if (!f_init && f_rd[1] && f_bank == SELW'(b)) assert (g_bank[b].hold_q == f_rd_word[1]);
    end
  end

  always @(posedge clk_i) begin
    if (!f_init && f_rd[2] && en_i && f_bank == '0) cover (rdata_o != '0);
    if (!f_init && f_rd[2] && en_i && f_bank == SELW'(NBANK - 1)) cover (rdata_o != '0);
    if (!f_init && f_written && en_i && we_i && waddr_i == f_addr && raddr_i == f_addr && wdata_i != f_word)
      cover (1'b1);
  end
