// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// sgm_top as the formal tasks of sgm_axi see it (tests/formal/axi_*.sby; docs/formal.md):
// the parameters and ports of rtl/sgm_top.sv, every output free in every cycle (Yosys
// anyseq), every input unused. A property of sgm_axi proven with this stub holds with any
// core behind it: whatever the stream handshake, busy, frame_done_o, the error events and
// the frame size the core reports, in any cycle and any combination.
module sgm_top #(
  parameter int D           = 64,
  parameter int MAX_WIDTH   = 1280,
  parameter int MAX_HEIGHT  = 1024,
  parameter int CENSUS_H    = 5,
  parameter int LANES       = 1,
  parameter int UNIQUENESS  = 1,
  parameter int AD_TERM     = 1,
  parameter int RIGHT_BLOCK = 64,
  parameter int EDGE_RESET  = 1,
  parameter int DEPTH       = 0,
  parameter int MIN_DISPARITY = 0,
  parameter int RECTIFY     = 0,
  parameter int RECTIFY_ROWS = 32,
  parameter int RECTIFY_GRID_LOG2 = 4,
  parameter int CONFIDENCE  = 0,
  parameter int MIN_WIDTH   = 0,
  localparam int OUT_W      = CONFIDENCE != 0 ? 24 : 16,
  localparam int XW         = $clog2(MAX_WIDTH + 1),
  localparam int YW         = $clog2(MAX_HEIGHT + 16)
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire  [15:0]   s_tdata_i,
  input  wire           s_tuser_i,
  input  wire           s_tlast_i,
  input  wire           s_tvalid_i,
  output logic          s_tready_o,
  output logic [OUT_W-1:0] m_tdata_o,
  output logic          m_tuser_o,
  output logic          m_tlast_o,
  output logic          m_tvalid_o,
  input  wire           m_tready_i,
  input  wire  [CFG_W-1:0] cfg_i,
  input  wire           mesh_we_i,
  input  wire           mesh_channel_i,
  input  wire  [11:0]   mesh_row_i,
  input  wire  [11:0]   mesh_col_i,
  input  wire  [17:0]   mesh_u_i,
  input  wire  [17:0]   mesh_v_i,
  input  wire           mesh_swap_i,
  output logic          mesh_swap_pending_o,
  output logic          rect_row_miss_o,
  output logic          busy_o,
  output logic          frame_done_o,
  output logic [3:0]    error_o,
  output logic [3:0]    error_event_o,
  output logic [XW-1:0] frame_width_o,
  output logic [YW-1:0] frame_height_o,
  output logic [XW-1:0] min_width_o
);

  (* anyseq *) logic          any_tready, any_tuser, any_tlast, any_tvalid, any_busy, any_done;
  (* anyseq *) logic [OUT_W-1:0] any_tdata;
  (* anyseq *) logic [3:0]    any_error, any_event;
  (* anyseq *) logic [XW-1:0] any_width, any_min_width;
  (* anyseq *) logic [YW-1:0] any_height;
  (* anyseq *) logic          any_pending, any_miss;

  assign s_tready_o     = any_tready;
  assign m_tdata_o      = any_tdata;
  assign m_tuser_o      = any_tuser;
  assign m_tlast_o      = any_tlast;
  assign m_tvalid_o     = any_tvalid;
  assign busy_o         = any_busy;
  assign frame_done_o   = any_done;
  assign error_o        = any_error;
  assign error_event_o  = any_event;
  assign frame_width_o  = any_width;
  assign frame_height_o = any_height;
  assign min_width_o    = any_min_width;
  assign mesh_swap_pending_o = any_pending;
  assign rect_row_miss_o     = any_miss;

endmodule
`default_nettype wire
