// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_axi: sgm_top with an AXI4-Lite control and status slave (32-bit data,
// one clock). The register map is docs/registers.md; the offsets and fields
// are defined once, in sw/include/sgm_regs.h, and the localparams below are
// checked against that header by tests/rtl/test_sgm_axi.cpp.
//
//   identification  ID, D, MAX_WIDTH, MAX_HEIGHT, CENSUS, MIN_WIDTH, LANES, FEATURES (read-only)
//   control         CTRL (enable, soft reset, hold), FRAME_SIZE, PENALTY, CONFIG,
//                   EDGE_RESET
//   status          STATUS (busy), FRAMES, ERROR (sticky, W1C), ERROR_COUNT,
//                   LAST_SIZE
//   interrupt       IRQ_ENABLE, IRQ_STATUS (W1C); irq_o = |(status & enable)
//
// Configuration: the bus writes FRAME_SIZE, PENALTY, CONFIG and EDGE_RESET (shadow
// registers). While CTRL.HOLD is 0 they are copied every cycle into the active
// set that drives sgm_top's cfg_*_i, and sgm_top takes the active set at the
// handshake of a frame's first beat, so a write in the middle of a frame acts
// from the next frame on. CTRL.HOLD = 1 freezes the active set, so that
// several registers change together (set HOLD, write, clear HOLD).
// CTRL.ENABLE = 0 holds back a start-of-frame beat (s_tready_o low while
// s_tuser_i is high), so the core stops at a frame boundary; a frame already
// started runs to its end. CTRL.SOFT_RESET = 1 resets sgm_top (not the
// registers) for SOFT_RESET_CYCLES cycles, with the input stream held.
// Undefined addresses answer SLVERR (reads return 0, writes are ignored);
// writes to read-only registers are ignored with OKAY.
//
// Parameters: D, MAX_WIDTH, MAX_HEIGHT, CENSUS_H, LANES, UNIQUENESS, AD_TERM,
// RIGHT_BLOCK, EDGE_RESET as sgm_top (FEATURES reads back the last four); ADDR_W AXI
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
  parameter int ADDR_W     = 8,
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
  // AXI4-Stream disparities out: {valid, zeros, disparity x 16}
  output logic [15:0]       m_tdata_o,
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
    $error("sgm_axi: ADDR_W = %0d: ADDR_W must be from 7 to 32 (the registers span byte offsets 0x00 .. 0x4C)", ADDR_W);
  end
