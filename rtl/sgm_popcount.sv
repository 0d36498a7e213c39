`default_nettype none
// sgm_popcount: number of ones in an N-bit census word (rank, and the Hamming
// distance of two signatures): 44 bits for the 9x5 census, 80 for the 9x9.
// LUT6-friendly: groups of six bits are counted by a 6:3 counter (full adders on
// bit triples, one LUT6 per output bit; with an xor in front for the Hamming
// distance each input group still fits); the ceil(N / 6) group counts are then
// added by a balanced tree of adders (level l adds pairs of (3 + l)-bit sums).
//
// Parameters: N input bits (>= 1); CNT_W = $clog2(N + 1) output bits.
// Latency: 0 (combinational).
module sgm_popcount #(
  parameter int  N     = 44,
  localparam int CNT_W = $clog2(N + 1)
) (
  input  wire  [N-1:0]     bits_i,
  output logic [CNT_W-1:0] count_o
);

  localparam int G      = (N + 5) / 6;                  // groups of six bits
  localparam int LEVELS = G > 1 ? $clog2(G) : 0;        // adder tree levels
  localparam int LEAVES = 1 << LEVELS;                  // groups padded to a power of two
  localparam int SW     = 3 + LEVELS;                   // width of every tree node (>= CNT_W)

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

  wire [6*LEAVES-1:0] x = {{(6*LEAVES-N){1'b0}}, bits_i};

  // Heap order: node k (k = 1 .. 2 LEAVES - 1) at node[(k-1) * SW +: SW], its
  // children 2k and 2k + 1; the leaves are k = LEAVES .. 2 LEAVES - 1, the root k = 1.
  logic [(2*LEAVES-1)*SW-1:0] node /*verilator split_var*/;
  for (genvar i = 0; i < LEAVES; i++) begin : g_leaf
    assign node[(LEAVES+i-1)*SW +: SW] = SW'(cnt6(x[6*i +: 6]));
  end
  for (genvar k = LEAVES - 1; k >= 1; k--) begin : g_add
    assign node[(k-1)*SW +: SW] = node[(2*k-1)*SW +: SW] + node[(2*k)*SW +: SW];
  end

  assign count_o = node[0 +: CNT_W];  // the root; its bits above CNT_W are 0 (N < 2^CNT_W)

endmodule
`default_nettype wire
