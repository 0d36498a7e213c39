`default_nettype none
// sgm_popcount44: number of ones in a 44-bit census word (rank, and the
// Hamming distance of two signatures), as a LUT6-friendly compressor tree.
// Level 1 puts full adders (3:2 counters) on bit triples: with an xor in
// front (Hamming distance) each is one LUT6 per output. The later levels
// count up to 6 bits of one weight with a 6:3 counter (one LUT6 per output
// bit) until every weight holds at most two bits; a 6-bit adder adds the two
// rows. The counters are plain logic (no +), so that synthesis does not map
// them to carry chains.
//
// Latency: 0 (combinational).
module sgm_popcount44 (
  input  wire  [43:0] bits_i,
  output logic [5:0]  count_o
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

  wire [43:0] x = bits_i;

  // Level 1: {c1[i], s1[i]} = x[3i] + x[3i+1] + x[3i+2], i = 0 .. 13
  // (x[42] and x[43] go on to level 2). Weights: s1 1, c1 2.
  logic [13:0] s1, c1;
  for (genvar i = 0; i < 14; i++) begin : g_l1
    assign {c1[i], s1[i]} = fa({x[3*i], x[3*i+1], x[3*i+2]});
  end

  // Level 2: a_j = ones of weight 1 (weights 1, 2, 4), b_j = ones of weight 2
  // (weights 2, 4, 8).
  wire [2:0] a0 = cnt6(s1[5:0]);
  wire [2:0] a1 = cnt6(s1[11:6]);
  wire [2:0] a2 = cnt6({2'b0, s1[12], s1[13], x[42], x[43]});
  wire [2:0] b0 = cnt6(c1[5:0]);
  wire [2:0] b1 = cnt6(c1[11:6]);
  wire [1:0] b2 = fa({1'b0, c1[12], c1[13]});                      // weights 2, 4

  // Level 3, per weight: 1 (3 bits), 2 (6), 4 (6), 8 (2).
  wire [1:0] l3_1 = fa({a0[0], a1[0], a2[0]});                      // weights 1, 2
  wire [2:0] l3_2 = cnt6({a0[1], a1[1], a2[1], b0[0], b1[0], b2[0]}); // weights 2, 4, 8
  wire [2:0] l3_4 = cnt6({a0[2], a1[2], a2[2], b0[1], b1[1], b2[1]}); // weights 4, 8, 16

  // Level 4: weight 8 holds four bits.
  wire [2:0] l4_8 = cnt6({2'b0, l3_2[2], l3_4[1], b0[2], b1[2]});   // weights 8, 16, 32

  // Two rows left (weight: 1 | 2 2 | 4 4 | 8 | 16 16 | 32): add them.
  assign count_o = {l4_8[2], l4_8[1], l4_8[0], l3_4[0], l3_2[0], l3_1[0]} +
                   {1'b0, l3_4[2], 1'b0, l3_2[1], l3_1[1], 1'b0};

endmodule
`default_nettype wire
