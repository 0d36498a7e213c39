`default_nettype none
// sgm_path_pe: one sub-PE of eq. (1) (docs/algorithm.md section 5), one
// disparity d of one path:
//   Lr = C + min(L(d), L(d-1) + P1, L(d+1) + P1, minL + P2r) - minL
// where L(.) are the path costs of the previous pixel on the path and minL
// their minimum. has_lo_i / has_hi_i say whether the d-1 / d+1 neighbours
// exist (0 for d = 0 / d = D-1). start_i selects the path start, Lr = C.
//
// Parameters: CW cost width, LW path-cost width (must hold Cmax + P2'max),
// PW penalty width.
// Latency: 0 (combinational).
module sgm_path_pe #(
  parameter int CW = 8,
  parameter int LW = 9,
  parameter int PW = 8
) (
  input  wire  [CW-1:0] cost_i,
  input  wire  [LW-1:0] prev_i,     // L(p-r, d)
  input  wire  [LW-1:0] prev_lo_i,  // L(p-r, d-1)
  input  wire  [LW-1:0] prev_hi_i,  // L(p-r, d+1)
  input  wire           has_lo_i,
  input  wire           has_hi_i,
  input  wire  [LW-1:0] min_prev_i, // min_k L(p-r, k)
  input  wire  [PW-1:0] p1_i,
  input  wire  [PW-1:0] p2r_i,
  input  wire           start_i,
  output logic [LW-1:0] lr_o
);

  // One bit of headroom over LW for the penalised terms.
  localparam int EW = LW + 1;

  wire [EW-1:0] same  = {1'b0, prev_i};
  wire [EW-1:0] lower = has_lo_i ? {1'b0, prev_lo_i} + EW'(p1_i) : {EW{1'b1}};
  wire [EW-1:0] upper = has_hi_i ? {1'b0, prev_hi_i} + EW'(p1_i) : {EW{1'b1}};
  wire [EW-1:0] jump  = {1'b0, min_prev_i} + EW'(p2r_i);

  wire [EW-1:0] m01  = lower < same ? lower : same;
  wire [EW-1:0] m23  = jump < upper ? jump : upper;
  wire [EW-1:0] best = m23 < m01 ? m23 : m01;

  // best - minL lies in 0 .. P2r, so the sum fits LW bits (Lr <= Cmax + P2').
  wire [EW-1:0] step = best - {1'b0, min_prev_i};
  wire [LW-1:0] sum  = LW'(EW'(cost_i) + step);

  assign lr_o = start_i ? LW'(cost_i) : sum;

endmodule
`default_nettype wire
