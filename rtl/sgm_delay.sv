`default_nettype none
// sgm_delay: DEPTH slots of delay for a WIDTH-bit bundle, advancing on en_i
// only (docs/rtl.md, step stream). Aligns side signals with a stage's latency.
//
// Parameters: WIDTH bits, DEPTH slots (>= 1).
// Latency: DEPTH slots. Throughput: one bundle per slot.
module sgm_delay #(
  parameter int WIDTH = 8,
  parameter int DEPTH = 1
) (
  input  wire              clk_i,
  input  wire              en_i,
  input  wire  [WIDTH-1:0] d_i,
  output logic [WIDTH-1:0] q_o
);

  logic [WIDTH-1:0] stage_q [0:DEPTH-1];

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      stage_q[0] <= d_i;
      for (int i = 1; i < DEPTH; i++) stage_q[i] <= stage_q[i-1];
    end
  end

  assign q_o = stage_q[DEPTH-1];

endmodule
`default_nettype wire
