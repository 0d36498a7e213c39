`default_nettype none
// sgm_path_loop: timing harness for place and route of the one single-cycle
// loop of the core, the 0 degree path recursion of sgm_path_engine (stage B,
// path r = 0): D sgm_path_pe sub-PEs fed by the previous pixel's Lr and
// min Lr, and the D-input sgm_min_tree whose result is registered for the
// next pixel. The PEs, the minimum tree and every register around the loop
// are connected exactly as in rtl/sgm_path_engine.sv (g_path[0], u_min0,
// lr0_q, min0_q, cost_b, p2r_b); keep the two in step.
//
// The whole core does not fit any iCE40 (see synth/README.md), so
// `make synth` routes this harness to give a real routed fmax for the loop.
// Its wide inputs (the D costs, P2r) come from a serial shift register and
// its outputs are XOR-reduced to one pin, so that the loop, not the I/O,
// sets the clock; the shift register and the reduction are registered and
// add no path to the loop.
//
// Parameters: D disparities, CW cost width, LW path-cost width, PW penalty width.
module sgm_path_loop #(
  parameter int D  = 16,
  parameter int CW = 7,
  parameter int LW = 9,
  parameter int PW = 8
) (
  input  wire  clk_i,
  input  wire  en_i,
  input  wire  din_i,     // serial data for the cost / penalty registers
  input  wire  start_i,   // path start (at_left in the engine)
  output logic dout_o     // XOR of the registered Lr and min Lr
);

  // Serial-in registers standing for the engine's stage-B inputs: cost_b
  // (registered costs), p2r_b (registered P2 lookup), p1 (configuration).
  localparam int SRW = D * CW + 2 * PW + 1;
  logic [SRW-1:0] sr_q;
  always_ff @(posedge clk_i) begin
    sr_q <= {sr_q[SRW-2:0], din_i};
  end

  logic [D*CW-1:0] cost_b;
  logic [PW-1:0]   p2r_b, p1;
  logic            start_b;
  always_ff @(posedge clk_i) begin
    if (en_i) {start_b, p1, p2r_b, cost_b} <= sr_q;
  end

  // The loop: sgm_path_engine stage B for r = 0.
  logic [D*LW-1:0] lr0_q;
  logic [LW-1:0]   min0_q;
  logic [D*LW-1:0] lr_b;
  wire  [(D+1)*LW-1:0] pw = {min0_q, lr0_q};

  for (genvar d = 0; d < D; d++) begin : g_pe
    sgm_path_pe #(.CW(CW), .LW(LW), .PW(PW)) u_pe (
      .cost_i     (cost_b[d*CW +: CW]),
      .prev_i     (pw[d*LW +: LW]),
      .prev_lo_i  (d > 0 ? pw[(d > 0 ? d - 1 : 0)*LW +: LW] : {LW{1'b0}}),
      .prev_hi_i  (d < D - 1 ? pw[(d < D - 1 ? d + 1 : d)*LW +: LW] : {LW{1'b0}}),
      .has_lo_i   (d > 0),
      .has_hi_i   (d < D - 1),
      .min_prev_i (min0_q),
      .p1_i       (p1),
      .p2r_i      (p2r_b),
      .start_i    (start_b),
      .lr_o       (lr_b[d*LW +: LW])
    );
  end

  logic [LW-1:0] min0_d;
  sgm_min_tree #(.N(D), .W(LW)) u_min0 (
    .values_i (lr_b),
    .min_o    (min0_d)
  );

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lr0_q  <= lr_b;
      min0_q <= min0_d;
    end
  end

  // Output: registered XOR reduction (a tree of its own, outside the loop).
  logic [LW-1:0] x_q;
  always_ff @(posedge clk_i) begin
    logic [LW-1:0] x;
    x = min0_q;
    for (int d = 0; d < D; d++) x = x ^ lr0_q[d*LW +: LW];
    x_q    <= x;
    dout_o <= ^x_q;
  end

endmodule
`default_nettype wire
