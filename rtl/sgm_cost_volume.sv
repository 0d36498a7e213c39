// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_cost_volume: the right census/rank delay line and D cost PEs
// (docs/algorithm.md section 3). For the slot entering at t it outputs the
// costs C(p, d), d = 0 .. D-1, of the left centre p of that slot.
//
// Inputs per slot (same slot of the left and right sgm_census_unit): left and
// right census/rank, the centre column col_i and valid_i; mode_i (0 rt, 1 rsad,
// 2 unified; 3 behaves as unified) is sampled with the slot and travels with
// it, so the top presents each frame's mode aligned with the census outputs;
// likewise the AD term's weight and cap (ad_weight_i, ad_cap_i; weight 0: off)
// with the centre grays lgray_i / rgray_i of the census units (sgm_cost_pe).
//
// Delay line: tap d holds the right census/rank of the slot d K slots earlier
// (K = LANES), which is right pixel x - d of the same row whenever x - d >= 0
// (the slots of a lane are consecutive positions of its rows, flush slots
// included, and lane k has every K-th slot: docs/lanes.md; K = 1 is the
// raster). Entries from another row or frame are only reached when col - d <
// 0, where the PE outputs Cmax.
//
// Structure: s1 input registers and the delay line (D taps of (NB + RKW + 8) bit
// registers, 58 / 95: census, rank and gray (AD_TERM = 0: 50 / 87), tap 0 = the slot's own right census; with K > 1 the
// K - 1 slots between two taps are one sgm_delay_ram of (D - 1) taps' width:
// a (K - 1)-word distributed RAM at a rotating pointer), s2 .. s4
// the three PE stages (sgm_cost_pe).
//
// MIN_DISPARITY = 1 builds the minimum disparity (docs/algorithm.md section 3): C(p, d)
// compares left x with right x - dmin - d, so the right entry enters the delay line
// dmin K slots late: for dmin K >= 3 from a memory of 2^ceil(log2(256 K)) entries written
// every slot and read dmin K - 2 slots behind (a synchronous read and one more register),
// for dmin K = 1, 2 from two registers; and PE d is outside when x - dmin - d < 0
// (its bound d + dmin registered, dmin_i being a constant of the frame). 0: none, dmin_i
// unused.
//
// AD_TERM = 0 builds no AD term: the PEs without it (sgm_cost_pe), the delay
// line without the gray (NB + RKW bit taps), no weight, cap or left gray
// registers; the AD inputs are ignored (sgm_stream_ctrl drops frames that ask
// for the term). The latency is the same.
//
// Parameters: D disparities, CW column bits, NB census bits (44 for the 9x5 census,
// 80 for the 9x9), LANES (K >= 1), AD_TERM (1: the AD term is built, 0: not),
// MIN_DISPARITY (1: the minimum disparity is built, 0: not);
// RKW rank bits and CBITS cost bits follow.
// Latency: LATENCY = 4 slots (1 + the PE's 3) for every parameter value:
// cost_o, col_o, valid_o during slot t belong to the input of slot t - 4.
// cost_o[d*CBITS +: CBITS] = C(p, d) (0 .. 2 NB). Throughput: one slot per enabled cycle.
module sgm_cost_volume #(
  parameter int  D     /*verilator public*/ = 64,
  parameter int  CW    = 11,
  parameter int  NB    = 44,
  parameter int  LANES /*verilator public*/ = 1,
  parameter int  AD_TERM /*verilator public*/ = 1,
  parameter int  MIN_DISPARITY /*verilator public*/ = 0,
  localparam int RKW   = $clog2(NB + 1),
  localparam int CBITS = $clog2(2 * NB + 1)
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire  [1:0]       mode_i,
  input  wire  [7:0]       dmin_i,       // the minimum disparity, a constant of the frame
  input  wire  [3:0]       ad_weight_i,  // AD term weight W (0: off), with the slot
  input  wire  [7:0]       ad_cap_i,     // AD term cap T, with the slot
  input  wire  [7:0]       lgray_i,      // left centre gray (the census unit's centre_o)
  input  wire  [7:0]       rgray_i,      // right centre gray
  input  wire  [NB-1:0]      lcensus_i,
  input  wire  [RKW-1:0]     lrank_i,
  input  wire  [CW-1:0]      col_i,
  input  wire  [NB-1:0]      rcensus_i,
  input  wire  [RKW-1:0]     rrank_i,
  input  wire                valid_i,
  output logic [D*CBITS-1:0] cost_o,
  output logic [CW-1:0]    col_o,
  output logic             valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 2 && D <= 256)) begin : g_bad_d
    $error("sgm_cost_volume: D = %0d: D must be from 2 to 256", D);
  end
  if (!(CW >= 1)) begin : g_bad_cw
    $error("sgm_cost_volume: CW = %0d: CW must be at least 1", CW);
  end
  if (!(NB == 44 || NB == 80)) begin : g_bad_nb
    $error("sgm_cost_volume: NB = %0d: NB must be 44 or 80 (9 CENSUS_H - 1 census bits, CENSUS_H 5 or 9)", NB);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_cost_volume: LANES = %0d: LANES must be at least 1", LANES);
  end
  if (!(AD_TERM == 0 || AD_TERM == 1)) begin : g_bad_ad_term
    $error("sgm_cost_volume: AD_TERM = %0d: AD_TERM must be 0 or 1", AD_TERM);
  end
  if (!(MIN_DISPARITY == 0 || MIN_DISPARITY == 1)) begin : g_bad_min_disparity
    $error("sgm_cost_volume: MIN_DISPARITY = %0d: MIN_DISPARITY must be 0 or 1", MIN_DISPARITY);
  end
