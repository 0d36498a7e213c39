`default_nettype none
// sgm_wta: winner-take-all and quadratic sub-pixel refinement
// (docs/algorithm.md section 6) at one pixel per slot.
//
//   d*   = argmin_d S(d), ties to the smallest d
//   disp = 16 d* + sign(a - b) * q,  q = (|a - b| * 16 + den) / (2 den)  (floor, 0 .. 8)
//          with a = S(d*-1), m = S(d*), b = S(d*+1), den = a + b - 2m,
//          when subpixel_i and 0 < d* < D-1 and den > 0; else disp = 16 d*.
//
// Structure (one register stage per slot, all stages advance only when en_i):
//   T1 .. T(TREE_STAGES)  binary comparator tree, LPS levels per stage. A node
//        is {b, a, m, d}: the candidate's cost m, its index d and the costs of
//        its neighbours a = S(d-1), b = S(d+1), carried along so that the
//        winner arrives with the three costs the refinement needs. The upper
//        (higher d) input wins only when strictly smaller: ties keep the
//        smallest d.
//   P    den = a + b - 2m, |num| = |a - b|, refine flag; dividend
//        N = 16 |num| + den and divisor V = 2 den of the quotient q.
//   Q1   restoring division, quotient bits 3 and 2 (q < 16 because N <= 17 den)
//   Q2   quotient bits 1 and 0; disp = 16 d* +- q without an adder (q < 16:
//        16 d* + q = {d*, q}, 16 d* - q = {d* - 1, 16 - q} for q > 0, d* - 1
//        computed in Q1); output registers.
//
// Parameters: D disparities (power of two, 16 .. 128), SW width of S,
// CW column bits, RW row bits of the slot position (passed through).
// Latency: LATENCY = TREE_STAGES + 3 slots (D = 16: 5, 32/64: 6, 128: 7): the
// result of the slot presented at enabled edge n is on the outputs after
// enabled edge n + LATENCY - 1. Throughput: one pixel per slot.
// Reset: only the valid_o pipeline (control); data registers start unknown.
module sgm_wta #(
  parameter int D  /*verilator public*/ = 64,
  parameter int SW /*verilator public*/ = 13,
  parameter int CW /*verilator public*/ = 11,
  parameter int RW /*verilator public*/ = 11,
  localparam int LD          = $clog2(D),
  localparam int DW          = LD + 4,
  localparam int LPS         = 2,                     // comparator levels per slot
  localparam int TREE_STAGES = (LD + LPS - 1) / LPS,
  localparam int LATENCY     /*verilator public*/ = TREE_STAGES + 3
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire              subpixel_i,   // per frame: sub-pixel refinement on
  // Slot input: S(d) = s_i[d*SW +: SW] and the position of the pixel.
  input  wire  [D*SW-1:0]  s_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire              valid_i,
  // Slot output, LATENCY slots later.
  output logic [LD-1:0]    d_o,
  output logic [DW-1:0]    disp_o,
  output logic [CW-1:0]    col_o,
  output logic [RW-1:0]    row_o,
  output logic             valid_o
);

  localparam int NW = 3 * SW + LD;  // tree node {b, a, m, d}
  localparam int QW = SW + 5;       // dividend / shifted divisor width (N < 2^(SW+5))

  // ------------------------------------------------------------ position pipe
  // Stage k (1 .. LATENCY) of the slot's position and valid flag; stage LATENCY
  // is the output. subpixel_i travels with the slot up to stage P.
  localparam int PW = CW + RW;
  logic [LATENCY*PW-1:0] pos_q;
  logic [LATENCY-1:0]    valid_q;
  logic [TREE_STAGES-1:0] sub_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      pos_q <= {pos_q[(LATENCY-1)*PW-1:0], row_i, col_i};
      sub_q <= {sub_q[TREE_STAGES-2:0], subpixel_i};
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= '0;
    else if (en_i) valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  assign {row_o, col_o} = pos_q[(LATENCY-1)*PW +: PW];
  assign valid_o        = valid_q[LATENCY-1];

  // ---------------------------------------------------- T: comparator tree
  // Level l has D >> l nodes; level LD is the winner. Levels l % LPS == 0 and
  // the last level are registered, the others are combinational.
  for (genvar l = 0; l <= LD; l++) begin : g_lvl
    logic [(D>>l)*NW-1:0] node;
    if (l == 0) begin : g_leaf
      for (genvar i = 0; i < D; i++) begin : g_d
        wire [SW-1:0] a, b;
        if (i == 0) begin : g_first
          assign a = '0;                       // no refinement at d = 0
        end else begin : g_a
          assign a = s_i[(i-1)*SW +: SW];
        end
        if (i == D - 1) begin : g_last
          assign b = '0;                       // no refinement at d = D-1
        end else begin : g_b
          assign b = s_i[(i+1)*SW +: SW];
        end
        assign node[i*NW +: NW] = {b, a, s_i[i*SW +: SW], LD'(i)};
      end
    end else begin : g_cmp
      logic [(D>>l)*NW-1:0] pick;
      for (genvar i = 0; i < (D >> l); i++) begin : g_node
        wire [NW-1:0] lo = g_lvl[l-1].node[(2*i)*NW +: NW];
        wire [NW-1:0] hi = g_lvl[l-1].node[(2*i+1)*NW +: NW];
        assign pick[i*NW +: NW] = hi[LD +: SW] < lo[LD +: SW] ? hi : lo;
      end
      if (l % LPS == 0 || l == LD) begin : g_reg
        always_ff @(posedge clk_i) begin
          if (en_i) node <= pick;
        end
      end else begin : g_comb
        assign node = pick;
      end
    end
  end

  // ---------------------------------------------------- P: offset operands
  wire [LD-1:0] win_d;
  wire [SW-1:0] win_a, win_m, win_b;
  assign {win_b, win_a, win_m, win_d} = g_lvl[LD].node;

  // den = a + b - 2m >= 0 because m is the minimum: exact in SW+1 bits.
  wire [SW:0]   den    = {1'b0, win_a} + {1'b0, win_b} - {win_m, 1'b0};
  wire          neg    = win_a < win_b;
  wire [SW-1:0] absnum = neg ? win_b - win_a : win_a - win_b;
  wire          refine = sub_q[TREE_STAGES-1] && win_d != '0 && win_d != LD'(D - 1) && den != '0;

  logic [QW-1:0]   p_num_q;   // N = 16 |num| + den
  logic [SW+1:0]   p_div_q;   // V = 2 den
  logic            p_neg_q, p_ref_q;
  logic [LD-1:0]   p_d_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      p_num_q <= {1'b0, absnum, 4'b0000} + {4'b0000, den};
      p_div_q <= {den, 1'b0};
      p_neg_q <= neg;
      p_ref_q <= refine;
      p_d_q   <= win_d;
    end
  end

  // ---------------------------------------------------- Q1: quotient bits 3, 2
  wire [QW-1:0] v3 = {p_div_q, 3'b000};
  wire [QW-1:0] v2 = {1'b0, p_div_q, 2'b00};
  wire          q3 = p_num_q >= v3;
  wire [QW-1:0] r3 = q3 ? p_num_q - v3 : p_num_q;
  wire          q2 = r3 >= v2;
  wire [QW-1:0] r2 = q2 ? r3 - v2 : r3;

  logic [QW-1:0] q_rem_q;
  logic [SW+1:0] q_div_q;
  logic [1:0]    q_hi_q;
  logic          q_neg_q, q_ref_q;
  logic [LD-1:0] q_d_q, q_dm1_q;  // d*, d* - 1

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      q_rem_q <= r2;
      q_div_q <= p_div_q;
      q_hi_q  <= {q3, q2};
      q_neg_q <= p_neg_q;
      q_ref_q <= p_ref_q;
      q_d_q   <= p_d_q;
      q_dm1_q <= p_d_q - 1'b1;
    end
  end

  // ---------------------------------------------------- Q2: quotient bits 1, 0
  wire [QW-1:0] v1 = {2'b00, q_div_q, 1'b0};
  wire [QW-1:0] v0 = {3'b000, q_div_q};
  wire          q1 = q_rem_q >= v1;
  wire [QW-1:0] r1 = q1 ? q_rem_q - v1 : q_rem_q;
  wire          q0 = r1 >= v0;
  wire [3:0]    q  = q_ref_q ? {q_hi_q, q1, q0} : 4'd0;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_o    <= q_d_q;
      disp_o <= q_neg_q && q != 4'd0 ? {q_dm1_q, 4'd0 - q} : {q_d_q, q};
    end
  end

endmodule
`default_nettype wire
