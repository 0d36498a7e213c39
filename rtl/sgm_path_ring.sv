// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_path_ring: the 0 degree path recursion of eq. (1) (docs/algorithm.md
// section 5), the one loop of the core: D sgm_path_pe sub-PEs fed by the
// previous pixel's Lr and min Lr, and the D-input minimum of their results,
// with LANES registers in the loop.
//
// LANES = K: K independent pixel streams (lanes) share the PEs and the tree by
// time multiplexing, slot K t + k belonging to lane k (docs/lanes.md), so
// the recursion of each lane may take K slots. The loop's logic is cut into K
// pipeline stages. Its units are the three parts of the sub-PE (sgm_path_pe:
// two carry chains each) and the levels of the minimum tree, built of 4-input
// nodes (six comparator chains side by side and a 4:1 select), U = 3 +
// ceil(log4 D) units of about equal delay on ECP5 (docs/notes/synthesis-log.md, "the loop
// alone"). Inner register j = 1 .. K - 1 sits after unit round(j U / K)
// (counted from 1; none before the first unit); a boundary inside the sub-PE
// takes at most one, and any further register placed there joins the loop
// register after the last tree level, which closes the loop. So K = U gives
// one unit per stage. The Lr vector travels beside the tree as many slots as
// the tree's registers (a rotating memory, sgm_delay_ram), and the inputs a
// sub-PE part takes later (min Lr of the previous
// pixel; cost, P2r and path start) are carried with the pixel. LANES = 1 is
// the loop of the single-lane core: combinational PEs and tree, one register
// after the tree.
//
// Throughput: one pixel per slot (en_i), each lane one pixel every K slots.
// Parameters: D disparities, CW cost width, LW path-cost width (Cmax + P2'max
// must fit), PW penalty width, LANES loop stages (>= 1).
// Latency: LATENCY = LANES slots from a pixel's inputs to its lr_o / min_o,
// which are the previous pixel's Lr of the lane of the slot being presented.
module sgm_path_ring #(
  parameter int D     = 64,
  parameter int CW    = 7,
  parameter int LW    = 9,
  parameter int PW    = 8,
  parameter int LANES /*verilator public*/ = 1,
  localparam int LATENCY = LANES
) (
  input  wire             clk_i,
  input  wire             rst_ni,   // the Lr carry's pointer (sgm_delay_ram)
  input  wire             en_i,
  input  wire  [PW-1:0]   p1_i,     // configuration (constant while the frame flows)
  // Slot input: the pixel of this slot's lane.
  input  wire  [D*CW-1:0] cost_i,
  input  wire  [PW-1:0]   p2r_i,
  input  wire             start_i,  // path start: Lr = C
  // LATENCY slots later: the pixel's Lr (d at lr_o[d*LW +: LW]) and its minimum.
  output logic [D*LW-1:0] lr_o,
  output logic [LW-1:0]   min_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 2 && D <= 256)) begin : g_bad_d
    $error("sgm_path_ring: D = %0d: D must be from 2 to 256", D);
  end
  if (!(LW >= CW)) begin : g_bad_lw
    $error("sgm_path_ring: LW = %0d: LW must be at least CW = %0d (the path cost holds the matching cost)", LW, CW);
  end
  if (!(LW >= PW)) begin : g_bad_lw_2
    $error("sgm_path_ring: LW = %0d: LW must be at least PW = %0d (the path cost holds the penalties)", LW, PW);
  end
  if (!(PW >= 1)) begin : g_bad_pw
    $error("sgm_path_ring: PW = %0d: PW must be at least 1", PW);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_path_ring: LANES = %0d: LANES must be at least 1", LANES);
  end
