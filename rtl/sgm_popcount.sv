// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_popcount: number of ones in an N-bit census word (rank, and the Hamming
// distance of two signatures): 44 bits for the 9x5 census, 80 for the 9x9.
// LUT6-friendly: full adders on bit triples (with an xor in front, for the
// Hamming distance, each output is still one LUT6) give T = ceil(N / 3) sum bits
// of weight 1 and T carry bits of weight 2; groups of six of each are counted by
// 6:3 counters (one LUT6 per output bit), the group counts of each weight summed,
// and count = ones(sums) + 2 ones(carries). The counters are plain logic (no +),
// so that synthesis does not map them to carry chains; only the group sums are
// adders. (xc7, Yosys 0.23, with the xor: N = 44 60 LUTs + 4 CARRY4, N = 80
// 122 LUTs + 4 CARRY4.)
//
// The outputs are the two weighted counts (count = ones1_o + 2 ones2_o), which
// sgm_census_unit registers and adds in its next stage (the popcount with its
// final adder was one ECP5 clock of 10.1 ns in sgm_cost_pe, 9.4 ns in
// sgm_census_unit), and the group counts they are the sums of (groups_o:
// count = sum of the G weight-1 groups + 2 sum of the G weight-2 groups), which
// sgm_cost_pe registers instead: the xor, the full adders and the counters are
// then its whole stage A (the group sums behind them would be the LFE5U-85F
// five-lane core's critical path at 7.7 to 8.7 ns).
//
// Parameters: N input bits (>= 2); CNT_W = $clog2(N + 1) count bits;
// G = ceil(ceil(N / 3) / 6) groups per weight.
// Latency: 0 (combinational).
module sgm_popcount #(
  parameter int  N     = 44,
  localparam int CNT_W = $clog2(N + 1),
  localparam int T     = (N + 2) / 3,  // full adders on bit triples
  localparam int G     = (T + 5) / 6   // 6:3 counters per weight
) (
  input  wire  [N-1:0]     bits_i,
  output logic [CNT_W-1:0] ones1_o,  // ones of weight 1 (the triples' sum bits)
  output logic [CNT_W-2:0] ones2_o,  // ones of weight 2 (their carries; <= N / 2)
  // Group g of weight 1 at [3g +: 3], of weight 2 at [3(G + g) +: 3] (0 .. 6 each).
  output logic [6*G-1:0]   groups_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(N >= 2)) begin : g_bad_n
    $error("sgm_popcount: N = %0d: N must be at least 2", N);
  end
`endif

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

  wire [3*T-1:0] x = {{(3*T-N){1'b0}}, bits_i};

  // Level 1: {c1[i], s1[i]} = x[3i] + x[3i+1] + x[3i+2]; padded to whole groups of six.
  logic [6*G-1:0] s1, c1;
  for (genvar i = 0; i < 6 * G; i++) begin : g_fa
    if (i < T) begin : g_bits
      assign {c1[i], s1[i]} = fa(x[3*i +: 3]);
    end else begin : g_pad
      assign {c1[i], s1[i]} = 2'b00;
    end
  end

  // Group counts, summed per weight; count = ones(s1) + 2 ones(c1) (< 2^CNT_W).
  for (genvar g = 0; g < G; g++) begin : g_group
    assign groups_o[3*g +: 3]     = cnt6(s1[6*g +: 6]);
    assign groups_o[3*(G+g) +: 3] = cnt6(c1[6*g +: 6]);
  end
  logic [CNT_W-1:0] ones_s, ones_c;
  always_comb begin
    ones_s = '0;
    ones_c = '0;
    for (int g = 0; g < G; g++) begin
      ones_s = ones_s + CNT_W'(groups_o[3*g +: 3]);
      ones_c = ones_c + CNT_W'(groups_o[3*(G+g) +: 3]);
    end
  end

  assign ones1_o = ones_s;
  assign ones2_o = ones_c[CNT_W-2:0];

  logic unused;
  assign unused = ones_c[CNT_W-1];  // ones(c1) <= N / 2 < 2^(CNT_W - 1)

endmodule
`default_nettype wire
