// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_lr_check: left-right validation (docs/algorithm.md section 7) at one
// pixel per slot, with the right disparities computed from the same S:
//
//   dR(xr) = argmin over d = 0 .. min(D-1, W-1-xr) of S(xr+d, d)  (ties: smallest d)
//   left (x, y) with winner d is valid iff x - dmin - d >= 0 and |dR(x-d) - d| <= tol_i
//   (dmin = dmin_i, the minimum disparity, 0 in a build without it; d and dR in the
//   search's own frame, 0 .. D-1, as docs/algorithm.md section 7 has them)
//   (check_en_i = 0: every pixel valid), and in either case only if the WTA
//   side's unique_i said the winner is unique (sgm_wta: uniqueness ratio).
//
// Two input streams:
//   S side    s_i, col_i, row_i, last_i, valid_i (+ width_i, height_i): the
//             slot stream; last_i flags the last column of a row, decided by
//             the source a slot or more earlier (a register here: the column
//             compare in front of the row tail's selects would be the LFE5U-85F
//             five-lane core's critical path at 104.6 MHz). It also drives the
//             output timing.
//   WTA side  d_i, disp_i, unique_i with their own position wta_col_i / wta_row_i /
//             wta_valid_i: the sgm_wta result of the same S, connected directly
//             (it arrives sgm_wta LATENCY slots after its S, no delay line of S
//             needed). Any lag L of the WTA side behind the S side with
//             0 <= L <= width - 1 slots works (the result of row y is read
//             during row y + 1 at its own column).
//
// Read side: rd_col_i / rd_row_i, the slot reads left pixel (rd_col_i,
// rd_row_i - 1) and the outputs follow its timing. With one lane the top
// connects the S-side position (the order of accesses below).
//
// Lanes (LANES = K, docs/lanes.md): the S and WTA sides may come in the
// slot order of K row lanes (slot K n + k belongs to lane k, each lane a raster
// of its own rows); the diagonal array and the row tail are then per lane: the
// state a slot continues is the one its lane left K slots earlier (the
// registers delayed K - 1 slots more in an sgm_delay_ram of depth K - 1). The
// memories hold ROW_BANKS rows (bank = row mod ROW_BANKS, a power of two), so
// the read side can run in raster order behind the lanes: every word of row y
// must be written before the read of row y + 1 reaches it (the row tail is
// written during the first D - 1 columns of the lane's next row, y + K), and
// row y + ROW_BANKS may overwrite it only after that read
// (tests/rtl/test_sgm_lr_check_lanes.cpp computes both from the schedule).
//
// Right disparities: a systolic diagonal array of D slots. After the S of
// pixel x, slot j holds (min S, argmin d) of right pixel x - j over d = 0 .. j:
// slot j takes slot j-1 of the previous pixel and compares it with S(x, j)
// (strict <, so the smallest d wins a tie); slot 0 restarts at (S(x, 0), 0),
// so every chain starts inside its own row. Right pixel xr is final
//   * when it leaves slot D-1, at column x = xr + D - 1 (xr <= W - D), or
//   * at the last column of the row for xr > W - D: its later candidates
//     xr + d > W - 1 do not exist. The argmins of slots 0 .. D-2 after
//     column W-1 (xr = W-1 .. W-D+1, in darg of the lane's next slot) are
//     written, xr = W-D+1 first, during the lane's next D-1 slots (columns
//     0 .. D-2 of its next row, where slot D-1 finalises nothing: no write
//     port conflict); entries 1 .. D-2 wait in a shift register (tail_q).
// dR goes through one registered write port into the dR memory (ROW_BANKS rows
// x MAX_WIDTH x log2(D) bit). The WTA result {d, disp} of (x, y) goes to the left
// memory (ROW_BANKS rows x MAX_WIDTH x (log2(D) + DW + 2) bit: with the unique and
// frame-pixel flags) at its own column. Both memories are addressed column-major,
// {column, row mod ROW_BANKS} (no multiplier in front of a block RAM address), and
// built by sgm_bank_ram: banks of one block RAM's depth, each read into a register
// of its own, the bank selected a slot later (RAM_LATENCY = 3 slots a read; the
// deep memory's read multiplexer behind the block RAMs' clock-to-out was the
// LFE5U-85F D = 64 core's critical path).
//
// Read side, at the S slot (x, y), y >= 1, for the left pixel (x, y-1):
//   R1  read the left word (x, y-1): on r1_word RAM_LATENCY slots later
//   R2  xr = x - d; read dR (xr, y-1) (a wrapped address when x < d: not used):
//       on r2_dr RAM_LATENCY slots later
//   R3  valid = (!check_en || (x >= dmin + d && |dR - d| <= tol)) && unique; output registers.
// Order of memory accesses (slot = S-side slot, a write at slot t is visible
// to reads at slots > t; the dR read of left pixel x is at slot x + 3 of its row):
//   * dR(xr), xr <= W-D, of row y is written at slot (xr + D, y) and read no
//     earlier than slot (xr + 3, y + 1).
//   * tail entry k (xr = W-D+1+k) of row y is written at slot (k + 1, y + 1);
//     the left pixel x that reads it has x - d = xr, so it reads at slot
//     (x + 3, y + 1) with x >= xr = k + 1 + (W - D): strictly later because
//     W >= D.
//   * the bank of row y is next written by row y + ROW_BANKS from slot (D, y +
//     ROW_BANKS) on; the last read of row y is at slot (2, y + 2).
//   * left words: (x, y) is written at slot (x, y) + L, L <= W-1, and read at
//     (x, y + 1); row y + ROW_BANKS writes the bank at (x, y + ROW_BANKS) + L.
// Stale words from an earlier frame or from flush rows are never read for a
// real pixel: every word read for row y was written by row y of this frame.
//
// The output slot carries left pixel (x, y-1): out_valid_o = 1 iff
// 1 <= y <= height (the flush row y = height carries the last frame row out)
// and the stored word of (x, y-1) says it was a frame pixel (wta_valid_i):
// a slot of an earlier frame still in flight after a frame switch may have a
// row inside the new frame's height, but its stored flag is 0.
// tol_i / check_en_i / height_i are sampled with the slot and travel with it.
//
// Parameters: D disparities (power of two), SW width of S, DW disparity width
// (log2(D) + 4), MAX_WIDTH (largest width; width >= max(D, 16) required),
// CW column bits (must hold width), RW row bits (must hold every virtual row
// of a frame, flush rows included), LANES (K >= 1), ROW_BANKS (rows per
// memory, a power of two: 2 with one lane and the S-side read position),
// UNIQUENESS (1: unique_i is stored and gates valid_o; 0: the WTA builds no
// uniqueness test, unique_i is ignored and the left word is one bit narrower),
// CONFIDENCE (1: the WTA side's confidence conf_i goes into a memory of its own beside
// the left word, same addresses, and conf_o is it where valid_o is 1 and 0 elsewhere
// (docs/algorithm.md section 7b); 0: conf_o is 0, conf_i ignored).
// Latency: one row plus LATENCY = 2 RAM_LATENCY + 1 = 7 slots: left pixel (x, y) presented on the
// WTA side is on the outputs after the enabled edge of S slot (x, y+1) plus
// LATENCY - 1 edges, i.e. S slot (x, y) + width + LATENCY - 1 edges.
// Throughput: one pixel per slot. Reset: control registers only (tail counter, dR write
// enable, out_valid pipeline, lane warm-up).
module sgm_lr_check #(
  parameter int D         /*verilator public*/ = 64,
  parameter int SW        /*verilator public*/ = 13,
  parameter int DW        /*verilator public*/ = $clog2(D) + 4,
  parameter int MAX_WIDTH /*verilator public*/ = 1024,
  parameter int CW        /*verilator public*/ = $clog2(MAX_WIDTH + 1),
  parameter int RW        /*verilator public*/ = 11,
  parameter int LANES     /*verilator public*/ = 1,
  parameter int ROW_BANKS /*verilator public*/ = 2,
  parameter int UNIQUENESS /*verilator public*/ = 1,
  parameter int CONFIDENCE /*verilator public*/ = 0,
  localparam int LD       = $clog2(D),
  // sgm_bank_ram's read latency: the dR read comes RAM_LATENCY slots after the left
  // word's, the outputs RAM_LATENCY more and one later.
  localparam int RAM_LATENCY /*verilator public*/ = 3,
  localparam int LATENCY  /*verilator public*/ = 2 * RAM_LATENCY + 1
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  // Per-frame configuration (constant while the frame's slots flow).
  input  wire  [CW-1:0]    width_i,
  input  wire  [RW-1:0]    height_i,
  input  wire  [2:0]       tol_i,        // tolerance in px
  input  wire  [7:0]       dmin_i,       // the minimum disparity (a constant of the frame)
  input  wire              check_en_i,   // 0: every pixel valid
  // S side: aggregated costs S(d) = s_i[d*SW +: SW] of the slot's pixel.
  input  wire  [D*SW-1:0]  s_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire              last_i,       // col_i == width_i - 1 (sgm_path_engine's last_o)
  input  wire              valid_i,
  // WTA side: winner and disparity of pixel (wta_col_i, wta_row_i).
  input  wire  [LD-1:0]    d_i,
  input  wire  [DW-1:0]    disp_i,
  input  wire              unique_i,     // the winner passed sgm_wta's uniqueness test
  input  wire  [7:0]       conf_i,       // the winner's confidence (sgm_wta, CONFIDENCE = 1)
  input  wire  [CW-1:0]    wta_col_i,
  input  wire  [RW-1:0]    wta_row_i,
  input  wire              wta_valid_i,
  // Read side: the slot reads left pixel (rd_col_i, rd_row_i - 1) (with one
  // lane the S-side position).
  input  wire  [CW-1:0]    rd_col_i,
  input  wire  [RW-1:0]    rd_row_i,
  // Output: left pixel (col_o, row_o) of the previous row.
  output logic [DW-1:0]    disp_o,
  output logic             valid_o,      // left-right check (and uniqueness) passed
  output logic [7:0]       conf_o,       // the confidence where valid_o, else 0 (CONFIDENCE = 1; else 0)
  output logic [CW-1:0]    col_o,
  output logic [RW-1:0]    row_o,
  output logic             out_valid_o   // the slot carries a pixel of the frame
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 16 && D <= 256 && (D & (D - 1)) == 0)) begin : g_bad_d
    $error("sgm_lr_check: D = %0d: D must be a power of two from 16 to 256", D);
  end
  if (!(DW == $clog2(D) + 4 || DW == $clog2(D + 256) + 4)) begin : g_bad_dw
    $error("sgm_lr_check: DW = %0d: DW must be $clog2(D) + 4 = %0d, or $clog2(D + 256) + 4 with the minimum disparity (the disparity and 4 fractional bits)", DW, $clog2(D) + 4);
  end
  if (!(MAX_WIDTH >= D && MAX_WIDTH >= 16)) begin : g_bad_max_width
    $error("sgm_lr_check: MAX_WIDTH = %0d: MAX_WIDTH must be at least max(D, 16) (D = %0d)", MAX_WIDTH, D);
  end
  if (!(CW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_cw
    $error("sgm_lr_check: CW = %0d: CW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", CW, MAX_WIDTH);
  end
  if (!(RW >= 2)) begin : g_bad_rw
    $error("sgm_lr_check: RW = %0d: RW must be at least 2", RW);
  end
  if (!(SW >= 1)) begin : g_bad_sw
    $error("sgm_lr_check: SW = %0d: SW must be at least 1", SW);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_lr_check: LANES = %0d: LANES must be at least 1", LANES);
  end
  if (!(ROW_BANKS >= 2 && (ROW_BANKS & (ROW_BANKS - 1)) == 0)) begin : g_bad_row_banks
    $error("sgm_lr_check: ROW_BANKS = %0d: ROW_BANKS must be a power of two >= 2", ROW_BANKS);
  end
  if (!(UNIQUENESS == 0 || UNIQUENESS == 1)) begin : g_bad_uniqueness
    $error("sgm_lr_check: UNIQUENESS = %0d: UNIQUENESS must be 0 or 1", UNIQUENESS);
  end
  if (!(CONFIDENCE == 0 || CONFIDENCE == 1)) begin : g_bad_confidence
    $error("sgm_lr_check: CONFIDENCE = %0d: CONFIDENCE must be 0 or 1", CONFIDENCE);
  end
`endif

  localparam int BW  = $clog2(ROW_BANKS);    // bank bits (row mod ROW_BANKS)
  localparam int MW  = ROW_BANKS * MAX_WIDTH; // words per memory
  localparam int MAW = $clog2(MW);
  localparam int UB  = UNIQUENESS != 0 ? 1 : 0;  // the unique flag in the left word
  localparam int LW  = LD + DW + UB;    // left word {frame pixel, unique, d, disp} has LW + 1 bits (no unique: UB = 0)

  // Word address of column col in bank b (row bank: row mod ROW_BANKS).
  // Column-major, {col, b}: no multiplier in front of the memories' addresses.
  function automatic logic [MAW-1:0] mem_addr(input logic [BW-1:0] b, input logic [CW-1:0] col);
    mem_addr = MAW'({col, b});
  endfunction

  // ------------------------------------------------------------ lane state
  // Per lane: the diagonal array (slots 0 .. D-2; slot D-1 is final and only
  // written out) and the row tail. The state of the slot's lane is the one it
  // left K slots earlier: with K = 1 the registers themselves, else the
  // registers (the state of the slot before) delayed K - 1 slots more in one
  // sgm_delay_ram (distributed RAM with an output register, or a register
  // chain in the ECP5 flow), as in sgm_cost_volume.
  localparam int STW = (D-1)*SW + 2*(D-1)*LD + CW + BW + LD;

  logic [(D-1)*SW-1:0] dmin_q, dmin_p;   // _q: next state of the previous slot; _p: of this lane
  logic [(D-1)*LD-1:0] darg_q, darg_p;
  logic [(D-1)*LD-1:0] tail_q, tail_p;     // entry k: dR(W-D+1+k)
  logic [CW-1:0]       tail_col_q, tail_col_p;   // column of entry 0
  logic [BW-1:0]       tail_bank_q, tail_bank_p;
  logic [LD-1:0]       tail_cnt_q, tail_cnt_p;   // entries left to write

  if (LANES == 1) begin : g_one_lane
    assign {dmin_p, darg_p, tail_p, tail_col_p, tail_bank_p, tail_cnt_p} =
           {dmin_q, darg_q, tail_q, tail_col_q, tail_bank_q, tail_cnt_q};
  end else begin : g_lanes
    localparam int GAP = LANES - 1;
    localparam int WW  = GAP > 1 ? $clog2(GAP + 1) : 1;
    logic [WW-1:0]  warm_q;   // slots since reset < GAP: the delay holds no state yet
    logic [STW-1:0] gap_out;
    sgm_delay_ram #(.WIDTH(STW), .DEPTH(GAP)) u_gap (
      .clk_i (clk_i),
      .rst_ni(rst_ni),
      .en_i  (en_i),
      .d_i   ({dmin_q, darg_q, tail_q, tail_col_q, tail_bank_q, tail_cnt_q}),
      .q_o   (gap_out)
    );
    always_ff @(posedge clk_i) begin
      if (!rst_ni) warm_q <= WW'(GAP);
      else if (en_i && warm_q != '0) warm_q <= warm_q - 1'b1;
    end
    assign {dmin_p, darg_p, tail_p, tail_col_p, tail_bank_p} = gap_out[STW-1:LD];
    assign tail_cnt_p = warm_q != '0 ? '0 : gap_out[LD-1:0];
  end

  // ------------------------------------------------------------ diagonal array
  logic [(D-1)*SW-1:0] nmin;    // next state of slots 0 .. D-2
  logic [D*LD-1:0]     narg;    // next argmin of slots 0 .. D-1

  assign nmin[0 +: SW] = s_i[0 +: SW];
  assign narg[0 +: LD] = '0;
  for (genvar j = 1; j < D; j++) begin : g_slot
    wire [SW-1:0] cand = s_i[j*SW +: SW];
    wire          take = cand < dmin_p[(j-1)*SW +: SW];
    assign narg[j*LD +: LD] = take ? LD'(j) : darg_p[(j-1)*LD +: LD];
    if (j < D - 1) begin : g_min
      assign nmin[j*SW +: SW] = take ? cand : dmin_p[(j-1)*SW +: SW];
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      dmin_q <= nmin;
      darg_q <= narg[(D-1)*LD-1:0];
    end
  end

  // ------------------------------------------------------------ row tail
  // width - (D - 1) registered with each slot, used from the next one on:
  // width_i is constant within a frame and the first slot of a row is never
  // its last (width >= 16); the compare behind a subtractor would be the 5-lane
  // core's critical path (8.8 ns on ECP5). The last column comes
  // with the slot (last_i).
  logic [CW-1:0] wmd_q;
  always_ff @(posedge clk_i) begin
    if (en_i) wmd_q <= width_i - CW'(D - 1);
  end
  wire last_col = valid_i && last_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      tail_cnt_q <= '0;
    end else if (en_i) begin
      if (last_col) tail_cnt_q <= LD'(D - 1);
      else if (tail_cnt_p != '0) tail_cnt_q <= tail_cnt_p - 1'b1;
      else tail_cnt_q <= '0;
    end
  end

  // The lane's first tail slot (the first slot of its next row): the argmins
  // the last column left in the diagonal array (darg_p) are the tail. Entry 0
  // is written at once (drw_data_q), entries 1 .. D-2 go to the shift register.
  // Loading from darg_p rather than from narg at the last column keeps the
  // diagonal's compare chain out of the tail's input selects (the LFE5U-85F
  // five-lane fifth-path build's critical path otherwise, 8.4 ns).
  wire tail_first = tail_cnt_p == LD'(D - 1);

  for (genvar k = 0; k < D - 1; k++) begin : g_tail
    wire [LD-1:0] shift_in, load_in;
    if (k < D - 2) begin : g_shift
      assign shift_in = tail_p[(k+1)*LD +: LD];
      assign load_in  = darg_p[(D-3-k)*LD +: LD];   // entry k + 1
    end else begin : g_end
      assign shift_in = tail_p[k*LD +: LD];
      assign load_in  = shift_in;
    end
    always_ff @(posedge clk_i) begin
      if (en_i) tail_q[k*LD +: LD] <= tail_first ? load_in : shift_in;
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (last_col) begin
        tail_col_q  <= wmd_q;
        tail_bank_q <= row_i[BW-1:0];
      end else if (tail_cnt_p != '0) begin
        tail_col_q  <= tail_col_p + 1'b1;
        tail_bank_q <= tail_bank_p;
      end else begin
        tail_col_q  <= tail_col_p;
        tail_bank_q <= tail_bank_p;
      end
    end
  end

  // ------------------------------------------------------------ dR memory
  // One registered write request per slot: the tail of the lane's previous row
  // during its D-1 slots, else slot D-1 of the diagonal (xr = x - (D-1) >= 0).
  wire steady = valid_i && col_i >= CW'(D - 1);

  logic           drw_en_q;
  logic [MAW-1:0] drw_addr_q;
  logic [LD-1:0]  drw_data_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) drw_en_q <= 1'b0;
    else if (en_i) drw_en_q <= tail_cnt_p != '0 || steady;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (tail_cnt_p != '0) begin
        drw_addr_q <= mem_addr(tail_bank_p, tail_col_p);
        drw_data_q <= tail_first ? darg_p[(D-2)*LD +: LD] : tail_p[0 +: LD];
      end else begin
        drw_addr_q <= mem_addr(row_i[BW-1:0], col_i - CW'(D - 1));
        drw_data_q <= narg[(D-1)*LD +: LD];
      end
    end
  end

  // ------------------------------------------------------------ left memory
  // Every WTA-side slot writes its word with its frame-pixel flag, so a word
  // read back is always the one of (x, y-1) of the same slot stream: output
  // validity comes from that flag, never from the position alone (a slot of an
  // earlier frame still in flight may have a row inside the next frame).
  wire [LW:0] lt_word;
  if (UNIQUENESS != 0) begin : g_uniq_word
    assign lt_word = {wta_valid_i, unique_i, d_i, disp_i};
  end else begin : g_word
    assign lt_word = {wta_valid_i, d_i, disp_i};
    wire unused_unique = unique_i;
  end

  // ------------------------------------------------------------ R1: the left word
  // The read side: left pixel (rd_col_i, rd_row_i - 1), read at this slot; the word
  // comes out of the memory RAM_LATENCY slots later (r1_word), its side band beside it.
  wire in_real = rd_row_i != '0 && rd_row_i <= height_i;   // previous row is a frame row
  wire [RW-1:0] rd_prev = rd_row_i - 1'b1;

  wire [LW:0] r1_word;
  sgm_bank_ram #(.WIDTH(LW + 1), .DEPTH(MW), .AW(MAW), .LATENCY(RAM_LATENCY)) u_lt_mem (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .we_i   (1'b1),
    .waddr_i(mem_addr(wta_row_i[BW-1:0], wta_col_i)),
    .wdata_i(lt_word),
    .raddr_i(mem_addr(rd_prev[BW-1:0], rd_col_i)),
    .rdata_o(r1_word)
  );

  localparam int R1W = CW + RW + BW + 1 + 3;   // {col, row, bank, check on, tol}
  logic [CW-1:0] r1_col;
  logic [RW-1:0] r1_row;
  logic [BW-1:0] r1_bank;
  logic          r1_chk;
  logic [2:0]    r1_tol;
  sgm_delay #(.WIDTH(R1W), .DEPTH(RAM_LATENCY)) u_r1_side (
    .clk_i(clk_i),
    .en_i (en_i),
    .d_i  ({rd_col_i, rd_prev, rd_prev[BW-1:0], check_en_i, tol_i}),
    .q_o  ({r1_col, r1_row, r1_bank, r1_chk, r1_tol})
  );

  // ------------------------------------------------------------ R2: the dR word
  logic          r1_real_q;   // the pipeline of the real flag, RAM_LATENCY slots (reset)
  wire  [LD-1:0] r1_d    = r1_word[DW +: LD];
  // x - dmin - d >= 0 (dmin_i: the minimum disparity, 0 without it; a constant of the frame)
  wire           r1_ok   = (CW + 9)'(r1_col) >= (CW + 9)'(r1_d) + (CW + 9)'(dmin_i);
  wire  [CW-1:0] r1_xr   = r1_col - CW'(r1_d);
  wire           r1_real = r1_real_q && r1_word[LW];  // (x, y-1) was a pixel of this frame
  wire           r1_uniq;  // the winner passed the uniqueness test (not built: always)
  if (UNIQUENESS != 0) begin : g_uniq_flag
    assign r1_uniq = r1_word[DW + LD];
  end else begin : g_flag
    assign r1_uniq = 1'b1;
  end

  // With x - d < 0 the address wraps (and may pass the memory's end): the word read is
  // not used (r2_ok is 0), and a clamp would sit on the address path.
  wire [LD-1:0] r2_dr;
  sgm_bank_ram #(.WIDTH(LD), .DEPTH(MW), .AW(MAW), .LATENCY(RAM_LATENCY)) u_dr_mem (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .we_i   (drw_en_q),
    .waddr_i(drw_addr_q),
    .wdata_i(drw_data_q),
    .raddr_i(mem_addr(r1_bank, r1_xr)),
    .rdata_o(r2_dr)
  );

  localparam int R2W = LD + DW + 1 + 1 + CW + RW + 1 + 3;   // {d, disp, unique, ok, col, row, check on, tol}
  logic [LD-1:0] r2_d;
  logic [DW-1:0] r2_disp;
  logic          r2_uniq, r2_ok, r2_chk;
  logic [CW-1:0] r2_col;
  logic [RW-1:0] r2_row;
  logic [2:0]    r2_tol;
  sgm_delay #(.WIDTH(R2W), .DEPTH(RAM_LATENCY)) u_r2_side (
    .clk_i(clk_i),
    .en_i (en_i),
    .d_i  ({r1_d, r1_word[0 +: DW], r1_uniq, r1_ok, r1_col, r1_row, r1_chk, r1_tol}),
    .q_o  ({r2_d, r2_disp, r2_uniq, r2_ok, r2_col, r2_row, r2_chk, r2_tol})
  );

  // ------------------------------------------------------------ R3 / outputs
  wire [LD-1:0] diff = r2_dr > r2_d ? r2_dr - r2_d : r2_d - r2_dr;
  wire          pass = (!r2_chk || (r2_ok && diff <= LD'(r2_tol))) && r2_uniq;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      disp_o  <= r2_disp;
      valid_o <= pass;
      col_o   <= r2_col;
      row_o   <= r2_row;
    end
  end

  // ------------------------------------------------------------ confidence
  // The same write and read addresses as the left word; R2's delay, then zeroed with pass.
  if (CONFIDENCE != 0) begin : g_conf
    wire [7:0] r1_conf, r2_conf;
    sgm_bank_ram #(.WIDTH(8), .DEPTH(MW), .AW(MAW), .LATENCY(RAM_LATENCY)) u_conf_mem (
      .clk_i  (clk_i),
      .en_i   (en_i),
      .we_i   (1'b1),
      .waddr_i(mem_addr(wta_row_i[BW-1:0], wta_col_i)),
      .wdata_i(conf_i),
      .raddr_i(mem_addr(rd_prev[BW-1:0], rd_col_i)),
      .rdata_o(r1_conf)
    );
    sgm_delay #(.WIDTH(8), .DEPTH(RAM_LATENCY)) u_r2_conf (
      .clk_i(clk_i),
      .en_i (en_i),
      .d_i  (r1_conf),
      .q_o  (r2_conf)
    );
    always_ff @(posedge clk_i) begin
      if (en_i) conf_o <= pass ? r2_conf : 8'd0;
    end
  end else begin : g_no_conf
    assign conf_o = 8'd0;
    wire unused_conf = ^conf_i;
  end

  // armed_q: a frame pixel has entered since reset. Before that, positions in
  // the pipeline and flags in the memories are power-up values, so nothing may
  // come out; after it, every word read for an output was written by the stream.
  logic armed_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) armed_q <= 1'b0;
    else if (en_i && valid_i) armed_q <= 1'b1;
  end

  // The real flag (reset): RAM_LATENCY slots to r1_real_q, RAM_LATENCY more to the output.
  logic [RAM_LATENCY-1:0] r1_real_pipe_q, r2_real_pipe_q;
  assign r1_real_q = r1_real_pipe_q[RAM_LATENCY-1];
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      r1_real_pipe_q <= '0;
      r2_real_pipe_q <= '0;
      out_valid_o    <= 1'b0;
    end else if (en_i) begin
      r1_real_pipe_q <= {r1_real_pipe_q[RAM_LATENCY-2:0], in_real && armed_q};
      r2_real_pipe_q <= {r2_real_pipe_q[RAM_LATENCY-2:0], r1_real};
      out_valid_o    <= r2_real_pipe_q[RAM_LATENCY-1];
    end
  end

endmodule
`default_nettype wire
