// SPDX-License-Identifier: Apache-2.0
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
// the Hamming distance as the popcount's group counts (sgm_popcount groups_o:
// the xor, the full adders and the 6:3 counters are the whole stage; with the
// group sums behind them it would be the LFE5U-85F five-lane core's critical path,
// 7.7 to 8.7 ns) and the out-of-image flag of the slot. Stage B selects by
// mode_i, which belongs to stage B's slot (the slot entered one enabled cycle
// earlier), and registers the three operands of the cost: the Hamming distance
// (the group sums), the rank term (diff xor sign; its + sign is the carry in
// of stage C) and the carry, each already selected by the mode and the
// out-of-image case (Cmax). Beside them, stage A registers min(AD, T) (T when
// outside), stage B its product with W (four shifted copies, divided by 8), and
// stage C adds the four: C = ham + rt + carry + term, one three-operand sum.
// AD_TERM = 0 builds no AD term (no min, product or sum; the gray and AD
// inputs are ignored, sgm_stream_ctrl drops frames that ask for it): stage C
// then adds the census cost alone, so the latency stays 3.
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
  input  wire  [8:0]        ad_lo_i,      // gray_L - T (9-bit two's complement), stage A's slot
  input  wire  [8:0]        ad_hi_i,      // gray_L + T, stage A's slot
  input  wire  [3:0]        ad_weight_i,  // W, stage B's slot (one enabled cycle behind stage A's)
  output logic [CBITS-1:0]  cost_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(NB == 44 || NB == 80)) begin : g_bad_nb
    $error("sgm_cost_pe: NB = %0d: NB must be 44 or 80 (9 CENSUS_H - 1 census bits, CENSUS_H 5 or 9)", NB);
  end
  if (!(AD_TERM == 0 || AD_TERM == 1)) begin : g_bad_ad_term
    $error("sgm_cost_pe: AD_TERM = %0d: AD_TERM must be 0 or 1", AD_TERM);
  end
`endif

  // The Hamming distance as the popcount's group counts (hamming = the weight-1
  // groups + 2 the weight-2 groups): stage A registers them, stage B sums them.
  localparam int G = ((NB + 2) / 3 + 5) / 6;  // groups per weight (sgm_popcount's G)
  logic [RKW-1:0] ham_ones1;  // the popcount's own sums: not used here
  logic [RKW-2:0] ham_ones2;
  logic [6*G-1:0] ham_groups;
  sgm_popcount #(.N(NB)) u_hamming (
    .bits_i   (lcensus_i ^ rcensus_i),
    .ones1_o  (ham_ones1),
    .ones2_o  (ham_ones2),
    .groups_o (ham_groups)
  );
  wire unused_ones = ^{ham_ones1, ham_ones2};

  // Stage A
  logic [RKW:0]   diff_q;  // lrank - rrank, two's complement (-NB .. NB)
  logic [6*G-1:0] grp_q;
  logic           out_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      diff_q <= {1'b0, lrank_i} - {1'b0, rrank_i};
      grp_q  <= ham_groups;
      out_q  <= outside_i;
    end
  end

  // Stage A, AD term: |gray_L - gray_R| from the two differences (the one that
  // does not borrow), truncated at T; stage B its product with W, divided by 8
  // (below 2^CBITS: see the header). AD > T iff gray_R < gray_L - T or gray_R >
  // gray_L + T: the caller's gray_L -+ T make both tests one comparison each,
  // beside the differences rather than behind them (the difference, then its
  // comparison with T, would be the LFE5U-85F five-lane core's critical path at
  // 8.1 ns).
  logic [CBITS-1:0] term_q;
  if (AD_TERM != 0) begin : g_ad
    wire [8:0] gd_lr = {1'b0, lgray_i} - {1'b0, rgray_i};
    wire [7:0] gd_rl = rgray_i - lgray_i;
    wire [7:0] ad    = gd_lr[8] ? gd_rl : gd_lr[7:0];
    wire       above = !ad_lo_i[8] && rgray_i < ad_lo_i[7:0];  // gray_L - gray_R > T
    wire       below = {1'b0, rgray_i} > ad_hi_i;              // gray_R - gray_L > T
    logic [7:0] adm_q;  // min(AD, T), T outside the image
    always_ff @(posedge clk_i) begin
      if (en_i) adm_q <= outside_i || above || below ? ad_cap_i : ad;
    end
    wire [11:0] prod = (ad_weight_i[0] ? 12'(adm_q) : 12'd0) + (ad_weight_i[1] ? 12'(adm_q) << 1 : 12'd0) +
                       (ad_weight_i[2] ? 12'(adm_q) << 2 : 12'd0) + (ad_weight_i[3] ? 12'(adm_q) << 3 : 12'd0);
    always_ff @(posedge clk_i) begin
      if (en_i) term_q <= prod[3 +: CBITS];
    end
    wire unused_prod = ^{prod[2:0], prod[11:3+CBITS]};  // the division by 8; above 2^CBITS: excluded
  end else begin : g_no_ad
    assign term_q = '0;
    wire unused_ad = ^{lgray_i, rgray_i, ad_cap_i, ad_lo_i, ad_hi_i, ad_weight_i};
  end

  // Stage B: the operands of C = ham_op + rt_op + rt_cin (+ the AD term):
  //   out_q:   ham_op = NB + (unified ? NB : 0), rt_op = 0, rt_cin = 0
  //   mode 0:  rt_op = diff ^ sign, rt_cin = sign: rt
  //   mode 1:  ham_op = ham
  //   unified: both: rt + rsad
  wire             neg     = diff_q[RKW];
  wire             use_rt  = mode_i != 2'd1;
  wire             use_ham = mode_i != 2'd0;
  wire [CBITS-1:0] cmax1   = CBITS'(NB);  // Cmax of rt and rsad, half of unified's
  wire [RKW-1:0]   rt_xor  = diff_q[RKW-1:0] ^ {RKW{neg}};
  logic [CBITS-1:0] ones1, ones2;  // the weight-1 and weight-2 group sums
  always_comb begin
    ones1 = '0;
    ones2 = '0;
    for (int g = 0; g < G; g++) begin
      ones1 = ones1 + CBITS'(grp_q[3*g +: 3]);
      ones2 = ones2 + CBITS'(grp_q[3*(G+g) +: 3]);
    end
  end
  wire [CBITS-1:0] ham = ones1 + (ones2 << 1);  // the Hamming distance (<= NB)

  logic [CBITS-1:0] ham_q, rt_q;
  logic             cin_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ham_q <= out_q ? (mode_i[1] ? CBITS'(2) * cmax1 : cmax1) : use_ham ? ham : '0;
      rt_q  <= !out_q && use_rt ? CBITS'(rt_xor) : '0;
      cin_q <= !out_q && use_rt && neg;
    end
  end

  // Stage C: C = census cost + AD term (no wrap: see the header; AD_TERM = 0: + 0).
  always_ff @(posedge clk_i) begin
    if (en_i) cost_o <= ham_q + rt_q + term_q + CBITS'(cin_q);
  end

endmodule
`default_nettype wire
