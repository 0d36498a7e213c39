// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// tb_sgm_top_files: a file-driven testbench of sgm_top for Icarus Verilog
// (make icarus; tests/icarus/icarus_frames.cpp writes the inputs and checks the
// output). Plain SystemVerilog that iverilog -g2012 accepts.
//
//   +cfg=FILE  the first line is the frame count, then one line per frame: its frame
//              configuration word (sgm_top cfg_i, rtl/sgm_cfg.svh) in hexadecimal, as
//              the testbenches pack it (tb/hardware_config.hpp); the frame size is
//              read from it.
//   +in=FILE   the input beats, one per line: tdata (hex) tuser tlast.
//   +out=FILE  written: one line per output beat, tdata (hex) tuser tlast, and
//              one line "done <error_o> <frame_width_o> <frame_height_o>" per
//              frame_done_o pulse.
//   +stall=N   the source idles and the sink is busy with probability N/256
//              per cycle (seeded, default 64); +seed=S.
//
// Each frame's configuration is presented from the acceptance of the previous
// frame's first beat on (the core latches it at the start of its frame).
// Exits with $fatal when the files are unreadable or the core stops moving.
module tb_sgm_top_files #(
  parameter int D          = 16,
  parameter int MAX_WIDTH  = 128,
  parameter int MAX_HEIGHT = 64,
  parameter int RIGHT_BLOCK = 64,  // sgm_top's fifth path, its default (0: not built; the weight field must then be 0)
  localparam int XW        = $clog2(MAX_WIDTH + 1),
  localparam int YW        = $clog2(MAX_HEIGHT + 16),
  localparam int MAX_FRAMES = 8,
  localparam int HANG_CYCLES = 100000
);
  logic          clk = 1'b0;
  logic          rst_n = 1'b0;
  logic [15:0]   s_tdata = '0;
  logic          s_tuser = 1'b0, s_tlast = 1'b0, s_tvalid = 1'b0;
  wire           s_tready;
  wire  [15:0]   m_tdata;
  wire           m_tuser, m_tlast, m_tvalid;
  logic          m_tready = 1'b0;
  logic [CFG_W-1:0] cfg_word = '0;
  wire           busy, frame_done;
  wire  [3:0]    error, error_event;
  wire  [XW-1:0] frame_width;
  wire  [YW-1:0] frame_height;
  wire           mesh_pending, rect_row_miss;

  sgm_top #(.D(D), .MAX_WIDTH(MAX_WIDTH), .MAX_HEIGHT(MAX_HEIGHT), .RIGHT_BLOCK(RIGHT_BLOCK)) dut (
    .clk_i         (clk),
    .rst_ni        (rst_n),
    .s_tdata_i     (s_tdata),
    .s_tuser_i     (s_tuser),
    .s_tlast_i     (s_tlast),
    .s_tvalid_i    (s_tvalid),
    .s_tready_o    (s_tready),
    .m_tdata_o     (m_tdata),
    .m_tuser_o     (m_tuser),
    .m_tlast_o     (m_tlast),
    .m_tvalid_o    (m_tvalid),
    .m_tready_i    (m_tready),
    .cfg_i         (cfg_word),
    .mesh_we_i     (1'b0),  // no rectification in this build
    .mesh_channel_i(1'b0),
    .mesh_row_i    (12'd0),
    .mesh_col_i    (12'd0),
    .mesh_u_i      (18'd0),
    .mesh_v_i      (18'd0),
    .mesh_swap_i   (1'b0),
    .mesh_swap_pending_o(mesh_pending),
    .rect_row_miss_o(rect_row_miss),
    .busy_o        (busy),
    .frame_done_o  (frame_done),
    .error_o       (error),
    .error_event_o (error_event),
    .frame_width_o (frame_width),
    .frame_height_o(frame_height)
  );

  always #5 clk = ~clk;

  logic [CFG_W-1:0] cfg [MAX_FRAMES];
  int frames, total_in, total_out, stall, seed;
  int in_fd, out_fd;

  // Presents frame k's configuration.
  task automatic present(input int k);
    cfg_word = cfg[k];
  endtask

  // Reads the next input beat into s_tdata/s_tuser/s_tlast.
  task automatic next_beat;
    int data, user, last;
    if ($fscanf(in_fd, "%h %d %d\n", data, user, last) != 3) $fatal(1, "tb: input file ends early");
    s_tdata = data[15:0];
    s_tuser = user[0];
    s_tlast = last[0];
  endtask

  initial begin
    string cfg_name, in_name, out_name;
    int cfg_fd, k, sent, received, presented, since_move, r;
    logic in_fire, out_fire;
    logic [CFG_W-1:0] word;
    if (!$value$plusargs("cfg=%s", cfg_name) || !$value$plusargs("in=%s", in_name) ||
        !$value$plusargs("out=%s", out_name))
      $fatal(1, "tb: usage: +cfg=FILE +in=FILE +out=FILE [+stall=N] [+seed=S]");
    if (!$value$plusargs("stall=%d", stall)) stall = 64;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    cfg_fd = $fopen(cfg_name, "r");
    in_fd = $fopen(in_name, "r");
    out_fd = $fopen(out_name, "w");
    if (cfg_fd == 0 || in_fd == 0 || out_fd == 0) $fatal(1, "tb: cannot open %s, %s or %s", cfg_name, in_name, out_name);
    if ($fscanf(cfg_fd, "%d\n", frames) != 1 || frames < 1 || frames > MAX_FRAMES)
      $fatal(1, "tb: %s: bad frame count", cfg_name);
    total_in = 0;
    for (k = 0; k < frames; k = k + 1) begin
      // (Icarus 11 scans into plain variables only, not array elements.)
      r = $fscanf(cfg_fd, "%h\n", word);
      if (r != 1) $fatal(1, "tb: %s: frame %0d: bad line", cfg_name, k);
      cfg[k] = word;
      total_in = total_in + int'(word[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W]) *
                            int'(word[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W]);
    end
    total_out = total_in;
    present(0);
    repeat (3) @(posedge clk);
    #1 rst_n = 1'b1;
    sent = 0;
    received = 0;
    presented = 0;
    since_move = 0;
    // Signals change 1 time unit after the rising edge; handshakes are sampled
    // at the falling edge and take effect at the next rising edge.
    while (received < total_out) begin
      if (!s_tvalid && sent < total_in && ({$random(seed)} % 256) >= stall) begin
        next_beat();
        s_tvalid = 1'b1;
      end
      m_tready = ({$random(seed)} % 256) >= stall;
      @(negedge clk);
      in_fire = s_tvalid && s_tready;
      out_fire = m_tvalid && m_tready;
      if (frame_done) $fdisplay(out_fd, "done %0d %0d %0d", error, frame_width, frame_height);
      if (out_fire) $fdisplay(out_fd, "%04h %0d %0d", m_tdata, m_tuser, m_tlast);
      since_move = in_fire || out_fire ? 0 : since_move + 1;
      if (since_move > HANG_CYCLES) $fatal(1, "tb: core hangs: %0d beats in, %0d out", sent, received);
      @(posedge clk);
      #1;
      if (in_fire) begin
        s_tvalid = 1'b0;
        sent = sent + 1;
        if (s_tuser && presented + 1 < frames) begin
          presented = presented + 1;
          present(presented);
        end
      end
      if (out_fire) received = received + 1;
    end
    // A few more cycles for the last frame_done_o pulse.
    repeat (64) begin
      @(negedge clk);
      if (frame_done) $fdisplay(out_fd, "done %0d %0d %0d", error, frame_width, frame_height);
      if (m_tvalid && m_tready) $fatal(1, "tb: output beat after the last frame");
      @(posedge clk);
    end
    $fclose(out_fd);
    $display("tb: %0d beats in, %0d out", sent, received);
    $finish;
  end
endmodule
