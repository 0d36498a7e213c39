`default_nettype none
// sgm_path_engine: the four causal path costs of eq. (1) and their sum S
// (docs/algorithm.md section 5) at one pixel per slot, D sub-PEs per path.
//
// Slots arrive in raster order of a virtual raster (docs/rtl.md): consecutive
// slots are consecutive positions, rows < 0 and >= height carry no pixel.
// Pipeline (one register stage per slot; slot t = the slot of the pixel's cost_i):
//   t - 3  read the previous-row memories at the pixel's column (col_i leads
//          cost_i by COL_LEAD >= 3 slots): M90[x], M45[x - 1], M135[x + 1]
//   t - 2  the memories' output register
//   t - 1  part (a) of the 45/90/135 degree sub-PEs (sgm_path_pe, CUTS = 3),
//          which needs only the previous row and P1
//   t      part (b) (min Lr of the previous row); (GRAY_LEAD = 1) the P2r
//          lookup ran in the slot before (block RAM, registered read: the grays
//          centre_i / nbr_i lead cost_i by one slot)
//   A      register the cost vector and position, and P2r behind the block RAM
//          (so that its clock-to-out is not part of the 0 degree loop; with
//          GRAY_LEAD = 0 the lookup runs here and P2r comes from the RAM port)
//   B      part (c) of the 45/90/135 degree sub-PEs (+ C, P2r, path start); the
//          0 degree path (sgm_path_ring, one lane) feeds back in the same
//          cycle (sub-PEs + D-input minimum = the single-cycle loop of the
//          design)
//   C      S = weighted sum of the four Lr (3,2,3,2, or equal when
//          weights_eq_i); Lr of 45/90/135 degrees written to the path memories
//          at the pixel's column; their minima enter sgm_min_pipe and are
//          written to the min memories MIN_LATENCY slots later
// Path memories (per vertical path: MAX_WIDTH words of D x LW bits and
// MAX_WIDTH words of LW bits for min Lr; synchronous read with enable -> block
// RAM). A word written by pixel x is read by the next row's pixels x - 1, x,
// x + 1, at the earliest (x - 1, M135) W - 1 - 3 slots after x's stage A,
// i.e. W - 6 - MIN_LATENCY slots after its min is written: MIN_WIDTH >= 16
// leaves a margin at every D (MIN_LATENCY <= 4). It is rewritten by the same
// row's pixel x at its stage C, after the reads of x - 1 .. x + 1 (at most
// 3 + 2 + 1 slots earlier).
//
// Parameters: D disparities, CW cost width, LW path-cost width (Cmax + P2'max
// must fit), PW penalty width, MAX_WIDTH, XW column bits, YW row bits, GRAY_LEAD
// (0 or 1, see stage A), COL_LEAD (>= 3: how many slots col_i leads cost_i;
// the engine delays it by COL_LEAD - 3 first). SW = LW + 4 holds the larger of
// the two weightings (10 x 2^LW).
// Latency: LATENCY = 3 slots from cost_i to s_o; row_i, centre_i and nbr_i of a
// pixel are presented GRAY_LEAD slots before its cost_i (valid_i with it),
// col_i COL_LEAD slots before.
// Throughput: 1 pixel per slot.
module sgm_path_engine #(
  parameter int D         = 64,
  parameter int CW        = 7,
  parameter int LW        = 9,
  parameter int PW        = 8,
  parameter int MAX_WIDTH = 1280,
  parameter int XW        = 11,
  parameter int YW        = 11,
  localparam int SW       = LW + 4,
  // 1: P2r registered behind the table (the grays lead by one slot); 0: P2r
  // straight from the table's read port into the sub-PEs (grays with the costs).
  parameter int GRAY_LEAD /*verilator public*/ = 1,
  parameter int COL_LEAD  /*verilator public*/ = 3,
  localparam int LATENCY  = 3
) (
  input  wire                 clk_i,
  input  wire                 rst_ni,
  input  wire                 en_i,
  // Per-frame configuration (constant while the frame's slots flow).
  input  wire  [XW-1:0]       width_i,
  input  wire  [PW-1:0]       p1_i,
  input  wire                 weights_eq_i,  // S weights: 0 = 3,2,3,2, 1 = equal (the paper's sum)
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
  // Slot output, LATENCY slots later.
  output logic [D*SW-1:0]     s_o,
  output logic [XW-1:0]       col_o,
  output logic [YW-1:0]       row_o,
  output logic                valid_o
);

  localparam int LWORD = D * LW;  // {Lr(D-1) .. Lr(0)} of one path
  localparam int AW    = $clog2(MAX_WIDTH);
  localparam int MIN_LATENCY = ($clog2(D) + 1) / 2;  // sgm_min_pipe's LATENCY

  // ------------------------------------------------------ previous-row reads
  // col_i leads cost_i by COL_LEAD slots; col_r leads it by 3 (the read slot).
  logic [XW-1:0] col_r;
  if (COL_LEAD > 3) begin : g_col_lead
    sgm_delay #(.WIDTH(XW), .DEPTH(COL_LEAD - 3)) u_col_lead (
      .clk_i (clk_i),
      .en_i  (en_i),
      .d_i   (col_i),
      .q_o   (col_r)
    );
  end else begin : g_col_read
    assign col_r = col_i;
  end

  // The column of the pixel at stage B (its path starts) and at stage C (the writes).
  logic [XW-1:0] col_b, col_c;
  sgm_delay #(.WIDTH(XW), .DEPTH(4)) u_col_b (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (col_r),
    .q_o   (col_b)
  );

  // Read addresses: M90 at x, M45 at x - 1 (unused at x = 0: 45 deg start),
  // M135 at x + 1 (unused at the last column: 135 deg start).
  wire [AW-1:0] addr90  = AW'(col_r);
  wire [AW-1:0] addr45  = col_r == '0 ? '0 : AW'(col_r - 1'b1);
  wire [AW-1:0] addr135 = col_r == width_i - 1'b1 ? '0 : AW'(col_r + 1'b1);

  logic [LWORD-1:0] mem45  [0:MAX_WIDTH-1];
  logic [LWORD-1:0] mem90  [0:MAX_WIDTH-1];
  logic [LWORD-1:0] mem135 [0:MAX_WIDTH-1];
  logic [LW-1:0]    min45  [0:MAX_WIDTH-1];
  logic [LW-1:0]    min90  [0:MAX_WIDTH-1];
  logic [LW-1:0]    min135 [0:MAX_WIDTH-1];

  // Read at t - 3, the memories' data at t - 2, their output register at t - 1.
  logic [3*LWORD-1:0] rd_m, rd_q;   // {135, 90, 45}
  logic [3*LW-1:0]    mrd_m, mrd_q, mrd_t;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_m  <= {mem135[addr135], mem90[addr90], mem45[addr45]};
      mrd_m <= {min135[addr135], min90[addr90], min45[addr45]};
      rd_q  <= rd_m;
      mrd_q <= mrd_m;
      mrd_t <= mrd_q;  // min Lr at part (b), one slot after part (a)
    end
  end

  // ------------------------------------------------------------------ stage A
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
  logic               valid_b;
  logic               valid_c;
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

  // Slot valid flags: the only registers with a reset.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_b <= 1'b0;
      valid_c <= 1'b0;
      valid_o <= 1'b0;
    end else if (en_i) begin
      valid_b <= valid_i;
      valid_c <= valid_b;
      valid_o <= valid_c;
    end
  end

  // ------------------------------------------------------------------ stage B
  wire at_left  = col_b == '0;
  wire at_right = col_b == width_i - 1'b1;
  wire at_top   = row_b == '0;

  // The 0 degree recursion (sgm_path_ring, one lane): its sub-PEs and minimum
  // feed back through the ring's register (lr0_c: the pixel's Lr at stage C).
  logic [D*LW-1:0] lr0_c;
  logic [LW-1:0]   min0_c;
  sgm_path_ring #(.D(D), .CW(CW), .LW(LW), .PW(PW), .LANES(1)) u_ring (
    .clk_i   (clk_i),
    .en_i    (en_i),
    .p1_i    (p1_i),
    .cost_i  (cost_b),
    .p2r_i   (p2r_b[0 +: PW]),
    .start_i (at_left),
    .lr_o    (lr0_c),
    .min_o   (min0_c)
  );

  // The 45, 90 and 135 degree paths: previous-row costs from the path
  // memories, parts (a) and (b) of the sub-PEs ahead of the pixel's stage B.
  wire [3:1] start = {at_right | at_top, at_top, at_left | at_top};

  logic [3*D*LW-1:0] lr_b;  // path r (1 .. 3), disparity d at lr_b[((r-1)*D+d)*LW +: LW]
  for (genvar r = 1; r < 4; r++) begin : g_path
    wire [LWORD-1:0] pw      = rd_q[(r-1)*LWORD +: LWORD];
    wire [LW-1:0]    min_prv = mrd_t[(r-1)*LW +: LW];
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
        .cost_i     (cost_b[d*CW +: CW]),
        .p2r_i      (p2r_b[r*PW +: PW]),
        .start_i    (start[r]),
        .lr_o       (lr_b[((r-1)*D+d)*LW +: LW])
      );
    end
  end

  logic [3*D*LW-1:0]  lr_c;  // 45, 90, 135 degrees
  logic [YW-1:0]      row_c;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lr_c    <= lr_b;
      col_c   <= col_b;
      row_c   <= row_b;
    end
  end

  // ------------------------------------------------------------------ stage C
  // Path r, disparity d at lr_all[(r*D+d)*LW +: LW]; min0_c is not needed.
  wire [4*D*LW-1:0] lr_all = {lr_c, lr0_c};
  logic unused_min0;
  assign unused_min0 = ^min0_c;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mem45[AW'(col_c)]  <= lr_all[1*D*LW +: D*LW];
      mem90[AW'(col_c)]  <= lr_all[2*D*LW +: D*LW];
      mem135[AW'(col_c)] <= lr_all[3*D*LW +: D*LW];
    end
  end

  // min Lr of 45/90/135 degrees, MIN_LATENCY slots later, at the column of the pixel.
  logic [3*LW-1:0] min_m;  // 45, 90, 135
  for (genvar r = 1; r < 4; r++) begin : g_min
    sgm_min_pipe #(.N(D), .W(LW)) u_min (
      .clk_i    (clk_i),
      .en_i     (en_i),
      .values_i (lr_all[r*D*LW +: D*LW]),
      .min_o    (min_m[(r-1)*LW +: LW])
    );
  end
  logic [AW-1:0] col_m;
  sgm_delay #(.WIDTH(AW), .DEPTH(MIN_LATENCY)) u_col_m (
    .clk_i (clk_i),
    .en_i  (en_i),
    .d_i   (AW'(col_c)),
    .q_o   (col_m)
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      min45[col_m]  <= min_m[0*LW +: LW];
      min90[col_m]  <= min_m[1*LW +: LW];
      min135[col_m] <= min_m[2*LW +: LW];
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
    wire [SW-1:0] a2 = weights_eq_i ? '0 : {2'b00, a, 1'b0};
    wire [SW-1:0] bw = weights_eq_i ? {3'b000, b} : {2'b00, b, 1'b0};
    assign s_c[d*SW +: SW] = a2 + {3'b000, a} + bw;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      s_o     <= s_c;
      col_o   <= col_c;
      row_o   <= row_c;
    end
  end

endmodule
`default_nettype wire
