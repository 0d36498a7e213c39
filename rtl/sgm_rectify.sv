// SPDX-License-Identifier: Apache-2.0
// sgm_rectify: rectification in the stream (docs/algorithm.md, section 13), bit-exact with
// the golden sgm::rectify, for CHANNELS images side by side (2 in sgm_top: the left and the
// right image, each with its own mesh; one control for both). Each output pixel's source
// position is the bilinear blend of the four mesh nodes around it (positions in 1/32 px,
// 18-bit signed), and its gray the bilinear blend of the four source pixels around that
// position, read in one cycle from a line buffer of ROWS source rows banked by row and
// column parity (any 2x2 neighbourhood is one read of each bank). A position outside the
// source gives gray 0 and m_outside_o = 1. A frame with enable_i = 0 passes through: the
// position is the pixel's own (gray unchanged, never outside) and its lag is 1.
//
// Schedule: the input (raw gray, AXI4-Stream video: tuser = start of frame, tlast = end of
// line) writes source rows into the buffer as one stream of rows across frames: a frame's
// row 0 follows the previous frame's last row. Output row y of a frame starts when its source
// rows 0 .. y + lag are in (or the frame's input is complete), and the input waits while it
// is lag + 1 rows ahead of the row being read (counting the rows of the frame before), or
// lag + 1 rows into a frame the output has not started. So the next frame's input runs while
// the previous frame's last rows leave: no flush between frames. A lag above ROWS - 2 is
// taken as ROWS - 2. The calibration must read no row outside y + lag + 2 - ROWS .. y + lag
// (sgm::lineBufferRows <= ROWS); a read outside sets row_miss_o (sticky from the frame's
// first pixel's read to the next frame's).
//
// Frame side band: width_i, height_i, lag_i, enable_i and info_i (INFO_W bits the core's
// stages need beside the frame, sgm_top's frame configuration word) are sampled with the
// input's start of frame; info_o is the output frame's, from its first beat to the next
// frame's. The input's framing is checked against width_i and height_i: tlast before the last
// column (error_set_o[0]), no tlast at the last column ([1]), tuser inside a frame ([2]; it
// starts the next frame). A row ends at tlast or at its last column; a tlast error abandons
// the frame: its other beats, and beats after the last row, are dropped until the next tuser
// (the rows not written are stale), and the output frame is always width x height beats (a
// width or height of 0 is taken as 1). m_error_o carries the frame's errors (a tuser inside
// it among them) on its last beat, 0 on every other beat. busy_o: a frame is in or on its way
// out.
//
// The mesh: NX x NY nodes per copy and channel (the frame's ((W-1) >> GRID_LOG2) + 2 used),
// written through mesh_we_i (mesh_channel_i selects the image) into the copy the newest
// input frame does not use; mesh_swap_i makes that copy the one used from the next input
// start of frame on. mesh_swap_pending_o is high from mesh_swap_i until the output runs on
// the new copy: a new mesh is written only while it is low (written whole, then swapped).
//
// Parameters: MAX_WIDTH, MAX_HEIGHT (frame), ROWS (line buffer rows, a power of two, 4 ..
// 256), GRID_LOG2 (mesh step 2^GRID_LOG2 px, 2 .. 6), CHANNELS (images, 1 or 2), INFO_W.
// Throughput: one pixel per clock within a row; 5 cycles at each output row's start (its
// rows checked, the first three mesh columns fetched) and 2 at each output frame's.
// Latency: output row y follows input row y + lag + 1; 5 + 3 cycles from a row's start to
// its first pixel.
`default_nettype none

module sgm_rectify #(
    parameter int MAX_WIDTH  /*verilator public*/ = 1280,
    parameter int MAX_HEIGHT /*verilator public*/ = 1024,
    parameter int ROWS       /*verilator public*/ = 32,
    parameter int GRID_LOG2  /*verilator public*/ = 4,
    parameter int CHANNELS   /*verilator public*/ = 1,
    parameter int INFO_W     /*verilator public*/ = 1,
    localparam int XW = $clog2(MAX_WIDTH + 1),
    localparam int YW = $clog2(MAX_HEIGHT + 1),
    localparam int LAGW = $clog2(ROWS),
    localparam int NX = ((MAX_WIDTH - 1) >> GRID_LOG2) + 2,
    localparam int NY = ((MAX_HEIGHT - 1) >> GRID_LOG2) + 2,
    localparam int NXW = $clog2(NX),
    localparam int NYW = $clog2(NY),
    localparam int CHW = CHANNELS > 1 ? $clog2(CHANNELS) : 1,
    localparam int CW = 18  // a mesh coordinate: signed, 1/32 px
) (
    input wire logic clk_i,
    input wire logic rst_ni,

    input  wire logic [    XW-1:0] width_i,   // sampled with the input's start of frame
    input  wire logic [    YW-1:0] height_i,
    input  wire logic [       7:0] lag_i,     // row lag of the calibration (above ROWS - 2: ROWS - 2)
    input  wire logic              enable_i,  // 0: the frame passes through
    input  wire logic [INFO_W-1:0] info_i,
    output logic      [INFO_W-1:0] info_o,    // the output frame's info_i

    input  wire logic                  mesh_we_i,
    input  wire logic        [CHW-1:0] mesh_channel_i,
    input  wire logic        [NYW-1:0] mesh_row_i,
    input  wire logic        [NXW-1:0] mesh_col_i,
    input  wire logic signed [ CW-1:0] mesh_u_i,
    input  wire logic signed [ CW-1:0] mesh_v_i,
    input  wire logic                  mesh_swap_i,
    output logic                       mesh_swap_pending_o,

    input  wire logic [8*CHANNELS-1:0] s_tdata_i,  // channel c in bits 8c + 7 .. 8c
    input  wire logic                  s_tvalid_i,
    output logic                       s_tready_o,
    input  wire logic                  s_tuser_i,
    input  wire logic                  s_tlast_i,

    output logic [8*CHANNELS-1:0] m_tdata_o,
    output logic                  m_tvalid_o,
    input  wire logic             m_tready_i,
    output logic                  m_tuser_o,
    output logic                  m_tlast_o,
    output logic [  CHANNELS-1:0] m_outside_o,

    output logic [2:0] m_error_o,    // the frame's framing errors, on its last beat
    output logic [2:0] error_set_o,  // one-cycle pulse per event
    output logic       busy_o,       // a frame is in, or on its way out
    output logic       row_miss_o
);
  localparam int G = 1 << GRID_LOG2;
  localparam int FB = 5;  // fraction bits of a position
  localparam int VW = CW + GRID_LOG2 + 2;  // a column blend: (G - fy) a + fy c
  localparam int HW = VW + GRID_LOG2 + 1;  // a position before the shift
  localparam int XHW = $clog2((MAX_WIDTH + 1) / 2);  // column pair index
  localparam int RHW = LAGW - 1;  // row pair index within the buffer
  localparam int NYH = (NY + 1) / 2;  // node rows per mesh bank
  localparam int MESH_COPY = NX * NYH;  // words of one copy in a bank
  localparam int MAW = $clog2(2 * MESH_COPY);
  localparam int RW = YW + 2;  // rows counted across two frames

  // An illegal parameter stops elaboration with a message naming it (Verilator, Yosys;
  // Icarus 11 has no elaboration system tasks: its builds leave the checks out).
`ifndef __ICARUS__
  if (ROWS < 4 || ROWS > 256 || (ROWS & (ROWS - 1)) != 0) begin : g_bad_rows
    $error("sgm_rectify: ROWS = %0d: a power of two, 4 .. 256", ROWS);
  end
  if (GRID_LOG2 < 2 || GRID_LOG2 > 6) begin : g_bad_grid
    $error("sgm_rectify: GRID_LOG2 = %0d: 2 .. 6 (mesh steps of 4 .. 64 px)", GRID_LOG2);
  end
  if (MAX_WIDTH < 8 || MAX_HEIGHT < 8 || MAX_WIDTH > 4096 || MAX_HEIGHT > 4096) begin : g_bad_frame
    $error("sgm_rectify: MAX_WIDTH = %0d, MAX_HEIGHT = %0d: 8 .. 4096", MAX_WIDTH, MAX_HEIGHT);
  end
  if (CHANNELS < 1 || CHANNELS > 2) begin : g_bad_channels
    $error("sgm_rectify: CHANNELS = %0d: 1 or 2", CHANNELS);
  end
  if (INFO_W < 1) begin : g_bad_info
    $error("sgm_rectify: INFO_W = %0d: at least 1", INFO_W);
  end
