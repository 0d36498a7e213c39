`default_nettype none
// sgm_cost_pe: matching cost C(p, d) of one disparity d (docs/algorithm.md
// section 3) from the left census/rank at x and the right census/rank at x - d:
//   rt      = |rank_L - rank_R|                      (mode 0)
//   rsad    = popcount(census_L xor census_R)        (mode 1)
//   unified = rt + rsad                              (mode 2; 3 is rejected upstream,
//                                                     but computes unified here)
//   outside_i (x - d < 0, decided by the caller): Cmax of the mode (44, 44, 88).
// plus the AD term (W = ad_weight_i, T = ad_cap_i; W = 0: off):
//   C += (W min(|gray_L - gray_R|, T)) >> 3     (outside: (W T) >> 3)
// The caller keeps Cmax + (W T) >> 3 below 2^CBITS (sgm_stream_ctrl rejects
// other settings), so the sum never wraps.
//
// Parameters: NB census bits, AD_TERM (the disparity only enters through outside_i).
// Latency: 3 enabled cycles. Stage A registers the rank difference (signed),
// the Hamming distance as its two weighted counts (sgm_popcount ones1_o + 2
// ones2_o; the popcount with its own final adder was the 5-lane core's critical
// path at 10.1 ns on ECP5) and the out-of-image flag of the slot; stage B
// selects by mode_i, which belongs to stage B's slot (the slot entered one
// enabled cycle earlier), and is one three-operand sum: the
// mode and the out-of-image case select its operands, and |rank difference| =
// (diff xor sign) + sign takes its +sign as the carry in, so no separate
// absolute value or output mux. Beside them, stage A registers min(AD, T) (T when
// outside), stage B its product with W (four shifted copies, divided by 8),
// and stage C adds the two.
// AD_TERM = 0 builds no AD term (no min, product or sum; the gray and AD
// inputs are ignored, sgm_stream_ctrl drops frames that ask for it): stage C
// then registers the census cost alone, so the latency stays 3.
// Throughput: one cost per enabled cycle. No control registers, no reset.
module sgm_cost_pe #(
  parameter int  NB    = 44,
  parameter int  AD_TERM = 1,   // 1: the AD term is built; 0: not (C = the census cost)
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
  input  wire  [7:0]        lgray_i,      // stage A's slot, with lcensus_i
  input  wire  [7:0]        rgray_i,      // stage A's slot, with rcensus_i
  input  wire  [7:0]        ad_cap_i,     // T, stage A's slot
  input  wire  [3:0]        ad_weight_i,  // W, stage B's slot (one enabled cycle behind stage A's)
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

  // Stage A, AD term: |gray_L - gray_R| from the two differences (the one that
  // does not borrow), truncated at T; stage B its product with W, divided by 8
  // (below 2^CBITS: see the header).
  logic [CBITS-1:0] term_q;
  if (AD_TERM != 0) begin : g_ad
    wire [8:0] gd_lr = {1'b0, lgray_i} - {1'b0, rgray_i};
    wire [7:0] gd_rl = rgray_i - lgray_i;
    wire [7:0] ad    = gd_lr[8] ? gd_rl : gd_lr[7:0];
    logic [7:0] adm_q;  // min(AD, T), T outside the image
    always_ff @(posedge clk_i) begin
      if (en_i) adm_q <= outside_i || ad > ad_cap_i ? ad_cap_i : ad;
    end
    wire [11:0] prod = (ad_weight_i[0] ? 12'(adm_q) : 12'd0) + (ad_weight_i[1] ? 12'(adm_q) << 1 : 12'd0) +
                       (ad_weight_i[2] ? 12'(adm_q) << 2 : 12'd0) + (ad_weight_i[3] ? 12'(adm_q) << 3 : 12'd0);
    always_ff @(posedge clk_i) begin
      if (en_i) term_q <= prod[3 +: CBITS];
    end
    wire unused_prod = ^{prod[2:0], prod[11:3+CBITS]};  // the division by 8; above 2^CBITS: excluded
  end else begin : g_no_ad
    assign term_q = '0;
    wire unused_ad = ^{lgray_i, rgray_i, ad_cap_i, ad_weight_i};
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

  logic [CBITS-1:0] cen_q;   // the census cost
  always_ff @(posedge clk_i) begin
    if (en_i) cen_q <= rt_op + ham_op + ham2_op + CBITS'(rt_cin);
  end

  // Stage C: C = census cost + AD term (no wrap: see the header; AD_TERM = 0: + 0).
  always_ff @(posedge clk_i) begin
    if (en_i) cost_o <= cen_q + term_q;
  end

endmodule
`default_nettype wire
