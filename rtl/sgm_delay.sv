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
