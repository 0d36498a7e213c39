// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_rectify_join: where the rectification in front of the core (sgm_rectify, sgm_top
// RECTIFY = 1) meets the core's output side. The left pixel's outside flag comes beside its
// beat out of the stream controller with the beat's slot (side_i); it waits in a FIFO of one
// bit per frame slot (row_i < height_i: the flush slots have none), in raster order, until
// the pixel's output word leaves the pipeline (res_valid_i, in raster order too), which it
// turns into 0 (disparity 0, invalid; depth 0): docs/algorithm.md section 13. The framing
// errors of the raw input, which sgm_rectify checks (its output frames are always whole),
// come on the rectified frame's last beat (frame_error_i when the stream controller takes it):
// unless the controller is dropping that frame (not busy: its configuration is out of range,
// ERROR.CONFIG alone), they are the frame's events (error_set_o) and join the controller's
// error_o until it starts or drops its next frame, so that error_o at frame_done_o is the
// frame's. busy_o: the controller's or the rectification's frame in flight.
//
// Parameters: DEPTH_LOG2, the FIFO's entries (2^DEPTH_LOG2: at least the frame slots in
// flight, the slots of a frame's flush; sgm_top sizes it by its rows of row positions
// beyond a frame), YW the row width, WORD_W the output word's width (sgm_top OUT_W: 16, or 24
// with the confidence, which is then 0 too).
// Latency: none (the word is masked in its cycle; the flag is read a cycle ahead).
// Throughput: one slot and one word per enabled cycle.
module sgm_rectify_join #(
  parameter int DEPTH_LOG2 = 12,
  parameter int YW         = 11,
  parameter int WORD_W     = 16
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,           // the pipeline's enable
  input  wire  [YW-1:0]    row_i,          // the slot's row (beyond the frame: a flush slot)
  input  wire  [YW-1:0]    height_i,
  input  wire              side_i,         // the slot's beat's outside flag
  input  wire              res_valid_i,    // the slot carries a frame pixel's output word
  input  wire  [WORD_W-1:0] res_word_i,
  output logic [WORD_W-1:0] res_word_o,    // 0 when the pixel's flag is set
  input  wire  [3:0]       ctrl_error_i,   // sgm_stream_ctrl error_o, error_set_o
  input  wire  [3:0]       ctrl_error_set_i,
  input  wire              beat_valid_i,   // sgm_rectify's output beat (m_tvalid_o, m_tready_i)
  input  wire              beat_ready_i,
  input  wire  [2:0]       frame_error_i,  // its m_error_o
  input  wire              lut_start_i,    // the controller starts a frame (dropped: ctrl_error_set_i[3])
  input  wire              ctrl_busy_i,    // sgm_stream_ctrl busy_o (0 while it drops a frame)
  input  wire              rect_busy_i,    // sgm_rectify busy_o
  output logic             busy_o,
  output logic [3:0]       error_o,
  output logic [3:0]       error_set_o
);
`ifndef __ICARUS__
  if (DEPTH_LOG2 < 4 || DEPTH_LOG2 > 24) begin : g_bad_depth
    $error("sgm_rectify_join: DEPTH_LOG2 = %0d: 4 .. 24", DEPTH_LOG2);
  end
  if (!(WORD_W == 16 || WORD_W == 24)) begin : g_bad_word_w
    $error("sgm_rectify_join: WORD_W = %0d: WORD_W must be 16 or 24", WORD_W);
  end
`endif

  logic                  flag_mem [0:(1 << DEPTH_LOG2) - 1];
  logic [DEPTH_LOG2-1:0] wr_q, rd_q;
  logic                  head_q;
  wire                   push = en_i && row_i < height_i;
  wire                   pop  = en_i && res_valid_i;
  wire  [DEPTH_LOG2-1:0] rd_d = pop ? rd_q + 1'b1 : rd_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_q <= '0;
      rd_q <= '0;
    end else begin
      if (push) wr_q <= wr_q + 1'b1;
      rd_q <= rd_d;
    end
  end
  // The head is read a cycle ahead (block RAM): the entry was written a flush's worth of
  // slots before it is needed.
  always_ff @(posedge clk_i) begin
    if (push) flag_mem[wr_q] <= side_i;
    head_q <= flag_mem[rd_d];
  end
  assign res_word_o  = res_valid_i && head_q ? '0 : res_word_i;
  logic [2:0] frame_error_q, frame_event_q;
  wire        frame_taken = beat_valid_i && beat_ready_i && ctrl_busy_i;
  always_ff @(posedge clk_i) begin
    if (!rst_ni || lut_start_i || ctrl_error_set_i[3]) frame_error_q <= '0;
    else if (frame_taken) frame_error_q <= frame_error_q | frame_error_i;
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni) frame_event_q <= '0;
    else frame_event_q <= frame_taken ? frame_error_i : 3'd0;
  end
  assign error_o     = ctrl_error_i | {1'b0, frame_error_q};
  assign error_set_o = ctrl_error_set_i | {1'b0, frame_event_q};
  assign busy_o      = ctrl_busy_i || rect_busy_i;

`ifndef SYNTHESIS
  // The bound of DEPTH_LOG2, checked wherever the core is simulated.
  logic [DEPTH_LOG2:0] count_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) count_q <= '0;
    else begin
      count_q <= count_q + (DEPTH_LOG2 + 1)'(push) - (DEPTH_LOG2 + 1)'(pop);
      if (push && !pop && count_q == (DEPTH_LOG2 + 1)'(1 << DEPTH_LOG2))
        $fatal(1, "sgm_rectify_join: the outside flags in flight exceed %0d", 1 << DEPTH_LOG2);
    end
  end
`endif

endmodule
`default_nettype wire
