// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_stream_ctrl (make formal, docs/formal.md). Included at the
// end of the module's body when SGM_FORMAL is defined (tests/formal/stream_ctrl_*.sby: yosys
// read -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed: the first cycle is in reset; the input stream follows AXI4-Stream (s_tvalid_i
// low in reset, held until s_tready_o with tdata, tuser and tlast unchanged). Everything
// else is free in every cycle: the configuration inputs, m_tready_i, lut_ready_i and the
// pipeline's result (res_valid_i, res_word_i). With SGM_FORMAL_PIPE (the
// stream_ctrl_live task) the pipeline follows its contract instead (docs/rtl.md, "The
// step stream"): a slot's result comes F_LAT slots after the slot, res_valid_i high exactly
// for the results of frame pixels, and m_tready_i is high (a sink that takes every beat).
//
// Asserted:
//   output stream   m_tvalid_o is low after reset and held until m_tready_i, with
//                   m_tdata_o, m_tuser_o and m_tlast_o unchanged while held;
//   output FIFO     never written when full nor read when empty; its count, pointers and
//                   room flag agree; a slot is enabled only with a free entry for its
//                   result;
//   input buffer    never written when full (s_tready_o low) nor read when empty; the
//                   head's flags (a beat is there, it is a start of frame) are the buffer's;
//                   an accepted beat leaves it once, unchanged, in order (a beat chosen
//                   freely is followed through it);
//   state           the state's flags (RUN, PAD or FLUSH) are the state's, busy_o is
//                   state != IDLE; no slot is decided in IDLE or FILL;
//   configuration   the check of a tuser beat's configuration is the range of docs/rtl.md
//                   ("Stream protocol and malformed frames"); the latched configuration
//                   changes only when IDLE takes a start of frame, so it is constant while
//                   a frame's slots flow;
//   framing         in a frame the slot position stays inside the frame (RUN, PAD) and its
//                   row/column end flags and first-slot flag equal their comparisons; the
//                   output position likewise; sof_o is set exactly on slot (0, 0);
//   errors          an error event (error_set_o[2:0]) leaves RUN for PAD (or FLUSH at the
//                   frame's last pixel); PAD, FLUSH and FILL take no input beat, a tuser
//                   inside a frame is not consumed (it starts the next frame); IDLE takes a
//                   start of frame with a configuration in range in the cycle it reaches the
//                   head of the buffer and drops any other beat in one cycle;
//   frame_done_o    pulses once, in the cycle after the push of a frame's last pixel.
// With SGM_FORMAL_PIPE, in addition (bounded response): a frame left by an error returns
// to IDLE within F_N cycles of the error event (stated in docs/formal.md).
// Covered: a frame completes, each framing error and a dropped configuration, a frame
// after a malformed one, the output FIFO full, an output beat held by m_tready_i low.

  logic [2:0] f_t = 3'd0;
  always @(posedge clk_i) if (f_t != 3'd7) f_t <= f_t + 3'd1;
  wire f_past_valid = f_t != 3'd0;

  wire f_in_hs   = s_tvalid_i && s_tready_o;
  wire f_out_hs  = m_tvalid_o && m_tready_i;
  wire f_idle    = state_q == IDLE;
  wire f_framing = state_q == RUN || state_q == PAD || state_q == FLUSH;

  // ------------------------------------------------------------ assumptions
  always @(*) begin
    if (!f_past_valid) assume (!rst_ni);
    if (!rst_ni) assume (!s_tvalid_i);
  end
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni && $past(s_tvalid_i && !s_tready_o))
      assume (s_tvalid_i && s_tdata_i == $past(s_tdata_i) && s_tuser_i == $past(s_tuser_i) &&
              s_tlast_i == $past(s_tlast_i));
  end

  // ------------------------------------------------------------ the configuration range
  // docs/rtl.md: width MIN_WIDTH .. MAX_WIDTH, height 9 .. MAX_HEIGHT, P2' >= P1, mode
  // 0 .. 2, uniqueness ratio 0 .. 99, the AD term's largest value (W T) >> 3 added to the
  // mode's Cmax (NB; unified 2 NB) within the cost word, fifth-path weight 0 .. 8, a path
  // restart (T != 0) of length 1 .. 15, output mode 0 .. 1, a rectification lag of at most
  // RECTIFY_ROWS - 2, and no lever the build lacks (the depth output, the minimum disparity,
  // the rectification and the confidence among them).
  // Written from the documented rules, not from the generated cfg_below_max /
  // cfg_levers_built, so that a wrong generated bound fails here; the field positions are
  // the word's (rtl/sgm_cfg.svh).
  localparam int F_CMAX_WORD = (1 << $clog2(2 * NB + 1)) - 1;
  function automatic logic f_in_range(input logic [CFG_W-1:0] c);
    logic [31:0] w, h, p1, p2, mode, u, adw, adcap, rw, rt, rlen, ad_top, out_mode, out_conf, dmin, rect, lag;
    w      = 32'(c[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W]);
    h      = 32'(c[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W]);
    p1     = 32'(c[CFG_PENALTY_P1_LSB +: CFG_PENALTY_P1_W]);
    p2     = 32'(c[CFG_PENALTY_P2_LSB +: CFG_PENALTY_P2_W]);
    mode   = 32'(c[CFG_CONFIG_MODE_LSB +: CFG_CONFIG_MODE_W]);
    u      = 32'(c[CFG_CONFIG_UNIQUENESS_LSB +: CFG_CONFIG_UNIQUENESS_W]);
    adw    = 32'(c[CFG_PENALTY_AD_WEIGHT_LSB +: CFG_PENALTY_AD_WEIGHT_W]);
    adcap  = 32'(c[CFG_PENALTY_AD_CAP_LSB +: CFG_PENALTY_AD_CAP_W]);
    rw     = 32'(c[CFG_PENALTY_RIGHT_WEIGHT_LSB +: CFG_PENALTY_RIGHT_WEIGHT_W]);
    rt     = 32'(c[CFG_EDGE_RESET_T_LSB +: CFG_EDGE_RESET_T_W]);
    rlen   = 32'(c[CFG_EDGE_RESET_LEN_LSB +: CFG_EDGE_RESET_LEN_W]);
    out_mode = 32'(c[CFG_OUTPUT_MODE_LSB +: CFG_OUTPUT_MODE_W]);
    out_conf = 32'(c[CFG_OUTPUT_CONFIDENCE_LSB +: CFG_OUTPUT_CONFIDENCE_W]);
    dmin   = 32'(c[CFG_MIN_DISPARITY_DMIN_LSB +: CFG_MIN_DISPARITY_DMIN_W]);
    rect   = 32'(c[CFG_RECTIFY_ENABLE_LSB +: CFG_RECTIFY_ENABLE_W]);
    lag    = 32'(c[CFG_RECTIFY_LAG_LSB +: CFG_RECTIFY_LAG_W]);
    ad_top = (mode == 32'd2 ? 32'(2 * NB) : 32'(NB)) + ((adw * adcap) >> 3);
    f_in_range = w >= 32'(MIN_WIDTH) && w <= 32'(MAX_WIDTH) && h >= 32'd9 && h <= 32'(MAX_HEIGHT) && p2 >= p1 &&
                 mode <= 32'd2 && u <= 32'd99 && ad_top <= 32'(F_CMAX_WORD) && rw <= 32'd8 &&
                 (rt == 32'd0 || rlen != 32'd0) && (UNIQUENESS != 0 || u == 32'd0) &&
                 (AD_TERM != 0 || adw == 32'd0) && (RIGHT_PATH != 0 || rw == 32'd0) && (EDGE_RESET != 0 || rt == 32'd0) &&
                 out_mode <= 32'd1 && (DEPTH != 0 || out_mode == 32'd0) && (MIN_DISPARITY != 0 || dmin == 32'd0) &&
                 (CONFIDENCE != 0 || out_conf == 32'd0) &&
                 (RECTIFY != 0 ? lag + 32'd2 <= 32'(RECTIFY_ROWS) : rect == 32'd0 && lag == 32'd0);
  endfunction
  wire f_cfg_in_range = f_in_range(cfg_i);
  // Entry i holds a tuser beat (its configuration word was written with it): its flag is
  // the range of its word.
  wire [1:0] f_tuser_in;
  for (genvar i = 0; i < 2; i++) begin : g_f_pend
    assign f_tuser_in[i] = (in_count_q == 2'd2 || (in_count_q == 2'd1 && in_rd_q == 1'(i))) && ibuf_q[i][17];
    always @(*) if (f_past_valid && f_tuser_in[i]) assert (pend_q[i][CFG_W] == f_in_range(pend_q[i][CFG_W-1:0]));
  end
  wire f_latched_in_range = f_in_range(cfg_o);

  // ------------------------------------------------------------ input beats in order
  // One accepted beat, chosen freely (f_pick), is followed through the input buffer: it
  // leaves it exactly once, as the buffer's head, unchanged, after the beats accepted
  // before it: no accepted beat is lost, changed, reordered or taken twice.
  (* anyseq *) logic f_pick;
  logic [1:0]  f_track = 2'd0;  // 0: none chosen yet, 1: in the buffer, 2: left it
  logic [17:0] f_beat;          // its {tuser, tlast, tdata}
  logic        f_ahead;         // a beat accepted before it is still in the buffer
  always @(posedge clk_i) begin
    if (!rst_ni) f_track <= 2'd0;
    else if (f_track == 2'd1 && in_pop) begin
      if (f_ahead) f_ahead <= 1'b0;
      else         f_track <= 2'd2;
    end else if (f_track == 2'd0 && in_push && f_pick) begin
      f_track <= 2'd1;
      f_beat  <= {s_tuser_i, s_tlast_i, s_tdata_i};
      f_ahead <= in_count_q == 2'd1 && !in_pop;
    end
  end
  always @(*) begin
    if (f_past_valid && f_track == 2'd1) begin
      if (f_ahead) assert (in_count_q == 2'd2 && ibuf_q[~in_rd_q] == f_beat);
      else         assert (in_count_q != 2'd0 && ibuf_q[in_rd_q] == f_beat);
    end
  end

  // The output position (pixels pushed) before the slot position (slots decided).
  wire f_out_behind = out_y_q < y_q || (out_y_q == y_q && out_x_q < x_q);

  // ------------------------------------------------------------ every cycle
  always @(*) begin
    if (f_past_valid) begin
      // state flags
      assert (state_q == IDLE || state_q == FILL || state_q == RUN || state_q == PAD || state_q == FLUSH);
      assert (run_q == (state_q == RUN));
      assert (gen_q == (state_q == PAD || state_q == FLUSH));
      assert (busy_o == !f_idle);
      if (f_idle || state_q == FILL) assert (!slot);
      // input buffer
      assert (in_count_q <= 2'd2);
      assert (s_tready_o == (in_count_q != 2'd2));
      assert (in_wr_q == (in_rd_q ^ in_count_q[0]));
      assert (head_ok_q == (in_count_q != 2'd0));
      assert (head_sof_q == (in_count_q != 2'd0 && ibuf_q[in_rd_q][17]));
      if (in_pop) assert (in_count_q != 2'd0);
      // output FIFO
      assert (count_q <= (FAW+1)'(FIFO_DEPTH));
      assert (32'(wr_q) == (32'(rd_q) + 32'(count_q) >= FIFO_DEPTH ? 32'(rd_q) + 32'(count_q) - FIFO_DEPTH :
                                                                      32'(rd_q) + 32'(count_q)));
      assert (32'(rd_q) < FIFO_DEPTH && 32'(wr_q) < FIFO_DEPTH);
      assert (room_q == (count_q < (FAW+1)'(FIFO_DEPTH - 1)));
      if (en_o) assert (count_q < (FAW+1)'(FIFO_DEPTH));
      if (push) assert (count_q < (FAW+1)'(FIFO_DEPTH));
      assert (m_tvalid_o == (count_q != '0));
      // configuration check, kept with each entry; a frame runs with a configuration in range
      assert (cfg_ok == f_cfg_in_range);
      if (!f_idle) assert (f_latched_in_range);
      // errors: no input beat taken outside RUN and IDLE, a tuser inside a frame kept
      if (!(state_q == RUN || f_idle)) assert (!in_pop);
      if (err_sof) assert (!in_pop);
      if (f_idle && head_ok_q) assert (in_pop != (head_sof_q && pend_ok));
      if (error_set_o[2:0] != 3'd0) assert (state_q == PAD || state_q == FLUSH);
    end
    // framing: positions inside the frame, flags equal to their comparisons
    if (f_past_valid && f_framing) begin
      assert (wm2_q == width_o - XW'(2) && hm1_q == height_o - YW'(1));
      assert (x_q < width_o && last_col_q == (x_q == width_o - XW'(1)));
      assert (out_x_q < width_o && out_eol_q == (out_x_q == width_o - XW'(1)));
      if (x_q != '0) assert (last_row_q == (y_q == hm1_q));
      if (out_x_q != '0) assert (out_last_row_q == (out_y_q == hm1_q));
      assert (out_y_q <= hm1_q);
    end
    if (f_past_valid && (state_q == RUN || state_q == PAD)) begin
      assert (y_q <= hm1_q);
      assert (first_q == (x_q == '0 && y_q == '0));
      // no more output pixels than slots enabled (each push is a slot's result)
      assert (en_o ? f_out_behind : f_out_behind || (out_y_q == y_q && out_x_q == x_q));
    end
    if (f_past_valid && state_q == FILL)
      assert (first_q && x_q == '0 && y_q == '0 && !last_col_q && out_x_q == '0 && out_y_q == '0 && !out_eol_q);
  end

  // ------------------------------------------------------------ cycle to cycle
  always @(posedge clk_i) begin
    if (f_past_valid && !$past(rst_ni)) assert (!m_tvalid_o && f_idle && !en_o && in_count_q == 2'd0);
    if (f_past_valid && $past(rst_ni)) begin
      if ($past(m_tvalid_o && !m_tready_i))
        assert (m_tvalid_o && m_tdata_o == $past(m_tdata_o) && m_tuser_o == $past(m_tuser_o) &&
                m_tlast_o == $past(m_tlast_o));
      // the latched configuration changes only when IDLE takes a start of frame
      if (!($past(f_idle && head_sof && pend_ok)))
        assert (cfg_o == $past(cfg_o));
      // IDLE takes a start of frame in range at once
      if ($past(f_idle && head_sof && pend_ok)) assert (state_q == FILL && lut_start_o);
      // a slot enters the pipeline the cycle after its decision; sof_o on slot (0, 0) of
      // the frame (flush rows, which count on past the frame, excepted)
      assert (en_o == $past(slot));
      if ($past(slot && state_q != FLUSH)) assert (sof_o == (col_o == '0 && row_o == '0));
      // frame_done_o: the cycle after the push of the frame's last pixel, in FLUSH
      assert (frame_done_o == $past(state_q == FLUSH && push && out_last));
      if (frame_done_o) assert (f_idle);
    end
  end

`ifdef SGM_FORMAL_PIPE
  // ------------------------------------------------------------ the pipeline's contract
  // A slot's result is presented F_LAT slots later (res_valid_i in the cycle of the later
  // slot's en_o), valid exactly for a frame pixel: row_o < height_o (the column is always
  // inside). Nothing before the first frame pixel after reset. The sink takes every beat.
  // The frame width is fixed (MIN_WIDTH = MAX_WIDTH = F_W), the height any of 9 .. MAX_HEIGHT.
  localparam int F_LAT = 3;
  localparam int F_W   = MAX_WIDTH;
  if (MIN_WIDTH != MAX_WIDTH) begin : g_f_bad_width
    $error("sgm_stream_ctrl_props: SGM_FORMAL_PIPE needs MIN_WIDTH = MAX_WIDTH");
  end
  logic [F_LAT-1:0] f_pipe;
  always @(posedge clk_i) begin
    if (!rst_ni) f_pipe <= '0;
    else if (en_o) f_pipe <= {f_pipe[F_LAT-2:0], row_o < height_o};
  end
  always @(*) begin
    if (en_o) assume (res_valid_i == f_pipe[F_LAT-1]);
    assume (m_tready_i);
  end

  // Cycles since a framing error event (error_set_o[2:0]), counted until the frame's
  // return to IDLE; F_N bounds them: the frame's pixels after the first slot (an error
  // at the first beat pads all the others) and the pipeline's latency.
  localparam int F_N = F_W * MAX_HEIGHT + F_LAT - 1;
  logic [15:0] f_err_age;
  always @(posedge clk_i) begin
    if (!rst_ni || state_d == IDLE) f_err_age <= 16'd0;
    else if (error_set_o[2:0] != 3'd0) f_err_age <= 16'd1;
    else if (f_err_age != 16'd0 && f_err_age != 16'hFFFF) f_err_age <= f_err_age + 16'd1;
  end
  always @(*) if (f_past_valid) assert (32'(f_err_age) <= F_N);

  // The invariants that close the induction: slots decided (f_p), slots enabled (f_q),
  // output pixels pushed (f_o) and the pipeline's flags agree.
  wire [31:0] f_p = 32'(y_q) * F_W + 32'(x_q);
  wire [31:0] f_q = f_p - 32'(en_o);
  wire [31:0] f_o = 32'(out_y_q) * F_W + 32'(out_x_q);
  wire [31:0] f_pixels = 32'(height_o) * F_W;
  always @(*) begin
    if (f_past_valid) begin
      assert (count_q <= (FAW+1)'(1));
      if (f_idle || state_q == FILL) begin
        assert (f_pipe == '0 && f_err_age == 16'd0);
        if (en_o) assert (row_o >= height_o);
      end
      if (state_q == RUN) assert (f_err_age == 16'd0);
      if (f_framing) begin
        if (en_o) assert (32'(row_o) * F_W + 32'(col_o) == f_p - 32'd1);
        assert (f_o == (f_q < F_LAT ? 32'd0 : f_q - F_LAT > f_pixels ? f_pixels : f_q - F_LAT));
        assert (f_p <= f_pixels + F_LAT);
        if (f_err_age != 16'd0) assert (state_q != RUN && 32'(f_err_age) < f_p);
      end
    end
  end
  // The output stream as its sink sees it: f_sink counts the beats taken in the frame
  // (0 .. W H - 1, then 0 again). tuser exactly on a frame's first beat, tlast exactly on
  // each row's last, so exactly W x H beats between two tuser beats. The sink takes every
  // beat here, so the FIFO holds at most the beat pushed in the cycle before: its entry is
  // the beat f_sink (the free task above proves the FIFO under any m_tready_i).
  logic [31:0] f_sink;
  always @(posedge clk_i) begin
    if (!rst_ni) f_sink <= 32'd0;
    else if (f_out_hs) f_sink <= f_sink == f_pixels - 32'd1 ? 32'd0 : f_sink + 32'd1;
  end
  wire [1:0] f_head_flags = fifo_q[rd_q][17:16];  // {tuser, tlast} of the beat presented
  always @(*) begin
    if (f_past_valid && f_out_hs) begin
      assert (m_tuser_o == (f_sink == 32'd0));
      assert (m_tlast_o == (f_sink % F_W == F_W - 1));
    end
    if (f_past_valid) begin
      if (f_framing) assert (f_sink == f_o - 32'(count_q));
      if (state_q == FILL || (f_idle && count_q == '0)) assert (f_sink == 32'd0);
      if (f_idle && count_q != '0) assert (f_sink == f_pixels - 32'd1);
      if (count_q != '0) assert (f_head_flags == {f_sink == 32'd0, f_sink % F_W == F_W - 1});
    end
  end

  // The pipeline's flags: f_pipe[j] is the flag of slot f_q - 1 - j.
  for (genvar j = 0; j < F_LAT; j++) begin : g_f_pipe
    always @(*) if (f_past_valid && f_framing) assert (f_pipe[j] == (f_q >= 32'(j + 1) && f_q - 32'(j + 1) < f_pixels));
  end
`endif

  // ------------------------------------------------------------ covers
  // Without SGM_FORMAL_PIPE: a tlast early, a tuser inside a frame, a configuration
  // dropped and the next start of frame taken (recovery from a dropped frame), the input
  // stalled (s_tready_o low with a beat waiting), the output FIFO full, an output beat held
  // two cycles. With it: a frame left by an error at its first beat padded, its results
  // pushed, the error's age counted. A missing tlast (a whole line, 16 beats or more), a
  // whole frame and the recovery from an error inside one (16 x 9 beats and the flush, about
  // 150 cycles) are deeper than smtbmc with z3 reaches: a cover at step 145 with every input
  // but the framing fixed did not return in 15 minutes. The properties hold for them by
  // induction (the bounded return to IDLE above); whole frames and every error kind are
  // reached by the simulation (docs/formal.md).
  logic f_dropped_cfg = 1'b0;  // a start of frame was dropped for its configuration
  always @(posedge clk_i) if (error_set_o[3]) f_dropped_cfg <= 1'b1;
  always @(posedge clk_i) begin
    if (f_t == 3'd7 && rst_ni && $past(rst_ni)) begin
`ifndef SGM_FORMAL_PIPE
      cover (error_set_o[0]);
      cover (error_set_o[2]);
      cover (error_set_o[3]);
      cover (f_dropped_cfg && state_q == FILL);
      cover (s_tvalid_i && !s_tready_o);
      cover (f_track == 2'd2 && $past(f_track == 2'd1 && f_ahead, 2));
      cover (count_q == (FAW+1)'(FIFO_DEPTH));
      cover ($past(m_tvalid_o && !m_tready_i) && $past(m_tvalid_o && !m_tready_i, 2) && f_out_hs);
`else
      cover (state_q == PAD && push && f_o == 32'd4);
      cover (f_err_age == 16'd6);
`endif
    end
  end