`endif

  localparam int ARITY = 4;  // inputs of a tree node (sgm_min_tree, N = ARITY)

  localparam int LEVELS = ($clog2(D) + 1) / 2;  // ceil(log4 D) = ceil(ceil(log2 D) / 2)
  localparam int P      = ARITY ** LEVELS;  // leaves of the complete tree
  localparam int UNITS  = 3 + LEVELS;    // units 0 .. 2: sub-PE parts; 2 + l: tree level l

  // The unit after which inner register j (1 .. LANES - 1) sits: round(j U / K) - 1.
  function automatic integer cut_unit(input integer j);
    cut_unit = (2 * j * UNITS + LANES) / (2 * LANES) - 1;
    if (cut_unit < 0) cut_unit = 0;
  endfunction

  // Inner registers after unit u as placed, before the sub-PE rule.
  function automatic integer placed(input integer u);
    integer j;
    placed = 0;
    for (j = 1; j < LANES; j++) if (cut_unit(j) == u) placed = placed + 1;
  endfunction

  // The sub-PE's registers (sgm_path_pe CUTS): after part (a) and after part (b).
  localparam int CUT_A  = placed(0) > 0 ? 1 : 0;
  localparam int CUT_B  = placed(1) > 0 ? 1 : 0;
  localparam int PE_CUTS = CUT_A + 2 * CUT_B;

  // Registers after unit u (2 .. UNITS - 1): the loop register after the last level.
  function automatic integer regs_after(input integer u);
    regs_after = placed(u);
    if (u == UNITS - 1) regs_after = regs_after + 1 + placed(0) - CUT_A + placed(1) - CUT_B;
  endfunction

  // ------------------------------------------------------------- the sub-PEs
  logic [D*LW-1:0] lr_fb;   // Lr of this lane's previous pixel (the ring's end)
  logic [LW-1:0]   min_fb;

  // The later inputs of the sub-PE parts, carried with the pixel: min Lr of the
  // previous pixel at part (b), the slot's cost, P2r and path start at part (c).
  logic [LW-1:0]   min_b;
  logic [D*CW-1:0] cost_c;
  logic [PW-1:0]   p2r_c;
  logic            start_c;
  logic [D*CW+PW:0] late_a, late_b;  // {cost, P2r, start} at the entry and at part (b)
  assign late_a = {cost_i, p2r_i, start_i};
  if (CUT_A == 1) begin : g_carry_a
    always_ff @(posedge clk_i) begin
      if (en_i) {min_b, late_b} <= {min_fb, late_a};
    end
  end else begin : g_pass_a
    assign {min_b, late_b} = {min_fb, late_a};
  end
  if (CUT_B == 1) begin : g_carry_b
    always_ff @(posedge clk_i) begin
      if (en_i) {cost_c, p2r_c, start_c} <= late_b;
    end
  end else begin : g_pass_b
    assign {cost_c, p2r_c, start_c} = late_b;
  end

  logic [D*LW-1:0] lr_pe;
  for (genvar d = 0; d < D; d++) begin : g_pe
    sgm_path_pe #(.CW(CW), .LW(LW), .PW(PW), .CUTS(PE_CUTS)) u_pe (
      .clk_i      (clk_i),
      .en_i       (en_i),
      .prev_i     (lr_fb[d*LW +: LW]),
      .prev_lo_i  (d > 0 ? lr_fb[(d > 0 ? d - 1 : 0)*LW +: LW] : {LW{1'b0}}),
      .prev_hi_i  (d < D - 1 ? lr_fb[(d < D - 1 ? d + 1 : d)*LW +: LW] : {LW{1'b0}}),
      .has_lo_i   (d > 0),
      .has_hi_i   (d < D - 1),
      .p1_i       (p1_i),
      .min_prev_i (min_b),
      .cost_i     (cost_c[d*CW +: CW]),
      .p2r_i      (p2r_c),
      .start_i    (start_c),
      .lr_o       (lr_pe[d*LW +: LW])
    );
  end

  // ------------------------------------------------------ the minimum tree
  // Level l (0 = the leaves: the D PE results padded with all ones to P) holds
  // P / 4^l nodes; node n of level l + 1 is the minimum of nodes 4n .. 4n + 3
  // of level l (the heap order of sgm_min_tree). lvl_in[l] = the nodes of
  // level l before the registers of its unit (2 + l), lvl_out[l] after them.
  localparam int VW = P * LW;
  // split_var: each level is its own variable for Verilator (no false loop).
  logic [VW-1:0] lvl_in  [LEVELS+1] /* verilator split_var */;
  logic [VW-1:0] lvl_out [LEVELS+1] /* verilator split_var */;

  assign lvl_in[0] = {{(P-D){{LW{1'b1}}}}, lr_pe};

  for (genvar l = 0; l <= LEVELS; l++) begin : g_level
    localparam int NR = regs_after(2 + l);
    if (NR == 0) begin : g_wire
      assign lvl_out[l] = lvl_in[l];
    end else begin : g_regs
      logic [NR*VW-1:0] chain_q;  // packed (Icarus: a continuous assignment from an unpacked array word)
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          chain_q[0 +: VW] <= lvl_in[l];
          for (int i = 1; i < NR; i++) chain_q[i*VW +: VW] <= chain_q[(i-1)*VW +: VW];
        end
      end
      assign lvl_out[l] = chain_q[(NR-1)*VW +: VW];
    end
    if (l < LEVELS) begin : g_nodes
      localparam int N = P / (ARITY ** (l + 1));  // nodes of level l + 1
      for (genvar n = 0; n < P; n++) begin : g_node
        if (n < N) begin : g_min
          sgm_min_tree #(.N(ARITY), .W(LW), .ARITY(ARITY)) u_node (
            .values_i (lvl_out[l][ARITY*n*LW +: ARITY*LW]),
            .min_o    (lvl_in[l+1][n*LW +: LW])
          );
        end else begin : g_pad
          assign lvl_in[l+1][n*LW +: LW] = {LW{1'b1}};
        end
      end
    end
  end

  // The Lr vector travels beside the tree as far as all of its registers
  // together (LR_DELAY = K slots minus the sub-PE's own registers), in a
  // rotating memory rather than a register chain (sgm_delay_ram: half the xc7
  // LUTs of the SRLs a chain becomes).
  function automatic integer lr_delay();
    integer l;
    lr_delay = 0;
    for (l = 0; l <= LEVELS; l++) lr_delay = lr_delay + regs_after(2 + l);
  endfunction
  localparam int LR_DELAY = lr_delay();
  sgm_delay_ram #(.WIDTH(D * LW), .DEPTH(LR_DELAY)) u_lr_carry (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .en_i   (en_i),
    .d_i    (lr_pe),
    .q_o    (lr_fb)
  );

  assign min_fb = lvl_out[LEVELS][0 +: LW];
  assign lr_o   = lr_fb;
  assign min_o  = min_fb;

endmodule
`default_nettype wire
