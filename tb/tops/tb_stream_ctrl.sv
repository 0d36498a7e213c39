// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// tb_stream_ctrl: sgm_stream_ctrl around a stand-in pipeline, for the stream
// protocol tests. The stand-in has a fixed latency of LAT slots; a slot at
// (col, row) with row < height is a frame pixel and comes out as
// disparity = {right, left} (low DW bits), validity flag = left[0]. Its P2
// table is "filled" FILL_CYCLES cycles after lut_start. The configuration is the
// frame configuration word (rtl/sgm_cfg.svh), given by the test; the stand-in uses
// only the frame size of the latched word.
module tb_stream_ctrl #(
  parameter int LAT         = 37,
  parameter int FILL_CYCLES = 20,
  parameter int XW          = 8,
  parameter int YW          = 8,
  parameter int DW          = 12
) (
  input  wire         clk_i,
  input  wire         rst_ni,
  input  wire  [15:0] s_tdata_i,
  input  wire         s_tuser_i,
  input  wire         s_tlast_i,
  input  wire         s_tvalid_i,
  output logic        s_tready_o,
  output logic [15:0] m_tdata_o,
  output logic        m_tuser_o,
  output logic        m_tlast_o,
  output logic        m_tvalid_o,
  input  wire         m_tready_i,
  input  wire [CFG_W-1:0] cfg_i,
  output logic        busy_o,
  output logic        frame_done_o,
  output logic [3:0]  error_o,
  output logic [3:0]  error_set_o,
  output logic        en_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(LAT >= 1)) begin : g_bad_lat
    $error("tb_stream_ctrl: LAT = %0d: LAT must be at least 1", LAT);
  end
  if (!(FILL_CYCLES >= 0 && FILL_CYCLES <= 255)) begin : g_bad_fill_cycles
    $error("tb_stream_ctrl: FILL_CYCLES = %0d: FILL_CYCLES must be from 0 to 255 (an 8-bit count)", FILL_CYCLES);
  end
`endif

  logic [XW-1:0] width;
  logic [YW-1:0] height;
  logic          lut_start;
  logic [7:0]    pix_l, pix_r;
  logic [XW-1:0] col;
  logic [YW-1:0] row;
  logic          sof;  // the frame's first slot (checked in the whole-core lane builds)
  logic [CFG_W-1:0] unused_cfg;  // the latched word: the stand-in has no stage that reads it

  // Stand-in P2 table: ready FILL_CYCLES cycles after a start.
  logic [7:0] fill_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) fill_q <= '0;
    else if (lut_start) fill_q <= 8'(FILL_CYCLES);
    else if (fill_q != '0) fill_q <= fill_q - 1'b1;
  end

  // Stand-in pipeline: LAT slots of delay.
  localparam int SLOT = 1 + DW + 1;  // {frame pixel, disparity, flag}
  logic [LAT*SLOT-1:0] pipe_q;
  wire [SLOT-1:0] slot_in = {row < height, DW'({pix_r, pix_l}), pix_l[0]};
  always_ff @(posedge clk_i) begin
    if (!rst_ni) pipe_q <= '0;
    else if (en_o) pipe_q <= {pipe_q[(LAT-1)*SLOT-1:0], slot_in};
  end
  wire [SLOT-1:0] slot_out = pipe_q[(LAT-1)*SLOT +: SLOT];

  sgm_stream_ctrl #(
    .MAX_WIDTH(200), .MIN_WIDTH(16), .MAX_HEIGHT(200), .XW(XW), .YW(YW), .FIFO_DEPTH(4)
  ) u_ctrl (
    .clk_i, .rst_ni,
    .s_tdata_i, .s_tuser_i, .s_tlast_i, .s_tvalid_i, .s_tready_o, .s_tside_i(1'b0),
    .m_tdata_o, .m_tuser_o, .m_tlast_o, .m_tvalid_o, .m_tready_i,
    .cfg_i, .cfg_o(unused_cfg), .width_o(width), .height_o(height),
    .lut_start_o(lut_start), .lut_ready_i(fill_q == '0),
    .en_o, .pix_left_o(pix_l), .pix_right_o(pix_r), .col_o(col), .row_o(row), .sof_o(sof), .side_o(unused_side),
    .res_valid_i(slot_out[SLOT-1]), .res_word_i({slot_out[0], 15'(slot_out[1 +: DW])}),
    .busy_o, .frame_done_o, .error_o, .error_set_o
  );

  logic unused_side;
  wire unused = &{1'b0, width, col, sof, unused_cfg, unused_side};

endmodule
`default_nettype wire
