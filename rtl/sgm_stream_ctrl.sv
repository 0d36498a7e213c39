// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// sgm_stream_ctrl: the AXI4-Stream side of the core. Turns input beats into
// pipeline slots (docs/rtl.md), generates the flush slots after a frame,
// latches the per-frame configuration at start of frame, frames the output
// (tuser on the first pixel, tlast on the last pixel of every line) through a
// small FIFO, and flags malformed frames.
//
// Frame protocol: beat 0 of a frame has tuser = 1, every beat at column W-1
// has tlast = 1, exactly W x H beats. A beat that breaks it (tuser inside a
// frame, tlast at another column, no tlast at column W-1) abandons the frame:
// its remaining slots are padded with zero pixels so that exactly W x H output
// beats still leave, error_o records why, and input beats are then dropped
// until the next tuser. A tuser inside a frame is not consumed: it starts the
// next frame. A frame whose configuration is out of range (width outside
// MIN_WIDTH .. MAX_WIDTH, height outside 9 .. MAX_HEIGHT, P2' below P1, cost
// mode 3, uniqueness ratio above 99, an AD term whose largest value added to the
// mode's Cmax leaves the cost word) is dropped whole, and so is a frame that asks
// for a run-time lever the build lacks (a uniqueness ratio other than 0 with
// UNIQUENESS = 0, an AD weight other than 0 with AD_TERM = 0, a fifth-path weight
// other than 0 with RIGHT_PATH = 0, a path restart threshold other than 0 with
// EDGE_RESET = 0, a depth output with DEPTH = 0, a minimum disparity with MIN_DISPARITY
// = 0, a rectification with RECTIFY = 0, the confidence with CONFIDENCE = 0), a fifth-path weight above 8, a path restart with
// length 0 or a rectification lag above RECTIFY_ROWS - 2.
//
// The configuration is one packed word, the frame configuration word cfg_i
// (rtl/sgm_cfg.svh, generated from regmap/sgm_regmap.def): sampled whole with the
// tuser beat's handshake (kept per input buffer entry with its range check) and
// latched whole into cfg_o when that frame starts (width_o / height_o are its
// frame size at the widths of the positions); the P2 table is refilled then (lut_start_o) and the
// frame's first slot follows when lut_ready_i is high. A two-entry input
// buffer keeps s_tready_o free of combinational paths from the stream inputs.
// The slot (en_o, pixels, position) is decided one cycle ahead and comes from
// registers: en_o drives every register of the pipeline, so it must not be
// the end of a logic path. The output FIFO's room is counted for the cycle of
// the decided slot as if this cycle pushed and did not pop (under back-pressure
// the FIFO holds one entry less, never one too many): the room then comes from
// count_q alone, not from en_o (the pipeline's enable, spread over the whole
// device) through the push.
//
// Parameters: MAX_WIDTH, MIN_WIDTH (>= max(D, 16)), MAX_HEIGHT (each at most
// FRAME_SIZE's 16-bit fields can hold, 65535), NB census bits (the
// cost word holds 0 .. 2^CBITS - 1, CBITS = bits of 2 NB), XW/YW column/row
// bits (rows count on past the frame while flushing: MAX_HEIGHT + flush rows
// must fit YW bits), FIFO_DEPTH, UNIQUENESS, AD_TERM, RIGHT_PATH, EDGE_RESET, DEPTH and
// MIN_DISPARITY, RECTIFY (sgm_top's: whether the build has the uniqueness test, the AD term,
// the fifth path, the path restart at strong edges, the depth output, the minimum disparity,
// the rectification; 0 rejects frames that set them), RECTIFY_ROWS (its line buffer rows),
// CONFIDENCE (the same for OUTPUT.CONFIDENCE), WORD_W the output word's bits (16 or 24).
// s_tside_i is a flag beside each beat that comes out with the beat's slot (side_o; sgm_top:
// the rectification's outside flag of the left pixel).
// Throughput: one beat per cycle in both directions when the output is ready.
module sgm_stream_ctrl #(
  parameter int MAX_WIDTH  = 1280,
  parameter int MIN_WIDTH  = 64,
  parameter int MAX_HEIGHT = 1024,
  parameter int NB         = 44,
  parameter int XW         = 11,
  parameter int YW         = 11,
  parameter int FIFO_DEPTH = 4,
  parameter int UNIQUENESS = 1,
  parameter int AD_TERM    = 1,
  parameter int RIGHT_PATH = 0,
  parameter int EDGE_RESET = 0,
  parameter int DEPTH      = 0,
  parameter int MIN_DISPARITY = 0,
  parameter int RECTIFY    = 0,
  parameter int RECTIFY_ROWS = 32,
  parameter int CONFIDENCE = 0,
  parameter int WORD_W     = 16
) (
  input  wire                 clk_i,
  input  wire                 rst_ni,
  // Input stream: tdata = {right[7:0], left[7:0]}.
  input  wire  [15:0]         s_tdata_i,
  input  wire                 s_tuser_i,
  input  wire                 s_tlast_i,
  input  wire                 s_tvalid_i,
  output logic                s_tready_o,
  input  wire                 s_tside_i,     // a flag beside the beat, given with its slot (side_o)
  // Output stream: tdata = the pipeline's output word (res_word_i).
  output logic [WORD_W-1:0]   m_tdata_o,
  output logic                m_tuser_o,
  output logic                m_tlast_o,
  output logic                m_tvalid_o,
  input  wire                 m_tready_i,
  // Run-time configuration: the frame configuration word (rtl/sgm_cfg.svh), sampled at start of frame.
  input  wire  [CFG_W-1:0]    cfg_i,
  // The latched configuration, constant while a frame's slots flow: the word, and its
  // frame size at the widths of the positions.
  output logic [CFG_W-1:0]    cfg_o,
  output logic [XW-1:0]       width_o,
  output logic [YW-1:0]       height_o,
  output logic                lut_start_o,
  input  wire                 lut_ready_i,
  // Pipeline slots.
  output logic                en_o,
  output logic [7:0]          pix_left_o,
  output logic [7:0]          pix_right_o,
  output logic [XW-1:0]       col_o,
  output logic [YW-1:0]       row_o,
  output logic                sof_o,         // the slot is the frame's first: (col_o, row_o) = (0, 0)
  output logic                side_o,        // the slot's beat's s_tside_i (0 in a slot of no beat)
  // Pipeline result of the current slot: a frame pixel when res_valid_i.
  input  wire                 res_valid_i,
  input  wire  [WORD_W-1:0]   res_word_i,    // the output word (sgm_top: disparity or depth, confidence)
  // Status.
  output logic                busy_o,        // a frame is in flight
  output logic                frame_done_o,  // one-cycle pulse: last output beat of a frame queued
  output logic [3:0]          error_o,       // sticky per frame, cleared at the next start of frame:
                                             // [0] tlast early, [1] tlast missing, [2] tuser inside
                                             // a frame, [3] configuration out of range
  output logic [3:0]          error_set_o    // one-cycle pulse per event: the error_o bits set this
                                             // cycle (counts every event, even a bit already set)
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(MIN_WIDTH >= 16)) begin : g_bad_min_width
    $error("sgm_stream_ctrl: MIN_WIDTH = %0d: MIN_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MIN_WIDTH);
  end
  if (!(MAX_WIDTH >= MIN_WIDTH && MAX_WIDTH <= CFG_FRAME_SIZE_WIDTH_MAX)) begin : g_bad_max_width
    $error("sgm_stream_ctrl: MAX_WIDTH = %0d: MAX_WIDTH must be from MIN_WIDTH = %0d to %0d (FRAME_SIZE.WIDTH)", MAX_WIDTH, MIN_WIDTH, CFG_FRAME_SIZE_WIDTH_MAX);
  end
  if (!(MAX_HEIGHT >= CFG_FRAME_SIZE_HEIGHT_MIN && MAX_HEIGHT <= CFG_FRAME_SIZE_HEIGHT_MAX)) begin : g_bad_max_height
    $error("sgm_stream_ctrl: MAX_HEIGHT = %0d: MAX_HEIGHT must be from %0d (the shortest frame) to %0d (FRAME_SIZE.HEIGHT)", MAX_HEIGHT, CFG_FRAME_SIZE_HEIGHT_MIN, CFG_FRAME_SIZE_HEIGHT_MAX);
  end
  if (!(NB == 44 || NB == 80)) begin : g_bad_nb
    $error("sgm_stream_ctrl: NB = %0d: NB must be 44 or 80 (9 CENSUS_H - 1 census bits, CENSUS_H 5 or 9)", NB);
  end
  if (!(XW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_xw
    $error("sgm_stream_ctrl: XW = %0d: XW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", XW, MAX_WIDTH);
  end
  if (!(YW >= $clog2(MAX_HEIGHT + 16))) begin : g_bad_yw
    $error("sgm_stream_ctrl: YW = %0d: YW must hold MAX_HEIGHT = %0d and the flush rows (at least $clog2(MAX_HEIGHT + 16) bits)", YW, MAX_HEIGHT);
  end
  if (!(FIFO_DEPTH >= 2)) begin : g_bad_fifo_depth
    $error("sgm_stream_ctrl: FIFO_DEPTH = %0d: FIFO_DEPTH must be at least 2", FIFO_DEPTH);
  end
  if (!(UNIQUENESS == 0 || UNIQUENESS == 1)) begin : g_bad_uniqueness
    $error("sgm_stream_ctrl: UNIQUENESS = %0d: UNIQUENESS must be 0 or 1", UNIQUENESS);
  end
  if (!(AD_TERM == 0 || AD_TERM == 1)) begin : g_bad_ad_term
    $error("sgm_stream_ctrl: AD_TERM = %0d: AD_TERM must be 0 or 1", AD_TERM);
  end
  if (!(RIGHT_PATH == 0 || RIGHT_PATH == 1)) begin : g_bad_right_path
    $error("sgm_stream_ctrl: RIGHT_PATH = %0d: RIGHT_PATH must be 0 or 1", RIGHT_PATH);
  end
  if (!(EDGE_RESET == 0 || EDGE_RESET == 1)) begin : g_bad_edge_reset
    $error("sgm_stream_ctrl: EDGE_RESET = %0d: EDGE_RESET must be 0 or 1", EDGE_RESET);
  end
  if (!(DEPTH == 0 || DEPTH == 1)) begin : g_bad_depth
    $error("sgm_stream_ctrl: DEPTH = %0d: DEPTH must be 0 or 1", DEPTH);
  end
  if (!(MIN_DISPARITY == 0 || MIN_DISPARITY == 1)) begin : g_bad_min_disparity
    $error("sgm_stream_ctrl: MIN_DISPARITY = %0d: MIN_DISPARITY must be 0 or 1", MIN_DISPARITY);
  end
  if (!(RECTIFY == 0 || RECTIFY == 1)) begin : g_bad_rectify
    $error("sgm_stream_ctrl: RECTIFY = %0d: RECTIFY must be 0 or 1", RECTIFY);
  end
  if (!(CONFIDENCE == 0 || CONFIDENCE == 1)) begin : g_bad_confidence
    $error("sgm_stream_ctrl: CONFIDENCE = %0d: CONFIDENCE must be 0 or 1", CONFIDENCE);
  end
  if (!(WORD_W == 16 || WORD_W == 24)) begin : g_bad_word_w
    $error("sgm_stream_ctrl: WORD_W = %0d: WORD_W must be 16 or 24", WORD_W);
  end
`endif

  typedef enum logic [2:0] {IDLE, FILL, RUN, PAD, FLUSH} state_e;
  state_e state_q;

  // ---------------------------------------------------------------- input buffer
  // Two entries, so that s_tready_o and every enable below come from registers.
  logic [17:0] ibuf_q [0:1];  // {tuser, tlast, tdata}
  logic        side_q [0:1];  // the beat's s_tside_i
  logic [1:0]  in_count_q;
  logic        in_rd_q, in_wr_q;
  wire         in_push  = s_tvalid_i && s_tready_o;
  wire [16:0]  head     = ibuf_q[in_rd_q][16:0];  // its tuser: head_sof_q below
  wire         head_eol = head[16];
  logic        in_pop;
  assign s_tready_o = in_count_q != 2'd2;
  // The head's two flags the slot decision reads (in_count_q != 0, and that with
  // the head's tuser) are kept in flip-flops of their own, written with the
  // buffer's next state, so that the decision does not read the buffer's
  // distributed RAM (the fifth-path core's critical path on the LFE5U-85F ran
  // from it through the start-of-frame check into the slot's clock enables).
  logic        head_ok_q, head_sof_q;
  wire         head_ok  = head_ok_q;
  wire         head_sof = head_sof_q;

  // Configuration at the start-of-frame handshake, applied when that frame
  // starts: one word per input buffer entry, so that a tuser beat keeps its own
  // configuration even when the next frame's tuser enters the buffer behind it
  // (a one-beat malformed frame).
  // The range check of the configuration is done as the word is written and kept with
  // it, so that the start-of-frame decision reads one flag (its comparisons behind the
  // entry's distributed RAM would be the 5-lane core's critical path at 95.8 MHz). In
  // range: every field at most its MAX and no lever the build lacks (cfg_below_max,
  // cfg_levers_built: generated from regmap/sgm_regmap.def into rtl/sgm_cfg.svh: cost
  // mode 0, 1 or 2, 3 is not a mode; uniqueness ratio 0 .. 99; fifth-path weight 0 .. 8),
  // and the bounds of the build and the rules across fields, checked here: MIN_WIDTH ..
  // MAX_WIDTH columns, MIN .. MAX_HEIGHT rows (the frame size whole, at its register
  // width), P2' >= P1 (the golden model's contract), a path restart length of at least
  // its MIN when the restart is on, and the AD term's largest value (W T) >> 3 added to
  // the mode's Cmax (NB, or 2 NB unified) within the cost word (the golden model's
  // Params::validate, costLimit).
  localparam int CBITS = $clog2(2 * NB + 1);
  wire [CFG_FRAME_SIZE_WIDTH_W-1:0]  cfg_width     = cfg_i[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W];
  wire [CFG_FRAME_SIZE_HEIGHT_W-1:0] cfg_height    = cfg_i[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W];
  wire [CFG_PENALTY_P1_W-1:0]        cfg_p1        = cfg_i[CFG_PENALTY_P1_LSB +: CFG_PENALTY_P1_W];
  wire [CFG_PENALTY_P2_W-1:0]        cfg_p2        = cfg_i[CFG_PENALTY_P2_LSB +: CFG_PENALTY_P2_W];
  wire [CFG_CONFIG_MODE_W-1:0]       cfg_mode      = cfg_i[CFG_CONFIG_MODE_LSB +: CFG_CONFIG_MODE_W];
  wire [CFG_PENALTY_AD_WEIGHT_W-1:0] cfg_ad_weight = cfg_i[CFG_PENALTY_AD_WEIGHT_LSB +: CFG_PENALTY_AD_WEIGHT_W];
  wire [CFG_PENALTY_AD_CAP_W-1:0]    cfg_ad_cap    = cfg_i[CFG_PENALTY_AD_CAP_LSB +: CFG_PENALTY_AD_CAP_W];
  wire [CFG_EDGE_RESET_T_W-1:0]      cfg_reset_t   = cfg_i[CFG_EDGE_RESET_T_LSB +: CFG_EDGE_RESET_T_W];
  wire [CFG_EDGE_RESET_LEN_W-1:0]    cfg_reset_len = cfg_i[CFG_EDGE_RESET_LEN_LSB +: CFG_EDGE_RESET_LEN_W];
  wire [CFG_RECTIFY_LAG_W-1:0]       cfg_rect_lag  = cfg_i[CFG_RECTIFY_LAG_LSB +: CFG_RECTIFY_LAG_W];
  wire [11:0] ad_max  = 12'(cfg_ad_weight) * 12'(cfg_ad_cap);
  wire [9:0]  ad_cmax = cfg_mode == 2'd2 ? 10'(2 * NB) : 10'(NB);
  wire        ad_fits = ad_cmax + 10'(ad_max[11:3]) <= 10'((1 << CBITS) - 1);
  wire        unused_ad = ^ad_max[2:0];
  wire cfg_ok = 32'(cfg_width) >= MIN_WIDTH && 32'(cfg_width) <= MAX_WIDTH &&
                32'(cfg_height) >= CFG_FRAME_SIZE_HEIGHT_MIN && 32'(cfg_height) <= MAX_HEIGHT &&
                cfg_p2 >= cfg_p1 && ad_fits &&
                (cfg_reset_t == 8'd0 || 32'(cfg_reset_len) >= CFG_EDGE_RESET_LEN_MIN) &&
                cfg_below_max(cfg_i) &&
                (RECTIFY == 0 || 32'(cfg_rect_lag) <= RECTIFY_ROWS - 2) &&
                cfg_levers_built(cfg_i, AD_TERM != 0, RIGHT_PATH != 0, UNIQUENESS != 0, EDGE_RESET != 0, DEPTH != 0,
                                 CONFIDENCE != 0, MIN_DISPARITY != 0, RECTIFY != 0);
  logic [CFG_W:0] pend_q [0:1];  // {in range, the word}
  always_ff @(posedge clk_i) begin
    if (in_push && s_tuser_i) pend_q[in_wr_q] <= {cfg_ok, cfg_i};
  end
  // The configuration of the head beat (meaningful when it is a tuser beat).
  logic [CFG_W-1:0] pend_cfg;
  logic             pend_ok;
  assign {pend_ok, pend_cfg} = pend_q[in_rd_q];

  // The frame size at the widths of the positions (in range: it fits them).
  assign width_o  = XW'(cfg_o[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W]);
  assign height_o = YW'(cfg_o[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W]);

  // ---------------------------------------------------------------- output FIFO
  localparam int FAW = $clog2(FIFO_DEPTH);
  logic [WORD_W+1:0] fifo_q [0:FIFO_DEPTH-1];  // {tuser, tlast, tdata}
  logic [FAW:0]   count_q;
  logic [FAW-1:0] rd_q, wr_q;
  wire pop  = m_tvalid_o && m_tready_i;
  wire push;
  // Room in the cycle of the slot decided now: this cycle's push is counted as
  // if it came (push = en_o && res_valid_i: en_o kept out of the slot's logic),
  // this cycle's pop is not counted.
  // room_q: count_q < FIFO_DEPTH - 1, written with the next count.
  logic room_q;
  wire  room = room_q;

  // ---------------------------------------------------------------- slots
  logic [XW-1:0] x_q;          // position of the next slot
  logic [YW-1:0] y_q;
  logic [XW-1:0] out_x_q;      // position of the next output pixel
  logic [YW-1:0] out_y_q;

  // Row and column ends as flags kept beside the positions, so that no
  // comparison with the configuration sits between the positions and the FSM
  // or the FIFO (otherwise the 5-lane core's critical path). wm2_q and hm1_q
  // follow width_o / height_o one cycle later: those change only in IDLE, and
  // the first slot comes after FILL. last_col_q: x_q == width - 1, kept
  // exact on every slot (width >= MIN_WIDTH >= 16, so 0 is never the last
  // column); last_row: y_q == height - 1, one cycle behind y_q, which is early
  // enough because y_q changes only at a last column and is next read at the
  // next one (>= 16 slots later). The same for the output positions.
  logic [XW-1:0] wm2_q;
  logic [YW-1:0] hm1_q;
  logic          last_col_q, last_row_q, out_eol_q, out_last_row_q;
  always_ff @(posedge clk_i) begin
    wm2_q          <= width_o - XW'(2);
    hm1_q          <= height_o - 1'b1;
    last_row_q     <= y_q == hm1_q;
    out_last_row_q <= out_y_q == hm1_q;
  end

  // first_q: x_q == 0 && y_q == 0, kept as a flag (set in IDLE, cleared by the
  // frame's first slot: the position never returns to (0, 0) within a frame),
  // so that the slot decision is a function of registers only (the 5-lane
  // core's critical path on the LFE5U-85F ran from y_q through this comparison
  // into the slot's clock enables).
  logic first_q;
  wire first_px = first_q;
  wire last_px  = last_col_q && last_row_q;

  // RUN takes the head beat as the next slot, except a tuser beat inside the
  // frame, which is left for the next frame.
  // run_q / gen_q: state_q == RUN / state_q is PAD or FLUSH, as flip-flops
  // written with the next state (no state decoding in front of the slot).
  logic run_q, gen_q;
  wire err_sof  = run_q && head_sof && !first_px;
  wire take     = run_q && head_ok && room && !err_sof;
  wire gen_slot = gen_q && room;
  // IDLE drops every beat but a start of frame with a valid configuration.
  wire drop     = state_q == IDLE && head_ok && !(head_sof && pend_ok);
  assign in_pop = take || drop;

  // The slot decided in this cycle enters the pipeline in the next.
  wire slot = take || gen_slot;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) en_o <= 1'b0;
    else         en_o <= slot;
  end
  always_ff @(posedge clk_i) begin
    if (slot) begin
      pix_left_o  <= take ? head[7:0] : 8'd0;
      pix_right_o <= take ? head[15:8] : 8'd0;
      side_o      <= take && side_q[in_rd_q];
      col_o       <= x_q;
      row_o       <= y_q;
      sof_o       <= first_px;  // a flag beside the position (no comparison behind col_o / row_o)
    end
  end
  assign busy_o = state_q != IDLE;

  // Framing errors of the beat being taken.
  wire err_early   = take && head_eol && !last_col_q;
  wire err_missing = take && !head_eol && last_col_q;

  assign push   = en_o && res_valid_i;
  wire out_last = out_eol_q && out_last_row_q;

  // The next state.
  state_e state_d;
  always_comb begin
    state_d = state_q;
    case (state_q)
      IDLE:  if (head_sof && pend_ok) state_d = FILL;
      FILL:  if (lut_ready_i && !lut_start_o) state_d = RUN;
      RUN:   if (err_sof) state_d = PAD;
             else if (take) begin
               if (last_px) state_d = FLUSH;
               else if (err_early || err_missing) state_d = PAD;
             end
      PAD:   if (gen_slot && last_px) state_d = FLUSH;
      FLUSH: if (push && out_last) state_d = IDLE;
      default: state_d = IDLE;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= IDLE;
      run_q   <= 1'b0;
      gen_q   <= 1'b0;
    end else begin
      state_q <= state_d;
      run_q   <= state_d == RUN;
      gen_q   <= state_d == PAD || state_d == FLUSH;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      lut_start_o  <= 1'b0;
      frame_done_o <= 1'b0;
      error_o      <= '0;
      error_set_o  <= '0;
    end else begin
      lut_start_o  <= 1'b0;
      frame_done_o <= 1'b0;
      error_set_o  <= '0;
      case (state_q)
        IDLE: if (head_sof) begin
          error_o     <= {~pend_ok, 3'b000};
          error_set_o <= {~pend_ok, 3'b000};
          if (pend_ok) begin
            cfg_o       <= pend_cfg;
            lut_start_o <= 1'b1;
          end
        end
        RUN: begin
          if (err_sof) begin
            error_o[2]     <= 1'b1;
            error_set_o[2] <= 1'b1;
          end else if (take) begin
            if (err_early) error_o[0] <= 1'b1;
            if (err_missing) error_o[1] <= 1'b1;
            error_set_o[1:0] <= {err_missing, err_early};
          end
        end
        FLUSH: if (push && out_last) frame_done_o <= 1'b1;
        default: ;
      endcase
    end
  end

  // Input buffer. The head after this cycle: the beat pushed now if the buffer is left empty,
  // else the other entry if the head is popped (the buffer held two), else the head.
  wire       in_left     = in_count_q != 2'd0 && !(in_pop && in_count_q == 2'd1);
  wire       head_ok_d   = in_left || in_push;
  wire       head_user_d = !in_left ? s_tuser_i : in_pop ? ibuf_q[~in_rd_q][17] : head_sof_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_count_q <= '0;
      in_rd_q    <= 1'b0;
      in_wr_q    <= 1'b0;
      head_ok_q  <= 1'b0;
      head_sof_q <= 1'b0;
    end else begin
      if (in_push) begin
        ibuf_q[in_wr_q] <= {s_tuser_i, s_tlast_i, s_tdata_i};
        side_q[in_wr_q] <= s_tside_i;
        in_wr_q         <= ~in_wr_q;
      end
      if (in_pop) in_rd_q <= ~in_rd_q;
      in_count_q <= in_count_q + (in_push ? 2'd1 : 2'd0) - (in_pop ? 2'd1 : 2'd0);
      head_ok_q  <= head_ok_d;
      head_sof_q <= head_ok_d && head_user_d;
    end
  end

  // Slot position: restarts at the frame's first slot, counts on through the flush rows.
  always_ff @(posedge clk_i) begin
    if (state_q == IDLE) begin
      x_q       <= '0;
      y_q       <= '0;
      first_q   <= 1'b1;
      last_col_q  <= 1'b0;
      out_x_q   <= '0;
      out_y_q   <= '0;
      out_eol_q <= 1'b0;
    end else begin
      if (slot) begin
        first_q <= 1'b0;
        if (last_col_q) begin
          x_q      <= '0;
          y_q      <= y_q + 1'b1;
          last_col_q <= 1'b0;
        end else begin
          x_q      <= x_q + 1'b1;
          last_col_q <= x_q == wm2_q;
        end
      end
      if (push) begin
        if (out_eol_q) begin
          out_x_q   <= '0;
          out_y_q   <= out_y_q + 1'b1;
          out_eol_q <= 1'b0;
        end else begin
          out_x_q   <= out_x_q + 1'b1;
          out_eol_q <= out_x_q == wm2_q;
        end
      end
    end
  end

  // Output FIFO.
  wire [FAW:0] count_d = count_q + (FAW+1)'(push) - (FAW+1)'(pop);
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      count_q <= '0;
      room_q  <= 1'b1;
      rd_q    <= '0;
      wr_q    <= '0;
    end else begin
      if (push) begin
        fifo_q[wr_q] <= {out_x_q == '0 && out_y_q == '0, out_eol_q, res_word_i};
        wr_q         <= wr_q == FAW'(FIFO_DEPTH - 1) ? '0 : wr_q + 1'b1;
      end
      if (pop) rd_q <= rd_q == FAW'(FIFO_DEPTH - 1) ? '0 : rd_q + 1'b1;
      count_q <= count_d;
      room_q  <= count_d < (FAW+1)'(FIFO_DEPTH - 1);
    end
  end

  assign m_tvalid_o = count_q != '0;
  assign m_tuser_o  = fifo_q[rd_q][WORD_W+1];
  assign m_tlast_o  = fifo_q[rd_q][WORD_W];
  assign m_tdata_o  = fifo_q[rd_q][WORD_W-1:0];

`ifdef SGM_FORMAL
  // The formal property set (tests/formal/sgm_stream_ctrl_props.svh; make formal, docs/formal.md).
`include "sgm_stream_ctrl_props.svh"
`endif

endmodule
`default_nettype wire
