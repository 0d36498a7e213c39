// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// sgm_axi: sgm_top with an AXI4-Lite control and status slave (32-bit data,
// one clock). The register map is docs/registers.md. Offsets, fields, masks
// and reset values are described once, in regmap/sgm_regmap.def, from which
// `make regmap` generates rtl/sgm_regmap.svh (included below), the frame
// configuration word rtl/sgm_cfg.svh (included above), the C header
// sw/include/sgm_regs.h and the tables of docs/registers.md.
//
//   identification  ID, D, MAX_WIDTH, MAX_HEIGHT, CENSUS, MIN_WIDTH, LANES, FEATURES (read-only)
//   control         CTRL (enable, soft reset, hold), FRAME_SIZE, PENALTY, CONFIG,
//                   EDGE_RESET, OUTPUT, DEPTH_FOCAL, DEPTH_BASELINE, MIN_DISPARITY, RECTIFY
//   meshes          MESH_ADDR, MESH_U, MESH_V (a write stores the node), MESH_CTRL
//   status          STATUS (busy), FRAMES, ERROR (sticky, W1C), ERROR_COUNT,
//                   LAST_SIZE
//   interrupt       IRQ_ENABLE, IRQ_STATUS (W1C); irq_o = |(status & enable)
//
// Configuration: the bus writes FRAME_SIZE, PENALTY, CONFIG, EDGE_RESET, OUTPUT,
// DEPTH_FOCAL, DEPTH_BASELINE, MIN_DISPARITY and RECTIFY (shadow registers). While CTRL.HOLD is 0 they are
// copied every cycle into the active set, the frame configuration word that drives
// sgm_top's cfg_i (cfg_from_regs packs the registers' fields), and sgm_top takes the
// active set at the handshake of a frame's first beat, so a write in the middle of a
// frame acts from the next frame on. CTRL.HOLD = 1 freezes the active set, so that
// several registers change together (set HOLD, write, clear HOLD).
// CTRL.ENABLE = 0 holds back a start-of-frame beat (s_tready_o low while
// s_tuser_i is high), so the core stops at a frame boundary; a frame already
// started runs to its end. CTRL.SOFT_RESET = 1 resets sgm_top (not the
// registers) for SOFT_RESET_CYCLES cycles, with the input stream held.
// The rectification's meshes (RECTIFY = 1): a write of MESH_V stores the node (MESH_U,
// MESH_V) at MESH_ADDR (column, row, image) into the mesh copy not in use and steps
// MESH_ADDR.COL; MESH_CTRL.SWAP makes the written copy the one used from the next start of
// frame; MESH_CTRL.PENDING is 1 until the core's output runs on it (no mesh write meanwhile).
// Without RECTIFY the mesh registers read and write as registers and reach nothing.
// Undefined addresses answer SLVERR (reads return 0, writes are ignored);
// writes to read-only registers are ignored with OKAY.
//
// Parameters: D, MAX_WIDTH, MAX_HEIGHT, CENSUS_H, LANES, UNIQUENESS, AD_TERM,
// RIGHT_BLOCK, EDGE_RESET, DEPTH, MIN_DISPARITY, RECTIFY, RECTIFY_ROWS, RECTIFY_GRID_LOG2,
// CONFIDENCE, MIN_WIDTH as sgm_top (FEATURES reads back UNIQUENESS .. CONFIDENCE; the
// MIN_WIDTH register the narrowest frame, MIN_WIDTH or the build's least); ADDR_W AXI
// address bits.
// Latency and throughput: those of sgm_top; register responses one cycle
// after the request.
module sgm_axi #(
  parameter int D          /*verilator public*/ = 64,
  parameter int MAX_WIDTH  /*verilator public*/ = 1280,
  parameter int MAX_HEIGHT /*verilator public*/ = 1024,
  parameter int CENSUS_H   /*verilator public*/ = 5,
  parameter int LANES      /*verilator public*/ = 1,
  parameter int UNIQUENESS /*verilator public*/ = 1,
  parameter int AD_TERM    /*verilator public*/ = 1,
  parameter int RIGHT_BLOCK /*verilator public*/ = 64,
  parameter int EDGE_RESET /*verilator public*/ = 1,
  parameter int DEPTH      /*verilator public*/ = 0,
  parameter int MIN_DISPARITY /*verilator public*/ = 0,
  parameter int RECTIFY    /*verilator public*/ = 0,
  parameter int RECTIFY_ROWS /*verilator public*/ = 32,
  parameter int RECTIFY_GRID_LOG2 /*verilator public*/ = 4,
  parameter int CONFIDENCE /*verilator public*/ = 0,
  parameter int MIN_WIDTH  /*verilator public*/ = 0,
  parameter int ADDR_W     = 8,
  localparam int OUT_W     = CONFIDENCE != 0 ? 24 : 16,  // sgm_top OUT_W
  localparam int XW        = $clog2(MAX_WIDTH + 1),
  localparam int YW        = $clog2(MAX_HEIGHT + 16)
) (
  input  wire               clk_i,
  input  wire               rst_ni,
  // AXI4-Stream video in: {right, left} gray, tuser = start of frame, tlast = end of line
  input  wire  [15:0]       s_tdata_i,
  input  wire               s_tuser_i,
  input  wire               s_tlast_i,
  input  wire               s_tvalid_i,
  output logic              s_tready_o,
  // AXI4-Stream disparities out: {valid, zeros, disparity x 16} or the depth, and with
  // CONFIDENCE the confidence in bits 23:16 (sgm_top OUT_W)
  output logic [OUT_W-1:0]  m_tdata_o,
  output logic              m_tuser_o,
  output logic              m_tlast_o,
  output logic              m_tvalid_o,
  input  wire               m_tready_i,
  // AXI4-Lite slave
  input  wire  [ADDR_W-1:0] s_axil_awaddr_i,
  input  wire  [2:0]        s_axil_awprot_i,
  input  wire               s_axil_awvalid_i,
  output logic              s_axil_awready_o,
  input  wire  [31:0]       s_axil_wdata_i,
  input  wire  [3:0]        s_axil_wstrb_i,
  input  wire               s_axil_wvalid_i,
  output logic              s_axil_wready_o,
  output logic [1:0]        s_axil_bresp_o,
  output logic              s_axil_bvalid_o,
  input  wire               s_axil_bready_i,
  input  wire  [ADDR_W-1:0] s_axil_araddr_i,
  input  wire  [2:0]        s_axil_arprot_i,
  input  wire               s_axil_arvalid_i,
  output logic              s_axil_arready_o,
  output logic [31:0]       s_axil_rdata_o,
  output logic [1:0]        s_axil_rresp_o,
  output logic              s_axil_rvalid_o,
  input  wire               s_axil_rready_i,
  // Interrupt (level, active high)
  output logic              irq_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(ADDR_W >= 7 && ADDR_W <= 32)) begin : g_bad_addr_w
    $error("sgm_axi: ADDR_W = %0d: ADDR_W must be from 7 to 32 (the registers span byte offsets 0x00 .. 0x70)", ADDR_W);
  end
