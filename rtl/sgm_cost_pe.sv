`default_nettype none
// sgm_cost_pe: matching cost C(p, d) of one disparity d (docs/algorithm.md
// section 3) from the left census/rank at x and the right census/rank at x - d:
//   rt      = |rank_L - rank_R|                      (mode 0)
//   rsad    = popcount(census_L xor census_R)        (mode 1)
//   unified = rt + rsad                              (mode 2, also 3)
//   outside_i (x - d < 0, decided by the caller): Cmax of the mode (80, 80, 160).
//
// Parameters: none (the disparity only enters through outside_i).
// Latency: 2 enabled cycles. Stage A registers |rank difference|, Hamming
// distance and the out-of-image flag of the slot; stage B selects by mode_i,
// which belongs to stage B's slot (the slot entered one enabled cycle earlier).
// Throughput: one cost per enabled cycle. No control registers, no reset.
module sgm_cost_pe (
  input  wire             clk_i,
  input  wire             en_i,
  input  wire  [1:0]      mode_i,
  input  wire  [79:0]     lcensus_i,
  input  wire  [6:0]      lrank_i,
  input  wire  [79:0]     rcensus_i,
  input  wire  [6:0]      rrank_i,
  input  wire             outside_i,
  output logic [7:0]      cost_o
);

  logic [6:0] hamming;
  sgm_popcount80 u_hamming (
    .bits_i  (lcensus_i ^ rcensus_i),
    .count_o (hamming)
  );

  // Stage A
  logic [6:0] rt_q, ham_q;
  logic       out_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rt_q  <= lrank_i >= rrank_i ? lrank_i - rrank_i : rrank_i - lrank_i;
      ham_q <= hamming;
      out_q <= outside_i;
    end
  end

  // Stage B
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      case (mode_i)
        2'd0:    cost_o <= out_q ? 8'd80  : {1'b0, rt_q};
        2'd1:    cost_o <= out_q ? 8'd80  : {1'b0, ham_q};
        default: cost_o <= out_q ? 8'd160 : {1'b0, rt_q} + {1'b0, ham_q};
      endcase
    end
  end

endmodule
`default_nettype wire
