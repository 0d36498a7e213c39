// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_path_pe: one sub-PE of eq. (1) (docs/algorithm.md section 5), one
// disparity d of one path:
//   Lr = C + min(L(d), L(d-1) + P1, L(d+1) + P1, minL + P2r) - minL
// where L(.) are the path costs of the previous pixel on the path and minL
// their minimum. has_lo_i / has_hi_i say whether the d-1 / d+1 neighbours
// exist (0 for d = 0 / d = D-1). start_i selects the path start, Lr = C.
//
// Computed in three parts of two carry chains each:
//   (a) side = min(L(d-1), L(d+1)) + P1
//   (b) rel  = min(side, L(d)) - minL
//   (c) Lr   = C + min(rel, P2r)
// (min(m, minL + P2r) - minL = min(m - minL, P2r) since m >= minL). CUTS is a
// mask of pipeline registers (enable en_i) after part (a) (bit 0) and after
// part (b) (bit 1); each part's inputs are presented when the pixel reaches
// it: prev_i, prev_lo_i, prev_hi_i, p1_i at the first slot, min_prev_i
// CUTS[0] slots later, cost_i, p2r_i, start_i CUTS[0] + CUTS[1] slots later
// (sgm_path_ring carries them with the pixel). With CUTS = 0 the PE is
// combinational and clk_i / en_i are unused.
//
// Parameters: CW cost width, LW path-cost width (must hold Cmax + P2'max),
// PW penalty width (P1, P2r; LW >= CW, PW), CUTS register mask (0 .. 3).
// Latency: CUTS[0] + CUTS[1] slots from prev_i to lr_o.
module sgm_path_pe #(
  parameter int CW   = 7,
  parameter int LW   = 9,
  parameter int PW   = 8,
  parameter int CUTS = 0
) (
  input  wire           clk_i,      // CUTS != 0 only
  input  wire           en_i,       // CUTS != 0 only
  // part (a)
  input  wire  [LW-1:0] prev_i,     // L(p-r, d)
  input  wire  [LW-1:0] prev_lo_i,  // L(p-r, d-1)
  input  wire  [LW-1:0] prev_hi_i,  // L(p-r, d+1)
  input  wire           has_lo_i,
  input  wire           has_hi_i,
  input  wire  [PW-1:0] p1_i,
  // part (b), CUTS[0] slots later
  input  wire  [LW-1:0] min_prev_i, // min_k L(p-r, k)
  // part (c), CUTS[0] + CUTS[1] slots later
  input  wire  [CW-1:0] cost_i,
  input  wire  [PW-1:0] p2r_i,
  input  wire           start_i,
  output logic [LW-1:0] lr_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(LW >= CW)) begin : g_bad_lw
    $error("sgm_path_pe: LW = %0d: LW must be at least CW = %0d (the path cost holds the matching cost)", LW, CW);
  end
  if (!(LW >= PW)) begin : g_bad_lw_2
    $error("sgm_path_pe: LW = %0d: LW must be at least PW = %0d (the path cost holds the penalties)", LW, PW);
  end
  if (!(PW >= 1)) begin : g_bad_pw
    $error("sgm_path_pe: PW = %0d: PW must be at least 1", PW);
  end
  if (!(CUTS >= 0 && CUTS <= 3)) begin : g_bad_cuts
    $error("sgm_path_pe: CUTS = %0d: CUTS must be from 0 to 3 (a mask of two registers)", CUTS);
  end
`endif

  // One bit of headroom over LW for the penalised terms.
  localparam int EW = LW + 1;

  // (a) L(d-1) + P1 and L(d+1) + P1 compete only with each other's P1 added,
  // so the smaller neighbour is picked first and P1 added once (all ones when
  // neither neighbour exists).
  wire [LW-1:0] nb     = !has_lo_i ? prev_hi_i :
                         !has_hi_i ? prev_lo_i :
                         prev_hi_i < prev_lo_i ? prev_hi_i : prev_lo_i;
  wire [EW-1:0] side_a = has_lo_i || has_hi_i ? {1'b0, nb} + EW'(p1_i) : {EW{1'b1}};

  // (b) rel = min(side, L(d)) - minL >= 0 (minL is the minimum of the L(.)).
  logic [EW-1:0] side;
  logic [LW-1:0] same;
  wire  [EW-1:0] m01   = side < {1'b0, same} ? side : {1'b0, same};
  wire  [EW-1:0] rel_b = m01 - {1'b0, min_prev_i};

  // (c) step = min(rel, P2r) fits PW bits; Lr = C + step <= Cmax + P2' fits
  // LW bits. At the path start the step is masked to 0 (Lr = C) in front of
  // the adder instead of a mux behind it.
  logic [EW-1:0] rel;
  wire  [PW-1:0] step = start_i ? {PW{1'b0}} : EW'(p2r_i) < rel ? p2r_i : rel[PW-1:0];

  assign lr_o = LW'(cost_i) + LW'(step);

  if ((CUTS & 1) != 0) begin : g_cut_a
    always_ff @(posedge clk_i) begin
      if (en_i) {side, same} <= {side_a, prev_i};
    end
  end else begin : g_comb_a
    assign {side, same} = {side_a, prev_i};
  end

  if ((CUTS & 2) != 0) begin : g_cut_b
    always_ff @(posedge clk_i) begin
      if (en_i) rel <= rel_b;
    end
  end else begin : g_comb_b
    assign rel = rel_b;
  end

  if (CUTS == 0) begin : g_unused
    logic unused_clk;
    assign unused_clk = ^{clk_i, en_i};
  end

endmodule
`default_nettype wire
