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
// LANES = K > 1 measures the loop of the planned re-schedule (docs/reschedule.md):
// K independent pixel streams (row lanes) share the PEs and the tree, so the
// recursion may take K clocks. K registers then sit in the loop: the loop's
// logic, in units of 2 for the PEs and 1 per ternary tree level, is cut into K
// nearly equal parts (a part with nothing left to cut is a plain register),
// and the Lr vector travels beside the minimum through the same registers.
// LANES = 1 is exactly today's loop (one register, after the tree).
//
// Parameters: D disparities, CW cost width, LW path-cost width, PW penalty
// width, LANES loop registers (1 .. 8).
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

  // The loop: sgm_path_engine stage B for r = 0, with LANES registers in it.
  function automatic integer log3_ceil(input integer n);
    integer p;
    log3_ceil = 0;
    for (p = 1; p < n; p = p * 3) log3_ceil = log3_ceil + 1;
  endfunction
  localparam int LEVELS = log3_ceil(D);
  localparam int P      = 3 ** LEVELS;
  localparam int UNITS  = 2 + LEVELS;  // PEs = 2 units, one per tree level

  // Registers after tree level l (l = 0: after the PEs): cut j = 1 .. LANES - 1
  // at unit round(j UNITS / LANES), the last register after the last level.
  function automatic integer regs_after(input integer l);
    integer j, u;
    regs_after = (l == LEVELS) ? 1 : 0;
    for (j = 1; j < LANES; j++) begin
      u = (j * UNITS + LANES / 2) / LANES;
      if ((u <= 2 ? 0 : (u - 2 > LEVELS ? LEVELS : u - 2)) == l) regs_after = regs_after + 1;
    end
  endfunction

  logic [D*LW-1:0] lr_fb;   // Lr of this lane's previous pixel
  logic [LW-1:0]   min_fb;  // and its minimum
  logic [D*LW-1:0] lr_b;
  wire  [(D+1)*LW-1:0] pw = {min_fb, lr_fb};

  for (genvar d = 0; d < D; d++) begin : g_pe
    sgm_path_pe #(.CW(CW), .LW(LW), .PW(PW)) u_pe (
      .cost_i     (cost_b[d*CW +: CW]),
      .prev_i     (pw[d*LW +: LW]),
      .prev_lo_i  (d > 0 ? pw[(d > 0 ? d - 1 : 0)*LW +: LW] : {LW{1'b0}}),
      .prev_hi_i  (d < D - 1 ? pw[(d < D - 1 ? d + 1 : d)*LW +: LW] : {LW{1'b0}}),
      .has_lo_i   (d > 0),
      .has_hi_i   (d < D - 1),
      .min_prev_i (min_fb),
      .p1_i       (p1),
      .p2r_i      (p2r_b),
      .start_i    (start_b),
      .lr_o       (lr_b[d*LW +: LW])
    );
  end

  // Level l of the ternary tree holds P / 3^l nodes (level 0: the leaves, padded
  // with all ones); lvl_in[l] is level l before its registers, lvl_out[l] after.
  // Each level travels with the Lr vector through regs_after(l) registers.
  localparam int VW = P * LW + D * LW;  // {nodes (at most P), Lr}
  logic [VW-1:0] lvl_in  [LEVELS+1];
  logic [VW-1:0] lvl_out [LEVELS+1];

  assign lvl_in[0] = {{(P-D){{LW{1'b1}}}}, lr_b, lr_b};

  for (genvar l = 0; l <= LEVELS; l++) begin : g_level
    localparam int NR = regs_after(l);
    if (NR == 0) begin : g_wire
      assign lvl_out[l] = lvl_in[l];
    end else begin : g_regs
      logic [VW-1:0] chain_q [NR];
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          chain_q[0] <= lvl_in[l];
          for (int i = 1; i < NR; i++) chain_q[i] <= chain_q[i-1];
        end
      end
      assign lvl_out[l] = chain_q[NR-1];
    end
    if (l < LEVELS) begin : g_nodes
      localparam int N = P / (3 ** (l + 1));  // nodes of level l + 1
      logic [P*LW-1:0] nodes;
      for (genvar n = 0; n < P; n++) begin : g_node
        if (n < N) begin : g_min
          wire [LW-1:0] a  = lvl_out[l][D*LW + (3*n+0)*LW +: LW];
          wire [LW-1:0] b  = lvl_out[l][D*LW + (3*n+1)*LW +: LW];
          wire [LW-1:0] c  = lvl_out[l][D*LW + (3*n+2)*LW +: LW];
          wire          ab = a <= b;
          wire          ac = a <= c;
          wire          bc = b <= c;
          assign nodes[n*LW +: LW] = ab && ac ? a : bc ? b : c;
        end else begin : g_pad
          assign nodes[n*LW +: LW] = {LW{1'b1}};
        end
      end
      assign lvl_in[l+1] = {nodes, lvl_out[l][0 +: D*LW]};
    end
  end

  assign lr_fb  = lvl_out[LEVELS][0 +: D*LW];
  assign min_fb = lvl_out[LEVELS][D*LW +: LW];

  // Observed registers: the Lr and minimum fed back (LANES = 1: lr0_q, min0_q).
  wire [D*LW-1:0] lr0_q  = lr_fb;
  wire [LW-1:0]   min0_q = min_fb;

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