`endif

  // ------------------------------------------------------------------ frames
  // The newest input frame's side band (in_*), and the output frame's (out_*). queued_q: the
  // input has started a frame the output has not (at most one).
  logic [XW-1:0] in_width_q, out_width_q;
  logic [YW-1:0] in_height_q, out_height_q;
  logic [LAGW-1:0] in_lag_q, out_lag_q;
  logic in_enable_q, out_enable_q;
  logic [INFO_W-1:0] in_info_q, out_info_q;
  logic in_sel_q, out_sel_q, swap_pending_q;
  logic [LAGW-1:0] in_base_q, out_base_q;  // the buffer slot of the frame's row 0
  logic queued_q;
  logic [RW-1:0] lead_q;  // queued: the rows of the output frame before the input frame's row 0
  logic in_active_q, out_active_q;
  logic [XW-1:0] in_x_q;
  logic [RW-1:0] in_row_q;  // the input frame's row being written; also its rows complete
  logic [RW-1:0] out_row_q;

  // Rows of the output frame the input has completed (it writes the next), and whether it is done.
  wire logic [RW-1:0] in_abs_row = queued_q ? lead_q + in_row_q : in_row_q;
  wire logic out_input_done = queued_q || !in_active_q;
  wire logic [LAGW-1:0] out_lag = out_enable_q ? out_lag_q : LAGW'(1);  // passing through: the
  wire logic [LAGW-1:0] in_lag = in_enable_q ? in_lag_q : LAGW'(1);     // identity reads y, y + 1
  logic p1_valid_q;  // stage 1 holds a pixel (its row p1_row_q: its source rows not read yet)
  logic [YW-1:0] p1_row_q;
  wire logic [RW-1:0] read_row = p1_valid_q ? RW'(p1_row_q) : out_row_q;
  // The input waits while lag + 1 rows ahead of the output row still to be read (stage 1's
  // pixel's row, or the row issued next; of the output frame's lag), while lag + 1 rows into a
  // frame the output has not started (of that frame's lag: the output frame may have been cut
  // short by a tuser inside it), and in the cycle the output is about to start a queued frame.
  // So when a frame's output starts, the input is at most ROWS - 1 rows into it: every row of
  // the frame is still in the buffer.
  wire logic in_ahead = !out_active_q ? queued_q :
      in_abs_row > read_row + RW'(out_lag) + 1'b1 || (queued_q && in_row_q > RW'(in_lag) + 1'b1);
  wire logic [LAGW-1:0] lag_sat = lag_i > 8'(ROWS - 2) ? LAGW'(ROWS - 2) : LAGW'(lag_i);
  wire logic in_sof = s_tvalid_i & s_tuser_i;
  assign s_tready_o = in_sof ? !queued_q : (!in_active_q || !in_ahead);
  wire logic in_take = s_tvalid_i & s_tready_o;
  wire logic in_first = in_take & s_tuser_i;
  wire logic in_write = in_take & (in_active_q | s_tuser_i);
  wire logic [XW-1:0] in_col = in_first ? '0 : in_x_q;
  wire logic [RW-1:0] in_row = in_first ? '0 : in_row_q;
  wire logic [XW-1:0] in_width = in_first ? (width_i == '0 ? XW'(1) : width_i) : in_width_q;
  wire logic [YW-1:0] in_height = in_first ? (height_i == '0 ? YW'(1) : height_i) : in_height_q;
  wire logic [LAGW-1:0] in_base = in_first ? in_base_q + LAGW'(in_row_q) : in_base_q;
  wire logic in_last_col = in_col == in_width - 1'b1;
  wire logic in_row_end = in_write && (s_tlast_i || in_last_col);
  wire logic in_frame_end = in_row_end && in_row + 1'b1 >= RW'(in_height);
  wire logic err_early = in_write && s_tlast_i && !in_last_col;
  wire logic err_missing = in_write && !s_tlast_i && in_last_col;
  wire logic err_inside = in_first && in_active_q;
  logic [2:0] in_err_q, prev_err_q;

  // ------------------------------------------------------------------ output row control
  localparam logic [1:0] S_IDLE = 2'd0, S_WAIT = 2'd1, S_FETCH = 2'd2, S_RUN = 2'd3;
  logic [1:0] state_q;
  logic [1:0] fetch_q;
  logic [XW-1:0] out_x_q;
  logic [NXW-1:0] col_q;  // the mesh column read this cycle
  logic fetch_req_q;  // the mesh reads col_q at this edge
  logic fetch_valid_q;  // mesh_rd_q holds the column asked for
  logic advance;  // the pixel pipeline moves: its output register is free

  wire logic [YW-1:0] out_y = out_row_q[YW-1:0];
  wire logic [NYW-1:0] node_row = NYW'(out_y >> GRID_LOG2);
  wire logic [GRID_LOG2:0] fy = {1'b0, out_y[GRID_LOG2-1:0]};
  wire logic [NYW-1:0] node_row_below = node_row + 1'b1;
  wire logic rows_ready = in_abs_row > out_row_q + RW'(out_lag) || out_input_done;
  wire logic [GRID_LOG2-1:0] fx = out_x_q[GRID_LOG2-1:0];
  wire logic issue = state_q == S_RUN && advance;
  wire logic row_end = out_x_q == out_width_q - 1'b1;
  wire logic column_end = fx == GRID_LOG2'(G - 1) && !row_end;
  wire logic [NXW-1:0] column_after = NXW'(out_x_q >> GRID_LOG2) + NXW'(3);
  // The next frame starts when the last pixel of the one before has left stage 1 (stage 2
  // reads the output frame's registers).
  wire logic out_start = state_q == S_IDLE && queued_q && !p1_valid_q;
  // The copy of the newest input frame: mesh writes go to the other. A swap takes effect at
  // the next input start of frame (this cycle's, if any).
  wire logic swap_now = in_first && (swap_pending_q || mesh_swap_i);
  wire logic in_sel_d = swap_now ? ~in_sel_q : in_sel_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= S_IDLE;
      in_active_q <= 1'b0;
      out_active_q <= 1'b0;
      queued_q <= 1'b0;
      lead_q <= '0;
      in_sel_q <= 1'b0;
      out_sel_q <= 1'b0;
      swap_pending_q <= 1'b0;
      in_base_q <= '0;
      out_base_q <= '0;
      in_x_q <= '0;
      in_row_q <= '0;
      out_row_q <= '0;
      out_x_q <= '0;
      fetch_q <= '0;
      col_q <= '0;
      fetch_req_q <= 1'b0;
      fetch_valid_q <= 1'b0;
      in_width_q <= '0;
      in_height_q <= '0;
      in_lag_q <= '0;
      in_enable_q <= 1'b0;
      out_width_q <= '0;
      out_height_q <= '0;
      out_lag_q <= '0;
      out_enable_q <= 1'b0;
      in_err_q <= '0;
      prev_err_q <= '0;
      error_set_o <= '0;
    end else begin
      if (mesh_swap_i) swap_pending_q <= 1'b1;
      error_set_o <= {err_inside, err_missing, err_early};
      // The errors of the newest input frame, and of the one before (cut by a tuser or not).
      if (in_first) begin
        prev_err_q <= in_err_q | {err_inside, 2'b00};
        in_err_q <= {1'b0, err_missing, err_early};
      end else begin
        in_err_q <= in_err_q | {1'b0, err_missing, err_early};
      end
      // Input: the frame's side band, columns and rows written.
      if (in_first) begin
        in_width_q <= width_i == '0 ? XW'(1) : width_i;  // a frame of no columns or rows: one
        in_height_q <= height_i == '0 ? YW'(1) : height_i;
        in_lag_q <= lag_sat;
        in_enable_q <= enable_i;
        in_base_q <= in_base;
        in_active_q <= 1'b1;
        queued_q <= 1'b1;
        // The rows of the output frame before this one's row 0: those the input wrote of it.
        lead_q <= out_active_q ? in_row_q : '0;
        in_sel_q <= in_sel_d;
        if (swap_now) swap_pending_q <= 1'b0;
      end
      if (in_write) begin
        if (in_row_end) begin
          in_x_q <= '0;
          in_row_q <= in_row + 1'b1;
          // The frame ends after its last row, or is abandoned at a framing error (its other
          // beats dropped until the next tuser, as sgm_stream_ctrl does).
          if (in_frame_end || err_early || err_missing) in_active_q <= 1'b0;
        end else begin
          in_x_q <= in_col + 1'b1;
          in_row_q <= in_row;
        end
      end
      // Output rows: start the queued frame, wait for the source rows, fetch the first three
      // mesh columns, run.
      fetch_valid_q <= fetch_req_q;
      fetch_req_q <= 1'b0;
      case (state_q)
        S_IDLE:
        if (out_start) begin
          out_width_q <= in_width_q;
          out_height_q <= in_height_q;
          out_lag_q <= in_lag_q;
          out_enable_q <= in_enable_q;
          out_sel_q <= in_sel_q;
          out_base_q <= in_base_q;
          out_row_q <= '0;
          out_active_q <= 1'b1;
          queued_q <= 1'b0;
          state_q <= S_WAIT;
        end
        S_WAIT:
        if (rows_ready) begin
          state_q <= S_FETCH;
          fetch_q <= 2'd0;
          col_q <= '0;
          fetch_req_q <= 1'b1;
          out_x_q <= '0;
        end
        S_FETCH: begin
          fetch_q <= fetch_q + 1'b1;
          col_q <= (col_q == NXW'(NX - 1)) ? col_q : col_q + 1'b1;
          fetch_req_q <= fetch_q < 2'd2;
          if (fetch_q == 2'd3) state_q <= S_RUN;
        end
        S_RUN:
        if (issue) begin
          if (row_end) begin
            out_x_q <= '0;
            out_row_q <= out_row_q + 1'b1;
            if (out_row_q + 1'b1 >= RW'(out_height_q)) begin
              out_active_q <= 1'b0;
              state_q <= S_IDLE;
            end else begin
              state_q <= S_WAIT;
            end
          end else begin
            out_x_q <= out_x_q + 1'b1;
          end
          if (column_end) begin
            col_q <= (column_after >= NXW'(NX)) ? NXW'(NX - 1) : column_after;
            fetch_req_q <= 1'b1;
          end
        end
        default: ;
      endcase
    end
  end
  assign mesh_swap_pending_o = swap_pending_q || in_sel_q != out_sel_q;
  assign busy_o = in_active_q || queued_q || out_active_q || p1_valid_q || p2_valid_q || m_tvalid_o;

  // ------------------------------------------------------------------ shared pixel pipeline
  // Stage 1 weights (column fraction), the frame's last column and row for stage 2.
  wire logic signed [GRID_LOG2+1:0] w_above = $signed({1'b0, (GRID_LOG2 + 1)'(G) - fy});
  wire logic signed [GRID_LOG2+1:0] w_below = $signed({1'b0, fy});
  wire logic signed [GRID_LOG2+1:0] w_left = $signed({1'b0, (GRID_LOG2 + 1)'(G) - {1'b0, fx}});
  wire logic signed [GRID_LOG2+1:0] w_right = $signed({1'b0, 1'b0, fx});
  logic [2:0] p1_err_q, p2_err_q;
  logic p2_valid_q, p1_user_q, p1_last_q, p2_user_q, p2_last_q;
  assign advance = !m_tvalid_o || m_tready_i;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      p1_valid_q <= 1'b0;
      p2_valid_q <= 1'b0;
      m_tvalid_o <= 1'b0;
    end else if (advance) begin
      p1_valid_q <= issue;
      p2_valid_q <= p1_valid_q;
      m_tvalid_o <= p2_valid_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (advance) begin
      p1_user_q <= out_x_q == '0 && out_row_q == '0;
      p1_last_q <= row_end;
      // The frame's errors with its last pixel: its input is done (or cut) by then.
      p1_err_q <= issue && row_end && out_row_q + 1'b1 >= RW'(out_height_q) ? (queued_q ? prev_err_q : in_err_q) : 3'd0;
      p2_err_q <= p1_err_q;
      m_error_o <= p2_err_q;
      p1_row_q <= out_y;
      p2_user_q <= p1_user_q;
      p2_last_q <= p1_last_q;
      m_tuser_o <= p2_user_q;
      m_tlast_o <= p2_last_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (in_first) in_info_q <= info_i;
    if (out_start) out_info_q <= in_info_q;
    if (advance && p2_valid_q && p2_user_q) info_o <= out_info_q;  // with the frame's first beat
  end
  // Rows the buffer holds while stage 2 reads (rows of the output frame): from in_abs_row - ROWS
  // (in_abs_row + 1 - ROWS once the input has written a beat of row in_abs_row) to in_abs_row -
  // 1 (complete), or to the frame's end when its input is done.
  wire logic [CHANNELS-1:0] row_miss_ch;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) row_miss_o <= 1'b0;
    else if (p1_valid_q && p1_user_q && advance) row_miss_o <= |row_miss_ch;  // a frame's first pixel
    else if (|row_miss_ch) row_miss_o <= 1'b1;
  end
  // Line buffer slots of the input's write: four banks by (slot parity, column parity), each
  // {column pair, slot pair} (column-major: no multiplier before the address).
  wire logic [LAGW-1:0] in_slot = in_base + LAGW'(in_row);
  wire logic [XHW+RHW-1:0] in_addr = {XHW'(in_col >> 1), in_slot[LAGW-1:1]};
  wire logic [1:0] in_bank = {in_slot[0], in_col[0]};

  // ------------------------------------------------------------------ channels
  for (genvar c = 0; c < CHANNELS; c++) begin : g_channel
    // Line buffer.
    logic [XHW+RHW-1:0] read_addr[4];  // stage 2 below
    logic [7:0] p2_pixel_q[4];
    // A bank's word of column pair j and slot pair k is j 2^RHW + k ({j, k}): column-major, so
    // the bank holds exactly the (MAX_WIDTH + 1) / 2 column pairs it uses (1280 columns: 10,240
    // words, 5 block RAMs of 2048 x 9; a depth of 2^(XHW + RHW) would round 640 pairs up to
    // 1024: 8 block RAMs). A read outside the source may address beyond it: its gray is not
    // used (p2_inside_q).
    localparam int LINE_WORDS = ((MAX_WIDTH + 1) / 2) << RHW;
    for (genvar b = 0; b < 4; b++) begin : g_line_bank
      logic [7:0] line_mem[0:LINE_WORDS - 1];
      always_ff @(posedge clk_i) begin
        if (in_write && in_bank == 2'(b)) line_mem[in_addr] <= s_tdata_i[8*c+:8];
      end
      always_ff @(posedge clk_i) begin
        if (advance) p2_pixel_q[b] <= line_mem[read_addr[b]];
      end
    end

    // Mesh memory: two banks by node-row parity, {u, v} a word. A node's word in its bank:
    // copy x NX x NYH + (row >> 1) x NX + column, exactly the words used (the mesh is the
    // largest memory at small steps; the products are by constants).
    logic [2*CW-1:0] mesh_rd_q[2];
    logic [MAW-1:0] mesh_read_addr[2];
    function automatic logic [MAW-1:0] mesh_word(input logic copy, input logic [NYW-1:0] row,
                                                 input logic [NXW-1:0] col);
      mesh_word = (copy ? MAW'(MESH_COPY) : MAW'(0)) + (MAW'(row) >> 1) * MAW'(NX) + MAW'(col);
    endfunction
    wire logic mesh_write = mesh_we_i && (CHANNELS == 1 || mesh_channel_i == CHW'(c));
    for (genvar b = 0; b < 2; b++) begin : g_mesh_bank
      logic [2*CW-1:0] mesh_mem[0:2*MESH_COPY-1];
      always_ff @(posedge clk_i) begin
        if (mesh_write && mesh_row_i[0] == 1'(b))
          mesh_mem[mesh_word(~in_sel_q, mesh_row_i, mesh_col_i)] <= {mesh_u_i, mesh_v_i};
      end
      always_ff @(posedge clk_i) mesh_rd_q[b] <= mesh_mem[mesh_read_addr[b]];
    end

    // Node rows i and i + 1 of column col_q (one per bank), and their blend with fy.
    assign mesh_read_addr[0] = mesh_word(out_sel_q, node_row[0] ? node_row_below : node_row, col_q);
    assign mesh_read_addr[1] = mesh_word(out_sel_q, node_row[0] ? node_row : node_row_below, col_q);
    wire logic [2*CW-1:0] node_above = node_row[0] ? mesh_rd_q[1] : mesh_rd_q[0];
    wire logic [2*CW-1:0] node_below = node_row[0] ? mesh_rd_q[0] : mesh_rd_q[1];
    wire logic signed [VW-1:0] blend_u = VW'($signed(node_above[2*CW-1:CW])) * VW'(w_above) +
        VW'($signed(node_below[2*CW-1:CW])) * VW'(w_below);
    wire logic signed [VW-1:0] blend_v = VW'($signed(node_above[CW-1:0])) * VW'(w_above) +
        VW'($signed(node_below[CW-1:0])) * VW'(w_below);

    // The column blends: left (column j), right (j + 1), next (j + 2) of the current span.
    logic signed [VW-1:0] left_u_q, left_v_q, right_u_q, right_v_q, next_u_q, next_v_q;
    always_ff @(posedge clk_i) begin
      if (state_q == S_FETCH && fetch_valid_q) begin
        // fetch_q = 1, 2, 3: columns 0, 1, 2 arrive.
        if (fetch_q == 2'd1) {left_u_q, left_v_q} <= {blend_u, blend_v};
        if (fetch_q == 2'd2) {right_u_q, right_v_q} <= {blend_u, blend_v};
        if (fetch_q == 2'd3) {next_u_q, next_v_q} <= {blend_u, blend_v};
      end else if (state_q == S_RUN && fetch_valid_q) begin
        {next_u_q, next_v_q} <= {blend_u, blend_v};
      end
      if (issue && column_end) begin
        {left_u_q, left_v_q} <= {right_u_q, right_v_q};
        {right_u_q, right_v_q} <= {next_u_q, next_v_q};
      end
    end

    // Stage 1: the source position, ((G - fx) left + fx right + G^2 / 2) >> 2 GRID_LOG2, or
    // the pixel's own when the frame passes through.
    wire logic signed [HW-1:0] sum_u = HW'(left_u_q) * HW'(w_left) + HW'(right_u_q) * HW'(w_right) +
        HW'(1 << (2 * GRID_LOG2 - 1));
    wire logic signed [HW-1:0] sum_v = HW'(left_v_q) * HW'(w_left) + HW'(right_v_q) * HW'(w_right) +
        HW'(1 << (2 * GRID_LOG2 - 1));
    logic signed [CW-1:0] p1_u_q, p1_v_q;
    always_ff @(posedge clk_i) begin
      if (advance) begin
        p1_u_q <= out_enable_q ? CW'(sum_u >>> (2 * GRID_LOG2)) : CW'({out_x_q, 5'd0});
        p1_v_q <= out_enable_q ? CW'(sum_v >>> (2 * GRID_LOG2)) : CW'({out_y, 5'd0});
      end
    end

    // Stage 2: inside or not, the 2x2 neighbourhood read from the four banks.
    wire logic signed [CW:0] u_last = $signed({1'b0, (CW'(out_width_q) - CW'(1)) << FB});
    wire logic signed [CW:0] v_last = $signed({1'b0, (CW'(out_height_q) - CW'(1)) << FB});
    wire logic in_source = !p1_u_q[CW-1] && !p1_v_q[CW-1] && $signed({p1_u_q[CW-1], p1_u_q}) <= u_last &&
        $signed({p1_v_q[CW-1], p1_v_q}) <= v_last;
    wire logic [CW-FB-1:0] x0 = p1_u_q[CW-1:FB];
    wire logic [CW-FB-1:0] y0 = p1_v_q[CW-1:FB];
    wire logic [CW-FB-1:0] x1 = (x0 == (CW - FB)'(out_width_q) - (CW - FB)'(1)) ? x0 : x0 + 1'b1;
    wire logic [CW-FB-1:0] y1 = (y0 == (CW - FB)'(out_height_q) - (CW - FB)'(1)) ? y0 : y0 + 1'b1;
    // The rows' buffer slots; bank (slot parity, column parity): its column is x0 or x1, its
    // slot that of y0 or y1.
    wire logic [LAGW-1:0] slot0 = out_base_q + LAGW'(y0);
    wire logic [LAGW-1:0] slot1 = out_base_q + LAGW'(y1);
    for (genvar b = 0; b < 4; b++) begin : g_read_addr
      wire logic [XHW-1:0] col_pair = (x0[0] == 1'(b & 1)) ? x0[XHW:1] : x1[XHW:1];
      wire logic [LAGW-2:0] slot_pair = (slot0[0] == 1'(b >> 1)) ? slot0[LAGW-1:1] : slot1[LAGW-1:1];
      assign read_addr[b] = {col_pair, slot_pair};
    end
    logic [FB-1:0] p2_ax_q, p2_ay_q;
    logic p2_x_odd_q, p2_y_odd_q, p2_inside_q;
    always_ff @(posedge clk_i) begin
      if (advance) begin
        p2_ax_q <= p1_u_q[FB-1:0];
        p2_ay_q <= p1_v_q[FB-1:0];
        p2_x_odd_q <= x0[0];
        p2_y_odd_q <= slot0[0];
        p2_inside_q <= in_source;
      end
    end
    wire logic [RW-1:0] y0_row = RW'(y0);
    wire logic [RW-1:0] y1_row = RW'(y1);
    assign row_miss_ch[c] = p1_valid_q && in_source && advance &&
        (y0_row + RW'(ROWS) < in_abs_row || (y0_row + RW'(ROWS) == in_abs_row && in_x_q != '0) ||
         (y1_row >= in_abs_row && !out_input_done));

    // Stage 3: the gray, ((32 - ax)(32 - ay) p00 + ax (32 - ay) p10 + (32 - ax) ay p01 + ax ay p11 + 512) >> 10.
    wire logic [7:0] p00 = p2_pixel_q[{p2_y_odd_q, p2_x_odd_q}];
    wire logic [7:0] p10 = p2_pixel_q[{p2_y_odd_q, ~p2_x_odd_q}];
    wire logic [7:0] p01 = p2_pixel_q[{~p2_y_odd_q, p2_x_odd_q}];
    wire logic [7:0] p11 = p2_pixel_q[{~p2_y_odd_q, ~p2_x_odd_q}];
    wire logic [FB:0] ax_left = (FB + 1)'(32) - {1'b0, p2_ax_q};
    wire logic [FB:0] ay_top = (FB + 1)'(32) - {1'b0, p2_ay_q};
    wire logic [17:0] gray_sum = 18'(ax_left) * 18'(ay_top) * 18'(p00) + 18'(p2_ax_q) * 18'(ay_top) * 18'(p10) +
        18'(ax_left) * 18'(p2_ay_q) * 18'(p01) + 18'(p2_ax_q) * 18'(p2_ay_q) * 18'(p11) + 18'd512;
    wire logic [7:0] gray = 8'(gray_sum >> 10);
    always_ff @(posedge clk_i) begin
      if (advance) begin
        m_tdata_o[8*c+:8] <= p2_inside_q ? gray : 8'd0;
        m_outside_o[c] <= !p2_inside_q;
      end
    end
  end

endmodule

`default_nettype wire
