// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_axi's registers (make formal, docs/formal.md). Included at
// the end of the module's body when SGM_FORMAL is defined (tests/formal/axi_*.sby: yosys
// read -formal -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// The tasks replace sgm_top by tests/formal/sgm_top_stub.sv, whose outputs are free in
// every cycle: what is proven here holds whatever the core reports. The AXI4-Lite master
// is the one assumed by sgm_axil_slave's property set (included in u_axil), which also
// proves the bus side; the stream inputs are free. Every write below is a bus write:
// accepted on the bus (AWVALID and AWREADY) at a word address, the bits of its enabled
// byte lanes, independent of the module's own decode.
//
// Asserted:
//   reset        after a reset cycle every register holds its reset value (registers.md),
//                the active configuration too;
//   RW           CTRL, FRAME_SIZE, PENALTY, CONFIG, EDGE_RESET, IRQ_ENABLE, OUTPUT,
//                DEPTH_FOCAL, DEPTH_BASELINE, MIN_DISPARITY, RECTIFY, MESH_U, MESH_V change
//                only by a write to their address, which replaces the bits of its enabled
//                byte lanes within the register's fields; reserved bits and CTRL.SOFT_RESET
//                hold 0;
//   meshes       MESH_ADDR changes only by a write to it (as RW) or, the cycle after a
//                write of MESH_V, by the step of its column; the core's mesh port stores
//                (MESH_U, MESH_V) at MESH_ADDR exactly in the cycle after each write of
//                MESH_V, and swaps exactly in the cycle after each write of MESH_CTRL with
//                SWAP = 1;
//   W1C          ERROR and IRQ_STATUS: next = (now & ~cleared) | events (ERROR: the core's
//                error_event_o; IRQ_STATUS: frame_done_o and any error event), so a clear
//                in the cycle of an event never loses the event; nothing else changes them;
//   counters     each ERROR_COUNT byte counts its kind's events and saturates at 255, a
//                write clears the bytes of its enabled lanes (to 1 when an event of the
//                byte's kind comes in the cycle of the clear); FRAMES counts frame_done_o,
//                LAST_SIZE takes the finished frame's size;
//   irq_o        = |(IRQ_STATUS & IRQ_ENABLE) in every cycle;
//   HOLD         while CTRL.HOLD is 1 the active configuration (the core's cfg_i)
//                does not change; while it is 0 the active set is the shadow registers of
//                the cycle before (the frame size whole);
//   soft reset   the core is in reset exactly in the SOFT_RESET_CYCLES cycles after each
//                write of CTRL.SOFT_RESET = 1 (counted from the last one); no input beat is
//                accepted while it is, nor a start-of-frame beat while CTRL.ENABLE is 0;
//                otherwise s_tready_o is the core's;
//   decode       the words 0x00 .. IRQ_STATUS (the map is dense) are registers and every
//                other address answers SLVERR (reads 0); a read returns the register's
//                value (the field layout of registers.md).
// Covered: an error event and an interrupt event in the cycle of their clear, the
// interrupt rising, a soft reset pulse ending, the active set taking a configuration
// written while HOLD was 1 once HOLD is cleared, a write to an undefined address, two
// error events counted.

  logic [1:0] f_t = 2'd0;
  always @(posedge clk_i) if (f_t != 2'd3) f_t <= f_t + 2'd1;
  wire f_past_valid = f_t != 2'd0;

  // The last register of the (dense) map.
  localparam logic [ADDR_W-1:0] F_LAST = ADDR_MESH_CTRL;

  // A write accepted on the bus, its word address, the mask of its enabled byte lanes,
  // the bits it writes as 1 in them; a read accepted and its word address.
  wire              f_wr    = s_axil_awvalid_i && s_axil_awready_o;
  wire [ADDR_W-1:0] f_wa    = {s_axil_awaddr_i[ADDR_W-1:2], 2'b00};
  wire [31:0]       f_lanes = {{8{s_axil_wstrb_i[3]}}, {8{s_axil_wstrb_i[2]}}, {8{s_axil_wstrb_i[1]}}, {8{s_axil_wstrb_i[0]}}};
  wire [31:0]       f_ones  = s_axil_wdata_i & f_lanes;
  wire              f_rd    = s_axil_arvalid_i && s_axil_arready_o;
  wire [ADDR_W-1:0] f_ra    = {s_axil_araddr_i[ADDR_W-1:2], 2'b00};

  // The register after a write of data in lanes to a register of fields mask.
  function automatic logic [31:0] f_write(input logic [31:0] old, input logic [31:0] data, input logic [31:0] lanes,
                                          input logic [31:0] mask);
    f_write = ((old & ~lanes) | (data & lanes)) & mask;
  endfunction

  wire [ERROR_KINDS-1:0] f_err_clear = f_wr && f_wa == ADDR_ERROR ? f_ones[ERROR_LAST_EARLY_LSB +: ERROR_KINDS] : '0;
  wire [1:0] f_irq_event = (2'(frame_done) << IRQ_STATUS_FRAME_DONE_LSB) | (2'(|error_event) << IRQ_STATUS_ERROR_LSB);
  wire [1:0] f_irq_clear = f_wr && f_wa == ADDR_IRQ_STATUS ? f_ones[1:0] : 2'd0;
  wire       f_sr_write  = f_wr && f_wa == ADDR_CTRL && f_ones[CTRL_SOFT_RESET_LSB];
  wire       f_hold      = ctrl_q[CTRL_HOLD_LSB];
  wire       f_enable    = ctrl_q[CTRL_ENABLE_LSB];
  wire [15:0] f_width    = frame_size_q[FRAME_SIZE_WIDTH_LSB +: 16];
  wire [15:0] f_height   = frame_size_q[FRAME_SIZE_HEIGHT_LSB +: 16];

  // Soft reset writes of the last SOFT_RESET_CYCLES cycles.
  logic [SOFT_RESET_CYCLES-1:0] f_sr_hist = '0;
  always @(posedge clk_i) f_sr_hist <= rst_ni ? {f_sr_hist[SOFT_RESET_CYCLES-2:0], f_sr_write} : '0;
  // The soft reset cycles left after that history: SOFT_RESET_CYCLES - j for the last write,
  // j + 1 cycles ago (f_sr_left[0]).
  wire [31:0] f_sr_left [0:SOFT_RESET_CYCLES];
  assign f_sr_left[SOFT_RESET_CYCLES] = 32'd0;
  for (genvar j = 0; j < SOFT_RESET_CYCLES; j++) begin : g_f_sr_left
    assign f_sr_left[j] = f_sr_hist[j] ? 32'(SOFT_RESET_CYCLES - j) : f_sr_left[j + 1];
  end

  // ------------------------------------------------------------ registers, cycle to cycle
  always @(posedge clk_i) begin
    if (f_past_valid && !$past(rst_ni)) begin
      assert (ctrl_q == 32'd0 && frame_size_q == 32'd0 && penalty_q == PENALTY_RESET && config_q == CONFIG_RESET &&
              edge_reset_q == EDGE_RESET_RESET && irq_enable_q == 32'd0 && output_q == 32'd0 &&
              focal_q == 32'd0 && baseline_q == 32'd0 && dmin_q == 32'd0 && rectify_q == 32'd0 &&
              mesh_addr_q == 32'd0 && mesh_u_q == 32'd0 && mesh_v_q == 32'd0 && !mesh_we_q && !mesh_swap_q);
      assert (act_cfg == cfg_from_regs(32'd0, PENALTY_RESET, CONFIG_RESET, EDGE_RESET_RESET, 32'd0, 32'd0, 32'd0, 32'd0,
                                       32'd0));
      assert (error_q == '0 && irq_status_q == 2'd0 && error_count_q == 32'd0 && frames_q == 32'd0 &&
              last_size_q == 32'd0 && !core_reset);
    end
    if (f_past_valid && $past(rst_ni)) begin
      // RW registers
      assert (ctrl_q == ($past(f_wr && f_wa == ADDR_CTRL) ?
                         f_write($past(ctrl_q), $past(s_axil_wdata_i), $past(f_lanes), CTRL_MASK) : $past(ctrl_q)));
      assert (frame_size_q == ($past(f_wr && f_wa == ADDR_FRAME_SIZE) ?
                               f_write($past(frame_size_q), $past(s_axil_wdata_i), $past(f_lanes), FRAME_SIZE_MASK) :
                               $past(frame_size_q)));
      assert (penalty_q == ($past(f_wr && f_wa == ADDR_PENALTY) ?
                            f_write($past(penalty_q), $past(s_axil_wdata_i), $past(f_lanes), PENALTY_MASK) :
                            $past(penalty_q)));
      assert (config_q == ($past(f_wr && f_wa == ADDR_CONFIG) ?
                           f_write($past(config_q), $past(s_axil_wdata_i), $past(f_lanes), CONFIG_MASK) :
                           $past(config_q)));
      assert (edge_reset_q == ($past(f_wr && f_wa == ADDR_EDGE_RESET) ?
                               f_write($past(edge_reset_q), $past(s_axil_wdata_i), $past(f_lanes), EDGE_RESET_MASK) :
                               $past(edge_reset_q)));
      assert (irq_enable_q == ($past(f_wr && f_wa == ADDR_IRQ_ENABLE) ?
                               f_write($past(irq_enable_q), $past(s_axil_wdata_i), $past(f_lanes), IRQ_ENABLE_MASK) :
                               $past(irq_enable_q)));
      assert (output_q == ($past(f_wr && f_wa == ADDR_OUTPUT) ?
                           f_write($past(output_q), $past(s_axil_wdata_i), $past(f_lanes), OUTPUT_MASK) :
                           $past(output_q)));
      assert (focal_q == ($past(f_wr && f_wa == ADDR_DEPTH_FOCAL) ?
                          f_write($past(focal_q), $past(s_axil_wdata_i), $past(f_lanes), DEPTH_FOCAL_MASK) :
                          $past(focal_q)));
      assert (baseline_q == ($past(f_wr && f_wa == ADDR_DEPTH_BASELINE) ?
                             f_write($past(baseline_q), $past(s_axil_wdata_i), $past(f_lanes), DEPTH_BASELINE_MASK) :
                             $past(baseline_q)));
      assert (dmin_q == ($past(f_wr && f_wa == ADDR_MIN_DISPARITY) ?
                         f_write($past(dmin_q), $past(s_axil_wdata_i), $past(f_lanes), MIN_DISPARITY_MASK) :
                         $past(dmin_q)));
      assert (rectify_q == ($past(f_wr && f_wa == ADDR_RECTIFY) ?
                            f_write($past(rectify_q), $past(s_axil_wdata_i), $past(f_lanes), RECTIFY_MASK) :
                            $past(rectify_q)));
      assert (mesh_u_q == ($past(f_wr && f_wa == ADDR_MESH_U) ?
                           f_write($past(mesh_u_q), $past(s_axil_wdata_i), $past(f_lanes), MESH_U_MASK) :
                           $past(mesh_u_q)));
      assert (mesh_v_q == ($past(f_wr && f_wa == ADDR_MESH_V) ?
                           f_write($past(mesh_v_q), $past(s_axil_wdata_i), $past(f_lanes), MESH_V_MASK) :
                           $past(mesh_v_q)));
      // the mesh port: a store the cycle after each MESH_V write, at MESH_ADDR, then the column steps
      assert (mesh_we_q == $past(f_wr && f_wa == ADDR_MESH_V));
      assert (mesh_swap_q == $past(f_wr && f_wa == ADDR_MESH_CTRL && f_ones[MESH_CTRL_SWAP_LSB]));
      if ($past(f_wr && f_wa == ADDR_MESH_ADDR))
        assert (mesh_addr_q == f_write($past(mesh_addr_q), $past(s_axil_wdata_i), $past(f_lanes), MESH_ADDR_MASK));
      else if ($past(mesh_we_q))
        assert (mesh_addr_q == (($past(mesh_addr_q) & ~32'hFFF) | 32'(12'($past(mesh_addr_q[11:0]) + 12'd1))));
      else
        assert (mesh_addr_q == $past(mesh_addr_q));
      // W1C: an event in the cycle of its clear wins; no event is lost
      assert (error_q == (($past(error_q) & ~$past(f_err_clear)) | $past(error_event)));
      assert (($past(error_event) & ~error_q) == '0);
      assert (irq_status_q == (($past(irq_status_q) & ~$past(f_irq_clear)) | $past(f_irq_event)));
      assert (($past(f_irq_event) & ~irq_status_q) == 2'd0);
      // FRAMES and LAST_SIZE
      if ($past(frame_done)) begin
        assert (frames_q == $past(frames_q) + 32'd1);
        assert (last_size_q == {16'($past(frame_height)), 16'($past(frame_width))});
      end else begin
        assert (frames_q == $past(frames_q) && last_size_q == $past(last_size_q));
      end
      // The active configuration: frozen while HOLD, else the shadow registers of the cycle before
      if ($past(f_hold)) begin
        assert (act_cfg == $past(act_cfg));
      end else begin
        // the word as the register map packs it; its frame size whole (16 bits each)
        assert (act_cfg == cfg_from_regs($past(frame_size_q), $past(penalty_q), $past(config_q), $past(edge_reset_q),
                                         $past(output_q), $past(focal_q), $past(baseline_q), $past(dmin_q),
                                         $past(rectify_q)));
        assert (act_cfg[CFG_FRAME_SIZE_WIDTH_LSB +: 16] == $past(f_width) &&
                act_cfg[CFG_FRAME_SIZE_HEIGHT_LSB +: 16] == $past(f_height));
      end
    end
  end

  // ERROR_COUNT: one saturating byte per error kind, cleared by a write in its lane (to 1 when
  // an event of its kind comes in the cycle of the clear).
  for (genvar k = 0; k < ERROR_KINDS; k++) begin : g_f_count
    wire [7:0] f_count = error_count_q[k*8 +: 8];
    always @(posedge clk_i) begin
      if (f_past_valid && $past(rst_ni)) begin
        // a clear restarts the byte; an event in the cycle of its clear counts (is not lost)
        if ($past(f_wr && f_wa == ADDR_ERROR_COUNT && s_axil_wstrb_i[k])) assert (f_count == 8'($past(error_event[k])));
        else if ($past(error_event[k])) assert (f_count == ($past(f_count) == 8'hFF ? 8'hFF : $past(f_count) + 8'd1));
        else assert (f_count == $past(f_count));
      end
    end
  end

  // ------------------------------------------------------------ every cycle
  always @(*) begin
    if (f_past_valid) begin
      // reserved bits hold 0; SOFT_RESET is a pulse and reads 0
      assert ((ctrl_q & ~CTRL_MASK) == 32'd0 && !ctrl_q[CTRL_SOFT_RESET_LSB]);
      assert ((penalty_q & ~PENALTY_MASK) == 32'd0 && (config_q & ~CONFIG_MASK) == 32'd0);
      assert ((edge_reset_q & ~EDGE_RESET_MASK) == 32'd0 && (irq_enable_q & ~IRQ_ENABLE_MASK) == 32'd0);
      assert ((output_q & ~OUTPUT_MASK) == 32'd0 && (focal_q & ~DEPTH_FOCAL_MASK) == 32'd0 &&
              (baseline_q & ~DEPTH_BASELINE_MASK) == 32'd0 && (dmin_q & ~MIN_DISPARITY_MASK) == 32'd0);
      assert ((rectify_q & ~RECTIFY_MASK) == 32'd0 && (mesh_addr_q & ~MESH_ADDR_MASK) == 32'd0 &&
              (mesh_u_q & ~MESH_U_MASK) == 32'd0 && (mesh_v_q & ~MESH_V_MASK) == 32'd0);
    end
    assert (irq_o == ((irq_status_q[IRQ_STATUS_FRAME_DONE_LSB] && irq_enable_q[IRQ_ENABLE_FRAME_DONE_LSB]) ||
                      (irq_status_q[IRQ_STATUS_ERROR_LSB] && irq_enable_q[IRQ_ENABLE_ERROR_LSB])));
    if (f_past_valid) begin
      // soft reset: exactly SOFT_RESET_CYCLES cycles after the last write of SOFT_RESET
      assert (core_reset == (f_sr_hist != '0));
      assert (32'(soft_reset_q) == f_sr_left[0]);
    end
    // the input stream: held during a soft reset, and a start of frame while disabled
    if (core_reset) assert (!s_tready_o);
    else if (!f_enable && s_tuser_i) assert (!s_tready_o);
    else assert (s_tready_o == core_tready);
  end

  // ------------------------------------------------------------ responses
  // What a read of word address f_ra returns in this cycle: the register's value in the
  // layout of registers.md (undefined addresses: SLVERR, and the slave returns 0).
  logic [31:0] f_rvalue;
  always @(*) begin
    case (f_ra)
      ADDR_ID:          f_rvalue = ID_VALUE;
      ADDR_D:           f_rvalue = 32'(D);
      ADDR_MAX_WIDTH:   f_rvalue = 32'(MAX_WIDTH);
      ADDR_MAX_HEIGHT:  f_rvalue = 32'(MAX_HEIGHT);
      ADDR_CENSUS:      f_rvalue = CENSUS_VALUE;
      ADDR_MIN_WIDTH:   f_rvalue = 32'(core_min_width);
      ADDR_LANES:       f_rvalue = 32'(LANES);
      ADDR_FEATURES:    f_rvalue = FEATURES_VALUE;
      ADDR_CTRL:        f_rvalue = ctrl_q;
      ADDR_FRAME_SIZE:  f_rvalue = frame_size_q;
      ADDR_PENALTY:     f_rvalue = penalty_q;
      ADDR_CONFIG:      f_rvalue = config_q;
      ADDR_STATUS:      f_rvalue = (32'(busy) << STATUS_BUSY_LSB) | (32'(core_reset) << STATUS_RESETTING_LSB);
      ADDR_FRAMES:      f_rvalue = frames_q;
      ADDR_ERROR:       f_rvalue = 32'(error_q) << ERROR_LAST_EARLY_LSB;
      ADDR_ERROR_COUNT: f_rvalue = error_count_q;
      ADDR_LAST_SIZE:   f_rvalue = last_size_q;
      ADDR_EDGE_RESET:  f_rvalue = edge_reset_q;
      ADDR_IRQ_ENABLE:  f_rvalue = irq_enable_q;
      ADDR_IRQ_STATUS:  f_rvalue = 32'(irq_status_q);
      ADDR_OUTPUT:      f_rvalue = output_q;
      ADDR_DEPTH_FOCAL: f_rvalue = focal_q;
      ADDR_DEPTH_BASELINE: f_rvalue = baseline_q;
      ADDR_MIN_DISPARITY: f_rvalue = dmin_q;
      ADDR_RECTIFY:     f_rvalue = rectify_q;
      ADDR_MESH_ADDR:   f_rvalue = mesh_addr_q;
      ADDR_MESH_U:      f_rvalue = mesh_u_q;
      ADDR_MESH_V:      f_rvalue = mesh_v_q;
      ADDR_MESH_CTRL:   f_rvalue = (32'(mesh_pending) << 1) | (32'(mesh_row_miss) << 2);
      default:          f_rvalue = 32'd0;
    endcase
  end
  // The expected response of the outstanding write and read, taken at their acceptance
  // (one of each at a time: sgm_axil_slave_props.svh).
  logic        f_bexp_err, f_rexp_err;
  logic [31:0] f_rexp;
  always @(posedge clk_i) begin
    if (f_wr) f_bexp_err <= f_wa > F_LAST;
    if (f_rd) begin
      f_rexp_err <= f_ra > F_LAST;
      f_rexp     <= f_rvalue;
    end
  end
  always @(*) begin
    if (f_past_valid && s_axil_bvalid_o) assert (s_axil_bresp_o == (f_bexp_err ? 2'b10 : 2'b00));
    if (f_past_valid && s_axil_rvalid_o) begin
      assert (s_axil_rresp_o == (f_rexp_err ? 2'b10 : 2'b00));
      assert (s_axil_rdata_o == (f_rexp_err ? 32'd0 : f_rexp));
    end
  end

  // ------------------------------------------------------------ covers
  // A PENALTY write accepted while HOLD was 1 (since the last reset).
  logic f_held_write = 1'b0;
  always @(posedge clk_i) begin
    if (!rst_ni) f_held_write <= 1'b0;
    else if (f_wr && f_wa == ADDR_PENALTY && f_hold && f_lanes != 32'd0) f_held_write <= 1'b1;
  end
  always @(posedge clk_i) begin
    if (f_t == 2'd3 && rst_ni && $past(rst_ni)) begin
      cover (($past(f_err_clear & error_event)) != '0);
      cover (($past(f_irq_clear & f_irq_event)) != 2'd0);
      cover (irq_o && !$past(irq_o));
      cover ($past(core_reset) && !core_reset);
      cover (f_held_write && !$past(f_hold) && act_cfg != $past(act_cfg));
      cover (f_wr && f_wa > F_LAST);
      cover (error_count_q[7:0] == 8'd2);
      cover (mesh_we_q && mesh_addr_q[11:0] == 12'd1);  // the second node of a row stored
      cover ($past(f_wr && f_wa == ADDR_ERROR_COUNT && s_axil_wstrb_i[0] && error_event[0]) && error_count_q[7:0] == 8'd1);
    end
  end
