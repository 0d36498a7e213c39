// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_bank_ram: a simple dual-port memory of DEPTH words of WIDTH bits (one write port,
// one read port, one clock) for block RAM, split by address into two banks where that
// takes fewer block RAMs than one memory.
//
// Why: synthesis maps a memory with one block RAM geometry for its whole depth. A block
// RAM is widest at MIN_BANK = 512 words (ECP5 DP16KD 512 x 36, 7-series RAMB36 512 x 72)
// and half as wide at each doubling of its depth, so a wide memory costs block RAMs in
// proportion to its depth rounded up to a power of two: 1280 words as 2048 (ECP5, 576
// bits: 64 DP16KD). As a bank of 1024 words and one of 256 (a 512-word geometry) it
// takes 32 + 16. The banks are split when the second bank, rounded up to a power of two
// and to at least MIN_BANK, is smaller than the first (1280 = 1024 + 256, 1536 = 1024 +
// 512; not 1920 = 1024 + 896, nor 640 = 512 + 128, which take as many block RAMs whole)
// and the word is wider than a block RAM at MIN_BANK words of the narrowest device
// (36 bits): narrower words fill a block RAM's width whatever its depth.
//
// Read: the word at raddr_i is on rdata_o two enabled clocks later (the memory's
// registered read, then an output register; with banks the bank select sits between
// the two, one LUT level behind the block RAM's clock-to-out). A read of the address
// written in the same clock returns the old word. Writes and reads advance on en_i only.
//
// Parameters: WIDTH bits, DEPTH words (>= 2), AW address bits (>= $clog2(DEPTH)),
// MIN_BANK and MIN_BANK_WIDTH (a power of two, >= 1) the depth and width of the widest
// block RAM geometry.
// BANKED (read-only): 1 when the memory is built as two banks.
// Latency: 2 enabled clocks from raddr_i to rdata_o. Throughput: one read and one write
// per clock.
module sgm_bank_ram #(
  parameter int WIDTH = 8,
  parameter int DEPTH = 1280,
  parameter int AW    = $clog2(DEPTH),
  // The block RAM's widest geometry (see above); smaller in the formal proof only.
  parameter int MIN_BANK       = 512,
  parameter int MIN_BANK_WIDTH = 36,
  // The first bank: the largest power of two below DEPTH; the second: the rest.
  localparam int HI_DEPTH = 1 << ($clog2(DEPTH + 1) - 1),
  localparam int LO_DEPTH = DEPTH - HI_DEPTH,
  localparam int LO_ROUND = LO_DEPTH > MIN_BANK ? 1 << $clog2(LO_DEPTH) : MIN_BANK,
  localparam int BANKED /*verilator public*/ =
      LO_DEPTH > 0 && LO_ROUND < HI_DEPTH && WIDTH > MIN_BANK_WIDTH ? 1 : 0
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
  if (!(MIN_BANK >= 1 && (MIN_BANK & (MIN_BANK - 1)) == 0)) begin : g_bad_min_bank
    $error("sgm_bank_ram: MIN_BANK = %0d: MIN_BANK must be a power of two", MIN_BANK);
  end
  if (!(MIN_BANK_WIDTH >= 1)) begin : g_bad_min_bank_width
    $error("sgm_bank_ram: MIN_BANK_WIDTH = %0d: MIN_BANK_WIDTH must be at least 1", MIN_BANK_WIDTH);
  end
`endif

  if (BANKED == 0) begin : g_one
    logic [WIDTH-1:0] mem [0:DEPTH-1];
    logic [WIDTH-1:0] rd_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        rd_q    <= mem[raddr_i];
        rdata_o <= rd_q;
      end
    end
  end else begin : g_banks
    // Bank hi: addresses 0 .. HI_DEPTH - 1; bank lo: HI_DEPTH .. DEPTH - 1.
    // HI_DEPTH is a power of two and LO_DEPTH at most HI_DEPTH: a bank-lo word's
    // address is the low LO_AW bits of its address.
    localparam int HI_AW = $clog2(HI_DEPTH);
    localparam int LO_AW = LO_DEPTH > 1 ? $clog2(LO_DEPTH) : 1;
    logic [WIDTH-1:0] mem_hi [0:HI_DEPTH-1];
    logic [WIDTH-1:0] mem_lo [0:LO_DEPTH-1];
    logic [WIDTH-1:0] rd_hi_q, rd_lo_q;
    logic             sel_lo_q;
    wire              w_lo = waddr_i >= AW'(HI_DEPTH);
    wire              r_lo = raddr_i >= AW'(HI_DEPTH);
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        if (we_i && !w_lo) mem_hi[waddr_i[HI_AW-1:0]] <= wdata_i;
        if (we_i && w_lo) mem_lo[waddr_i[LO_AW-1:0]] <= wdata_i;
        rd_hi_q  <= mem_hi[raddr_i[HI_AW-1:0]];
        rd_lo_q  <= mem_lo[raddr_i[LO_AW-1:0]];
        sel_lo_q <= r_lo;
        rdata_o  <= sel_lo_q ? rd_lo_q : rd_hi_q;
      end
    end
  end

`ifdef SGM_FORMAL
  `include "sgm_bank_ram_props.svh"
`endif

endmodule
`default_nettype wire
