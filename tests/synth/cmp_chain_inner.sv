// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// The inner module of tests/synth/cmp_chain_case.sv (`make ecp5-cmp-check`):
// comparisons that SYNTH_ECP5_CMP_CHAIN=cmp_chain_inner.sv keeps as carry
// chains, in each of the two instances.
module cmp_chain_inner (
  input  wire [7:0] a_i,
  input  wire [7:0] b_i,
  input  wire [3:0] c_i,
  output wire [2:0] y_o
);
  assign y_o[0] = a_i < b_i;
  assign y_o[1] = a_i >= {4'b0, c_i};
  assign y_o[2] = b_i > 8'd100;
endmodule
`default_nettype wire
