// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_min_tree: combinational minimum of N unsigned values, a tree of
// ARITY-input nodes (ceil(log_ARITY N) levels). A node compares its inputs
// pairwise, all comparisons side by side, and selects with one ARITY:1 mux:
// fewer levels than a binary tree for about the same LUTs. ARITY = 3 (the
// default) is the tree of the 45/90/135 degree path minima; sgm_path_ring
// builds the 0 degree loop's tree from 4-input nodes (N = 4, ARITY = 4),
// one level fewer at D = 64 (docs/algorithm.md section 5).
//
// Parameters: N inputs (>= 1), W bits each, ARITY node inputs (3 or 4).
// Latency: 0 (combinational). Throughput: one minimum per cycle.
module sgm_min_tree #(
  parameter int N     = 64,
  parameter int W     = 9,
  parameter int ARITY = 3
) (
  input  wire  [N*W-1:0] values_i,  // value i in values_i[i*W +: W]
  output logic [W-1:0]   min_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(N >= 1)) begin : g_bad_n
    $error("sgm_min_tree: N = %0d: N must be at least 1", N);
  end
  if (!(W >= 1)) begin : g_bad_w
    $error("sgm_min_tree: W = %0d: W must be at least 1", W);
  end
  if (!(ARITY == 3 || ARITY == 4)) begin : g_bad_arity
    $error("sgm_min_tree: ARITY = %0d: ARITY must be 3 or 4", ARITY);
  end
`endif

  // Nodes of a complete ARITY-ary tree over P = ARITY^LEVELS leaves, heap
  // order: node 0 is the root, node n has children A n + 1 .. A n + A, leaves
  // are I .. I+P-1 with I = (P-1)/(A-1) inner nodes. Missing leaves hold all
  // ones and never win (synthesis folds them away).
  function automatic integer tree_levels(input integer n);
    integer p;
    tree_levels = 0;
    for (p = 1; p < n; p = p * ARITY) tree_levels = tree_levels + 1;
  endfunction

  localparam int LEVELS = tree_levels(N);
  localparam int P      = ARITY ** LEVELS;
  localparam int I      = (P - 1) / (ARITY - 1);

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
    wire [W-1:0] a  = node[(ARITY*n+1)*W +: W];
    wire [W-1:0] b  = node[(ARITY*n+2)*W +: W];
    wire [W-1:0] c  = node[(ARITY*n+3)*W +: W];
    wire         ab = a <= b;
    wire         ac = a <= c;
    wire         bc = b <= c;
    if (ARITY == 4) begin : g_four
      wire [W-1:0] e  = node[(ARITY*n+4)*W +: W];
      wire         ae = a <= e;
      wire         be = b <= e;
      wire         ce = c <= e;
      assign node[n*W +: W] = ab && ac && ae ? a : !ab && bc && be ? b : !ac && !bc && ce ? c : e;
    end else begin : g_three
      assign node[n*W +: W] = ab && ac ? a : bc ? b : c;
    end
  end

  assign min_o = node[0 +: W];

endmodule
`default_nettype wire
