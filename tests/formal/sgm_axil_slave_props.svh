// SPDX-License-Identifier: Apache-2.0
// The formal property set of sgm_axil_slave (make formal, docs/formal.md). Included in the
// module's body when SGM_FORMAL is defined (tests/formal/*.sby: yosys read -formal
// -DSGM_FORMAL); no other flow defines it. Its names start with f_.
//
// Assumed of the AXI4-Lite master (the top-level inputs): the first cycle is in reset;
// AWVALID, WVALID and ARVALID are low while rst_ni is low; once raised, a VALID stays
// high until its READY, with its address, protection, data and strobes unchanged (a reset
// ends the transfer). BREADY and RREADY are free, and so is the register file's answer
// (reg_werr_i, reg_rerr_i, reg_rdata_i): any value in any cycle.
//
// Asserted of the slave:
//   reset          no response is pending in the cycle after a reset cycle;
//   hold           BVALID and RVALID stay high until BREADY / RREADY, BRESP, RRESP and
//                  RDATA unchanged while held;
//   one at a time  counted per channel, writes accepted (AW and W handshakes) minus B
//                  handshakes and reads accepted minus R handshakes are exactly BVALID
//                  and RVALID: at most one write and one read outstanding, no response
//                  without its request, no request lost;
//   decode         BRESP is SLVERR exactly when reg_werr_i was high at the write's
//                  acceptance; RRESP likewise with reg_rerr_i, RDATA is reg_rdata_i of
//                  that cycle, or 0 with SLVERR;
//   register port  reg_we_o is high exactly in the cycles a write is accepted (one strobe
//                  per write) with the accepted address, data and strobes on reg_waddr_o,
//                  reg_wdata_o, reg_wstrb_o; reg_re_o exactly when a read is accepted,
//                  with its address on reg_raddr_o;
//   the slave's own promises (its header): AW and W are accepted together (AWREADY =
//                  WREADY), a write is accepted whenever AWVALID and WVALID are high and
//                  no write response waits, a read whenever ARVALID is high and no read
//                  response waits (so the slave never stalls a master that takes its
//                  responses).
// Covered: a write and a read completing with OKAY and with SLVERR, B and R held two
// cycles by the master, writes and reads back to back at the slave's full rate (one
// every 2 cycles), a read and a write accepted in one cycle, a reset while responses wait.

  localparam logic [1:0] F_OKAY   = 2'b00;
  localparam logic [1:0] F_SLVERR = 2'b10;

  // Cycles since the start, saturating at 3: $past(x, n) is meaningful from f_t >= n.
  logic [1:0] f_t = 2'd0;
  always @(posedge clk_i) if (f_t != 2'd3) f_t <= f_t + 2'd1;
  wire f_past_valid = f_t != 2'd0;

  wire f_aw_hs = s_axil_awvalid_i && s_axil_awready_o;
  wire f_w_hs  = s_axil_wvalid_i && s_axil_wready_o;
  wire f_b_hs  = s_axil_bvalid_o && s_axil_bready_i;
  wire f_ar_hs = s_axil_arvalid_i && s_axil_arready_o;
  wire f_r_hs  = s_axil_rvalid_o && s_axil_rready_i;

  // ------------------------------------------------------------ the master (assumed)
  always @(*) begin
    if (!f_past_valid) assume (!rst_ni);
    if (!rst_ni) assume (!s_axil_awvalid_i && !s_axil_wvalid_i && !s_axil_arvalid_i);
  end

  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni) begin
      if ($past(s_axil_awvalid_i && !s_axil_awready_o))
        assume (s_axil_awvalid_i && s_axil_awaddr_i == $past(s_axil_awaddr_i) && s_axil_awprot_i == $past(s_axil_awprot_i));
      if ($past(s_axil_wvalid_i && !s_axil_wready_o))
        assume (s_axil_wvalid_i && s_axil_wdata_i == $past(s_axil_wdata_i) && s_axil_wstrb_i == $past(s_axil_wstrb_i));
      if ($past(s_axil_arvalid_i && !s_axil_arready_o))
        assume (s_axil_arvalid_i && s_axil_araddr_i == $past(s_axil_araddr_i) && s_axil_arprot_i == $past(s_axil_arprot_i));
    end
  end

  // ------------------------------------------------------------ outstanding transactions
  // Accepted requests minus responses taken, per channel (2 bits: an excess shows).
  logic [1:0] f_aw_out = 2'd0, f_w_out = 2'd0, f_ar_out = 2'd0;
  // The register file's answer at the acceptance of the outstanding write and read.
  logic        f_werr, f_rerr;
  logic [31:0] f_rdata;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_aw_out <= 2'd0;
      f_w_out  <= 2'd0;
      f_ar_out <= 2'd0;
    end else begin
      f_aw_out <= f_aw_out + 2'(f_aw_hs) - 2'(f_b_hs);
      f_w_out  <= f_w_out + 2'(f_w_hs) - 2'(f_b_hs);
      f_ar_out <= f_ar_out + 2'(f_ar_hs) - 2'(f_r_hs);
    end
    if (f_aw_hs) f_werr <= reg_werr_i;
    if (f_ar_hs) begin
      f_rerr  <= reg_rerr_i;
      f_rdata <= reg_rdata_i;
    end
  end

  // ------------------------------------------------------------ the slave (asserted)
  always @(posedge clk_i) begin
    if (f_past_valid && !$past(rst_ni)) assert (!s_axil_bvalid_o && !s_axil_rvalid_o);
    if (f_past_valid && $past(rst_ni)) begin
      if ($past(s_axil_bvalid_o && !s_axil_bready_i))
        assert (s_axil_bvalid_o && s_axil_bresp_o == $past(s_axil_bresp_o));
      if ($past(s_axil_rvalid_o && !s_axil_rready_i))
        assert (s_axil_rvalid_o && s_axil_rresp_o == $past(s_axil_rresp_o) && s_axil_rdata_o == $past(s_axil_rdata_o));
    end
  end

  always @(*) begin
    if (f_past_valid) begin
      assert (f_aw_out == {1'b0, s_axil_bvalid_o});
      assert (f_w_out == {1'b0, s_axil_bvalid_o});
      assert (f_ar_out == {1'b0, s_axil_rvalid_o});
      if (s_axil_bvalid_o) assert (s_axil_bresp_o == (f_werr ? F_SLVERR : F_OKAY));
      if (s_axil_rvalid_o) begin
        assert (s_axil_rresp_o == (f_rerr ? F_SLVERR : F_OKAY));
        assert (s_axil_rdata_o == (f_rerr ? 32'd0 : f_rdata));
      end
    end
    assert (reg_we_o == f_aw_hs);
    assert (reg_re_o == f_ar_hs);
    if (reg_we_o) begin
      assert (reg_waddr_o == s_axil_awaddr_i);
      assert (reg_wdata_o == s_axil_wdata_i);
      assert (reg_wstrb_o == s_axil_wstrb_i);
    end
    if (reg_re_o) assert (reg_raddr_o == s_axil_araddr_i);
    assert (f_aw_hs == f_w_hs);
    if (s_axil_awvalid_i && s_axil_wvalid_i && !s_axil_bvalid_o) assert (s_axil_awready_o && s_axil_wready_o);
    if (s_axil_arvalid_i && !s_axil_rvalid_o) assert (s_axil_arready_o);
  end

  // ------------------------------------------------------------ covers
  always @(posedge clk_i) begin
    if (f_t == 2'd3 && rst_ni) begin
      cover (f_b_hs && s_axil_bresp_o == F_OKAY);
      cover (f_r_hs && s_axil_rresp_o == F_OKAY && s_axil_rdata_o != 32'd0);
      cover (f_b_hs && s_axil_bresp_o == F_SLVERR);
      cover (f_r_hs && s_axil_rresp_o == F_SLVERR);
      cover (f_b_hs && $past(s_axil_bvalid_o && !s_axil_bready_i) && $past(s_axil_bvalid_o && !s_axil_bready_i, 2));
      cover (f_r_hs && $past(s_axil_rvalid_o && !s_axil_rready_i) && $past(s_axil_rvalid_o && !s_axil_rready_i, 2));
      cover (f_aw_hs && $past(f_b_hs) && $past(f_aw_hs, 2));
      cover (f_ar_hs && $past(f_r_hs) && $past(f_ar_hs, 2));
      cover (f_aw_hs && f_ar_hs);
    end
    if (f_past_valid) cover (!rst_ni && s_axil_bvalid_o && s_axil_rvalid_o);
  end
