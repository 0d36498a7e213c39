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
//   T0   the D/2 comparisons of the tree's first level, registered with S (the
//        first tree stage from the path engine's registers was the 5-lane core's
//        critical path, 10.0 ns on ECP5; a register behind every level instead
//        would cost the LUT6 that merges two levels of 2:1 selects on xc7)
//   T1 .. T(TREE_STAGES-1)  binary comparator tree: T1 selects level 1 by T0's
//        registered comparisons and compares and selects level 2, each stage
//        after it one level (a comparison and a select: two levels per stage
//        were the 5-lane D = 16 core's critical path on ECP5 with -abc9, 8.4 ns,
//        118.5 MHz; 123.3 MHz with one). A node
//        is {b, a, m, d}: the candidate's cost m, its index d and the costs of
//        its neighbours a = S(d-1), b = S(d+1), carried along so that the
//        winner arrives with the three costs the refinement needs. The upper
//        (higher d) input wins only when strictly smaller: ties keep the
//        smallest d.
//   P    den = a + b - 2m, |num| = |a - b|, refine flag; dividend
//        N = 16 |num| + den and divisor V = 2 den of the quotient q.
//   Q3 .. Q0  restoring division, one quotient bit per slot, 3 down to 0 (q < 16
//        because N <= 17 den; two bits per slot were 10.5 ns on ECP5); after
//        Q0 disp = 16 d* +- q without an adder (q < 16: 16 d* + q = {d*, q},
//        16 d* - q = {d* - 1, 16 - q} for q > 0, d* - 1 computed in Q3);
//        output registers.
//
// Parameters: D disparities (power of two, 16 .. 128), SW width of S,
// CW column bits, RW row bits of the slot position (passed through).
// Latency: LATENCY = TREE_STAGES + 5 slots (D = 16: 9, 32: 10, 64: 11, 128: 12): the
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
  localparam int TREE_STAGES = LD,                    // T0, T1 (levels 1, 2), levels 3 .. LD
  localparam int LATENCY     /*verilator public*/ = TREE_STAGES + 5
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

  // ---------------------------------------------------- T0: first-level comparisons
  // c1_q[i]: S(2i+1) < S(2i) (the upper input wins only when strictly smaller).
  logic [D*SW-1:0] s_q;
  logic [D/2-1:0]  c1_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      s_q <= s_i;
      for (int i = 0; i < D / 2; i++) c1_q[i] <= s_i[(2*i+1)*SW +: SW] < s_i[(2*i)*SW +: SW];
    end
  end

  // ---------------------------------------------------- T: comparator tree
  // Level l has D >> l nodes; level LD is the winner. Levels 2 .. LD are
  // registered, level 1 is combinational and selects by c1_q.
  for (genvar l = 0; l <= LD; l++) begin : g_lvl
    logic [(D>>l)*NW-1:0] node;
    if (l == 0) begin : g_leaf
      for (genvar i = 0; i < D; i++) begin : g_d
        wire [SW-1:0] a, b;
        if (i == 0) begin : g_first
          assign a = '0;                       // no refinement at d = 0
        end else begin : g_a
          assign a = s_q[(i-1)*SW +: SW];
        end
        if (i == D - 1) begin : g_last
          assign b = '0;                       // no refinement at d = D-1
        end else begin : g_b
          assign b = s_q[(i+1)*SW +: SW];
        end
        assign node[i*NW +: NW] = {b, a, s_q[i*SW +: SW], LD'(i)};
      end
    end else begin : g_cmp
      logic [(D>>l)*NW-1:0] pick;
      for (genvar i = 0; i < (D >> l); i++) begin : g_node
        wire [NW-1:0] lo = g_lvl[l-1].node[(2*i)*NW +: NW];
        wire [NW-1:0] hi = g_lvl[l-1].node[(2*i+1)*NW +: NW];
        wire          up = l == 1 ? c1_q[i] : hi[LD +: SW] < lo[LD +: SW];
        assign pick[i*NW +: NW] = up ? hi : lo;
      end
      if (l >= 2) begin : g_reg
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

  // ---------------------------------------------------- Q3 .. Q0: one quotient bit each
  // Stage j (3 .. 0) of the restoring division: bit j = rem >= V 2^j, rem -= it.
  // Word j of qs is the input of stage j: the P registers for stage 3, the
  // registers qs_q[j] behind stage j + 1 for the others (rem of stage 3 = N);
  // the quotient bits decided so far are in hi (bits 3 .. j+1).
  localparam int XQ = QW + SW + 2 + 4 + 2 + 2 * LD;  // {rem, V, hi, neg, refine, d*, d* - 1}
  logic [3*XQ-1:0] qs_q;
  wire  [3*XQ-1:0] qs_d;   // word j - 1: the result of stage j
  wire  [XQ-1:0]   q3_in = {p_num_q, p_div_q, 4'd0, p_neg_q, p_ref_q, p_d_q, p_d_q - 1'b1};
  wire  [4*XQ-1:0] qs    = {q3_in, qs_q};
  for (genvar j = 3; j >= 1; j--) begin : g_qstep
    wire [QW-1:0]   rem, v;
    wire [SW+1:0]   div;
    wire [3:0]      hi;
    wire [2*LD+1:0] rest;  // {neg, refine, d*, d* - 1}
    assign {rem, div, hi, rest} = qs[j*XQ +: XQ];
    assign v = QW'(div) << j;
    wire qb = rem >= v;
    assign qs_d[(j-1)*XQ +: XQ] = {qb ? rem - v : rem, div, hi | (4'(qb) << j), rest};
  end

  always_ff @(posedge clk_i) begin
    if (en_i) qs_q <= qs_d;
  end

  // Q0: bit 0; disp = 16 d* +- q by concatenation; output registers.
  wire [QW-1:0] rem0;
  wire [SW+1:0] div0;
  wire [3:0]    hi0;
  wire          neg0, ref0;
  wire [LD-1:0] d0, dm10;
  assign {rem0, div0, hi0, neg0, ref0, d0, dm10} = qs[0 +: XQ];
  wire          q0 = rem0 >= QW'(div0);
  wire [3:0]    q  = ref0 ? hi0 | {3'b000, q0} : 4'd0;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_o    <= d0;
      disp_o <= neg0 && q != 4'd0 ? {dm10, 4'd0 - q} : {d0, q};
    end
  end

endmodule
`default_nettype wire