`endif

  localparam int LATENCY /*verilator public*/ = 4;
  localparam int GW = AD_TERM != 0 ? 8 : 0;  // the gray in the delay line
  localparam int EW = NB + RKW + GW;  // delay line entry: {gray, rank, census}

  // ------------------------------------------------------------ s1
  logic [NB-1:0]  lcensus1_q;
  logic [RKW-1:0] lrank1_q;
  logic [CW-1:0] col1_q, col2_q, col3_q;
  logic [1:0]    mode1_q, mode2_q;
  logic          valid1_q, valid2_q, valid3_q;
  logic [EW-1:0]       tap0_q;  // tap 0
  wire  [EW-1:0]       right_in, right_shifted;
  logic [(D-1)*EW-1:0] taps_q;  // taps 1 .. D-1
  wire  [D*EW-1:0]     line = {taps_q, tap0_q};

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lcensus1_q <= lcensus_i;
      lrank1_q   <= lrank_i;
      col1_q     <= col_i;
      mode1_q    <= mode_i;
      col2_q     <= col1_q;
      mode2_q    <= mode1_q;
      col3_q     <= col2_q;
      col_o      <= col3_q;
    end
  end

  // The AD term's operands: the left gray, the cap and gray -+ cap (the PEs'
  // two tests of AD > T) with stage A's slot, the weight with stage B's
  // (AD_TERM = 0: none; the PEs ignore their AD inputs).
  logic [7:0] lgray1_q, adcap1_q;
  logic [8:0] adlo1_q, adhi1_q;
  logic [3:0] adw2_q;
  if (AD_TERM != 0) begin : g_ad
    logic [3:0] adw1_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        lgray1_q <= lgray_i;
        adcap1_q <= ad_cap_i;
        adlo1_q  <= {1'b0, lgray_i} - {1'b0, ad_cap_i};
        adhi1_q  <= {1'b0, lgray_i} + {1'b0, ad_cap_i};
        adw1_q   <= ad_weight_i;
        adw2_q   <= adw1_q;
      end
    end
    assign right_in = {rgray_i, rrank_i, rcensus_i};
  end else begin : g_no_ad
    assign {lgray1_q, adcap1_q, adlo1_q, adhi1_q, adw2_q} = '0;
    assign right_in = {rrank_i, rcensus_i};
    wire unused_ad = ^{lgray_i, rgray_i, ad_cap_i, ad_weight_i};
  end

  // The right entry of dmin K slots before this one (MIN_DISPARITY = 1), else this slot's.
  if (MIN_DISPARITY != 0) begin : g_shift
    localparam int SAW = $clog2(256 * LANES);  // dmin K - 2 < 2^SAW
    localparam int SKW = $clog2(255 * LANES + 1);
    logic [EW-1:0]  shift_mem [0:(1 << SAW) - 1];
    logic [SAW-1:0] wr_ptr_q;
    logic [EW-1:0]  rd_q, rd2_q, in1_q, in2_q;
    logic [SKW-1:0] lag_q;  // dmin K, a constant of the frame
    always_ff @(posedge clk_i) begin
      lag_q <= SKW'(dmin_i) * SKW'(LANES);
    end
    always_ff @(posedge clk_i) begin
      if (!rst_ni) wr_ptr_q <= '0;
      else if (en_i) wr_ptr_q <= wr_ptr_q + 1'b1;
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        shift_mem[wr_ptr_q] <= right_in;
        rd_q  <= shift_mem[wr_ptr_q - SAW'(lag_q - SKW'(2))];  // written dmin K - 2 slots ago
        rd2_q <= rd_q;
        in1_q <= right_in;
        in2_q <= in1_q;
      end
    end
    assign right_shifted = lag_q == '0 ? right_in : lag_q == SKW'(1) ? in1_q : lag_q == SKW'(2) ? in2_q : rd2_q;
  end else begin : g_no_shift
    assign right_shifted = right_in;
    wire unused_dmin = ^dmin_i;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) tap0_q <= right_shifted;
  end

  // Tap d of slot n + 1 = tap d - 1 of slot n - (K - 1): taps 1 .. D-1 are taps
  // 0 .. D-2 delayed by K slots (K = 1: one register, the shift register).
  sgm_delay_ram #(.WIDTH((D - 1) * EW), .DEPTH(LANES)) u_taps (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .en_i   (en_i),
    .d_i    (line[0 +: (D-1)*EW]),
    .q_o    (taps_q)
  );

  // ------------------------------------------------------------ s2 .. s4: PEs
  for (genvar d = 0; d < D; d++) begin : g_pe
    wire outside;  // x - dmin - d < 0
    wire [7:0] rgray;  // the right gray at x - d (AD_TERM = 0: none)
    if (AD_TERM != 0) begin : g_gray
      assign rgray = line[d*EW+NB+RKW +: GW];
    end else begin : g_no_gray
      assign rgray = '0;
    end
    if (MIN_DISPARITY != 0) begin : g_dmin
      // The bound d + dmin (up to 510) registered: the comparison is one register's.
      localparam int BW = (CW > 9 ? CW : 9) + 1;
      logic [BW-1:0] bound_q;
      logic          outside_q;
      always_ff @(posedge clk_i) begin
        bound_q <= BW'(d) + BW'(dmin_i);
      end
      always_ff @(posedge clk_i) begin
        if (en_i) outside_q <= BW'(col_i) < bound_q;
      end
      assign outside = outside_q;
    end else if (d == 0) begin : g_d0
      assign outside = 1'b0;
    end else begin : g_dn
      // Decided on col_i and registered beside col1_q: each PE's flag is one
      // register, not a comparison of col1_q shared with its neighbours (the
      // D comparisons, merged by synthesis into one chain across the PEs, were
      // the five-lane core's critical path on the LFE5U-85F).
      logic outside_q;
      always_ff @(posedge clk_i) begin
        if (en_i) outside_q <= {{(32-CW){1'b0}}, col_i} < 32'(d);
      end
      assign outside = outside_q;
    end

    sgm_cost_pe #(.NB(NB), .AD_TERM(AD_TERM)) u_pe (
      .clk_i     (clk_i),
      .en_i      (en_i),
      .mode_i    (mode2_q),
      .lcensus_i (lcensus1_q),
      .lrank_i   (lrank1_q),
      .rcensus_i (line[d*EW +: NB]),
      .rrank_i   (line[d*EW+NB +: RKW]),
      .outside_i (outside),
      .lgray_i   (lgray1_q),
      .rgray_i   (rgray),
      .ad_cap_i  (adcap1_q),
      .ad_lo_i   (adlo1_q),
      .ad_hi_i   (adhi1_q),
      .ad_weight_i(adw2_q),
      .cost_o    (cost_o[d*CBITS +: CBITS])
    );
  end

  // Control: valid chain (reset).
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid1_q <= 1'b0;
      valid2_q <= 1'b0;
      valid3_q <= 1'b0;
      valid_o  <= 1'b0;
    end else if (en_i) begin
      valid1_q <= valid_i;
      valid2_q <= valid1_q;
      valid3_q <= valid2_q;
      valid_o  <= valid3_q;
    end
  end

endmodule
`default_nettype wire
