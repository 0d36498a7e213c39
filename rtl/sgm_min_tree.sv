`default_nettype none
// sgm_min_tree: combinational minimum of N unsigned values (comparator tree,
// ceil(log2 N) levels). Used for min Lr of every path (docs/algorithm.md
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

  // Nodes of a complete binary tree over P = 2^ceil(log2 N) leaves, heap order:
  // node 1 is the root, node n has children 2n and 2n+1, leaves are P .. 2P-1.
  // Missing leaves hold all ones and never win.
  localparam int LEVELS = $clog2(N);
  localparam int P      = 1 << LEVELS;

  // split_var: each node is its own variable for Verilator (no false loop).
  logic [2*P*W-1:W] node /* verilator split_var */;

  for (genvar i = 0; i < P; i++) begin : g_leaf
    if (i < N) begin : g_used
      assign node[(P+i)*W +: W] = values_i[i*W +: W];
    end else begin : g_pad
      assign node[(P+i)*W +: W] = {W{1'b1}};
    end
  end

  for (genvar n = 1; n < P; n++) begin : g_node
    wire [W-1:0] a = node[(2*n)*W +: W];
    wire [W-1:0] b = node[(2*n+1)*W +: W];
    assign node[n*W +: W] = b < a ? b : a;
  end

  if (P == 1) begin : g_single
    assign min_o = values_i[0 +: W];
  end else begin : g_tree
    assign min_o = node[1*W +: W];
  end

endmodule
`default_nettype wire