`endif

  // ------------------------------------------------------------ register map
  // Byte offsets and reset values: the same numbers as sw/include/sgm_regs.h.
  localparam logic [ADDR_W-1:0] ADDR_ID          /*verilator public*/ = ADDR_W'('h00);
  localparam logic [ADDR_W-1:0] ADDR_D           /*verilator public*/ = ADDR_W'('h04);
  localparam logic [ADDR_W-1:0] ADDR_MAX_WIDTH   /*verilator public*/ = ADDR_W'('h08);
  localparam logic [ADDR_W-1:0] ADDR_MAX_HEIGHT  /*verilator public*/ = ADDR_W'('h0C);
  localparam logic [ADDR_W-1:0] ADDR_CENSUS      /*verilator public*/ = ADDR_W'('h10);
  localparam logic [ADDR_W-1:0] ADDR_MIN_WIDTH   /*verilator public*/ = ADDR_W'('h14);
  localparam logic [ADDR_W-1:0] ADDR_LANES       /*verilator public*/ = ADDR_W'('h18);
  localparam logic [ADDR_W-1:0] ADDR_FEATURES    /*verilator public*/ = ADDR_W'('h1C);
  localparam logic [ADDR_W-1:0] ADDR_CTRL        /*verilator public*/ = ADDR_W'('h20);
  localparam logic [ADDR_W-1:0] ADDR_FRAME_SIZE  /*verilator public*/ = ADDR_W'('h24);
  localparam logic [ADDR_W-1:0] ADDR_PENALTY     /*verilator public*/ = ADDR_W'('h28);
  localparam logic [ADDR_W-1:0] ADDR_CONFIG      /*verilator public*/ = ADDR_W'('h2C);
  localparam logic [ADDR_W-1:0] ADDR_STATUS      /*verilator public*/ = ADDR_W'('h30);
  localparam logic [ADDR_W-1:0] ADDR_FRAMES      /*verilator public*/ = ADDR_W'('h34);
  localparam logic [ADDR_W-1:0] ADDR_ERROR       /*verilator public*/ = ADDR_W'('h38);
  localparam logic [ADDR_W-1:0] ADDR_ERROR_COUNT /*verilator public*/ = ADDR_W'('h3C);
  localparam logic [ADDR_W-1:0] ADDR_LAST_SIZE   /*verilator public*/ = ADDR_W'('h40);
  localparam logic [ADDR_W-1:0] ADDR_EDGE_RESET  /*verilator public*/ = ADDR_W'('h44);
  localparam logic [ADDR_W-1:0] ADDR_IRQ_ENABLE  /*verilator public*/ = ADDR_W'('h48);
  localparam logic [ADDR_W-1:0] ADDR_IRQ_STATUS  /*verilator public*/ = ADDR_W'('h4C);

  localparam logic [31:0] ID_VALUE       /*verilator public*/ = 32'h5347_4D05;  // "SGM", version 5
  // The reset values are the golden model's defaults for the build (sgm::buildDefaults):
  // "default" when it has the fifth path, the uniqueness ratio, the AD term and the path
  // restart, else
  // "four-path" (the defaults before issue 15).
  localparam bit      FULL_DEFAULTS  = RIGHT_BLOCK != 0 && UNIQUENESS != 0 && AD_TERM != 0 && EDGE_RESET != 0;
  localparam logic [31:0] PENALTY_RESET  /*verilator public*/ =
      FULL_DEFAULTS ? 32'h4314_C818    // P1 24, P2' 200, AD cap 20, AD weight 3, W5 4
                    : 32'h0014_6412;   // P1 18, P2' 100, AD cap 20, AD weight 0 (off), W5 0 (off)
  localparam logic [31:0] CONFIG_RESET   /*verilator public*/ =
      FULL_DEFAULTS ? 32'h0F00_5131    // rsad, sub-pixel, LR tol 1, fill, median, uniqueness 15 (no snap)
                    : 32'h0000_7131;   // rsad, sub-pixel, LR tol 1, fill, snap, median
  // EDGE_RESET: [7:0] T (0 off), [11:8] R, [20:16] path flags.
  localparam logic [31:0] EDGE_RESET_RESET /*verilator public*/ =
      FULL_DEFAULTS ? 32'h001B_0628    // T 40, R 6, paths 0, 45, 135 degrees and the fifth
                    : 32'h001F_0500;   // off (T 0), R 5, every path: the golden EdgeReset{}
  localparam logic [31:0] EDGE_RESET_MASK  = 32'h001F_0FFF;
  localparam logic [31:0] CTRL_MASK      = 32'h0000_0005;  // ENABLE, HOLD (SOFT_RESET reads 0)
  localparam logic [31:0] CONFIG_MASK    = 32'h7F03_7733;
  localparam logic [31:0] PENALTY_MASK   = 32'hFFFF_FFFF;
  localparam logic [31:0] IRQ_MASK       = 32'h0000_0003;
  // FEATURES: the run-time levers of the build, one bit each (the rest reserved, 0).
  localparam int FEATURES_UNIQUENESS_BIT /*verilator public*/ = 0;
  localparam int FEATURES_AD_TERM_BIT    /*verilator public*/ = 1;
  localparam int FEATURES_RIGHT_PATH_BIT /*verilator public*/ = 2;
  localparam int FEATURES_EDGE_RESET_BIT /*verilator public*/ = 3;
  localparam int FEATURES_RIGHT_BLOCK_LSB /*verilator public*/ = 8;  // [11:8]: log2 of the fifth path's block
  localparam logic [31:0] FEATURES_VALUE /*verilator public*/ =
      (UNIQUENESS != 0 ? 32'd1 << FEATURES_UNIQUENESS_BIT : 32'd0) | (AD_TERM != 0 ? 32'd1 << FEATURES_AD_TERM_BIT : 32'd0) |
      (RIGHT_BLOCK != 0 ? (32'd1 << FEATURES_RIGHT_PATH_BIT) | (32'($clog2(RIGHT_BLOCK)) << FEATURES_RIGHT_BLOCK_LSB) : 32'd0) |
      (EDGE_RESET != 0 ? 32'd1 << FEATURES_EDGE_RESET_BIT : 32'd0);
  localparam int CENSUS_WIDTH  = 9;  // the window of sgm_census_unit: 9 x CENSUS_H
  localparam int CENSUS_HEIGHT = CENSUS_H;
  localparam int SOFT_RESET_CYCLES = 4;

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

  function automatic logic defined(input logic [ADDR_W-1:0] a);
    case (a)
      ADDR_ID, ADDR_D, ADDR_MAX_WIDTH, ADDR_MAX_HEIGHT, ADDR_CENSUS, ADDR_MIN_WIDTH, ADDR_LANES, ADDR_FEATURES, ADDR_CTRL,
      ADDR_FRAME_SIZE, ADDR_PENALTY,
      ADDR_CONFIG, ADDR_STATUS, ADDR_FRAMES, ADDR_ERROR, ADDR_ERROR_COUNT, ADDR_LAST_SIZE, ADDR_EDGE_RESET, ADDR_IRQ_ENABLE,
      ADDR_IRQ_STATUS: defined = 1'b1;
      default: defined = 1'b0;
    endcase
  endfunction

  // The bits of a write that its byte strobes enable.
  wire [31:0] wmask = {{8{reg_wstrb[3]}}, {8{reg_wstrb[2]}}, {8{reg_wstrb[1]}}, {8{reg_wstrb[0]}}};
  wire [3:0]  wset  = reg_wdata[3:0] & wmask[3:0];  // low bits written as 1 (W1C)

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
  wire wr_irq_status  = reg_we && waddr == ADDR_IRQ_STATUS;

  assign reg_werr = !defined(waddr);
  assign reg_rerr = !defined(raddr);

  // ------------------------------------------------------------ control registers
  logic [31:0] ctrl_q, frame_size_q, penalty_q, config_q, edge_reset_q, irq_enable_q;
  logic [$clog2(SOFT_RESET_CYCLES + 1)-1:0] soft_reset_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      ctrl_q       <= '0;
      frame_size_q <= '0;
      penalty_q    <= PENALTY_RESET;
      config_q     <= CONFIG_RESET;
      edge_reset_q <= EDGE_RESET_RESET;
      irq_enable_q <= '0;
      soft_reset_q <= '0;
    end else begin
      if (wr_ctrl) ctrl_q <= merge(ctrl_q, reg_wdata, wmask, CTRL_MASK);
      if (wr_frame_size) frame_size_q <= merge(frame_size_q, reg_wdata, wmask, 32'hFFFF_FFFF);
      if (wr_penalty) penalty_q <= merge(penalty_q, reg_wdata, wmask, PENALTY_MASK);
      if (wr_config) config_q <= merge(config_q, reg_wdata, wmask, CONFIG_MASK);
      if (wr_edge_reset) edge_reset_q <= merge(edge_reset_q, reg_wdata, wmask, EDGE_RESET_MASK);
      if (wr_irq_enable) irq_enable_q <= merge(irq_enable_q, reg_wdata, wmask, IRQ_MASK);
      if (wr_ctrl && wset[1]) soft_reset_q <= ($bits(soft_reset_q))'(SOFT_RESET_CYCLES);
      else if (soft_reset_q != '0) soft_reset_q <= soft_reset_q - 1'b1;
    end
  end

  wire enable     = ctrl_q[0];
  wire hold       = ctrl_q[2];
  wire core_reset = soft_reset_q != '0;

  // Active configuration: follows the shadow registers unless held. A size
  // that does not fit the core's counters is passed as 0, which the core
  // rejects (error_o[3]) like any other out-of-range size.
  logic [XW-1:0] act_width;
  logic [YW-1:0] act_height;
  logic [31:0]   act_penalty;
  logic [30:0]   act_config;
  logic [20:0]   act_edge_reset;
  wire  [15:0]   shadow_width  = frame_size_q[15:0];
  wire  [15:0]   shadow_height = frame_size_q[31:16];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      act_width   <= '0;
      act_height  <= '0;
      act_penalty <= PENALTY_RESET;
      act_config  <= CONFIG_RESET[30:0];
      act_edge_reset <= EDGE_RESET_RESET[20:0];
    end else if (!hold) begin
      act_width   <= 32'(shadow_width) <= MAX_WIDTH ? shadow_width[XW-1:0] : '0;
      act_height  <= 32'(shadow_height) <= MAX_HEIGHT ? shadow_height[YW-1:0] : '0;
      act_penalty <= penalty_q;
      act_config  <= config_q[30:0];
      act_edge_reset <= edge_reset_q[20:0];
    end
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

  assign s_tready_o = core_tready && !hold_input;

  sgm_top #(
    .D(D), .MAX_WIDTH(MAX_WIDTH), .MAX_HEIGHT(MAX_HEIGHT), .CENSUS_H(CENSUS_H), .LANES(LANES), .UNIQUENESS(UNIQUENESS),
    .AD_TERM(AD_TERM), .RIGHT_BLOCK(RIGHT_BLOCK), .EDGE_RESET(EDGE_RESET)
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
    .cfg_width_i   (act_width),
    .cfg_height_i  (act_height),
    .cfg_p1_i      (act_penalty[7:0]),
    .cfg_p2_i      (act_penalty[15:8]),
    .cfg_ad_cap_i  (act_penalty[23:16]),
    .cfg_ad_weight_i(act_penalty[27:24]),
    .cfg_right_weight_i(act_penalty[31:28]),
    .cfg_reset_t_i (act_edge_reset[7:0]),
    .cfg_reset_len_i(act_edge_reset[11:8]),
    .cfg_reset_paths_i(act_edge_reset[20:16]),
    .cfg_mode_i    (act_config[1:0]),
    .cfg_subpixel_i(act_config[4]),
    .cfg_lr_en_i   (act_config[5]),
    .cfg_lr_tol_i  (act_config[10:8]),
    .cfg_fill_i    (act_config[12]),
    .cfg_snap_i    (act_config[13]),
    .cfg_median_i  (act_config[14]),
    .cfg_p2_mode_i (act_config[16]),
    .cfg_weights_i (act_config[17]),
    .cfg_unique_i  (act_config[30:24]),
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
  logic [3:0]  error_q;
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
      error_q      <= (error_q & ~(wr_error ? wset[3:0] : 4'd0)) | error_event;
      irq_status_q <= (irq_status_q & ~(wr_irq_status ? wset[1:0] : 2'd0)) | {|error_event, frame_done};
    end
  end

  // Saturating event counters, one per error kind; a write clears the
  // counters of its enabled byte lanes.
  for (genvar k = 0; k < 4; k++) begin : g_count
    always_ff @(posedge clk_i) begin
      if (!rst_ni || (wr_error_count && reg_wstrb[k])) error_count_q[k*8 +: 8] <= '0;
      else if (error_event[k] && error_count_q[k*8 +: 8] != 8'hFF)
        error_count_q[k*8 +: 8] <= error_count_q[k*8 +: 8] + 1'b1;
    end
  end

  assign irq_o = |(irq_status_q & irq_enable_q[1:0]);

  // ------------------------------------------------------------ read data
  always_comb begin
    case (raddr)
      ADDR_ID:          reg_rdata = ID_VALUE;
      ADDR_D:           reg_rdata = 32'(D);
      ADDR_MAX_WIDTH:   reg_rdata = 32'(MAX_WIDTH);
      ADDR_MAX_HEIGHT:  reg_rdata = 32'(MAX_HEIGHT);
      ADDR_CENSUS:      reg_rdata = {16'd0, 8'(CENSUS_HEIGHT), 8'(CENSUS_WIDTH)};
      ADDR_MIN_WIDTH:   reg_rdata = 32'(core_min_width);
      ADDR_LANES:       reg_rdata = 32'(LANES);
      ADDR_FEATURES:    reg_rdata = FEATURES_VALUE;
      ADDR_CTRL:        reg_rdata = ctrl_q;
      ADDR_FRAME_SIZE:  reg_rdata = frame_size_q;
      ADDR_PENALTY:     reg_rdata = penalty_q;
      ADDR_CONFIG:      reg_rdata = config_q;
      ADDR_STATUS:      reg_rdata = {30'd0, core_reset, busy};
      ADDR_FRAMES:      reg_rdata = frames_q;
      ADDR_ERROR:       reg_rdata = {28'd0, error_q};
      ADDR_ERROR_COUNT: reg_rdata = error_count_q;
      ADDR_LAST_SIZE:   reg_rdata = last_size_q;
      ADDR_EDGE_RESET:  reg_rdata = edge_reset_q;
      ADDR_IRQ_ENABLE:  reg_rdata = irq_enable_q;
      ADDR_IRQ_STATUS:  reg_rdata = {30'd0, irq_status_q};
      default:          reg_rdata = 32'd0;
    endcase
  end

  wire unused = &{1'b0, reg_re, reg_waddr[1:0], reg_raddr[1:0], error, act_config[3:2], act_config[7:6], act_config[11], act_config[15], act_config[23:18], act_edge_reset[15:12], shadow_width[15:XW],
                  shadow_height[15:YW]};

endmodule
`default_nettype wire
