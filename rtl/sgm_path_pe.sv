`default_nettype none
// sgm_path_pe: one sub-PE of eq. (1) (docs/algorithm.md section 5), one
// disparity d of one path:
//   Lr = C + min(L(d), L(d-1) + P1, L(d+1) + P1, minL + P2r) - minL
// where L(.) are the path costs of the previous pixel on the path and minL
// their minimum. has_lo_i / has_hi_i say whether the d-1 / d+1 neighbours
// exist (0 for d = 0 / d = D-1). start_i selects the path start, Lr = C.
//
// Two halves: (a) the neighbours, min(L(d), min(L(d-1), L(d+1)) + P1) = m01;
// (b) the jump minL + P2r, its comparison with m01, - minL and + C. With
// CUT = 1 a register (enable en_i) sits between the halves, and the inputs
// of half (b) (cost_i, start_i, min_prev_i, p2r_i) are presented one slot
// after those of half (a) (prev_i, prev_lo_i, prev_hi_i, has_*, p1_i): the
// instantiating pipeline (sgm_path_ring) carries them with the pixel. With
// CUT = 0 the PE is combinational and clk_i / en_i are unused.
//
// Parameters: CW cost width, LW path-cost width (must hold Cmax + P2'max),
// PW penalty width (P1, P2r; LW >= CW, PW), CUT (0 or 1) register between
// the halves.
// Latency: CUT slots from the half-(a) inputs to lr_o (0: combinational).
module sgm_path_pe #(
  parameter int CW  = 7,
  parameter int LW  = 9,
  parameter int PW  = 8,
  parameter int CUT = 0
) (
  input  wire           clk_i,      // CUT = 1 only
  input  wire           en_i,       // CUT = 1 only
  // half (a)
  input  wire  [LW-1:0] prev_i,     // L(p-r, d)
  input  wire  [LW-1:0] prev_lo_i,  // L(p-r, d-1)
  input  wire  [LW-1:0] prev_hi_i,  // L(p-r, d+1)
  input  wire           has_lo_i,
  input  wire           has_hi_i,
  input  wire  [PW-1:0] p1_i,
  // half (b), CUT slots after half (a)
  input  wire  [CW-1:0] cost_i,
  input  wire  [LW-1:0] min_prev_i, // min_k L(p-r, k)
  input  wire  [PW-1:0] p2r_i,
  input  wire           start_i,
  output logic [LW-1:0] lr_o
);

  // One bit of headroom over LW for the penalised terms.
  localparam int EW = LW + 1;

  // L(d-1) + P1 and L(d+1) + P1 compete only with each other's P1 added, so
  // the smaller neighbour is picked first and P1 added once:
  // min(L(d-1), L(d+1)) + P1 (all ones when neither neighbour exists).
  wire [LW-1:0] nb   = !has_lo_i ? prev_hi_i :
                       !has_hi_i ? prev_lo_i :
                       prev_hi_i < prev_lo_i ? prev_hi_i : prev_lo_i;
  wire [EW-1:0] side = has_lo_i || has_hi_i ? {1'b0, nb} + EW'(p1_i) : {EW{1'b1}};
  wire [EW-1:0] same = {1'b0, prev_i};
  wire [EW-1:0] m01_a = side < same ? side : same;

  logic [EW-1:0] m01;  // m01_a as seen by half (b)
  if (CUT == 1) begin : g_cut
    always_ff @(posedge clk_i) begin
      if (en_i) m01 <= m01_a;
    end
  end else begin : g_comb
    assign m01 = m01_a;
    logic unused_clk;
    assign unused_clk = ^{clk_i, en_i};
  end

  wire [EW-1:0] jump = {1'b0, min_prev_i} + EW'(p2r_i);

  // best - minL lies in 0 .. P2r, so it fits PW bits (modulo 2^PW is exact)
  // and only the low PW bits of best are selected; Lr = C + step <= Cmax +
  // P2' fits LW bits. At the path start the step is masked to 0 (Lr = C) in
  // front of the adder instead of a mux behind it.
  wire [PW-1:0] best = jump < m01 ? jump[PW-1:0] : m01[PW-1:0];
  wire [PW-1:0] step = start_i ? {PW{1'b0}} : best - min_prev_i[PW-1:0];

  assign lr_o = LW'(cost_i) + LW'(step);

endmodule
`default_nettype wire
