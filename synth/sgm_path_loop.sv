// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_path_loop: timing harness for place and route of the one single-cycle
// loop of the core, the 0 degree path recursion (rtl/sgm_path_ring.sv, the
// module sgm_path_engine instantiates as u_ring): D sgm_path_pe sub-PEs fed by
// the previous pixel's Lr and min Lr, and the D-input minimum whose result is
// registered for the next pixel, with registered inputs as in the engine
// (cost_b, p2r_b).
//
// The whole core does not fit any iCE40 (see synth/README.md), so
// `make synth` routes this harness to give a real routed fmax for the loop.
// Its wide inputs (the D costs, P2r) come from a serial shift register and
// its outputs are XOR-reduced to one pin, so that the loop, not the I/O,
// sets the clock; the shift register and the reduction are registered and
// add no path to the loop.
//
// LANES = K > 1 measures the loop of the planned re-schedule (docs/lanes.md):
// K independent pixel streams (row lanes) share the PEs and the tree, so the
// recursion may take K clocks, and the ring has K registers in the loop (its
// header says where). LANES = 1 is the core's loop today (one register, after
// the tree).
//
// Parameters: D disparities, CW cost width, LW path-cost width, PW penalty
// width, LANES loop registers (>= 1).
module sgm_path_loop #(
  parameter int D     = 16,
  parameter int CW    = 7,
  parameter int LW    = 9,
  parameter int PW    = 8,
  parameter int LANES = 1
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

  // The loop: rtl/sgm_path_ring.sv, the module the core's sgm_path_engine
  // instantiates for its 0 degree path (there at LANES = 1).
  logic [D*LW-1:0] lr0_q;
  logic [LW-1:0]   min0_q;
  sgm_path_ring #(.D(D), .CW(CW), .LW(LW), .PW(PW), .LANES(LANES)) u_ring (
    .clk_i   (clk_i),
    .rst_ni  (1'b1),   // no reset pin: the Lr carry's pointer starts at its power-up value
    .en_i    (en_i),
    .p1_i    (p1),
    .cost_i  (cost_b),
    .p2r_i   (p2r_b),
    .start_i (start_b),
    .lr_o    (lr0_q),
    .min_o   (min0_q)
  );

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
