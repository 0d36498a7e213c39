// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_bank_ram: a simple dual-port memory (one write port, one read port, one clock)
// of DEPTH words of WIDTH bits, built as banks of one block RAM's depth, each read
// into a register of its own, the bank selected a clock later.
//
// Why: synthesis builds a deep memory from block RAMs stacked in depth with a
// multiplexer behind their outputs, so one clock holds the block RAM's clock-to-out,
// the route from block RAMs spread over the device and the multiplexer's LUT levels
// (the LR check's word memory, 16 block RAMs deep at six lanes, was the D = 64 core's
// critical path on the LFE5U-85F: 4.26 ns clock-to-out, 4 ns of route, four LUT
// levels). Here each bank's read word goes into a register of its own, which the
// placer puts beside its block RAM, and the multiplexer runs from those registers in
// the next clock. The banks hold exactly the words a single memory would (the last one
// may be shorter), so the block RAM count does not change.
//
// Banks: BANK words, the depth of one 18-Kbit block RAM (ECP5 DP16KD, Xilinx RAMB18)
// in its narrowest geometry that holds WIDTH bits: 16384, 8192, 4096, 2048, 1024 words
// for up to 1, 2, 4, 9, 18 bits, 512 words beyond (36 bits; wider words take block RAMs
// side by side). The bank of address a is a / BANK, its word a mod BANK (bit fields).
//
// Read: the word at raddr_i (below DEPTH) is on rdata_o after the third enabled clock
// from raddr_i's (the block RAM's registered read, the bank's register, the select
// register), also with one bank, so that a user's pipeline does not depend on the
// parameters. A read of the address written in the same clock returns the old word.
// An address at or above DEPTH reads an undefined word. Writes and reads advance on
// en_i only.
//
// Parameters: WIDTH bits (>= 1), DEPTH words (>= 2), AW address bits (>= $clog2(DEPTH)),
// BANK words per bank (a power of two; the default follows WIDTH as above, smaller in
// the formal proof only), LATENCY the read latency the user expects (must be 3: the
// module checks its user's pipeline).
// Latency: 3 enabled clocks from raddr_i to rdata_o. Throughput: one read and one write
// per clock.
module sgm_bank_ram #(
  parameter int WIDTH   = 18,
  parameter int DEPTH   = 2048,
  parameter int AW      = $clog2(DEPTH),
  parameter int BANK    = WIDTH <= 1 ? 16384 : WIDTH <= 2 ? 8192 : WIDTH <= 4 ? 4096 :
                          WIDTH <= 9 ? 2048 : WIDTH <= 18 ? 1024 : 512,
  parameter int LATENCY = 3,
  localparam int NBANK  = (DEPTH + BANK - 1) / BANK,
  localparam int SELW   = NBANK > 1 ? $clog2(NBANK) : 1
) (
  input  wire              clk_i,
  input  wire              en_i,
  input  wire              we_i,
  input  wire  [AW-1:0]    waddr_i,
  input  wire  [WIDTH-1:0] wdata_i,
  input  wire  [AW-1:0]    raddr_i,
  output logic [WIDTH-1:0] rdata_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(WIDTH >= 1)) begin : g_bad_width
    $error("sgm_bank_ram: WIDTH = %0d: WIDTH must be at least 1", WIDTH);
  end
  if (!(DEPTH >= 2)) begin : g_bad_depth
    $error("sgm_bank_ram: DEPTH = %0d: DEPTH must be at least 2", DEPTH);
  end
  if (!(AW >= $clog2(DEPTH))) begin : g_bad_aw
    $error("sgm_bank_ram: AW = %0d: AW must hold DEPTH = %0d words (at least $clog2(DEPTH) bits)", AW, DEPTH);
  end
  if (!(BANK >= 2 && (BANK & (BANK - 1)) == 0)) begin : g_bad_bank
    $error("sgm_bank_ram: BANK = %0d: BANK must be a power of two >= 2", BANK);
  end
  if (!(LATENCY == 3)) begin : g_bad_latency
    $error("sgm_bank_ram: LATENCY = %0d: the read latency is 3 (the block RAM, the bank register, the select)", LATENCY);
  end
`endif

  // The address split into bank and word: bit fields (BANK a power of two).
  function automatic logic [SELW-1:0] bank_of(input logic [AW-1:0] a);
    bank_of = SELW'(32'(a) / BANK);
  endfunction

  logic [SELW-1:0]  sel_q, sel_bank_q;   // the read's bank, a clock and two clocks later
  logic [WIDTH-1:0] bank_word [0:NBANK-1];

  for (genvar b = 0; b < NBANK; b++) begin : g_bank
    localparam int WORDS = b < NBANK - 1 ? BANK : DEPTH - (NBANK - 1) * BANK;
    logic [WIDTH-1:0] mem [0:WORDS-1];
    logic [WIDTH-1:0] rd_q;     // the block RAM's registered read
    logic [WIDTH-1:0] hold_q;   // the bank's register
    localparam int WAW = WORDS > 1 ? $clog2(WORDS) : 1;   // the bank's address bits
    wire  [WAW-1:0]   waddr = waddr_i[WAW-1:0];
    wire  [WAW-1:0]   raddr = raddr_i[WAW-1:0];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        if (we_i && bank_of(waddr_i) == SELW'(b)) mem[waddr] <= wdata_i;
        rd_q   <= mem[raddr];
        hold_q <= rd_q;
      end
    end
    assign bank_word[b] = hold_q;
  end

  // The select: a for loop over the banks rather than an index, so that a bank number
  // past the last (an address at or above DEPTH) gives zeros, not X, in simulation.
  logic [WIDTH-1:0] selected;
  always_comb begin
    selected = '0;
    for (int b = 0; b < NBANK; b++) if (sel_bank_q == SELW'(b)) selected = bank_word[b];
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sel_q      <= bank_of(raddr_i);
      sel_bank_q <= sel_q;
      rdata_o    <= selected;
    end
  end

`ifdef SGM_FORMAL
  `include "sgm_bank_ram_props.svh"
`endif

endmodule
`default_nettype wire
