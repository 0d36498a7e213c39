`default_nettype none
// sgm_min_tree: combinational minimum of N unsigned values (ternary comparator
// tree, ceil(log3 N) levels: each node compares its three inputs pairwise and
// selects with one 3:1 mux, fewer LUTs and levels than a binary tree). Used for min Lr of every path (docs/algorithm.md
// section 5); in the 0 degree path it sits inside the single-cycle recursion.
//
// Parameters: N inputs (>= 1), W bits each.
// Latency: 0 (combinational). Throughput: one minimum per cycle.
module sgm_min_tree #(
  parameter int N = 64,
  parameter int W = 9
) (
  input  wire  [N*W-1:0] values_i,  // value i in values_i[i*W +: W]
  output logic [W-1:0]   min_o
);

  // Nodes of a complete ternary tree over P = 3^LEVELS leaves, heap order:
  // node 0 is the root, node n has children 3n+1 .. 3n+3, leaves are
  // I .. I+P-1 with I = (P-1)/2 inner nodes. Missing leaves hold all ones and
  // never win (synthesis folds them away).
  function automatic integer log3_ceil(input integer n);
    integer p;
    log3_ceil = 0;
    for (p = 1; p < n; p = p * 3) log3_ceil = log3_ceil + 1;
  endfunction

  localparam int LEVELS = log3_ceil(N);
  localparam int P      = 3 ** LEVELS;
  localparam int I      = (P - 1) / 2;

  // split_var: each node is its own variable for Verilator (no false loop).
  logic [(I+P)*W-1:0] node /* verilator split_var */;

  for (genvar i = 0; i < P; i++) begin : g_leaf
    if (i < N) begin : g_used
      assign node[(I+i)*W +: W] = values_i[i*W +: W];
    end else begin : g_pad
      assign node[(I+i)*W +: W] = {W{1'b1}};
    end
  end

  for (genvar n = 0; n < I; n++) begin : g_node
    wire [W-1:0] a  = node[(3*n+1)*W +: W];
    wire [W-1:0] b  = node[(3*n+2)*W +: W];
    wire [W-1:0] c  = node[(3*n+3)*W +: W];
    wire         ab = a <= b;
    wire         ac = a <= c;
    wire         bc = b <= c;
    assign node[n*W +: W] = ab && ac ? a : bc ? b : c;
  end

  assign min_o = node[0 +: W];

endmodule
`default_nettype wire
