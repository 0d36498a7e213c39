// SPDX-License-Identifier: Apache-2.0
// sgm_rectify: rectification in the stream (docs/algorithm.md, section 13), bit-exact with
// the golden sgm::rectify. Each output pixel's source position is the bilinear blend of the
// four mesh nodes around it (positions in 1/32 px, 18-bit signed), and its gray the bilinear
// blend of the four source pixels around that position, read in one cycle from a line
// buffer of ROWS source rows banked by row and column parity (any 2x2 neighbourhood is one
// read of each bank). A position outside the source gives gray 0 and m_outside_o = 1.
//
// Schedule: the input (raw gray, AXI4-Stream video: tuser = start of frame, tlast = end of
// line) writes source row r while output row y = r - lag_i - 1 is read; output row y starts
// when source rows 0 .. y + lag_i are in (or the frame is), and the input waits while it is
// lag_i + 1 rows ahead. The calibration must read no row outside y + lag_i + 2 - ROWS ..
// y + lag_i (sgm-eval calib-mesh: rows + 1 <= ROWS); a read outside sets row_miss_o (sticky
// until the next start of frame). After the input frame the remaining lag_i rows are
// flushed; the next frame's first pixel waits for that.
//
// The mesh: NX x NY nodes per copy (the frame's ((W-1) >> GRID_LOG2) + 2 used), written
// through mesh_we_i into the copy not in use (after this cycle's start of frame, if any);
// mesh_swap_i makes that copy the one in use from the next start of frame (or this cycle's),
// mesh_swap_pending_o until then. Writes between mesh_swap_i and that start of frame go to
// the copy about to be used: a new mesh is written whole, then swapped.
//
// Parameters: MAX_WIDTH, MAX_HEIGHT (frame), ROWS (line buffer rows, a power of two, 4 ..
// 256), GRID_LOG2 (mesh step 2^GRID_LOG2 px, 2 .. 6).
// Throughput: one pixel per clock within a row; 4 cycles at each output row's start (the
// first mesh columns), lag_i rows of flush per frame. Latency: output row y follows input
// row y + lag_i + 1, 4 + 3 cycles from a row's start to its first pixel.
`default_nettype none

module sgm_rectify #(
    parameter int MAX_WIDTH  /*verilator public*/ = 1280,
    parameter int MAX_HEIGHT /*verilator public*/ = 1024,
    parameter int ROWS       /*verilator public*/ = 32,
    parameter int GRID_LOG2  /*verilator public*/ = 4,
    localparam int XW = $clog2(MAX_WIDTH + 1),
    localparam int YW = $clog2(MAX_HEIGHT + 1),
    localparam int LAGW = $clog2(ROWS),
    localparam int NX = ((MAX_WIDTH - 1) >> GRID_LOG2) + 2,
    localparam int NY = ((MAX_HEIGHT - 1) >> GRID_LOG2) + 2,
    localparam int NXW = $clog2(NX),
    localparam int NYW = $clog2(NY),
    localparam int CW = 18  // a mesh coordinate: signed, 1/32 px
) (
    input wire logic clk_i,
    input wire logic rst_ni,

    input wire logic [  XW-1:0] width_i,   // sampled at the start of frame
    input wire logic [  YW-1:0] height_i,
    input wire logic [LAGW-1:0] lag_i,     // row lag of the calibration, 0 .. ROWS - 2

    input  wire logic                  mesh_we_i,
    input  wire logic        [NYW-1:0] mesh_row_i,
    input  wire logic        [NXW-1:0] mesh_col_i,
    input  wire logic signed [ CW-1:0] mesh_u_i,
    input  wire logic signed [ CW-1:0] mesh_v_i,
    input  wire logic                  mesh_swap_i,
    output logic                       mesh_swap_pending_o,

    input  wire logic [7:0] s_tdata_i,
    input  wire logic       s_tvalid_i,
    output logic            s_tready_o,
    input  wire logic       s_tuser_i,
    input  wire logic       s_tlast_i,

    output logic [7:0] m_tdata_o,
    output logic       m_tvalid_o,
    input  wire logic  m_tready_i,
    output logic       m_tuser_o,
    output logic       m_tlast_o,
    output logic       m_outside_o,

    output logic row_miss_o
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
`endif

  // ------------------------------------------------------------------ frame and counters
  logic [XW-1:0] width_q;
  logic [YW-1:0] height_q;
  logic [LAGW-1:0] lag_q;
  logic in_active_q, out_active_q, sel_q, swap_pending_q;
  logic [XW-1:0] in_x_q;
  logic [YW:0] in_row_q;  // the source row being written; also the rows complete
  logic [YW:0] out_row_q;

  wire logic in_sof = s_tvalid_i & s_tuser_i;
  // The input waits at a start of frame until the previous frame is out, and within a frame
  // while it is lag + 1 rows ahead of the output row.
  wire logic in_ahead = in_row_q > out_row_q + (YW + 1)'(lag_q) + 1'b1;
  assign s_tready_o = in_sof ? !out_active_q : (!in_active_q || !in_ahead);
  wire logic in_take = s_tvalid_i & s_tready_o;
  wire logic in_first = in_take & s_tuser_i;
  wire logic in_write = in_take & (in_active_q | s_tuser_i);
  wire logic [XW-1:0] in_col = in_first ? '0 : in_x_q;
  wire logic [YW:0] in_row = in_first ? '0 : in_row_q;

  // ------------------------------------------------------------------ line buffer
  // Four banks by (row parity, column parity), each {column pair, row pair} (column-major:
  // no multiplier before the address).
  wire logic [LAGW-1:0] in_slot = in_row[LAGW-1:0];
  wire logic [XHW+RHW-1:0] in_addr = {XHW'(in_col >> 1), in_slot[LAGW-1:1]};
  wire logic [1:0] in_bank = {in_slot[0], in_col[0]};
  logic [XHW+RHW-1:0] read_addr[4];  // stage 2 below
  logic [7:0] p2_pixel_q[4];
  logic advance;
  for (genvar b = 0; b < 4; b++) begin : g_line_bank
    logic [7:0] line_mem[0:(1 << (XHW + RHW)) - 1];
    always_ff @(posedge clk_i) begin
      if (in_write && in_bank == 2'(b)) line_mem[in_addr] <= s_tdata_i;
    end
    always_ff @(posedge clk_i) begin
      if (advance) p2_pixel_q[b] <= line_mem[read_addr[b]];
    end
  end

  // ------------------------------------------------------------------ mesh memory
  // Two banks by node-row parity, {u, v} a word. A node's word in its bank: copy x NX x NYH
  // + (row >> 1) x NX + column, exactly the words used (the mesh is the largest memory at
  // small steps; the products are by constants).
  logic [2*CW-1:0] mesh_rd_q[2];
  logic [MAW-1:0] mesh_read_addr[2];
  function automatic logic [MAW-1:0] mesh_word(input logic copy, input logic [NYW-1:0] row,
                                               input logic [NXW-1:0] col);
    mesh_word = (copy ? MAW'(MESH_COPY) : MAW'(0)) + (MAW'(row) >> 1) * MAW'(NX) + MAW'(col);
  endfunction
  // The copy in use after this cycle (a swap takes effect at a start of frame): writes go to the other.
  wire logic swap_now = in_first && (swap_pending_q || mesh_swap_i);
  wire logic sel_d = swap_now ? ~sel_q : sel_q;
  for (genvar b = 0; b < 2; b++) begin : g_mesh_bank
    logic [2*CW-1:0] mesh_mem[0:2*MESH_COPY-1];
    always_ff @(posedge clk_i) begin
      if (mesh_we_i && mesh_row_i[0] == 1'(b))
        mesh_mem[mesh_word(~sel_d, mesh_row_i, mesh_col_i)] <= {mesh_u_i, mesh_v_i};
    end
    always_ff @(posedge clk_i) mesh_rd_q[b] <= mesh_mem[mesh_read_addr[b]];
  end

  // ------------------------------------------------------------------ output rows
  localparam logic [1:0] S_IDLE = 2'd0, S_WAIT = 2'd1, S_FETCH = 2'd2, S_RUN = 2'd3;
  logic [1:0] state_q;
  logic [1:0] fetch_q;
  logic [XW-1:0] out_x_q;
  logic [NXW-1:0] col_q;  // the mesh column read this cycle
  logic fetch_req_q;  // the mesh reads col_q at this edge
  logic fetch_valid_q;  // mesh_rd_q holds the column asked for
  logic signed [VW-1:0] left_u_q, left_v_q, right_u_q, right_v_q, next_u_q, next_v_q;

  wire logic [YW-1:0] out_y = out_row_q[YW-1:0];
  wire logic [NYW-1:0] node_row = NYW'(out_y >> GRID_LOG2);
  wire logic [GRID_LOG2:0] fy = {1'b0, out_y[GRID_LOG2-1:0]};
  wire logic [NYW-1:0] node_row_below = node_row + 1'b1;
  wire logic rows_ready = in_row_q > out_row_q + (YW + 1)'(lag_q) || in_row_q >= (YW + 1)'(height_q);

  // Node rows i and i + 1 of column col_q (one per bank), and their blend with fy.
  assign mesh_read_addr[0] = mesh_word(sel_q, node_row[0] ? node_row_below : node_row, col_q);
  assign mesh_read_addr[1] = mesh_word(sel_q, node_row[0] ? node_row : node_row_below, col_q);
  wire logic [2*CW-1:0] node_above = node_row[0] ? mesh_rd_q[1] : mesh_rd_q[0];
  wire logic [2*CW-1:0] node_below = node_row[0] ? mesh_rd_q[0] : mesh_rd_q[1];
  wire logic signed [GRID_LOG2+1:0] w_above = $signed({1'b0, (GRID_LOG2 + 1)'(G) - fy});
  wire logic signed [GRID_LOG2+1:0] w_below = $signed({1'b0, fy});
  wire logic signed [VW-1:0] blend_u = VW'($signed(node_above[2*CW-1:CW])) * VW'(w_above) +
      VW'($signed(node_below[2*CW-1:CW])) * VW'(w_below);
  wire logic signed [VW-1:0] blend_v = VW'($signed(node_above[CW-1:0])) * VW'(w_above) +
      VW'($signed(node_below[CW-1:0])) * VW'(w_below);

  // The pixel pipeline advances when its output register is free.
  logic p1_valid_q, p2_valid_q;
  assign advance = !m_tvalid_o || m_tready_i;
  wire logic [GRID_LOG2-1:0] fx = out_x_q[GRID_LOG2-1:0];
  wire logic issue = state_q == S_RUN && advance;
  wire logic row_end = out_x_q == width_q - 1'b1;
  wire logic column_end = fx == GRID_LOG2'(G - 1) && !row_end;
  wire logic [NXW-1:0] column_after = NXW'(out_x_q >> GRID_LOG2) + NXW'(3);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= S_IDLE;
      in_active_q <= 1'b0;
      out_active_q <= 1'b0;
      sel_q <= 1'b0;
      swap_pending_q <= 1'b0;
      in_x_q <= '0;
      in_row_q <= '0;
      out_row_q <= '0;
      out_x_q <= '0;
      fetch_q <= '0;
      col_q <= '0;
      fetch_req_q <= 1'b0;
      fetch_valid_q <= 1'b0;
      width_q <= '0;
      height_q <= '0;
      lag_q <= '0;
    end else begin
      if (mesh_swap_i) swap_pending_q <= 1'b1;
      // Input: columns and rows written.
      if (in_first) begin
        width_q <= width_i;
        height_q <= height_i;
        lag_q <= lag_i;
        in_active_q <= 1'b1;
        out_active_q <= 1'b1;
        out_row_q <= '0;
        state_q <= S_WAIT;
        if (swap_now) begin
          sel_q <= sel_d;
          swap_pending_q <= 1'b0;
        end
      end
      if (in_write) begin
        if (s_tlast_i) begin
          in_x_q <= '0;
          in_row_q <= in_row + 1'b1;
          if (in_row + 1'b1 >= (in_first ? (YW + 1)'(height_i) : (YW + 1)'(height_q))) in_active_q <= 1'b0;
        end else begin
          in_x_q <= in_col + 1'b1;
          in_row_q <= in_row;
        end
      end
      // Output rows: wait for the source rows, fetch the first three mesh columns, run.
      fetch_valid_q <= fetch_req_q;
      fetch_req_q <= 1'b0;
      case (state_q)
        S_WAIT:
        if (!in_first && rows_ready) begin
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
            if (out_row_q + 1'b1 >= (YW + 1)'(height_q)) begin
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
      if (in_first) state_q <= S_WAIT;
    end
  end

  // The column blends: left (column j), right (j + 1), next (j + 2) of the current span.
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

  // Stage 1: the source position, ((G - fx) left + fx right + G^2 / 2) >> 2 GRID_LOG2.
  wire logic signed [GRID_LOG2+1:0] w_left = $signed({1'b0, (GRID_LOG2 + 1)'(G) - {1'b0, fx}});
  wire logic signed [GRID_LOG2+1:0] w_right = $signed({1'b0, 1'b0, fx});
  wire logic signed [HW-1:0] sum_u = HW'(left_u_q) * HW'(w_left) + HW'(right_u_q) * HW'(w_right) +
      HW'(1 << (2 * GRID_LOG2 - 1));
  wire logic signed [HW-1:0] sum_v = HW'(left_v_q) * HW'(w_left) + HW'(right_v_q) * HW'(w_right) +
      HW'(1 << (2 * GRID_LOG2 - 1));
  logic signed [CW-1:0] p1_u_q, p1_v_q;
  logic p1_user_q, p1_last_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      p1_valid_q <= 1'b0;
    end else if (advance) begin
      p1_valid_q <= issue;
    end
  end
  always_ff @(posedge clk_i) begin
    if (advance) begin
      p1_u_q <= CW'(sum_u >>> (2 * GRID_LOG2));
      p1_v_q <= CW'(sum_v >>> (2 * GRID_LOG2));
      p1_user_q <= out_x_q == '0 && out_row_q == '0;
      p1_last_q <= row_end;
    end
  end

  // Stage 2: inside or not, the 2x2 neighbourhood read from the four banks.
  wire logic signed [CW:0] u_last = $signed({1'b0, (CW'(width_q) - CW'(1)) << FB});
  wire logic signed [CW:0] v_last = $signed({1'b0, (CW'(height_q) - CW'(1)) << FB});
  wire logic in_source = !p1_u_q[CW-1] && !p1_v_q[CW-1] && $signed({p1_u_q[CW-1], p1_u_q}) <= u_last &&
      $signed({p1_v_q[CW-1], p1_v_q}) <= v_last;
  wire logic [CW-FB-1:0] x0 = p1_u_q[CW-1:FB];
  wire logic [CW-FB-1:0] y0 = p1_v_q[CW-1:FB];
  wire logic [CW-FB-1:0] x1 = (x0 == (CW - FB)'(width_q) - (CW - FB)'(1)) ? x0 : x0 + 1'b1;
  wire logic [CW-FB-1:0] y1 = (y0 == (CW - FB)'(height_q) - (CW - FB)'(1)) ? y0 : y0 + 1'b1;
  // Bank (row parity, column parity): its column is x0 or x1, its row y0 or y1.
  for (genvar b = 0; b < 4; b++) begin : g_read_addr
    wire logic [XHW-1:0] col_pair = (x0[0] == 1'(b & 1)) ? x0[XHW:1] : x1[XHW:1];
    wire logic [LAGW-2:0] row_pair = (y0[0] == 1'(b >> 1)) ? y0[LAGW-1:1] : y1[LAGW-1:1];
    assign read_addr[b] = {col_pair, row_pair};
  end
  logic [FB-1:0] p2_ax_q, p2_ay_q;
  logic p2_x_odd_q, p2_y_odd_q, p2_inside_q, p2_user_q, p2_last_q;
  always_ff @(posedge clk_i) begin
    if (advance) begin
      p2_ax_q <= p1_u_q[FB-1:0];
      p2_ay_q <= p1_v_q[FB-1:0];
      p2_x_odd_q <= x0[0];
      p2_y_odd_q <= y0[0];
      p2_inside_q <= in_source;
      p2_user_q <= p1_user_q;
      p2_last_q <= p1_last_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni) p2_valid_q <= 1'b0;
    else if (advance) p2_valid_q <= p1_valid_q;
  end

  // Rows the buffer holds while the pixel is read: the rows complete (in_row_q .. ) and not
  // yet overwritten (from in_row_q + 1 - ROWS on).
  wire logic [YW:0] y0_row = (YW + 1)'(y0);
  wire logic [YW:0] y1_row = (YW + 1)'(y1);
  wire logic miss = p1_valid_q && in_source && advance &&
      (y0_row + (YW + 1)'(ROWS) <= in_row_q || (y1_row >= in_row_q && in_row_q < (YW + 1)'(height_q)));
  always_ff @(posedge clk_i) begin
    if (!rst_ni || in_first) row_miss_o <= 1'b0;
    else if (miss) row_miss_o <= 1'b1;
  end

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
    if (!rst_ni) begin
      m_tvalid_o <= 1'b0;
    end else if (advance) begin
      m_tvalid_o <= p2_valid_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (advance) begin
      m_tdata_o <= p2_inside_q ? gray : 8'd0;
      m_outside_o <= !p2_inside_q;
      m_tuser_o <= p2_user_q;
      m_tlast_o <= p2_last_q;
    end
  end
  assign mesh_swap_pending_o = swap_pending_q;

endmodule

`default_nettype wire