`endif

  // ------------------------------------------------------------ register map
  // Offsets, field positions, masks, reset values and the build's constant registers:
  // rtl/sgm_regmap.svh, generated from regmap/sgm_regmap.def (`make regmap`). The reset
  // values are the golden model's defaults for the build (sgm::buildDefaults): those of a
  // build with the fifth path, the uniqueness ratio, the AD term and the path restart, else
  // the four-path preset.
  localparam bit FULL_DEFAULTS = RIGHT_BLOCK != 0 && UNIQUENESS != 0 && AD_TERM != 0 && EDGE_RESET != 0;
`include "sgm_regmap.svh"

  // ------------------------------------------------------------ bus
  logic              reg_we, reg_re, reg_werr, reg_rerr;
  logic [ADDR_W-1:0] reg_waddr, reg_raddr;
  logic [31:0]       reg_wdata, reg_rdata;
  logic [3:0]        reg_wstrb;

  sgm_axil_slave #(.ADDR_W(ADDR_W)) u_axil (
    .clk_i           (clk_i),
    .rst_ni          (rst_ni),
    .s_axil_awaddr_i (s_axil_awaddr_i),
    .s_axil_awprot_i (s_axil_awprot_i),
    .s_axil_awvalid_i(s_axil_awvalid_i),
    .s_axil_awready_o(s_axil_awready_o),
    .s_axil_wdata_i  (s_axil_wdata_i),
    .s_axil_wstrb_i  (s_axil_wstrb_i),
    .s_axil_wvalid_i (s_axil_wvalid_i),
    .s_axil_wready_o (s_axil_wready_o),
    .s_axil_bresp_o  (s_axil_bresp_o),
    .s_axil_bvalid_o (s_axil_bvalid_o),
    .s_axil_bready_i (s_axil_bready_i),
    .s_axil_araddr_i (s_axil_araddr_i),
    .s_axil_arprot_i (s_axil_arprot_i),
    .s_axil_arvalid_i(s_axil_arvalid_i),
    .s_axil_arready_o(s_axil_arready_o),
    .s_axil_rdata_o  (s_axil_rdata_o),
    .s_axil_rresp_o  (s_axil_rresp_o),
    .s_axil_rvalid_o (s_axil_rvalid_o),
    .s_axil_rready_i (s_axil_rready_i),
    .reg_we_o        (reg_we),
    .reg_waddr_o     (reg_waddr),
    .reg_wdata_o     (reg_wdata),
    .reg_wstrb_o     (reg_wstrb),
    .reg_werr_i      (reg_werr),
    .reg_re_o        (reg_re),
    .reg_raddr_o     (reg_raddr),
    .reg_rdata_i     (reg_rdata),
    .reg_rerr_i      (reg_rerr)
  );

  // Word addresses (byte address bits [1:0] are ignored); is one a register?
  wire [ADDR_W-1:0] waddr = {reg_waddr[ADDR_W-1:2], 2'b00};
  wire [ADDR_W-1:0] raddr = {reg_raddr[ADDR_W-1:2], 2'b00};


  // The bits of a write that its byte strobes enable.
  wire [31:0] wmask = {{8{reg_wstrb[3]}}, {8{reg_wstrb[2]}}, {8{reg_wstrb[1]}}, {8{reg_wstrb[0]}}};
  wire [31:0] wset  = reg_wdata & wmask;  // bits written as 1 (W1C, W1P)

  function automatic logic [31:0] merge(input logic [31:0] old, input logic [31:0] data, input logic [31:0] mask,
                                        input logic [31:0] fields);
    merge = ((old & ~mask) | (data & mask)) & fields;
  endfunction

  wire wr_ctrl        = reg_we && waddr == ADDR_CTRL;
  wire wr_frame_size  = reg_we && waddr == ADDR_FRAME_SIZE;
  wire wr_penalty     = reg_we && waddr == ADDR_PENALTY;
  wire wr_config      = reg_we && waddr == ADDR_CONFIG;
  wire wr_edge_reset  = reg_we && waddr == ADDR_EDGE_RESET;
  wire wr_error       = reg_we && waddr == ADDR_ERROR;
  wire wr_error_count = reg_we && waddr == ADDR_ERROR_COUNT;
  wire wr_irq_enable  = reg_we && waddr == ADDR_IRQ_ENABLE;
  wire wr_output      = reg_we && waddr == ADDR_OUTPUT;
  wire wr_focal       = reg_we && waddr == ADDR_DEPTH_FOCAL;
  wire wr_baseline    = reg_we && waddr == ADDR_DEPTH_BASELINE;
  wire wr_dmin        = reg_we && waddr == ADDR_MIN_DISPARITY;
  wire wr_rectify     = reg_we && waddr == ADDR_RECTIFY;
  wire wr_mesh_addr   = reg_we && waddr == ADDR_MESH_ADDR;
  wire wr_mesh_u      = reg_we && waddr == ADDR_MESH_U;
  wire wr_mesh_v      = reg_we && waddr == ADDR_MESH_V;
  wire wr_mesh_ctrl   = reg_we && waddr == ADDR_MESH_CTRL;
  wire wr_irq_status  = reg_we && waddr == ADDR_IRQ_STATUS;

  assign reg_werr = !reg_defined(waddr);
  assign reg_rerr = !reg_defined(raddr);

  // ------------------------------------------------------------ control registers
  logic [31:0] ctrl_q, frame_size_q, penalty_q, config_q, edge_reset_q, irq_enable_q;
  logic [31:0] output_q, focal_q, baseline_q, dmin_q, rectify_q, mesh_addr_q, mesh_u_q, mesh_v_q;
  logic        mesh_we_q, mesh_swap_q;
  logic [$clog2(SOFT_RESET_CYCLES + 1)-1:0] soft_reset_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      ctrl_q       <= '0;
      frame_size_q <= '0;
      penalty_q    <= PENALTY_RESET;
      config_q     <= CONFIG_RESET;
      edge_reset_q <= EDGE_RESET_RESET;
      irq_enable_q <= '0;
      output_q     <= '0;
      focal_q      <= '0;
      baseline_q   <= '0;
      dmin_q       <= '0;
      rectify_q    <= '0;
      mesh_addr_q  <= '0;
      mesh_u_q     <= '0;
      mesh_v_q     <= '0;
      mesh_we_q    <= 1'b0;
      mesh_swap_q  <= 1'b0;
      soft_reset_q <= '0;
    end else begin
      if (wr_ctrl) ctrl_q <= merge(ctrl_q, reg_wdata, wmask, CTRL_MASK);
      if (wr_frame_size) frame_size_q <= merge(frame_size_q, reg_wdata, wmask, FRAME_SIZE_MASK);
      if (wr_penalty) penalty_q <= merge(penalty_q, reg_wdata, wmask, PENALTY_MASK);
      if (wr_config) config_q <= merge(config_q, reg_wdata, wmask, CONFIG_MASK);
      if (wr_edge_reset) edge_reset_q <= merge(edge_reset_q, reg_wdata, wmask, EDGE_RESET_MASK);
      if (wr_irq_enable) irq_enable_q <= merge(irq_enable_q, reg_wdata, wmask, IRQ_ENABLE_MASK);
      if (wr_output) output_q <= merge(output_q, reg_wdata, wmask, OUTPUT_MASK);
      if (wr_focal) focal_q <= merge(focal_q, reg_wdata, wmask, DEPTH_FOCAL_MASK);
      if (wr_baseline) baseline_q <= merge(baseline_q, reg_wdata, wmask, DEPTH_BASELINE_MASK);
      if (wr_dmin) dmin_q <= merge(dmin_q, reg_wdata, wmask, MIN_DISPARITY_MASK);
      if (wr_rectify) rectify_q <= merge(rectify_q, reg_wdata, wmask, RECTIFY_MASK);
      if (wr_mesh_u) mesh_u_q <= merge(mesh_u_q, reg_wdata, wmask, MESH_U_MASK);
      if (wr_mesh_v) mesh_v_q <= merge(mesh_v_q, reg_wdata, wmask, MESH_V_MASK);
      // A write of MESH_V stores the node (the cycle after, from the registers) and steps the column.
      mesh_we_q   <= wr_mesh_v;
      mesh_swap_q <= wr_mesh_ctrl && wset[MESH_CTRL_SWAP_LSB];
      if (wr_mesh_addr) mesh_addr_q <= merge(mesh_addr_q, reg_wdata, wmask, MESH_ADDR_MASK);
      else if (mesh_we_q)
        mesh_addr_q[MESH_ADDR_COL_LSB +: MESH_ADDR_COL_W] <= mesh_addr_q[MESH_ADDR_COL_LSB +: MESH_ADDR_COL_W] + 1'b1;
      if (wr_ctrl && wset[CTRL_SOFT_RESET_LSB]) soft_reset_q <= ($bits(soft_reset_q))'(SOFT_RESET_CYCLES);
      else if (soft_reset_q != '0) soft_reset_q <= soft_reset_q - 1'b1;
    end
  end

  wire enable     = ctrl_q[CTRL_ENABLE_LSB];
  wire hold       = ctrl_q[CTRL_HOLD_LSB];
  wire core_reset = soft_reset_q != '0;

  // Active configuration: the frame configuration word of the shadow registers, which
  // it follows unless held. The frame size goes whole (16 bits each): the core drops a
  // size it cannot take (error_o[3]) like any other configuration out of range.
  logic [CFG_W-1:0] act_cfg;

  always_ff @(posedge clk_i) begin
    if (!rst_ni)
      act_cfg <= cfg_from_regs(32'd0, PENALTY_RESET, CONFIG_RESET, EDGE_RESET_RESET, 32'd0, 32'd0, 32'd0, 32'd0, 32'd0);
    else if (!hold)
      act_cfg <= cfg_from_regs(frame_size_q, penalty_q, config_q, edge_reset_q, output_q, focal_q, baseline_q,
                               dmin_q, rectify_q);
  end

  // ------------------------------------------------------------ core
  // A start-of-frame beat waits while the core is disabled; no beat passes
  // while the core is in its soft reset.
  wire hold_input = core_reset || (!enable && s_tuser_i);
  logic        core_tready, busy, frame_done;
  logic [3:0]  error, error_event;
  logic [XW-1:0] frame_width;
  logic [YW-1:0] frame_height;
  logic [XW-1:0] core_min_width;
  logic        mesh_pending, mesh_row_miss;

  assign s_tready_o = core_tready && !hold_input;

  sgm_top #(
    .D(D), .MAX_WIDTH(MAX_WIDTH), .MAX_HEIGHT(MAX_HEIGHT), .CENSUS_H(CENSUS_H), .LANES(LANES), .UNIQUENESS(UNIQUENESS),
    .AD_TERM(AD_TERM), .RIGHT_BLOCK(RIGHT_BLOCK), .EDGE_RESET(EDGE_RESET), .DEPTH(DEPTH),
    .MIN_DISPARITY(MIN_DISPARITY), .RECTIFY(RECTIFY), .RECTIFY_ROWS(RECTIFY_ROWS),
    .RECTIFY_GRID_LOG2(RECTIFY_GRID_LOG2), .CONFIDENCE(CONFIDENCE), .MIN_WIDTH(MIN_WIDTH)
  ) u_core (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni && !core_reset),
    .s_tdata_i     (s_tdata_i),
    .s_tuser_i     (s_tuser_i),
    .s_tlast_i     (s_tlast_i),
    .s_tvalid_i    (s_tvalid_i && !hold_input),
    .s_tready_o    (core_tready),
    .m_tdata_o     (m_tdata_o),
    .m_tuser_o     (m_tuser_o),
    .m_tlast_o     (m_tlast_o),
    .m_tvalid_o    (m_tvalid_o),
    .m_tready_i    (m_tready_i),
    .cfg_i         (act_cfg),
    .mesh_we_i     (mesh_we_q),
    .mesh_channel_i(mesh_addr_q[MESH_ADDR_RIGHT_LSB]),
    .mesh_row_i    (mesh_addr_q[MESH_ADDR_ROW_LSB +: MESH_ADDR_ROW_W]),
    .mesh_col_i    (mesh_addr_q[MESH_ADDR_COL_LSB +: MESH_ADDR_COL_W]),
    .mesh_u_i      (mesh_u_q[MESH_U_U_LSB +: MESH_U_U_W]),
    .mesh_v_i      (mesh_v_q[MESH_V_V_LSB +: MESH_V_V_W]),
    .mesh_swap_i   (mesh_swap_q),
    .mesh_swap_pending_o(mesh_pending),
    .rect_row_miss_o(mesh_row_miss),
    .busy_o        (busy),
    .frame_done_o  (frame_done),
    .error_o       (error),
    .error_event_o (error_event),
    .frame_width_o (frame_width),
    .frame_height_o(frame_height),
    .min_width_o   (core_min_width)
  );

  // ------------------------------------------------------------ status
  logic [31:0] frames_q, last_size_q;
  logic [ERROR_KINDS-1:0] error_q;
  logic [31:0] error_count_q;  // byte k: events of kind k
  logic [1:0]  irq_status_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      frames_q     <= '0;
      last_size_q  <= '0;
      error_q      <= '0;
      irq_status_q <= '0;
    end else begin
      if (frame_done) begin
        frames_q    <= frames_q + 1'b1;
        last_size_q <= {16'(frame_height), 16'(frame_width)};
      end
      // Sticky bits: an event in the cycle of a clear wins.
      error_q      <= (error_q & ~(wr_error ? wset[ERROR_KINDS-1:0] : '0)) | error_event;
      irq_status_q <= (irq_status_q & ~(wr_irq_status ? wset[1:0] : 2'd0)) | {|error_event, frame_done};
    end
  end

  // Saturating event counters, one per error kind; a write clears the
  // counters of its enabled byte lanes. An event in the cycle of the clear
  // counts (the counter restarts at 1), as ERROR keeps it.
  for (genvar k = 0; k < 4; k++) begin : g_count
    always_ff @(posedge clk_i) begin
      if (!rst_ni) error_count_q[k*8 +: 8] <= '0;
      else if (wr_error_count && reg_wstrb[k]) error_count_q[k*8 +: 8] <= 8'(error_event[k]);
      else if (error_event[k] && error_count_q[k*8 +: 8] != 8'hFF)
        error_count_q[k*8 +: 8] <= error_count_q[k*8 +: 8] + 1'b1;
    end
  end

  assign irq_o = |(irq_status_q & irq_enable_q[1:0]);

  // ------------------------------------------------------------ read data
  always_comb begin
    case (raddr)
      ADDR_ID:          reg_rdata = ID_VALUE;
      ADDR_D:           reg_rdata = D_VALUE;
      ADDR_MAX_WIDTH:   reg_rdata = MAX_WIDTH_VALUE;
      ADDR_MAX_HEIGHT:  reg_rdata = MAX_HEIGHT_VALUE;
      ADDR_CENSUS:      reg_rdata = CENSUS_VALUE;
      ADDR_MIN_WIDTH:   reg_rdata = 32'(core_min_width);
      ADDR_LANES:       reg_rdata = LANES_VALUE;
      ADDR_FEATURES:    reg_rdata = FEATURES_VALUE;
      ADDR_CTRL:        reg_rdata = ctrl_q;
      ADDR_FRAME_SIZE:  reg_rdata = frame_size_q;
      ADDR_PENALTY:     reg_rdata = penalty_q;
      ADDR_CONFIG:      reg_rdata = config_q;
      ADDR_STATUS:      reg_rdata = 32'(busy) << STATUS_BUSY_LSB | 32'(core_reset) << STATUS_RESETTING_LSB;
      ADDR_FRAMES:      reg_rdata = frames_q;
      ADDR_ERROR:       reg_rdata = 32'(error_q) << ERROR_LAST_EARLY_LSB;
      ADDR_ERROR_COUNT: reg_rdata = error_count_q;
      ADDR_LAST_SIZE:   reg_rdata = last_size_q;
      ADDR_EDGE_RESET:  reg_rdata = edge_reset_q;
      ADDR_IRQ_ENABLE:  reg_rdata = irq_enable_q;
      ADDR_IRQ_STATUS:  reg_rdata = 32'(irq_status_q);
      ADDR_OUTPUT:      reg_rdata = output_q;
      ADDR_DEPTH_FOCAL: reg_rdata = focal_q;
      ADDR_DEPTH_BASELINE: reg_rdata = baseline_q;
      ADDR_MIN_DISPARITY: reg_rdata = dmin_q;
      ADDR_RECTIFY:     reg_rdata = rectify_q;
      ADDR_MESH_ADDR:   reg_rdata = mesh_addr_q;
      ADDR_MESH_U:      reg_rdata = mesh_u_q;
      ADDR_MESH_V:      reg_rdata = mesh_v_q;
      ADDR_MESH_CTRL:   reg_rdata = 32'(mesh_pending) << MESH_CTRL_PENDING_LSB |
                                    32'(mesh_row_miss) << MESH_CTRL_ROW_MISS_LSB;
      default:          reg_rdata = 32'd0;
    endcase
  end

  wire unused = &{1'b0, reg_re, reg_waddr[1:0], reg_raddr[1:0], error, wset};

`ifdef SGM_FORMAL
  // The formal property set (tests/formal/sgm_axi_props.svh; make formal, docs/formal.md).
`include "sgm_axi_props.svh"
`endif

endmodule
`default_nettype wire
