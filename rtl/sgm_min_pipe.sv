// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_min_pipe: pipelined minimum of N unsigned values, a tree of 4-input
// nodes (sgm_min_tree, N = ARITY = 4) with a register after every level, so
// that one stage holds one node (six comparator chains side by side and a
// 4:1 select, docs/lanes.md). The minima of the 45, 90 and 135 degree
// paths (sgm_path_engine), which are needed only a row later. IN_REG = 1
// registers the values first (where the schedule has a slot to spare: the
// values come from registers that also feed the path memories, and the route
// from them into the first level was a critical path of the five-lane core).
//
// Parameters: N inputs (>= 1), W bits each, IN_REG (0 or 1).
// Latency: LATENCY = ceil(log4 N) + IN_REG slots (ceil(log4 N) = 0 for N = 1).
// Throughput: one minimum per slot (en_i).
module sgm_min_pipe #(
  parameter int N = 64,
  parameter int W = 9,
  parameter int IN_REG = 0,
  localparam int ARITY   = 4,
  localparam int LEVELS  = ($clog2(N) + 1) / 2,  // ceil(log4 N)
  localparam int LATENCY = LEVELS + IN_REG
) (
  input  wire            clk_i,
  input  wire            en_i,
  input  wire  [N*W-1:0] values_i,  // value i in values_i[i*W +: W]
  output logic [W-1:0]   min_o      // LATENCY slots later
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(N >= 1)) begin : g_bad_n
    $error("sgm_min_pipe: N = %0d: N must be at least 1", N);
  end
  if (!(W >= 1)) begin : g_bad_w
    $error("sgm_min_pipe: W = %0d: W must be at least 1", W);
  end
  if (!(IN_REG == 0 || IN_REG == 1)) begin : g_bad_in_reg
    $error("sgm_min_pipe: IN_REG = %0d: IN_REG must be 0 or 1", IN_REG);
  end
`endif

  localparam int P = ARITY ** LEVELS;  // leaves of the complete tree

  // Level l holds P / 4^l values (padded with all ones, which never win);
  // value n of level l + 1 is the minimum of values 4n .. 4n + 3 of level l,
  // registered. split_var: each level is its own variable for Verilator.
  logic [P*W-1:0] lvl [LEVELS+1] /* verilator split_var */;

  logic [N*W-1:0] values;
  if (IN_REG != 0) begin : g_in_reg
    logic [N*W-1:0] values_q;
    always_ff @(posedge clk_i) begin
      if (en_i) values_q <= values_i;
    end
    assign values = values_q;
  end else begin : g_in_now
    assign values = values_i;
  end
  assign lvl[0] = {{(P-N){{W{1'b1}}}}, values};

  for (genvar l = 0; l < LEVELS; l++) begin : g_level
    localparam int NN = P / (ARITY ** (l + 1));  // values of level l + 1
    logic [NN*W-1:0] node_d, node_q;
    for (genvar n = 0; n < NN; n++) begin : g_node
      sgm_min_tree #(.N(ARITY), .W(W), .ARITY(ARITY)) u_node (
        .values_i (lvl[l][ARITY*n*W +: ARITY*W]),
        .min_o    (node_d[n*W +: W])
      );
    end
    always_ff @(posedge clk_i) begin
      if (en_i) node_q <= node_d;
    end
    assign lvl[l+1] = {{(P-NN){{W{1'b1}}}}, node_q};
  end

  assign min_o = lvl[LEVELS][0 +: W];

endmodule
`default_nettype wire
