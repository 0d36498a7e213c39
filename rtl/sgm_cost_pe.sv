`default_nettype none
// sgm_cost_pe: matching cost C(p, d) of one disparity d (docs/algorithm.md
// section 3) from the left census/rank at x and the right census/rank at x - d:
//   rt      = |rank_L - rank_R|                      (mode 0)
//   rsad    = popcount(census_L xor census_R)        (mode 1)
//   unified = rt + rsad                              (mode 2; 3 is rejected upstream,
//                                                     but computes unified here)
//   outside_i (x - d < 0, decided by the caller): Cmax of the mode (44, 44, 88).
//
// Parameters: none (the disparity only enters through outside_i).
// Latency: 2 enabled cycles. Stage A registers the rank difference (signed),
// the Hamming distance as its two weighted counts (sgm_popcount ones1_o + 2
// ones2_o; the popcount with its own final adder was the 5-lane core's critical
// path at 10.1 ns on ECP5) and the out-of-image flag of the slot; stage B
// selects by mode_i, which belongs to stage B's slot (the slot entered one
// enabled cycle earlier), and is one three-operand sum: the
// mode and the out-of-image case select its operands, and |rank difference| =
// (diff xor sign) + sign takes its +sign as the carry in, so no separate
// absolute value or output mux.
// Throughput: one cost per enabled cycle. No control registers, no reset.
module sgm_cost_pe #(
  parameter int  NB    = 44,
  localparam int RKW   = $clog2(NB + 1),
  localparam int CBITS = $clog2(2 * NB + 1)
) (
  input  wire               clk_i,
  input  wire               en_i,
  input  wire  [1:0]        mode_i,
  input  wire  [NB-1:0]     lcensus_i,
  input  wire  [RKW-1:0]    lrank_i,
  input  wire  [NB-1:0]     rcensus_i,
  input  wire  [RKW-1:0]    rrank_i,
  input  wire               outside_i,
  output logic [CBITS-1:0]  cost_o
);

  // The Hamming distance as its two weighted counts (hamming = ham1 + 2 ham2):
  // stage A registers them, stage B adds them into the cost.
  logic [RKW-1:0] ham1;
  logic [RKW-2:0] ham2;
  sgm_popcount #(.N(NB)) u_hamming (
    .bits_i  (lcensus_i ^ rcensus_i),
    .ones1_o (ham1),
    .ones2_o (ham2)
  );

  // Stage A
  logic [RKW:0]   diff_q;  // lrank - rrank, two's complement (-NB .. NB)
  logic [RKW-1:0] ham1_q;
  logic [RKW-2:0] ham2_q;
  logic           out_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      diff_q <= {1'b0, lrank_i} - {1'b0, rrank_i};
      ham1_q <= ham1;
      ham2_q <= ham2;
      out_q  <= outside_i;
    end
  end

  // Stage B: cost = rt_op + ham_op + rt_cin.
  //   out_q:   NB + (unified ? NB : 0)
  //   mode 0:  (diff ^ sign) + sign      = rt
  //   mode 1:  ham
  //   unified: (diff ^ sign) + ham + sign = rt + rsad
  wire             neg     = diff_q[RKW];
  wire             use_rt  = mode_i != 2'd1;
  wire             use_ham = mode_i != 2'd0;
  wire [CBITS-1:0] cmax1   = CBITS'(NB);  // Cmax of rt and rsad, half of unified's
  wire [RKW-1:0]   rt_xor  = diff_q[RKW-1:0] ^ {RKW{neg}};
  wire [CBITS-1:0] rt_op   = out_q ? cmax1 : use_rt ? CBITS'(rt_xor) : '0;
  wire [CBITS-1:0] ham_op  = out_q ? (mode_i[1] ? cmax1 : '0) : use_ham ? CBITS'(ham1_q) : '0;
  wire [CBITS-1:0] ham2_op = !out_q && use_ham ? CBITS'({ham2_q, 1'b0}) : '0;
  wire             rt_cin  = !out_q && use_rt && neg;

  always_ff @(posedge clk_i) begin
    if (en_i) cost_o <= rt_op + ham_op + ham2_op + CBITS'(rt_cin);
  end

endmodule
`default_nettype wire
