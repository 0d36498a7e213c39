`default_nettype none
// sgm_popcount80: number of ones in an 80-bit census word (rank, and the
// Hamming distance of two signatures), as a LUT6-friendly compressor tree.
// Level 1 puts full adders (3:2 counters) on bit triples: with an xor in
// front (Hamming distance) each is one LUT6 per output. The later levels
// count up to 6 bits of one weight with a 6:3 counter (one LUT6 per output
// bit) until every weight holds at most two bits; a 7-bit adder adds the two
// rows. The counters are plain logic (no +), so that synthesis does not map
// them to carry chains.
//
// Latency: 0 (combinational).
module sgm_popcount80 (
  input  wire  [79:0] bits_i,
  output logic [6:0]  count_o
);

  // {carry, sum} of three bits.
  function automatic [1:0] fa(input [2:0] v);
    fa = {(v[0] & v[1]) | (v[0] & v[2]) | (v[1] & v[2]), ^v};
  endfunction

  // Number of ones in six bits (0 .. 6).
  function automatic [2:0] cnt6(input [5:0] v);
    logic [1:0] a, b;
    logic       c;
    a    = fa(v[2:0]);
    b    = fa(v[5:3]);
    c    = a[0] & b[0];
    cnt6 = {(a[1] & b[1]) | (a[1] & c) | (b[1] & c), a[1] ^ b[1] ^ c, a[0] ^ b[0]};
  endfunction

  wire [79:0] x = bits_i;

  // Level 1: {c1[i], s1[i]} = x[3i] + x[3i+1] + x[3i+2], i = 0 .. 25
  // (x[78] and x[79] go on to level 2). Weights: s1 1, c1 2.
  logic [25:0] s1, c1;
  for (genvar i = 0; i < 26; i++) begin : g_l1
    assign {c1[i], s1[i]} = fa({x[3*i], x[3*i+1], x[3*i+2]});
  end

  // Level 2: groups of six. s2_j = sum of s1[6j +: 6] (weights 1, 2, 4),
  // c2_j = sum of c1[6j +: 6] (weights 2, 4, 8), j = 0 .. 3.
  logic [11:0] s2, c2;
  for (genvar j = 0; j < 4; j++) begin : g_l2
    assign s2[3*j +: 3] = cnt6(s1[6*j +: 6]);
    assign c2[3*j +: 3] = cnt6(c1[6*j +: 6]);
  end
  wire [2:0] r2 = cnt6({2'b0, s1[24], s1[25], x[78], x[79]});  // weights 1, 2, 4

  // Level 3.
  wire [2:0] l3_0 = cnt6({1'b0, s2[0], s2[3], s2[6], s2[9], r2[0]});       // weights 1, 2, 4
  wire [2:0] l3_1 = cnt6({s2[1], s2[4], s2[7], s2[10], r2[1], c2[0]});     // weights 2, 4, 8
  wire [2:0] l3_2 = cnt6({1'b0, c2[3], c2[6], c2[9], c1[24], c1[25]});     // weights 2, 4, 8
  wire [2:0] l3_3 = cnt6({s2[2], s2[5], s2[8], s2[11], r2[2], c2[1]});     // weights 4, 8, 16
  wire [1:0] l3_4 = fa({c2[4], c2[7], c2[10]});                            // weights 4, 8
  wire [2:0] l3_5 = cnt6({2'b0, c2[2], c2[5], c2[8], c2[11]});             // weights 8, 16, 32

  // Levels 4 to 6.
  wire [1:0] l4_0 = fa({l3_0[1], l3_1[0], l3_2[0]});                       // weights 2, 4
  wire [2:0] l4_1 = cnt6({1'b0, l3_0[2], l3_1[1], l3_2[1], l3_3[0], l3_4[0]}); // weights 4, 8, 16
  wire [2:0] l4_2 = cnt6({1'b0, l3_1[2], l3_2[2], l3_3[1], l3_4[1], l3_5[0]}); // weights 8, 16, 32
  wire [2:0] l5_0 = cnt6({2'b0, l4_1[2], l4_2[1], l3_3[2], l3_5[1]});     // weights 16, 32, 64
  wire [1:0] l6_0 = fa({l5_0[1], l4_2[2], l3_5[2]});                       // weights 32, 64

  // Two rows left: add them.
  assign count_o = {l6_0, l5_0[0], l4_1[1], l4_0, l3_0[0]} +
                   {l5_0[2], 2'b0, l4_2[0], l4_1[0], 2'b0};

endmodule
`default_nettype wire
