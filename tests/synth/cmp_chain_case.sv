// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// `make ecp5-cmp-check`: the comparison map's carry-chain exception
// (synth/ecp5_cmp.tcl, SYNTH_ECP5_CMP_CHAIN). Two instances of
// cmp_chain_inner (3 comparisons each, kept) beside 2 comparisons of its own
// (mapped to LUT logic).
module cmp_chain_case (
  input  wire [7:0] a_i,
  input  wire [7:0] b_i,
  input  wire [3:0] c_i,
  output wire [7:0] y_o
);
  cmp_chain_inner u_first  (.a_i(a_i), .b_i(b_i), .c_i(c_i), .y_o(y_o[2:0]));
  cmp_chain_inner u_second (.a_i(b_i), .b_i(a_i), .c_i(~c_i), .y_o(y_o[5:3]));
  assign y_o[6] = a_i <= b_i;
  assign y_o[7] = {4'b0, c_i} < b_i;
endmodule
`default_nettype wire
