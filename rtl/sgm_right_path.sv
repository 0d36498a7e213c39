// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_right_path: the fifth path, 0 degrees from the right (r = (1, 0)), in
// blocks of BLOCK = B pixels with one block of look-ahead (docs/algorithm.md
// section 12, golden sgm::addRightPath with block B), streamed at one pixel
// per slot: the costs of each row lane are held in a short ring of words, two
// backward passes run the recursion of eq. (1) from right to left over them,
// and every pixel leaves LATENCY slots after it entered with its costs and a
// side bundle, and L5_LAG slots after that its weighted L5 (W5 times the fifth
// path's Lr vector, the term the path engine adds to S).
//
// Blocks of a row of width W: [jB, (j+1)B) for j = 0 .. m-2 and the last block
// [(m-1)B, W), m = max(1, floor(W / B)) (B .. 2B-1 pixels; the row when W <
// 2B). Block j's pass starts (Lr = C) at column x0 + 2B - 1, the last block's
// at W - 1, and runs down to x0; only the block's own columns are kept.
//
// Schedule (in lane slots, u = the slots since the lane's row r began: the
// pixel of column x enters at u = x; rows follow each other in a lane): a pass
// is decided at the slot of its start u and runs from the lane's next slot (the
// decision is registered, K slots):
//   pass of block j < m-1: steps u = x0 + 2B + 1 .. x0 + 4B, column
//     x0 + 2B - 1 - (u - x0 - 2B - 1) (the block's columns in the last B steps);
//   the last block's pass: W - x0 steps from u = x0 + 2B + 1 (m >= 2) or u = W + 1
//     (m = 1), columns W - 1 down to x0.
// So passes of blocks of one parity never overlap, nor do the last block's and
// the next row's first (it ends where that starts): ring PASS = j mod 2 runs
// the blocks of its parity (two sgm_path_ring, LANES lanes each). A pass reads
// a column at most 4B lane slots after it entered. Passes starting at u >=
// W are recognised from the next row's column x = u - W (at most B); a pass
// decoded from a row outside the frame computes garbage that no valid pixel
// reads (a row's passes read only that row's words).
//
// Memories (words per lane M = DLY + 1, the lane's word n mod M holds its
// pixel of lane time n; block RAM, registered reads, one write and one read
// port each): the costs and gray twice (one copy per pass ring), the costs and
// the side bundle once more for the output, and the L5 of each ring. A pass's
// L5 of column x is written at most 4B lane slots plus the ring's pipeline
// (3 + LANES slots) after the pixel entered, readable a slot later; the output
// reads the pixel's costs K DLY - 1 slots after it entered (two registers
// follow) and its L5 L5_LAG - 2 slots after that (then four registers: the
// read, one more, the select with half the product, the sum): K DLY + L5_LAG
// - 3 >= 4B K + 4 + K, DLY = 4B + 1 + ceil(5 / LANES) (no slot to spare at one
// lane, L5_LAG = 2: mutation rp-delay). A pass keeps the memory address
// of its column (not the lane's word), so that the read address is a register
// (its decrement is taken a step ahead and carried with the lane's state); its start address is a register too (the lane's previous
// write address, or the one of its row's column W - 1, kept per lane).
//
// EDGE_RESET = 1 builds the path restart at strong edges (docs/algorithm.md
// section 12, golden addRightPath with Params::edgeReset): with reset_en_i and
// T = reset_t_i != 0 a pass starts again (Lr = C) at every column whose last R
// = reset_len_i steps of the pass, the step into it included, cross a gray
// step |dI| >= T. The pass's count (steps since its last strong edge,
// saturating at R; R at its start) comes back per lane after K slots at stage
// 2, from the edge flag registered behind |dI| (stage 1), and the restart joins
// the pass start at the ring's input (with K >= 2 lanes the ring registers it
// before the sub-PEs use it). EDGE_RESET = 0 builds none of it (the reset_* ports
// unused).
//
// Parameters: D disparities, CW cost width, LW path-cost width (Cmax + P2'max
// must fit), PW penalty width, BLOCK (B, a power of two >= 2), XW column bits,
// LANES (K >= 1 row lanes, slot K t + k belongs to lane k), SIDE_W side bundle
// bits, L5_LAG (2 .. 3K + 2: the slots l5w_o comes after cost_o; a pixel's L5
// word is overwritten no earlier than 3K + 3 slots after its output slot).
// L5W = LW + 4 bits per weighted value (W5 <= 15).
// Inputs per slot (en_i): the pixel's costs, its left gray and column, and the
// side bundle; width_i, p1_i constant while a frame flows (width_i changes
// only between frames, at least one slot before the frame's first).
// Latency: LATENCY = K DLY + 1 slots from a pixel's inputs to its cost_o /
// side_o, L5_LAG more to its l5w_o. Throughput: one pixel per slot.
// Reset: the memories keep their words, so side_o is all zeros until LATENCY
// slots have passed since rst_ni (the side bundle's valid flags then read 0, as
// a reset register chain's would).
module sgm_right_path #(
  parameter int D      = 64,
  parameter int CW     = 7,
  parameter int LW     = 9,
  parameter int PW     = 8,
  parameter int BLOCK  /*verilator public*/ = 32,
  parameter int XW     = 11,
  parameter int LANES  /*verilator public*/ = 1,
  parameter int SIDE_W = 1,
  parameter int L5_LAG /*verilator public*/ = 2,
  parameter int EDGE_RESET /*verilator public*/ = 0,
  localparam int L5W   = LW + 4,
  localparam int DLY   = 4 * BLOCK + 1 + (5 + LANES - 1) / LANES,
  localparam int LATENCY /*verilator public*/ = LANES * DLY + 1
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [XW-1:0]    width_i,
  input  wire  [PW-1:0]    p1_i,
  input  wire  [3:0]       weight_i,  // W5 (constant while a frame flows)
  // The path restart at strong edges (EDGE_RESET = 1; constant while a frame flows).
  input  wire  [7:0]       reset_t_i,     // T: a strong edge's gray step; 0 = off
  input  wire  [3:0]       reset_len_i,   // R: steps restarted from the edge on (1 .. 15)
  input  wire              reset_en_i,    // the fifth path restarts
  // P2 table fill (sgm_p2_lut, the table of the four forward paths); lut_ready_o
  // is this table's ready and lut_ready_i (the other tables filled with it: the
  // top stays wiring only, the hierarchical synthesis flows need that).
  input  wire              lut_start_i,
  input  wire  [PW-1:0]    p2_i,
  input  wire              p2_mode_i,
  input  wire              lut_ready_i,
  output logic             lut_ready_o,
  // Slot input.
  input  wire  [D*CW-1:0]  cost_i,
  input  wire  [7:0]       gray_i,
  input  wire  [XW-1:0]    col_i,
  input  wire  [SIDE_W-1:0] side_i,
  // LATENCY slots later.
  output logic [D*CW-1:0]  cost_o,
  output logic [SIDE_W-1:0] side_o,
  // LATENCY + L5_LAG slots later: W5 L5(d) at l5w_o[d*L5W +: L5W].
  output logic [D*L5W-1:0] l5w_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 2 && D <= 256)) begin : g_bad_d
    $error("sgm_right_path: D = %0d: D must be from 2 to 256", D);
  end
  if (!(LW >= CW)) begin : g_bad_lw
    $error("sgm_right_path: LW = %0d: LW must be at least CW = %0d (the path cost holds the matching cost)", LW, CW);
  end
  if (!(LW >= PW)) begin : g_bad_lw_2
    $error("sgm_right_path: LW = %0d: LW must be at least PW = %0d (the path cost holds the penalties)", LW, PW);
  end
  if (!(PW >= 1)) begin : g_bad_pw
    $error("sgm_right_path: PW = %0d: PW must be at least 1", PW);
  end
  if (!(BLOCK >= 2 && (BLOCK & (BLOCK - 1)) == 0)) begin : g_bad_block
    $error("sgm_right_path: BLOCK = %0d: BLOCK must be a power of two >= 2", BLOCK);
  end
  if (!(XW >= $clog2(BLOCK + 1))) begin : g_bad_xw
    $error("sgm_right_path: XW = %0d: XW must hold BLOCK = %0d (the next row's column of a late pass start)", XW, BLOCK);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_right_path: LANES = %0d: LANES must be at least 1", LANES);
  end
  if (!(SIDE_W >= 1)) begin : g_bad_side_w
    $error("sgm_right_path: SIDE_W = %0d: SIDE_W must be at least 1", SIDE_W);
  end
  if (!(L5_LAG >= 2 && L5_LAG <= 3 * LANES + 2)) begin : g_bad_l5_lag
    $error("sgm_right_path: L5_LAG = %0d: L5_LAG must be from 2 to 3 LANES + 2 (LANES = %0d)", L5_LAG, LANES);
  end
  if (!(EDGE_RESET == 0 || EDGE_RESET == 1)) begin : g_bad_edge_reset
    $error("sgm_right_path: EDGE_RESET = %0d: EDGE_RESET must be 0 or 1", EDGE_RESET);
  end
