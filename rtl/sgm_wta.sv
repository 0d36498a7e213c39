// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_wta: winner-take-all and quadratic sub-pixel refinement
// (docs/algorithm.md section 6) at one pixel per slot.
//
//   d*   = argmin_d S(d), ties to the smallest d
//   disp = 16 d* + sign(a - b) * q,  q = (|a - b| * 16 + den) / (2 den)  (floor, 0 .. 8)
//          with a = S(d*-1), m = S(d*), b = S(d*+1), den = a + b - 2m,
//          when subpixel_i and 0 < d* < D-1 and den > 0; else disp = 16 d*.
//   unique = sec (100 - U) >= 100 S(d*), sec = min S(k) over |k - d*| > 1
//          (docs/algorithm.md section 7: the uniqueness ratio U = uniq_i, 0 .. 99;
//          U = 0 passes every pixel because sec >= S(d*)).
//
// Structure (one register stage per slot, all stages advance only when en_i):
//   T0   the D/2 comparisons of the tree's first level, registered with S (the
//        first tree stage from the path engine's registers would be the 5-lane core's
//        critical path, 10.0 ns on ECP5; a register behind every level instead
//        would cost the LUT6 that merges two levels of 2:1 selects on xc7)
//   T1 .. T(TREE_STAGES-1)  binary comparator tree: T1 selects level 1 by T0's
//        registered comparisons and compares and selects level 2, each stage
//        after it one level (a comparison and a select: two levels per stage
//        would be the 5-lane D = 16 core's critical path on ECP5 with -abc9, 8.4 ns,
//        118.5 MHz; 123.3 MHz with one). A node
//        is {b, a, m, d}: the candidate's cost m, its index d and the costs of
//        its neighbours a = S(d-1), b = S(d+1), carried along so that the
//        winner arrives with the three costs the refinement needs. The upper
//        (higher d) input wins only when strictly smaller: ties keep the
//        smallest d. For the uniqueness test a node over the disparities
//        [lo, hi] also carries sec = min S(k) over k in [lo, hi], |k - d| > 1,
//        exf = min S(k) over (lo, hi] and exl = min S(k) over [lo, hi) (a leaf:
//        all three "none" = all ones, which no min changes; at the root sec is
//        a real cost because D >= 4). Merging lo-half L = [lo, c] and hi-half
//        R = [c + 1, hi]: sec = min(L.sec, L.d = c ? R.exf : R.m) when L wins,
//        min(R.sec, R.d = c + 1 ? L.exl : L.m) when R wins; exf = min(L.exf,
//        R.m); exl = min(L.m, R.exl). The candidates are compared beside the
//        winner's comparison and selected by it: a 2:1 select more in front of
//        a comparison and one behind it.
//   P    den = a + b - 2m, |num| = |a - b|, refine flag; dividend
//        N = 16 |num| + den and divisor V = 2 den of the quotient q.
//   Q3 .. Q0  restoring division, one quotient bit per slot, 3 down to 0 (q < 16
//        because N <= 17 den; two bits per slot would take 10.5 ns on ECP5); after
//        Q0 disp = 16 d* +- q without an adder (q < 16: 16 d* + q = {d*, q},
//        16 d* - q = {d* - 1, 16 - q} for q > 0, d* - 1 computed in Q3);
//        output registers. Beside them the uniqueness product
//        sec (100 - U) by shift and add, two bits of (100 - U) per stage (P:
//        bits 1..0, Q3: 3..2, Q2: 5..4, Q1: 6), 100 m = 64 m + 32 m + 4 m
//        (P: 64 m + 32 m, Q3: + 4 m), compared in Q0.
//
// MIN_DISPARITY = 1 (the minimum disparity, docs/algorithm.md section 3): disp is the
// true disparity, 16 (dmin + d*) +- q, dmin = dmin_i (a constant of the frame) added to d*
// and d* - 1 in Q0 beside the last quotient bit; DW = ceil(log2(D + 256)) + 4 bits. d_o
// stays the search's d* (0 .. D - 1). 0: DW = log2(D) + 4, dmin_i unused.
//
// UNIQUENESS = 0 builds no uniqueness test: the nodes carry {b, a, m, d} only
// (no sec / exf / exl, no candidate selects, unless CONFIDENCE), no product, no U pipeline;
// unique_o is constant 1 and uniq_i is ignored (sgm_stream_ctrl drops frames
// that ask for a ratio). The latency is the same.
//
// CONFIDENCE = 1 (docs/algorithm.md section 7b): conf_o = floor(256 (sec - m) / (sec + 1)),
// 0 .. 255, the winner's confidence before the LR check (sgm_lr_check zeroes it where the
// pixel is invalid). The nodes carry sec also without the uniqueness test. From stage P
// on, a restoring division of (sec - m) 2^8 by V = sec + 1, one quotient bit per stage
// (rem < V, so 2 rem < 2^(SW+1) and the quotient has 8 bits): C7 .. C0, of which C7 .. C4
// run beside Q3 .. Q0; the other results wait 4 more stages for C3 .. C0 (LATENCY + 4).
// 0: conf_o is 0 and nothing of it is built.
//
// Parameters: D disparities (a power of two from 16 to 256), SW width of S,
// CW column bits, RW row bits of the slot position (passed through),
// UNIQUENESS (1: the uniqueness test is built, 0: not), MIN_DISPARITY (1: built, 0: not),
// CONFIDENCE (1: built, 0: not).
// Latency: LATENCY = TREE_STAGES + 5 slots (D = 16: 9, 32: 10, 64: 11, 128: 12), 4 more
// with CONFIDENCE: the result of the slot presented at enabled edge n is on the outputs
// after enabled edge n + LATENCY - 1. Throughput: one pixel per slot.
// Reset: only the valid_o pipeline (control); data registers start unknown.
module sgm_wta #(
  parameter int D  /*verilator public*/ = 64,
  parameter int SW /*verilator public*/ = 13,
  parameter int CW /*verilator public*/ = 11,
  parameter int RW /*verilator public*/ = 11,
  parameter int UNIQUENESS /*verilator public*/ = 1,
  parameter int MIN_DISPARITY /*verilator public*/ = 0,
  parameter int CONFIDENCE /*verilator public*/ = 0,
  localparam int LD          = $clog2(D),
  localparam int DW          = (MIN_DISPARITY != 0 ? $clog2(D + 256) : LD) + 4,
  localparam int TREE_STAGES = LD,                    // T0, T1 (levels 1, 2), levels 3 .. LD
  localparam int CONF_WAIT   = CONFIDENCE != 0 ? 4 : 0,  // C3 .. C0 behind Q0
  localparam int LATENCY     /*verilator public*/ = TREE_STAGES + 5 + CONF_WAIT
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire              subpixel_i,   // per frame: sub-pixel refinement on
  input  wire  [6:0]       uniq_i,       // per frame: uniqueness ratio U in %, 0 .. 99 (0: off)
  input  wire  [7:0]       dmin_i,       // per frame: the minimum disparity (MIN_DISPARITY = 1)
  // Slot input: S(d) = s_i[d*SW +: SW] and the position of the pixel.
  input  wire  [D*SW-1:0]  s_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire              valid_i,
  // Slot output, LATENCY slots later.
  output logic [LD-1:0]    d_o,
  output logic [DW-1:0]    disp_o,
  output logic             unique_o,     // the winner passes the uniqueness test
  output logic [7:0]       conf_o,       // the winner's confidence (CONFIDENCE = 1; else 0)
  output logic [CW-1:0]    col_o,
  output logic [RW-1:0]    row_o,
  output logic             valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 16 && D <= 256 && (D & (D - 1)) == 0)) begin : g_bad_d
    $error("sgm_wta: D = %0d: D must be a power of two from 16 to 256", D);
  end
  if (!(MIN_DISPARITY == 0 || MIN_DISPARITY == 1)) begin : g_bad_min_disparity
    $error("sgm_wta: MIN_DISPARITY = %0d: MIN_DISPARITY must be 0 or 1", MIN_DISPARITY);
  end
  if (!(SW >= 1)) begin : g_bad_sw
    $error("sgm_wta: SW = %0d: SW must be at least 1", SW);
  end
  if (!(CW >= 1)) begin : g_bad_cw
    $error("sgm_wta: CW = %0d: CW must be at least 1", CW);
  end
  if (!(RW >= 1)) begin : g_bad_rw
    $error("sgm_wta: RW = %0d: RW must be at least 1", RW);
  end
  if (!(UNIQUENESS == 0 || UNIQUENESS == 1)) begin : g_bad_uniqueness
    $error("sgm_wta: UNIQUENESS = %0d: UNIQUENESS must be 0 or 1", UNIQUENESS);
  end
  if (!(CONFIDENCE == 0 || CONFIDENCE == 1)) begin : g_bad_confidence
    $error("sgm_wta: CONFIDENCE = %0d: CONFIDENCE must be 0 or 1", CONFIDENCE);
  end
