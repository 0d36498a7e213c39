// SPDX-License-Identifier: Apache-2.0
// Comparisons of every kind that synth/ecp5_cmp_lut.v maps (and two it leaves
// to synth_ecp5: wider than the limit), for `make ecp5-cmp-check`: the mapped
// module must equal this one (Yosys equiv_make / equiv_simple).
module cmp_cases (
  input  wire        [8:0]  a,
  input  wire        [8:0]  b,
  input  wire        [3:0]  c,
  input  wire signed [6:0]  sa,
  input  wire signed [6:0]  sb,
  input  wire        [11:0] w,
  input  wire        [12:0] v,
  output wire        [17:0] y
);
  assign y[0]  = a < b;
  assign y[1]  = a <= b;
  assign y[2]  = a > b;
  assign y[3]  = a >= b;
  assign y[4]  = c < a;                  // operands of different widths
  assign y[5]  = a >= c;
  assign y[6]  = sa < sb;                // signed
  assign y[7]  = sa >= sb;
  assign y[8]  = sa > sb;
  assign y[9]  = sa <= sb;
  assign y[10] = sa < $signed(c);
  assign y[11] = a < 9'd77;              // a constant operand
  assign y[12] = w < v;                  // 13 bits: left to synth_ecp5
  assign y[13] = w >= {3'b0, a};         // 12 bits: the limit
  assign y[14] = sa > -7'sd3;
  assign y[15] = $signed(w) <= $signed(v);
  assign y[16] = sa < $signed({1'b0, c}); // signed with a positive operand
  assign y[17] = {1'b0, c} > b;
endmodule
