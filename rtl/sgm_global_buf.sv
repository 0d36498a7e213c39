// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_global_buf: a net of very high fan-out onto the FPGA's clock network.
//
// The pipeline enable of sgm_top reaches every flip-flop of the datapath
// (about 64,000 at D = 64 with six lanes). Routed through the fabric it is the
// most congested net of the ECP5 place and route (router2's congestion map of
// D = 64 at six lanes, docs/notes/synthesis-log.md, "Place and route"). With the macro
// SGM_ECP5_GLOBAL defined (the ECP5 flow, synth/pnr.mk PNR_DEFINES) the net
// goes through a DCCA, the ECP5 clock-network buffer, and nextpnr routes it on
// one of the global networks that reach every slice; otherwise (simulation, the
// other flows, whose tools promote or replicate such nets themselves) the
// module is a wire.
//
// Parameters: none. Latency: 0 (combinational; on ECP5 the global network's
// insertion delay, which nextpnr's timing analysis includes).
module sgm_global_buf (
  input  wire sig_i,
  output wire sig_o
);

`ifdef SGM_ECP5_GLOBAL
  DCCA u_dcca (
    .CLKI (sig_i),
    .CE   (1'b1),
    .CLKO (sig_o)
  );
`else
  assign sig_o = sig_i;
`endif

endmodule
`default_nettype wire
