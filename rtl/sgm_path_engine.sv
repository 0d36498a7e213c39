// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_path_engine: the four causal path costs of eq. (1) and their sum S
// (docs/algorithm.md section 5) at one pixel per slot, D sub-PEs per path.
//
// Slots: LANES = K lanes share the engine slot by slot (slot K n + k belongs
// to lane k, docs/lanes.md). Each lane is a virtual raster of its own
// (docs/rtl.md): consecutive slots of a lane are consecutive positions, rows
// < 0 and >= height carry no pixel; lane k holds rows k, k + K, k + 2K, ...
// and runs SKEW columns behind lane k - 1 (lane 0 one group of rows later
// behind lane K - 1). With K = 1 the slots are the raster of the frame.
// Pipeline (one register stage per slot; t = the slot of the pixel's cost_i,
// B = t + 1, B' = B + K - 1, C = B + K):
//   -      (GRAY_LEAD = 1) the P2r lookup runs in the slot before t (block
//          RAM, registered read: the grays centre_i / nbr_i lead cost_i by one
//          slot)
//   t      register the cost vector and position, and P2r behind the block
//          RAM (its clock-to-out is then not part of the 0 degree loop; with
//          GRAY_LEAD = 0 the lookup runs here and P2r comes from the RAM port)
//   B      the 0 degree path (sgm_path_ring, K lanes: the loop's K stages,
//          its Lr at C)
//   B' - 4 read the previous-row memories at the pixel's column x (col_i
//          leads cost_i by COL_LEAD >= 3 slots): M90[x], M45[x - 1], M135[x + 1]
//   B' - 3 the memories' output register
//   B' - 2 part (a) of the 45/90/135 degree sub-PEs (sgm_path_pe, CUTS = 3),
//          which needs only the previous row and P1
//   B' - 1 part (b) (min Lr of the previous row)
//   B'     part (c): + C, P2r, path start (cost and P2r carried K - 1 slots)
//   C      S = weighted sum of the four Lr (3,2,3,2, or equal when
//          weights_eq_i), plus the fifth path's W5 L5 (l5w_i, from
//          sgm_right_path, with RIGHT_PATH = 1), registered to s_o; Lr of 45/90/135 degrees written
//          to the path memories at the pixel's column (45 degrees
//          W45_DELAY = max(0, K - 4) slots later); each word's minimum enters
//          sgm_min_pipe as the word is written and is written to the path's
//          min memory MIN_DELAY slots after it (MIN_LATENCY, the tree's, or one more)
// Path memories (per vertical path: MAX_WIDTH words of D x LW bits and
// MAX_WIDTH words of LW bits for min Lr; synchronous read with enable -> block
// RAM). Row y reads the words row y - 1 wrote at x - 1 .. x + 1 at slot
// B' - 4 of its pixel x; the writer (the lane before, SKEW columns ahead) wrote
// x + 1 (SKEW - 1) K + 1 slots before that pixel's B', and its minimum
// MIN_LATENCY slots after C: SKEW = 1 + ceil((5 + MIN_LATENCY) / K) keeps
// every read behind its write. Row y overwrites word x at its pixel x's C,
// after its own reads of x (pixel x + 1's read of M45[x] comes K slots after
// pixel x's: the 45 degree write waits max(0, K - 4) slots, so that the read
// comes strictly before it and never relies on the block RAM's read-during-
// write behaviour across ports). With K = 1 a
// word written at x is read by the next row W - 4 slots later at the earliest
// (x - 1, M135), at least W - 6 - MIN_LATENCY slots after its minimum
// (W >= MIN_WIDTH); with K lanes lane 0 reads lane K - 1 of the previous
// group, K (W - 2 - (K - 1) SKEW) + 1 slots after its writes: W >= MIN_WIDTH
// = K SKEW + 1 (9 .. 11 at K = 1, 19 at D = 64 and K = 6; docs/lanes.md).
//
// Parameters: D disparities, CW cost width, LW path-cost width (Cmax + P2'max
// must fit), PW penalty width, MAX_WIDTH, XW column bits, YW row bits, GRAY_LEAD
// (0 or 1, see t), COL_LEAD (>= 3: how many slots col_i leads cost_i), LANES
// (K >= 1), RIGHT_PATH (1: S adds l5w_i, W5 L5 with W5 <= 15 in L5W = LW + 4
// bits). SW = LW + 4 + RIGHT_PATH holds the larger of the two weightings
// (10 x 2^LW, with the fifth path (10 + 15) x 2^LW).
// EDGE_RESET = 1 builds the path restart at strong edges (docs/algorithm.md
// section 12, golden Params::edgeReset): path r starts again (Lr = C, as at
// the frame's border) at every pixel whose last R = reset_len_i steps along
// the path, the step into it included, cross a gray step |dI| >= T =
// reset_t_i, for the paths marked in reset_paths_i (T = 0: none). A 4-bit
// count per path (the steps since its last strong edge, saturating at R; R at
// a path start) travels with the path: for 0 degrees K slots beside the ring
// (decided at B, the ring's path start), for 45/90/135 degrees beside min Lr
// in the min memories (MW = LW + 4 bits; decided at B' - 1 from the previous
// row's count; with K >= 2 lanes ORed there with the border start and
// registered, so that part (c) sees a flip-flop as its path start, as without
// the restart; with one lane registered and ORed at B'). EDGE_RESET = 0
// builds none of it (the reset_* ports unused).
// Latency: LATENCY = K + 2 slots from cost_i to s_o (l5w_i K + 1 slots after
// the pixel's cost_i); row_i, centre_i and nbr_i
// of a pixel are presented GRAY_LEAD slots before its cost_i (valid_i with
// it), col_i COL_LEAD slots before.
// Throughput: 1 pixel per slot (each lane one pixel every K slots).
module sgm_path_engine #(
  parameter int D         = 64,
  parameter int CW        = 7,
  parameter int LW        = 9,
  parameter int PW        = 8,
  parameter int MAX_WIDTH = 1280,
  parameter int XW        = 11,
  parameter int YW        = 11,
  parameter int RIGHT_PATH = 0,
  parameter int EDGE_RESET /*verilator public*/ = 0,
  localparam int L5W      = LW + 4,
  localparam int MW       = LW + (EDGE_RESET != 0 ? 4 : 0),  // min memory word: {count, min Lr}
  localparam int SW       = LW + 4 + (RIGHT_PATH != 0 ? 1 : 0),
  // 1: P2r registered behind the table (the grays lead by one slot); 0: P2r
  // straight from the table's read port into the sub-PEs (grays with the costs).
  parameter int GRAY_LEAD /*verilator public*/ = 1,
  parameter int COL_LEAD  /*verilator public*/ = 3,
  parameter int LANES     /*verilator public*/ = 1,
  localparam int MIN_LATENCY = ($clog2(D) + 1) / 2,  // sgm_min_pipe's LATENCY
  // Columns lane k runs behind lane k - 1 (the rows above must be written).
  localparam int SKEW     /*verilator public*/ = 1 + (5 + MIN_LATENCY + LANES - 1) / LANES,
  // The narrowest frame the schedule supports (lane 0 reads lane K - 1).
  localparam int MIN_WIDTH /*verilator public*/ = LANES * SKEW + 1,
  localparam int LATENCY  = LANES + 2
) (
  input  wire                 clk_i,
  input  wire                 rst_ni,
  input  wire                 en_i,
  // Per-frame configuration (constant while the frame's slots flow).
  input  wire  [XW-1:0]       width_i,
  input  wire  [PW-1:0]       p1_i,
  input  wire                 weights_eq_i,  // S weights: 0 = 3,2,3,2, 1 = equal (the paper's sum)
  // The path restart at strong edges (EDGE_RESET = 1).
  input  wire  [7:0]          reset_t_i,     // T: a strong edge's gray step; 0 = off
  input  wire  [3:0]          reset_len_i,   // R: steps restarted from the edge on (1 .. 15)
  input  wire  [3:0]          reset_paths_i, // bit r: path r (0, 45, 90, 135 degrees) restarts
  // P2 table fill (sgm_p2_lut): start with p1_i / p2_i / p2_mode_i, ready when filled.
  input  wire                 lut_start_i,
  input  wire  [PW-1:0]       p2_i,
  input  wire                 p2_mode_i,     // 0 knee, 1 paper (P2' / dI)
  output logic                lut_ready_o,
  // Slot input: the pixel's costs, position and left-image grays.
  input  wire  [D*CW-1:0]     cost_i,
  // The column of the pixel of slot t + COL_LEAD (its previous-row reads).
  input  wire  [XW-1:0]       col_i,
  // The row of the pixel of the next slot, like the grays (GRAY_LEAD slots ahead of
  // cost_i; rows outside the frame carry no pixel, valid_i = 0 with the costs).
  input  wire  [YW-1:0]       row_i,
  input  wire                 valid_i,
  // The left-image grays of the pixel of the next slot (GRAY_LEAD slots ahead of cost_i).
  input  wire  [7:0]          centre_i,
  input  wire  [31:0]         nbr_i,     // I(p - r): 0, 45, 90, 135 degrees, 8 bits each
  // The fifth path's W5 L5 of the pixel, K + 1 slots after its cost_i (RIGHT_PATH = 1).
  input  wire  [D*L5W-1:0]    l5w_i,
  // Slot output, LATENCY slots later.
  output logic [D*SW-1:0]     s_o,
  output logic [XW-1:0]       col_o,
  output logic [YW-1:0]       row_o,
  output logic                last_o,    // col_o == width_i - 1 (decided at slot B, carried)
  output logic                valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 2 && D <= 256)) begin : g_bad_d
    $error("sgm_path_engine: D = %0d: D must be from 2 to 256", D);
  end
  if (!(LW >= CW)) begin : g_bad_lw
    $error("sgm_path_engine: LW = %0d: LW must be at least CW = %0d (the path cost holds the matching cost)", LW, CW);
  end
  if (!(LW >= PW)) begin : g_bad_lw_2
    $error("sgm_path_engine: LW = %0d: LW must be at least PW = %0d (the path cost holds the penalties)", LW, PW);
  end
  if (!(PW >= 1)) begin : g_bad_pw
    $error("sgm_path_engine: PW = %0d: PW must be at least 1", PW);
  end
  if (!(MAX_WIDTH >= MIN_WIDTH)) begin : g_bad_max_width
    $error("sgm_path_engine: MAX_WIDTH = %0d: MAX_WIDTH must be at least the narrowest frame, MIN_WIDTH = LANES SKEW + 1 = %0d", MAX_WIDTH, MIN_WIDTH);
  end
  if (!(XW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_xw
    $error("sgm_path_engine: XW = %0d: XW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", XW, MAX_WIDTH);
  end
  if (!(YW >= 2)) begin : g_bad_yw
    $error("sgm_path_engine: YW = %0d: YW must be at least 2", YW);
  end
  if (!(RIGHT_PATH == 0 || RIGHT_PATH == 1)) begin : g_bad_right_path
    $error("sgm_path_engine: RIGHT_PATH = %0d: RIGHT_PATH must be 0 or 1", RIGHT_PATH);
  end
  if (!(EDGE_RESET == 0 || EDGE_RESET == 1)) begin : g_bad_edge_reset
    $error("sgm_path_engine: EDGE_RESET = %0d: EDGE_RESET must be 0 or 1", EDGE_RESET);
  end
  if (!(GRAY_LEAD == 0 || GRAY_LEAD == 1)) begin : g_bad_gray_lead
    $error("sgm_path_engine: GRAY_LEAD = %0d: GRAY_LEAD must be 0 or 1", GRAY_LEAD);
  end
  if (!(COL_LEAD >= 3)) begin : g_bad_col_lead
    $error("sgm_path_engine: COL_LEAD = %0d: COL_LEAD must be at least 3", COL_LEAD);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_path_engine: LANES = %0d: LANES must be at least 1", LANES);
  end
`endif

  localparam int LWORD = D * LW;  // {Lr(D-1) .. Lr(0)} of one path
  localparam int AW    = $clog2(MAX_WIDTH);
  localparam int K     = LANES;
  localparam int W45_DELAY = K > 4 ? K - 4 : 0;  // the 45 degree write waits for pixel x + 1's read

  // ------------------------------------------------------------------ slot t
  logic [31:0] dI;
  for (genvar r = 0; r < 4; r++) begin : g_grad
    wire [7:0] n = nbr_i[r*8 +: 8];
    assign dI[r*8 +: 8] = centre_i > n ? centre_i - n : n - centre_i;
  end

  logic [4*PW-1:0] p2r_a, p2r_b;
  sgm_p2_lut #(.PW(PW), .NPORTS(4)) u_p2_lut (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .start_i (lut_start_i),
    .p1_i    (p1_i),
    .p2_i    (p2_i),
    .mode_i  (p2_mode_i),
    .ready_o (lut_ready_o),
    .en_i    (en_i),
    .idx_i   (dI),
    .p2r_o   (p2r_a)
  );

  logic [YW-1:0]      row_a;  // row_i, GRAY_LEAD slots later (see g_p2r_reg)
  logic [D*CW-1:0]    cost_b;
  logic [YW-1:0]      row_b;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      cost_b  <= cost_i;
      row_b   <= row_a;
    end
  end

  // The row (and P2r) one register more when they lead the costs.
  if (GRAY_LEAD == 1) begin : g_p2r_reg
    always_ff @(posedge clk_i) begin
      if (en_i) p2r_b <= p2r_a;
      if (en_i) row_a <= row_i;
    end
  end else begin : g_p2r_ram
    assign p2r_b = p2r_a;
    assign row_a = row_i;
  end

  // Slot valid flags (B .. C, then s_o): the only registers with a reset.
  logic [K:0] valid_q;  // valid_q[i]: the slot at B + i
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_q <= '0;
      valid_o <= 1'b0;
    end else if (en_i) begin
      valid_q <= {valid_q[K-1:0], valid_i};
      valid_o <= valid_q[K];
    end
  end

  // The column at B (path starts), COL_LEAD + 1 slots after col_i.
  logic [XW-1:0] col_b;
  sgm_delay #(.WIDTH(XW), .DEPTH(COL_LEAD + 1)) u_col_b (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (col_i),
    .q_o   (col_b)
  );

  // ------------------------------------------------------------------ slot B
  wire at_left  = col_b == '0;
  wire at_right = col_b == width_i - 1'b1;
  wire at_top   = row_b == '0;
  // The 45/90/135 degree path starts at B (carried to B' with the cost).
  wire [3:1] start_b = {at_right | at_top, at_top, at_left | at_top};

  // ------------------------------------------------- the path restart (EDGE_RESET)
  // edge_t[r]: pixel p's step along path r is a strong edge of a restarting
  // path (at slot t); start0: the 0 degree path start at B (the border or a
  // restart); start_pe[r]: the path start of path r (1 .. 3) at B', the border
  // or a restart (with K >= 2 lanes one register: the border start taken at
  // B' - 1 and ORed with the restart there, so that part (c) sees a flip-flop,
  // as without the restart); count_v[r]: its count at B' (before the path start).
  logic       start0;
  logic [3:1] start;     // the border starts carried to B' (below, with the cost)
  logic [3:1] start_pe;
  logic [11:0] count_v;  // path r at [(r-1)*4 +: 4]
  logic [11:0] count_prev;  // the previous row's counts at B' - 1 (from the min memories)
  if (EDGE_RESET != 0) begin : g_restart
    wire [3:0] on = reset_paths_i & {4{reset_t_i != 8'd0}};
    logic [3:0] edge_g, edge_t;
    for (genvar r = 0; r < 4; r++) begin : g_edge
      assign edge_g[r] = on[r] && dI[r*8 +: 8] >= reset_t_i;
    end
    if (GRAY_LEAD == 1) begin : g_edge_reg
      always_ff @(posedge clk_i) begin
        if (en_i) edge_t <= edge_g;
      end
    end else begin : g_edge_now
      assign edge_t = edge_g;
    end
    // 0 degrees at B: the lane's previous count comes back after K slots.
    logic edge_b;
    always_ff @(posedge clk_i) begin
      if (en_i) edge_b <= edge_t[0];
    end
    logic [3:0] count0_prev;
    wire  [4:0] count0_inc = {1'b0, count0_prev} + 5'd1;
    wire        near0      = count0_inc < {1'b0, reset_len_i};
    wire  [3:0] count0     = at_left ? reset_len_i : edge_b ? 4'd0 : near0 ? count0_inc[3:0] : reset_len_i;
    sgm_delay #(.WIDTH(4), .DEPTH(K)) u_count0 (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   (count0),
      .q_o   (count0_prev)
    );
    assign start0 = at_left || (on[0] && (edge_b || near0));
    // 45/90/135 degrees at B' - 1 = t + K - 1.
    logic [3:1] edge_v;
    if (K > 1) begin : g_edge_carry
      sgm_delay #(.WIDTH(3), .DEPTH(K - 1)) u_edge_v (
        .clk_i (clk_i),
        .en_i  (en_i),
        .d_i   (edge_t[3:1]),
        .q_o   (edge_v)
      );
    end else begin : g_edge_at_t
      assign edge_v = edge_t[3:1];
    end
    logic [3:1] restart_d;  // path r restarts (at B' - 1)
    for (genvar r = 1; r < 4; r++) begin : g_count
      wire [3:0] prev = count_prev[(r-1)*4 +: 4];
      wire [4:0] inc  = {1'b0, prev} + 5'd1;
      wire       near = inc < {1'b0, reset_len_i};
      assign restart_d[r] = on[r] && (edge_v[r] || near);
      always_ff @(posedge clk_i) begin
        if (en_i) count_v[(r-1)*4 +: 4] <= edge_v[r] ? 4'd0 : near ? inc[3:0] : reset_len_i;
      end
    end
    if (K > 1) begin : g_start_early
      // The border starts at B' - 1: start_b carried K - 2 slots.
      logic [3:1] start_m1, start_q;
      if (K > 2) begin : g_start_carry
        sgm_delay #(.WIDTH(3), .DEPTH(K - 2)) u_start_m1 (
          .clk_i (clk_i),
          .en_i  (en_i),
          .d_i   (start_b),
          .q_o   (start_m1)
        );
      end else begin : g_start_at_b
        assign start_m1 = start_b;
      end
      always_ff @(posedge clk_i) begin
        if (en_i) start_q <= start_m1 | restart_d;
      end
      assign start_pe = start_q;
    end else begin : g_start_or
      // One lane: B' - 1 comes before B, where the border starts are known; the
      // restart is registered and ORed with them at B'.
      logic [3:1] restart_q;
      always_ff @(posedge clk_i) begin
        if (en_i) restart_q <= restart_d;
      end
      assign start_pe = start | restart_q;
    end
  end else begin : g_no_restart
    assign start0    = at_left;
    assign start_pe  = start;
    assign count_v   = '0;
    wire unused_reset = ^{reset_t_i, reset_len_i, reset_paths_i, count_prev};
  end

  // The 0 degree recursion (sgm_path_ring, K lanes): its sub-PEs and minimum
  // feed back through the ring's registers (lr0_c: the pixel's Lr at C).
  logic [D*LW-1:0] lr0_c;
  logic [LW-1:0]   min0_c;
  sgm_path_ring #(.D(D), .CW(CW), .LW(LW), .PW(PW), .LANES(K)) u_ring (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .en_i    (en_i),
    .p1_i    (p1_i),
    .cost_i  (cost_b),
    .p2r_i   (p2r_b[0 +: PW]),
    .start_i (start0),
    .lr_o    (lr0_c),
    .min_o   (min0_c)
  );

  // Part (c) of the 45/90/135 degree paths runs at B' = B + K - 1: the cost,
  // their P2r and path starts carried K - 1 slots.
  logic [D*CW-1:0] cost_p;
  logic [3*PW-1:0] p2r_p;
  logic [XW-1:0]   col_p;
  logic [YW-1:0]   row_p;
  logic            last_p;
  if (K > 1) begin : g_carry
    sgm_delay_ram #(.WIDTH(D*CW + 3*PW + 3 + XW + YW + 1), .DEPTH(K - 1)) u_carry (
      .clk_i  (clk_i),
      .rst_ni (rst_ni),
      .en_i   (en_i),
      .d_i    ({cost_b, p2r_b[PW +: 3*PW], start_b, col_b, row_b, at_right}),
      .q_o    ({cost_p, p2r_p, start, col_p, row_p, last_p})
    );
  end else begin : g_no_carry
    assign {cost_p, p2r_p, start, col_p, row_p, last_p} = {cost_b, p2r_b[PW +: 3*PW], start_b, col_b, row_b, at_right};
  end

  // ------------------------------------------------------ previous-row reads
  // At B' - 4: col_i delayed COL_LEAD - 3 + K - 1 slots.
  localparam int READ_DELAY = COL_LEAD - 3 + K - 1;
  // Read addresses: M90 at x, M45 at x - 1 (unused at x = 0: 45 deg start),
  // M135 at x + 1 (unused at the last column: 135 deg start). When the column
  // is there a slot before the read (READ_DELAY > 0) the addresses are
  // computed then and registered, so that no comparison with the width sits in
  // front of the memories (distributed RAM reads asynchronously). The unused
  // reads take the column itself (x + 0 at the last column, x - 0 at x = 0): the
  // border checks are an adder's carry, not a constant, so that synthesis does
  // not make them a synchronous reset gated by en_i (on the ECP5 a LUT from the
  // global enable into the flip-flops' LSR: a critical path of the fifth-path
  // core on the LFE5U-85F).
  function automatic logic [3*AW-1:0] read_addrs(input logic [XW-1:0] col, input logic [XW-1:0] width);
    read_addrs = {AW'(col + XW'(col != width - 1'b1)), AW'(col), AW'(col - XW'(col != '0))};
  endfunction
  logic [AW-1:0] addr90, addr45, addr135;
  if (READ_DELAY > 0) begin : g_addr_reg
    logic [XW-1:0] col_e;  // the column one slot before the read
    if (READ_DELAY > 1) begin : g_col_early
      sgm_delay #(.WIDTH(XW), .DEPTH(READ_DELAY - 1)) u_col_e (
        .clk_i (clk_i),
        .en_i  (en_i),
        .d_i   (col_i),
        .q_o   (col_e)
      );
    end else begin : g_col_now
      assign col_e = col_i;
    end
    always_ff @(posedge clk_i) begin
      if (en_i) {addr135, addr90, addr45} <= read_addrs(col_e, width_i);
    end
  end else begin : g_addr_now
    assign {addr135, addr90, addr45} = read_addrs(col_i, width_i);
  end

  logic [LWORD-1:0] mem45  [0:MAX_WIDTH-1];
  logic [LWORD-1:0] mem90  [0:MAX_WIDTH-1];
  logic [LWORD-1:0] mem135 [0:MAX_WIDTH-1];
  logic [MW-1:0]    min45  [0:MAX_WIDTH-1];  // {count (EDGE_RESET), min Lr}
  logic [MW-1:0]    min90  [0:MAX_WIDTH-1];
  logic [MW-1:0]    min135 [0:MAX_WIDTH-1];

  // Read at B' - 4, the memories' data at B' - 3, their output register at B' - 2.
  logic [3*LWORD-1:0] rd_m, rd_q;   // {135, 90, 45}
  logic [3*MW-1:0]    mrd_m, mrd_q, mrd_t;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_m  <= {mem135[addr135], mem90[addr90], mem45[addr45]};
      mrd_m <= {min135[addr135], min90[addr90], min45[addr45]};
      rd_q  <= rd_m;
      mrd_q <= mrd_m;
      mrd_t <= mrd_q;  // min Lr at part (b), one slot after part (a)
    end
  end

  // ------------------------------------------------------------------ slot B'
  logic [3*D*LW-1:0] lr_b;  // path r (1 .. 3), disparity d at lr_b[((r-1)*D+d)*LW +: LW]
  for (genvar r = 1; r < 4; r++) begin : g_path
    wire [LWORD-1:0] pw      = rd_q[(r-1)*LWORD +: LWORD];
    wire [LW-1:0]    min_prv = mrd_t[(r-1)*MW +: LW];
    for (genvar d = 0; d < D; d++) begin : g_pe
      sgm_path_pe #(.CW(CW), .LW(LW), .PW(PW), .CUTS(3)) u_pe (
        .clk_i      (clk_i),
        .en_i       (en_i),
        .prev_i     (pw[d*LW +: LW]),
        .prev_lo_i  (d > 0 ? pw[(d > 0 ? d - 1 : 0)*LW +: LW] : {LW{1'b0}}),
        .prev_hi_i  (d < D - 1 ? pw[(d < D - 1 ? d + 1 : d)*LW +: LW] : {LW{1'b0}}),
        .has_lo_i   (d > 0),
        .has_hi_i   (d < D - 1),
        .p1_i       (p1_i),
        .min_prev_i (min_prv),
        .cost_i     (cost_p[d*CW +: CW]),
        .p2r_i      (p2r_p[(r-1)*PW +: PW]),
        .start_i    (start_pe[r]),
        .lr_o       (lr_b[((r-1)*D+d)*LW +: LW])
      );
    end
  end

  logic [3*D*LW-1:0]  lr_c;  // 45, 90, 135 degrees
  logic [XW-1:0]      col_c;
  logic [YW-1:0]      row_c;
  logic               last_c;
  logic [11:0]        count_c;  // the counts written beside min Lr: R at a path start
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int r = 1; r < 4; r++)
        count_c[(r-1)*4 +: 4] <= start[r] ? reset_len_i : count_v[(r-1)*4 +: 4];
      lr_c    <= lr_b;
      col_c   <= col_p;
      row_c   <= row_p;
      last_c  <= last_p;
    end
  end

  // ------------------------------------------------------------------ slot C
  // Path r, disparity d at lr_all[(r*D+d)*LW +: LW]; min0_c is not needed.
  wire [4*D*LW-1:0] lr_all = {lr_c, lr0_c};
  logic unused_min0;
  assign unused_min0 = ^min0_c;

  // The 45 degree word waits W45_DELAY slots (pixel x + 1 of the lane reads M45[x]
  // K - 4 slots after pixel x's C).
  logic [AW-1:0]    col_w45;
  logic [LWORD-1:0] lr_w45;
  if (W45_DELAY > 0) begin : g_w45_wait
    sgm_delay #(.WIDTH(AW + LWORD), .DEPTH(W45_DELAY)) u_w45 (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   ({AW'(col_c), lr_all[1*D*LW +: D*LW]}),
      .q_o   ({col_w45, lr_w45})
    );
  end else begin : g_w45_now
    assign {col_w45, lr_w45} = {AW'(col_c), lr_all[1*D*LW +: D*LW]};
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mem45[col_w45]     <= lr_w45;
      mem90[AW'(col_c)]  <= lr_all[2*D*LW +: D*LW];
      mem135[AW'(col_c)] <= lr_all[3*D*LW +: D*LW];
    end
  end

  // min Lr of 45/90/135 degrees, MIN_DELAY slots after their Lr words are
  // written (the 45 degree word W45_DELAY slots after C), at the same column:
  // the tree's MIN_LATENCY, and one slot more (its values registered first)
  // where the lanes' SKEW leaves one to spare ((SKEW - 1) K >= 6 + MIN_LATENCY;
  // never at one lane, whose SKEW has none).
  localparam int MIN_IN_REG = LANES * (SKEW - 1) - 5 - MIN_LATENCY > 0 ? 1 : 0;
  localparam int MIN_DELAY  = MIN_LATENCY + MIN_IN_REG;
  wire [3*LWORD-1:0] lr_wr  = {lr_all[3*D*LW +: D*LW], lr_all[2*D*LW +: D*LW], lr_w45};
  wire [2*AW-1:0]    col_wr = {AW'(col_c), col_w45};  // 90 and 135, 45
  logic [3*LW-1:0] min_m;  // 45, 90, 135
  for (genvar r = 1; r < 4; r++) begin : g_min
    sgm_min_pipe #(.N(D), .W(LW), .IN_REG(MIN_IN_REG)) u_min (
      .clk_i    (clk_i),
      .en_i     (en_i),
      .values_i (lr_wr[(r-1)*LWORD +: LWORD]),
      .min_o    (min_m[(r-1)*LW +: LW])
    );
  end
  logic [AW-1:0] col_m, col_m45;
  sgm_delay #(.WIDTH(2*AW), .DEPTH(MIN_DELAY)) u_col_m (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (col_wr),
    .q_o   ({col_m, col_m45})
  );
  // The counts beside them (EDGE_RESET): the 45 degree count W45_DELAY slots
  // after C as its word, all three MIN_DELAY slots more.
  logic [3*MW-1:0] min_wd;  // {count, min Lr} of 45, 90, 135 degrees
  if (EDGE_RESET != 0) begin : g_count_wr
    logic [3:0] count45_w;
    if (W45_DELAY > 0) begin : g_c45_wait
      sgm_delay #(.WIDTH(4), .DEPTH(W45_DELAY)) u_c45 (
        .clk_i (clk_i),
        .en_i  (en_i),
        .d_i   (count_c[3:0]),
        .q_o   (count45_w)
      );
    end else begin : g_c45_now
      assign count45_w = count_c[3:0];
    end
    logic [11:0] count_m;
    sgm_delay #(.WIDTH(12), .DEPTH(MIN_DELAY)) u_count_m (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   ({count_c[11:4], count45_w}),
      .q_o   (count_m)
    );
    for (genvar r = 0; r < 3; r++) begin : g_word
      assign min_wd[r*MW +: MW] = {count_m[r*4 +: 4], min_m[r*LW +: LW]};
      assign count_prev[r*4 +: 4] = mrd_t[r*MW + LW +: 4];
    end
  end else begin : g_min_only
    assign min_wd     = min_m;
    assign count_prev = '0;
    wire unused_count = ^count_c;
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      min45[col_m45] <= min_wd[0*MW +: MW];
      min90[col_m]   <= min_wd[1*MW +: MW];
      min135[col_m]  <= min_wd[2*MW +: MW];
    end
  end

  // S = 3 (L0 + L90) + 2 (L45 + L135) = (a << 1) + a + (b << 1), a = L0 + L90,
  // b = L45 + L135 (docs/algorithm.md section 5: path weights 3, 2, 3, 2), or
  // with equal weights S = a + b: the same three-operand adder, (a << 1) zeroed
  // and b not shifted.
  logic [D*SW-1:0] s_c;
  for (genvar d = 0; d < D; d++) begin : g_sum
    wire [LW:0]   a  = {1'b0, lr_all[(0*D+d)*LW +: LW]} + {1'b0, lr_all[(2*D+d)*LW +: LW]};
    wire [LW:0]   b  = {1'b0, lr_all[(1*D+d)*LW +: LW]} + {1'b0, lr_all[(3*D+d)*LW +: LW]};
    wire [SW-1:0] a2 = weights_eq_i ? '0 : SW'({a, 1'b0});
    wire [SW-1:0] bw = weights_eq_i ? SW'(b) : SW'({b, 1'b0});
    if (RIGHT_PATH != 0) begin : g_five
      assign s_c[d*SW +: SW] = a2 + SW'(a) + bw + SW'(l5w_i[d*L5W +: L5W]);
    end else begin : g_four
      assign s_c[d*SW +: SW] = a2 + SW'(a) + bw;
    end
  end
  if (RIGHT_PATH == 0) begin : g_no_five
    wire unused_l5w = ^l5w_i;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      s_o     <= s_c;
      col_o   <= col_c;
      row_o   <= row_c;
      last_o  <= last_c;
    end
  end

endmodule
`default_nettype wire
