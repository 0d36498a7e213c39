// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_axil_slave: an AXI4-Lite slave (32-bit data) turned into a simple
// register port: one write strobe (address, data, byte strobes) and one read
// strobe (address) per transaction, each answered in the same cycle by the
// register file with an error flag (SLVERR) and, for reads, the data.
//
// One transaction of each kind at a time: a write is taken when both AWVALID
// and WVALID are high and no write response is waiting (AWREADY = WREADY, the
// AXI rule lets a slave wait for both); a read when no read response is
// waiting. Responses are registered and held until BREADY / RREADY. Reads and
// writes are independent (a read and a write may be taken in the same cycle).
// AWPROT / ARPROT are accepted and ignored.
//
// Parameters: ADDR_W address bits (byte addresses; bits [1:0] are ignored).
// Latency: the response one cycle after the request is taken.
// Throughput: one write every 2 cycles and one read every 2 cycles when the
// master is always ready.
module sgm_axil_slave #(
  parameter int ADDR_W = 8
) (
  input  wire               clk_i,
  input  wire               rst_ni,
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
  // Register port
  output logic              reg_we_o,      // one cycle per write
  output logic [ADDR_W-1:0] reg_waddr_o,
  output logic [31:0]       reg_wdata_o,
  output logic [3:0]        reg_wstrb_o,
  input  wire               reg_werr_i,    // the write address is not a register (SLVERR)
  output logic              reg_re_o,      // one cycle per read
  output logic [ADDR_W-1:0] reg_raddr_o,
  input  wire  [31:0]       reg_rdata_i,
  input  wire               reg_rerr_i     // the read address is not a register (SLVERR)
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(ADDR_W >= 3 && ADDR_W <= 32)) begin : g_bad_addr_w
    $error("sgm_axil_slave: ADDR_W = %0d: ADDR_W must be from 3 to 32 (byte addresses, bits [1:0] ignored)", ADDR_W);
  end
`endif

  localparam logic [1:0] RESP_OKAY   = 2'b00;
  localparam logic [1:0] RESP_SLVERR = 2'b10;

  // ------------------------------------------------------------ write
  wire take_write = s_axil_awvalid_i && s_axil_wvalid_i && !s_axil_bvalid_o;

  assign s_axil_awready_o = take_write;
  assign s_axil_wready_o  = take_write;
  assign reg_we_o         = take_write;
  assign reg_waddr_o      = s_axil_awaddr_i;
  assign reg_wdata_o      = s_axil_wdata_i;
  assign reg_wstrb_o      = s_axil_wstrb_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s_axil_bvalid_o <= 1'b0;
      s_axil_bresp_o  <= RESP_OKAY;
    end else if (take_write) begin
      s_axil_bvalid_o <= 1'b1;
      s_axil_bresp_o  <= reg_werr_i ? RESP_SLVERR : RESP_OKAY;
    end else if (s_axil_bready_i) begin
      s_axil_bvalid_o <= 1'b0;
    end
  end

  // ------------------------------------------------------------ read
  assign s_axil_arready_o = !s_axil_rvalid_o;
  assign reg_re_o         = s_axil_arvalid_i && !s_axil_rvalid_o;
  assign reg_raddr_o      = s_axil_araddr_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s_axil_rvalid_o <= 1'b0;
      s_axil_rresp_o  <= RESP_OKAY;
      s_axil_rdata_o  <= '0;
    end else if (reg_re_o) begin
      s_axil_rvalid_o <= 1'b1;
      s_axil_rresp_o  <= reg_rerr_i ? RESP_SLVERR : RESP_OKAY;
      s_axil_rdata_o  <= reg_rerr_i ? 32'd0 : reg_rdata_i;
    end else if (s_axil_rready_i) begin
      s_axil_rvalid_o <= 1'b0;
    end
  end

  wire unused = &{1'b0, s_axil_awprot_i, s_axil_arprot_i};

`ifdef SGM_FORMAL
  // The formal property set (tests/formal/sgm_axil_slave_props.svh; make formal, docs/formal.md).
`include "sgm_axil_slave_props.svh"
`endif

endmodule
`default_nettype wire
