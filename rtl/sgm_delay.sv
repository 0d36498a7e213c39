// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_delay: DEPTH slots of delay for a WIDTH-bit bundle, advancing on en_i
// only (docs/rtl.md, step stream). Aligns side signals with a stage's latency.
//
// Parameters: WIDTH bits, DEPTH slots (>= 1).
// Latency: DEPTH slots. Throughput: one bundle per slot.
module sgm_delay #(
  parameter int WIDTH = 8,
  parameter int DEPTH = 1
) (
  input  wire              clk_i,
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
    $error("sgm_delay: WIDTH = %0d: WIDTH must be at least 1", WIDTH);
  end
  if (!(DEPTH >= 1)) begin : g_bad_depth
    $error("sgm_delay: DEPTH = %0d: DEPTH must be at least 1", DEPTH);
  end
`endif

  // One packed shift register, newest bundle in the low WIDTH bits. (Icarus 11
  // does not propagate a word of an unpacked array written in a for loop to a
  // continuous assignment.)
  logic [DEPTH*WIDTH-1:0] stage_q;

  if (DEPTH == 1) begin : g_one
    always_ff @(posedge clk_i) begin
      if (en_i) stage_q <= d_i;
    end
  end else begin : g_shift
    always_ff @(posedge clk_i) begin
      if (en_i) stage_q <= {stage_q[(DEPTH-1)*WIDTH-1:0], d_i};
    end
  end

  assign q_o = stage_q[DEPTH*WIDTH-1 -: WIDTH];

endmodule
`default_nettype wire
