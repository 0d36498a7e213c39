// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_delay_ram: DEPTH slots of delay for a wide WIDTH-bit bundle, advancing on
// en_i only, held in a small memory instead of a register chain: DEPTH - 1 words
// written and read at one rotating pointer (asynchronous read: distributed RAM),
// then an output register. Same behaviour as sgm_delay of the same DEPTH once
// DEPTH slots have passed since reset; the bundles of those first slots are
// undefined (as a register chain's power-up contents are).
//
// Why: Yosys maps a register chain of three or more slots to one SRL16E per bit
// on xc7 (a LUT each), a memory to RAM32M, which keeps 8 bits of a rotating
// delay in 4 LUTs (its write port reads at the same pointer): half the slice
// LUTs (docs/notes/synthesis-log.md). On ECP5 the memory becomes DPR16X4 (4 bits each),
// which takes six LUT positions (two slices of RAM, the write port's slice)
// for 4 bits: there a register chain is the cheaper form, since a flip-flop
// fed by a flip-flop takes no LUT position. Defining SGM_DELAY_CHAIN (the
// ECP5 flow does, synth/pnr.mk PNR_DEFINES) builds the register chain
// (sgm_delay) instead: the same values after DEPTH slots.
// Use it for the wide delays of the engine; narrow ones stay sgm_delay.
//
// Parameters: WIDTH bits, DEPTH slots (>= 1; DEPTH 1 is one register).
// Latency: DEPTH slots. Throughput: one bundle per slot.
module sgm_delay_ram #(
  parameter int WIDTH = 8,
  parameter int DEPTH = 3
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [WIDTH-1:0] d_i,
  output logic [WIDTH-1:0] q_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(WIDTH >= 1)) begin : g_bad_width
    $error("sgm_delay_ram: WIDTH = %0d: WIDTH must be at least 1", WIDTH);
  end
  if (!(DEPTH >= 1)) begin : g_bad_depth
    $error("sgm_delay_ram: DEPTH = %0d: DEPTH must be at least 1", DEPTH);
  end
`endif

`ifdef SGM_DELAY_CHAIN
  localparam bit CHAIN = 1'b1;
`else
  localparam bit CHAIN = 1'b0;
`endif

  if (DEPTH == 1) begin : g_one
    always_ff @(posedge clk_i) begin
      if (en_i) q_o <= d_i;
    end
    logic unused_rst;
    assign unused_rst = rst_ni;
  end else if (CHAIN) begin : g_chain
    sgm_delay #(.WIDTH(WIDTH), .DEPTH(DEPTH)) u_chain (
      .clk_i(clk_i),
      .en_i (en_i),
      .d_i  (d_i),
      .q_o  (q_o)
    );
    logic unused_rst;
    assign unused_rst = rst_ni;
  end else begin : g_ram
    localparam int WORDS = DEPTH - 1;
    localparam int PTRW  = WORDS > 1 ? $clog2(WORDS) : 1;
    logic [WIDTH-1:0] mem [0:WORDS-1];
    logic [PTRW-1:0]  ptr_q;

    // The word at the pointer was written WORDS slots ago.
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        mem[ptr_q] <= d_i;
        q_o        <= mem[ptr_q];
      end
    end

    always_ff @(posedge clk_i) begin
      if (!rst_ni) ptr_q <= '0;
      else if (en_i) ptr_q <= ptr_q == PTRW'(WORDS - 1) ? '0 : ptr_q + 1'b1;
    end

`ifdef SGM_FORMAL
    // The formal property set (tests/formal/sgm_delay_ram_props.svh; make formal, docs/formal.md).
`include "sgm_delay_ram_props.svh"
`endif
  end

endmodule
`default_nettype wire