`endif

  localparam int SEC = UNIQUENESS != 0 || CONFIDENCE != 0 ? 1 : 0;  // the nodes carry sec
  localparam int UF = SEC != 0 ? 3 : 0;  // uniqueness fields of a node
  localparam int NW = (3 + UF) * SW + LD;  // tree node {exl, exf, sec, b, a, m, d} ({b, a, m, d} without them)
  localparam int UW = SW + 7;       // sec (100 - U) and 100 m: below 2^(SW+7)
  localparam logic [SW-1:0] NONE = '1;  // "no cost" of sec / exf / exl (never below a cost)
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
      pos_q  <= {pos_q[(LATENCY-1)*PW-1:0], row_i, col_i};
      sub_q  <= {sub_q[TREE_STAGES-2:0], subpixel_i};
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
        if (SEC != 0) begin : g_u
          assign node[i*NW +: NW] = {NONE, NONE, NONE, b, a, s_q[i*SW +: SW], LD'(i)};
        end else begin : g_nu
          assign node[i*NW +: NW] = {b, a, s_q[i*SW +: SW], LD'(i)};
        end
      end
    end else begin : g_cmp
      logic [(D>>l)*NW-1:0] pick;
      for (genvar i = 0; i < (D >> l); i++) begin : g_node
        wire [NW-1:0] lo = g_lvl[l-1].node[(2*i)*NW +: NW];
        wire [NW-1:0] hi = g_lvl[l-1].node[(2*i+1)*NW +: NW];
        wire [SW-1:0] lo_m = lo[LD +: SW];
        wire [SW-1:0] hi_m = hi[LD +: SW];
        wire          up = l == 1 ? c1_q[i] : hi_m < lo_m;
        // Uniqueness fields (level 1: two leaves, no comparison needed).
        wire [SW-1:0] sec, exf, exl;
        if (SEC == 0) begin : g_none
          assign {sec, exf, exl} = '0;  // not built: the node has no such fields
        end else if (l == 1) begin : g_pair
          assign sec = NONE;
          assign exf = hi_m;
          assign exl = lo_m;
        end else begin : g_merge
          wire [SW-1:0] lo_sec = lo[LD + 3*SW +: SW], lo_exf = lo[LD + 4*SW +: SW], lo_exl = lo[LD + 5*SW +: SW];
          wire [SW-1:0] hi_sec = hi[LD + 3*SW +: SW], hi_exf = hi[LD + 4*SW +: SW], hi_exl = hi[LD + 5*SW +: SW];
          // lo's winner is its last index c / hi's winner its first index c + 1.
          wire          lo_at_c  = lo[l-2:0] == '1;
          wire          hi_at_c1 = hi[l-2:0] == '0;
          wire [SW-1:0] lo_cand  = lo_at_c ? hi_exf : hi_m;   // for a lo winner
          wire [SW-1:0] hi_cand  = hi_at_c1 ? lo_exl : lo_m;  // for a hi winner
          wire [SW-1:0] sec_lo   = lo_cand < lo_sec ? lo_cand : lo_sec;
          wire [SW-1:0] sec_hi   = hi_cand < hi_sec ? hi_cand : hi_sec;
          assign sec = up ? sec_hi : sec_lo;
          assign exf = hi_m < lo_exf ? hi_m : lo_exf;
          assign exl = hi_exl < lo_m ? hi_exl : lo_m;
        end
        if (SEC != 0) begin : g_pick_u
          assign pick[i*NW +: NW] = {exl, exf, sec, up ? hi[0 +: 3*SW + LD] : lo[0 +: 3*SW + LD]};
        end else begin : g_pick
          assign pick[i*NW +: NW] = up ? hi : lo;
          wire unused_u = ^{sec, exf, exl};
        end
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
  assign {win_b, win_a, win_m, win_d} = g_lvl[LD].node[0 +: 3*SW+LD];  // the root's sec: below; exf, exl: unused

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

  // The Q0 results: on the outputs directly, or CONF_WAIT stages later (CONFIDENCE).
  logic [LD-1:0] q0_d_q;
  logic [DW-1:0] q0_disp_q;
  logic          q0_unique_q;

  // Uniqueness (UNIQUENESS = 0: not built, every winner passes; uniq_i ignored).
  // sec_times: sec (k2[1] 2 + k2[0]) 2^sh, two bits of the product by shift and add.
  function automatic logic [UW-1:0] sec_times(input logic [SW-1:0] sec, input logic [1:0] k2, input int sh);
    sec_times = (k2[0] ? UW'(sec) << sh : '0) + (k2[1] ? UW'(sec) << (sh + 1) : '0);
  endfunction
  if (UNIQUENESS != 0) begin : g_uniq
    // uniq_i travels with the slot up to stage P.
    logic [TREE_STAGES*7-1:0] uniq_q;
    always_ff @(posedge clk_i) begin
      if (en_i) uniq_q <= {uniq_q[(TREE_STAGES-1)*7-1:0], uniq_i};
    end
    wire [SW-1:0] win_sec = g_lvl[LD].node[3*SW+LD +: SW];

    // Uniqueness: sec (100 - U) >= 100 m, by shift and add beside the division.
    // k = 100 - U; stage P adds k[1:0] sec and 96 m, Q3 k[3:2], Q2 k[5:4], Q1 k[6]
    // and Q3 the 4 m; Q0 compares (the output register holds the flag).
    wire [6:0]    u_k = 7'd100 - uniq_q[(TREE_STAGES-1)*7 +: 7];
    // uP_*: after stage P, u3_* after Q3, u2_* after Q2, u1_* after Q1.
    logic [UW-1:0] uP_acc_q, u3_acc_q, u2_acc_q, u1_acc_q;  // the product so far
    logic [UW-1:0] uP_m_q, u3_m_q, u2_m_q, u1_m_q;          // 96 m after P, 100 m from Q3 on
    logic [SW-1:0] uP_sec_q, u3_sec_q, u2_sec_q;            // sec, carried to Q1
    logic [SW-1:0] uP_m4_q;                                 // m, for Q3's 4 m
    logic [6:2]    uP_k_q;                                  // the bits of k still to add
    logic [6:4]    u3_k_q;
    logic          u2_k_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        uP_acc_q <= sec_times(win_sec, u_k[1:0], 0);
        uP_m_q   <= (UW'(win_m) << 6) + (UW'(win_m) << 5);
        uP_m4_q  <= win_m;
        uP_sec_q <= win_sec;
        uP_k_q   <= u_k[6:2];
        u3_acc_q <= uP_acc_q + sec_times(uP_sec_q, uP_k_q[3:2], 2);
        u3_m_q   <= uP_m_q + (UW'(uP_m4_q) << 2);
        u3_sec_q <= uP_sec_q;
        u3_k_q   <= uP_k_q[6:4];
        u2_acc_q <= u3_acc_q + sec_times(u3_sec_q, u3_k_q[5:4], 4);
        u2_m_q   <= u3_m_q;
        u2_sec_q <= u3_sec_q;
        u2_k_q   <= u3_k_q[6];
        u1_acc_q <= u2_acc_q + sec_times(u2_sec_q, {1'b0, u2_k_q}, 6);
        u1_m_q   <= u2_m_q;
        q0_unique_q <= u1_acc_q >= u1_m_q;
      end
    end
  end else begin : g_no_uniq
    assign q0_unique_q = 1'b1;
    wire unused_uniq = ^uniq_i;
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

  // The true disparity's integer part: d* (and d* - 1) plus dmin.
  wire [DW-5:0] d0_true, dm10_true;
  if (MIN_DISPARITY != 0) begin : g_dmin
    assign d0_true   = (DW-4)'(d0) + (DW-4)'(dmin_i);
    assign dm10_true = (DW-4)'(dm10) + (DW-4)'(dmin_i);
  end else begin : g_no_dmin
    assign d0_true   = d0;
    assign dm10_true = dm10;
    wire unused_dmin = ^dmin_i;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      q0_d_q    <= d0;
      q0_disp_q <= neg0 && q != 4'd0 ? {dm10_true, 4'd0 - q} : {d0_true, q};
    end
  end

  // ---------------------------------------------------- C7 .. C0: the confidence
  // rem starts at sec - m (< V = sec + 1); stage j: rem = 2 rem, bit j = rem >= V, rem -= it.
  if (CONFIDENCE != 0) begin : g_conf
    wire [SW-1:0] win_sec = g_lvl[LD].node[3*SW+LD +: SW];
    logic [8*(SW+1)-1:0] c_rem_q;  // word k: the input of stage C(k) (word 7: after P, k - 1: after C(k))
    logic [8*(SW+1)-1:0] c_div_q;  // V, carried with it
    logic [8*8-1:0]      c_quo_q;  // the quotient bits so far, carried with it
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        c_rem_q[7*(SW+1) +: SW+1] <= {1'b0, win_sec - win_m};
        c_div_q[7*(SW+1) +: SW+1] <= {1'b0, win_sec} + 1'b1;
        c_quo_q[7*8 +: 8]         <= '0;
      end
    end
    for (genvar j = 7; j >= 1; j--) begin : g_cstep  // stage C(j) reads word j, writes word j - 1
      wire [SW+1:0] twice = {c_rem_q[j*(SW+1) +: SW+1], 1'b0};
      wire [SW+1:0] v     = {1'b0, c_div_q[j*(SW+1) +: SW+1]};
      wire          bit_j = twice >= v;
      wire [SW+1:0] rest  = bit_j ? twice - v : twice;
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          c_rem_q[(j-1)*(SW+1) +: SW+1] <= rest[SW:0];  // rest < V <= 2^SW
          c_div_q[(j-1)*(SW+1) +: SW+1] <= c_div_q[j*(SW+1) +: SW+1];
          c_quo_q[(j-1)*8 +: 8]         <= c_quo_q[j*8 +: 8] | (8'(bit_j) << j);
        end
      end
      wire unused_rest = rest[SW+1];
    end
    // C0: bit 0 into the output register; the Q0 results wait CONF_WAIT stages.
    wire [SW+1:0] twice0 = {c_rem_q[0 +: SW+1], 1'b0};
    wire          bit0   = twice0 >= {1'b0, c_div_q[0 +: SW+1]};
    logic [CONF_WAIT*(LD+DW+1)-1:0] wait_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        conf_o <= c_quo_q[0 +: 8] | {7'd0, bit0};
        wait_q <= {wait_q[0 +: (CONF_WAIT-1)*(LD+DW+1)], q0_d_q, q0_disp_q, q0_unique_q};
      end
    end
    assign {d_o, disp_o, unique_o} = wait_q[(CONF_WAIT-1)*(LD+DW+1) +: LD+DW+1];
  end else begin : g_no_conf
    assign conf_o = 8'd0;
    assign {d_o, disp_o, unique_o} = {q0_d_q, q0_disp_q, q0_unique_q};
  end

endmodule
`default_nettype wire