`endif

  localparam int K    = LANES;
  localparam int LB   = $clog2(BLOCK);
  localparam int M    = DLY + 1;                       // words per lane
  localparam int AW   = $clog2(M);                     // word in a lane
  localparam int RA   = $clog2(K * M);                 // memory address
  localparam int LNW  = K > 1 ? $clog2(K) : 1;
  localparam int UW   = (XW > LB + 2 ? XW : LB + 2) + 1;  // u < W + 2B
  localparam int SCW  = LB + 1;                        // steps left, < 2B
  localparam int CWD  = D * CW;

  // ------------------------------------------------------------ per frame
  // m, the last block's start and the decode bounds (width_i is constant for a
  // frame and changes a slot or more before it: registered here).
  wire  [XW-1:0] blocks_raw = width_i >> LB;
  logic [XW-1:0] m_q;          // m - 1
  logic [UW-1:0] w_q, reg_max_q, last_col_q;
  logic [XW-1:0] wm1_q;        // W - 1
  logic [SCW-1:0] last_steps_q;
  always_ff @(posedge clk_i) begin
    m_q          <= blocks_raw == '0 ? '0 : blocks_raw - 1'b1;
    w_q          <= UW'(width_i);
    wm1_q        <= width_i - 1'b1;
    // Regular passes start at u = x0 + 2B <= x0_last + B (j <= m - 2).
    reg_max_q    <= UW'((blocks_raw == '0 ? '0 : blocks_raw - 1'b1) << LB) + UW'(BLOCK);
    // The last pass: u = x0_last + 2B (m >= 2) or W (m = 1), i.e. the next row's column
    // u - W = (m + 1) B - W (m >= 2) or 0 (m = 1).
    last_col_q   <= blocks_raw <= XW'(1) ? '0
                                         : UW'((blocks_raw + 1'b1) << LB) - UW'(width_i);
    last_steps_q <= SCW'(width_i - ((blocks_raw == '0 ? '0 : blocks_raw - 1'b1) << LB));
  end

  // ------------------------------------------------------------ slot counters
  // lane_q: the slot's lane (slot count mod K); n_q: the lane time mod M (the
  // word of this slot's pixel); base_q = lane_q M, top_q = base_q + M - 1 (the
  // lane's first and last address).
  logic [LNW-1:0] lane_q;
  logic [AW-1:0]  n_q;
  logic [RA-1:0]  base_q, top_q, wr_addr_q;  // wr_addr_q = base_q + n_q, the slot's write address
  wire            lane_wrap = lane_q == LNW'(K - 1);
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      lane_q    <= '0;
      n_q       <= '0;
      base_q    <= '0;
      top_q     <= RA'(M - 1);
      wr_addr_q <= '0;
    end else if (en_i) begin
      lane_q    <= lane_wrap ? '0 : lane_q + 1'b1;
      base_q    <= lane_wrap ? '0 : base_q + RA'(M);
      top_q     <= lane_wrap ? RA'(M - 1) : top_q + RA'(M);
      wr_addr_q <= lane_wrap ? (n_q == AW'(M - 1) ? '0 : RA'(n_q) + 1'b1) : wr_addr_q + RA'(M);
      if (lane_wrap) n_q <= n_q == AW'(M - 1) ? '0 : n_q + 1'b1;
    end
  end

  // ------------------------------------------------------------ pass starts
  wire [UW-1:0] ua = UW'(col_i);
  wire [UW-1:0] ub = UW'(col_i) + w_q;
  wire a_reg  = ua >= UW'(2 * BLOCK) && ua[LB-1:0] == '0 && ua <= reg_max_q;
  wire b_reg  = ub >= UW'(2 * BLOCK) && ub[LB-1:0] == '0 && ub <= reg_max_q;
  wire b_last = ua == last_col_q;
  wire [UW-1:0] u_start = a_reg ? ua : ub;
  wire          start_any  = a_reg || b_reg || b_last;
  wire          start_ring = b_last ? m_q[0] : u_start[LB];  // block j = u / B - 2: parity of u / B
  // Start address: the column before u (the lane's previous word: its write
  // address K slots ago), or, for the last pass, that of column W - 1 of the
  // lane's previous row (kept per lane when it is written; the next row's
  // column u - W < W - 1).
  logic [RA-1:0] prev_addr, row_end;
  sgm_delay #(.WIDTH(RA), .DEPTH(K)) u_prev_addr (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (wr_addr_q),
    .q_o   (prev_addr)
  );
  // Per lane (a K-slot ring: the lane's own value comes back each K slots).
  sgm_delay #(.WIDTH(RA), .DEPTH(K)) u_row_end (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (col_i == wm1_q ? wr_addr_q : row_end),
    .q_o   (row_end)
  );
  wire [SCW-1:0] start_left = b_last ? last_steps_q - 1'b1 : SCW'(2 * BLOCK - 1);
  // The decision, K slots later (the lane's next slot, where the pass runs its
  // first step; the start column's word is the same).
  logic          dec_any, dec_ring, dec_last;
  logic [SCW-1:0] dec_left;
  logic [RA-1:0] dec_addr;
  sgm_delay #(.WIDTH(3 + SCW + RA), .DEPTH(K)) u_decision (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   ({start_any, start_ring, b_last, start_left, b_last ? row_end : prev_addr}),
    .q_o   ({dec_any, dec_ring, dec_last, dec_left, dec_addr})
  );

  // ------------------------------------------------------------ block parity of the pixel
  wire [XW-1:0] jx     = col_i >> LB;
  wire          parity = jx > m_q ? m_q[0] : jx[0];

  // ------------------------------------------------------------ read addresses
  // The output copy and the L5 words are read from counters of their own that
  // run RD_OFF slots behind the write address (the address of slot t is that of
  // slot t - RD_OFF): the output copy K DLY - 1 slots after the pixel's write
  // (then its block RAM's read register and one more: LATENCY = K DLY + 1), the
  // L5 words L5_LAG - 2 slots after that (then the read register, one more,
  // the ring select with the two halves of the W5 product, and their sum).
  logic [2*RA-1:0] cnt_addr;  // {L5, output copy}
  for (genvar i = 0; i < 2; i++) begin : g_rd_addr
    localparam int RD_OFF = i == 0 ? K * DLY - 1 : K * DLY + L5_LAG - 3;
    localparam int T0     = (4 * K * M - RD_OFF) % (K * M);  // the slot count RD_OFF before 0, mod K M
    // The address lane_rq M + n_rq itself is the register (as wr_addr_q), so
    // that no adder sits in front of the block RAM (a critical path of the
    // five-lane core on the LFE5U-85F).
    logic [LNW-1:0] lane_rq;
    logic [AW-1:0]  n_rq;
    logic [RA-1:0]  addr_rq;
    wire            wrap = lane_rq == LNW'(K - 1);
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        lane_rq <= LNW'(T0 % K);
        n_rq    <= AW'(T0 / K);
        addr_rq <= RA'((T0 % K) * M + T0 / K);
      end else if (en_i) begin
        lane_rq <= wrap ? '0 : lane_rq + 1'b1;
        addr_rq <= wrap ? (n_rq == AW'(M - 1) ? '0 : RA'(n_rq) + 1'b1) : addr_rq + RA'(M);
        if (wrap) n_rq <= n_rq == AW'(M - 1) ? '0 : n_rq + 1'b1;
      end
    end
    assign cnt_addr[i*RA +: RA] = addr_rq;
  end
  wire [RA-1:0] out_addr = cnt_addr[0 +: RA];
  wire [RA-1:0] l5_addr  = cnt_addr[RA +: RA];

  // ------------------------------------------------------------ output copy
  localparam int PWD = CWD + 8;              // pass copy: {gray, costs}
  localparam int OWD = SIDE_W + 1 + CWD;     // output copy: {side, parity, costs}
  logic [OWD-1:0] out_mem [0:K*M-1];
  logic [OWD-1:0] out_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      out_mem[wr_addr_q] <= {side_i, parity, cost_i};
      out_q            <= out_mem[out_addr];
    end
  end

  // ------------------------------------------------------------ the two passes
  logic [2*PW-1:0] p2r;
  logic [15:0]     lut_idx;
  logic            lut_ready_own;
  assign lut_ready_o = lut_ready_own && lut_ready_i;
  sgm_p2_lut #(.PW(PW), .NPORTS(2)) u_p2_lut (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .start_i (lut_start_i),
    .p1_i    (p1_i),
    .p2_i    (p2_i),
    .mode_i  (p2_mode_i),
    .ready_o (lut_ready_own),
    .en_i    (en_i),
    .idx_i   (lut_idx),
    .p2r_o   (p2r)
  );

  logic [2*D*LW-1:0] l5_q;  // ring r at [r*D*LW +: D*LW] (packed: Icarus)

  for (genvar r = 0; r < 2; r++) begin : g_pass
    // This ring's copy of the costs and grays.
    logic [PWD-1:0] pass_mem [0:K*M-1];
    always_ff @(posedge clk_i) begin
      if (en_i) pass_mem[wr_addr_q] <= {gray_i, cost_i};
    end

    // Per-lane state, K slots back (the lane's previous step): active, steps
    // left after that step, its memory address, whether the pass is the row's
    // last (every step kept). Packed and in sgm_delay (Icarus).
    logic [K-1:0]   act_q;
    logic           last_k;
    logic [SCW-1:0] left_k;
    logic [RA-1:0]  next_k;  // the lane's word after its previous step's (one below, wrapping)
    wire start = dec_any && dec_ring == 1'(r);
    wire step  = start || (act_q[K-1] && left_k != '0);
    logic           last_d;
    logic [SCW-1:0] left_d;
    logic [RA-1:0]  addr_d;
    always_comb begin
      if (start) begin
        last_d = dec_last;
        left_d = dec_left;
        addr_d = dec_addr;
      end else begin
        last_d = last_k;
        left_d = left_k - 1'b1;
        addr_d = next_k;
      end
    end
    // The word of the lane's next step, taken now and carried K slots (base_q /
    // top_q are this slot's lane's, the same lane's K slots later), so that the
    // read address is a register or the decision's (no comparison and decrement
    // in front of the block RAM: the five-lane core's critical path on the
    // LFE5U-85F).
    wire [RA-1:0] next_d = addr_d == base_q ? top_q : addr_d - 1'b1;  // the lane's previous word
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        act_q <= '0;
      end else if (en_i) begin
        act_q[0] <= step;
        for (int i = 1; i < K; i++) act_q[i] <= act_q[i-1];
      end
    end
    sgm_delay #(.WIDTH(1 + SCW + RA), .DEPTH(K)) u_lane_state (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   ({last_d, left_d, next_d}),
      .q_o   ({last_k, left_k, next_k})
    );
    // Keep the step's L5 when it is one of its block's columns.
    wire keep = step && (last_d || left_d < SCW'(BLOCK));

    // Stage 1: the column's costs and gray (registered read), registered once
    // more (the block RAM's clock-to-out and its depth multiplexer stay out of
    // the |dI| and the table lookup behind it).
    wire [RA-1:0] rd_addr = addr_d;
    logic [PWD-1:0] rd_q, rd_r;
    logic           start0, keep0, start1, keep1;
    logic [RA-1:0]  addr0, addr1;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        rd_q   <= pass_mem[rd_addr];
        start0 <= start;
        keep0  <= keep;
        addr0  <= rd_addr;
        rd_r   <= rd_q;
        start1 <= start0;
        keep1  <= keep0;
        addr1  <= addr0;
      end
    end
    wire [7:0]     gray1 = rd_r[CWD +: 8];
    wire [CWD-1:0] cost1 = rd_r[0 +: CWD];
    // The previous step's gray (column + 1) of the lane: K slots ago.
    logic [7:0] gray_prev;
    sgm_delay #(.WIDTH(8), .DEPTH(K)) u_gray_prev (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   (gray1),
      .q_o   (gray_prev)
    );
    assign lut_idx[r*8 +: 8] = gray1 > gray_prev ? gray1 - gray_prev : gray_prev - gray1;

    // The restart (EDGE_RESET): the step's edge flag registered behind |dI|
    // (stage 1), the count at stage 2 (the lane's count K slots back).
    logic restart2;
    logic start2;
    if (EDGE_RESET != 0) begin : g_restart
      wire        on = reset_en_i && reset_t_i != 8'd0;
      logic       edge2;
      always_ff @(posedge clk_i) begin
        if (en_i) edge2 <= on && lut_idx[r*8 +: 8] >= reset_t_i;
      end
      logic [3:0] count_prev;
      wire  [4:0] inc  = {1'b0, count_prev} + 5'd1;
      wire        near = inc < {1'b0, reset_len_i};
      sgm_delay #(.WIDTH(4), .DEPTH(K)) u_count (
        .clk_i (clk_i),
        .en_i  (en_i),
        .d_i   (start2 ? reset_len_i : edge2 ? 4'd0 : near ? inc[3:0] : reset_len_i),
        .q_o   (count_prev)
      );
      assign restart2 = on && (edge2 || near);
    end else begin : g_no_restart
      assign restart2 = 1'b0;
    end

    // Stage 2: P2r from the table; the ring.
    logic [CWD-1:0] cost2;
    logic           keep2;
    logic [RA-1:0]  addr2;
    always_ff @(posedge clk_i) begin
      if (en_i) {cost2, start2, keep2, addr2} <= {cost1, start1, keep1, addr1};
    end
    logic [D*LW-1:0] lr;
    logic [LW-1:0]   unused_min;
    sgm_path_ring #(.D(D), .CW(CW), .LW(LW), .PW(PW), .LANES(K)) u_ring (
      .clk_i   (clk_i),
      .rst_ni  (rst_ni),
      .en_i    (en_i),
      .p1_i    (p1_i),
      .cost_i  (cost2),
      .p2r_i   (p2r[r*PW +: PW]),
      .start_i (start2 | restart2),
      .lr_o    (lr),
      .min_o   (unused_min)
    );
    // Stage 2 + K: the step's Lr, written to this ring's L5 memory at its word.
    logic          keep3;
    logic [RA-1:0] addr3;
    sgm_delay #(.WIDTH(1 + RA), .DEPTH(K)) u_step_delay (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   ({keep2, addr2}),
      .q_o   ({keep3, addr3})
    );
    logic [D*LW-1:0] l5_mem [0:K*M-1];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        if (keep3) l5_mem[addr3] <= lr;
        l5_q[r*D*LW +: D*LW] <= l5_mem[l5_addr];
      end
    end
  end

  if (EDGE_RESET == 0) begin : g_no_reset_cfg
    wire unused_reset = ^{reset_t_i, reset_len_i, reset_en_i};
  end

  // ------------------------------------------------------------ output
  // The output copy registered once more (the block RAM's clock-to-out stays
  // out of the stages behind). warm_q: LATENCY - 1 slots have passed since
  // reset, so that side_o is zeros for LATENCY slots (the output word was
  // written after the reset).
  localparam int WW = $clog2(LATENCY + 1);
  logic [WW-1:0] warm_cnt_q;
  logic          warm_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      warm_cnt_q <= '0;
      warm_q     <= 1'b0;
    end else if (en_i && !warm_q) begin
      warm_cnt_q <= warm_cnt_q + 1'b1;
      warm_q     <= warm_cnt_q == WW'(LATENCY - 2);
    end
  end
  logic [SIDE_W-1:0] side_r;
  logic [CWD-1:0]    cost_r;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) side_r <= '0;
    else if (en_i) side_r <= warm_q ? out_q[OWD-1 -: SIDE_W] : '0;
  end
  always_ff @(posedge clk_i) begin
    if (en_i) cost_r <= out_q[0 +: CWD];
  end
  assign side_o = side_r;
  assign cost_o = cost_r;
  // The L5 words registered once more behind the block RAM (its clock-to-out
  // stays out of the select and the product); the pixel's block parity picks
  // the ring and the product's two halves are formed (v (w0 + 2 w1) and
  // 4 v (w2 + 2 w3), an adder each), then their sum.
  logic [2*D*LW-1:0] l5_r;
  always_ff @(posedge clk_i) begin
    if (en_i) l5_r <= l5_q;
  end
  logic l5_parity;
  sgm_delay #(.WIDTH(1), .DEPTH(L5_LAG - 1)) u_parity (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (out_q[CWD]),
    .q_o   (l5_parity)
  );
  wire [D*LW-1:0] l5 = l5_parity ? l5_r[D*LW +: D*LW] : l5_r[0 +: D*LW];
  for (genvar d = 0; d < D; d++) begin : g_weight
    wire [LW-1:0]  v = l5[d*LW +: LW];
    logic [L5W-1:0] lo_q, hi_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        lo_q <= (weight_i[0] ? L5W'(v)      : '0) + (weight_i[1] ? L5W'(v) << 1 : '0);
        hi_q <= (weight_i[2] ? L5W'(v) << 2 : '0) + (weight_i[3] ? L5W'(v) << 3 : '0);
        l5w_o[d*L5W +: L5W] <= lo_q + hi_q;
      end
    end
  end

endmodule
`default_nettype wire
