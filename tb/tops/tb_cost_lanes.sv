`default_nettype none
// tb_cost_lanes: test wrapper for tests/rtl/test_tb_cost_lanes.cpp:
// sgm_cost_volume (9x5 census) built with LANES, its parameters public so
// that the test reads the build's D, LANES and latency. The test drives the
// census of both images straight from the golden model, slots in lane order.
module tb_cost_lanes #(
  parameter int D     /*verilator public*/ = 16,
  parameter int LANES /*verilator public*/ = 2,
  parameter int CW    = 8
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [1:0]       mode_i,
  input  wire  [43:0]      lcensus_i,
  input  wire  [5:0]       lrank_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [43:0]      rcensus_i,
  input  wire  [5:0]       rrank_i,
  input  wire              valid_i,
  output logic [D*7-1:0]   cost_o,
  output logic [CW-1:0]    col_o,
  output logic             valid_o
);

  // Mirror of sgm_cost_volume::LATENCY (checked by the test's slot arithmetic).
  localparam int COST_LATENCY /*verilator public*/ = 3;

  sgm_cost_volume #(.D(D), .CW(CW), .NB(44), .LANES(LANES)) u_cost (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .en_i      (en_i),
    .mode_i    (mode_i),
    .lcensus_i (lcensus_i),
    .lrank_i   (lrank_i),
    .col_i     (col_i),
    .rcensus_i (rcensus_i),
    .rrank_i   (rrank_i),
    .valid_i   (valid_i),
    .cost_o    (cost_o),
    .col_o     (col_o),
    .valid_o   (valid_o)
  );

endmodule
`default_nettype wire
