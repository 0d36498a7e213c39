// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_median5x5: 5x5 median over the valid pixels (docs/algorithm.md section 9).
// Over the 5x5 window clipped to the image, taking only valid pixels, the
// output is the lower median of the n valid values (element (n - 1) / 2 of the
// ascending order). An invalid centre stays invalid (value passed through).
// The last two rows (window clipped by the bottom edge) pass through unchanged.
// median_en_i = 0 passes every pixel through unchanged, with the same latency.
//
// Window: 4 line buffers of MAX_WIDTH x (DW + 2) bit {frame pixel, valid,
// disp}, packed into one simple-dual-port memory of MAX_WIDTH x 4 (DW + 2) bit
// (block RAM: one synchronous read with enable at address x, the shifted word
// written back one slot later at the previous address). The column of slot
// (x, y) holds rows y-4 .. y at column x and shifts into a 5x5 register
// window; the centre is the slot two columns and two rows back:
// col = x >= 2 ? x - 2 : W + x - 2, row = x >= 2 ? y - 2 : y - 3. Entries whose position lies outside
// 0 .. W-1 x 0 .. H-1 are excluded (masked by position exactly like the census
// window), so stale data of other rows, frames or flush slots is never used.
// The row test belongs to the column (its slot row, fixed while it is in the
// window): live = valid and row inside; the column test belongs to the centre.
//
// Selection, bitwise (radix) k-th smallest, MSB first, two pipeline stages per
// bit (the count, then the decision): with C the candidates (initially the n counted entries) and k = (n-1)/2,
// at bit b let z = #{e in C : bit b of v_e = 0}; if k < z the result has bit
// b = 0 and C keeps those entries, else bit b = 1, k -= z and C keeps the
// entries with bit b = 1. The stages carry m = 2 k + 1 (m = n at the start, so
// no (n - 1) / 2 behind the count: it would be the five-lane core's critical path
// on the LFE5U-85F at 8.0 ns): k >= z iff m > 2 z, and k -= z is m -= 2 z.
// No comparators and no sorting: per bit one 25-input
// popcount, a 6-bit compare / subtract and 25 AND-ORs. Entry bits travel as
// bit planes; plane b is dropped after its stage.
//   stage 0   line-buffer read, pixel register
//   stage 0b  both registered once more (the block RAM's clock-to-out alone)
//   stage A   window shift, live flags, column masks of the centre
//   stage S   counted set, n (25-input popcount) = m
//   2 DW stages one result bit per two (count | decide), the last one drives
//             the outputs (the count alone was one ECP5 clock of 10.1 ns)
// Cost (Yosys 0.23 synth_xilinx, xc7): DW = 8, MAX_WIDTH = 128: ~830 LUT +
// 65 SRL16, ~530 FF, 67 CARRY4, line buffer in 26 RAM64M (40-bit words do not
// fit one RAMB18); DW = 10, MAX_WIDTH = 512: ~955 LUT + 80 SRL16, ~610 FF,
// 1 RAMB36. Roughly 65 LUT per bit stage. For comparison, a rank counter
// (300 comparators, 25 24-input popcounts) measured 2.2k LUT, one keeping
// partial counts across shifts (110 comparators) 1.9k LUT.
//
// Parameters: DW disparity width (4 fractional bits), MAX_WIDTH largest frame
// width (memory 2^ceil(log2 MAX_WIDTH) deep), CW column/width bits, RW
// row/height bits (must hold height + 3 flush rows).
// Positions: every slot carries (col_i, row_i) of a virtual raster (rows >=
// height_i are flush slots); width_i >= 16, height_i >= 9 and median_en_i are
// constant per frame. The output position is computed from the input position;
// out_valid_o = the centre lies inside the frame and its own slot was a frame
// pixel (in_valid_i, stored with it: a slot of an earlier frame still in
// flight after a frame switch may have a position inside the new frame).
// Latency: LATENCY_ROWS * width + LATENCY slots (pixel (x, y) leaves 2 DW + 4
// slots after input slot (x + 2, y + 2), stage 0b included).
// Throughput: one pixel per enabled slot.
module sgm_median5x5 #(
  parameter int DW        /*verilator public*/ = 8,
  parameter int MAX_WIDTH /*verilator public*/ = 128,
  parameter int CW                             = $clog2(MAX_WIDTH + 1),
  parameter int RW        /*verilator public*/ = 11
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  input  wire           median_en_i,
  input  wire  [CW-1:0] width_i,
  input  wire  [RW-1:0] height_i,
  input  wire  [DW-1:0] disp_i,
  input  wire           valid_i,
  input  wire           in_valid_i,
  input  wire  [CW-1:0] col_i,
  input  wire  [RW-1:0] row_i,
  output logic [DW-1:0] disp_o,
  output logic          valid_o,
  output logic [CW-1:0] col_o,
  output logic [RW-1:0] row_o,
  output logic          out_valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(DW >= 5)) begin : g_bad_dw
    $error("sgm_median5x5: DW = %0d: DW must be at least 5 (4 fractional bits)", DW);
  end
  if (!(MAX_WIDTH >= 16)) begin : g_bad_max_width
    $error("sgm_median5x5: MAX_WIDTH = %0d: MAX_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MAX_WIDTH);
  end
  if (!(CW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_cw
    $error("sgm_median5x5: CW = %0d: CW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", CW, MAX_WIDTH);
  end
  if (!(RW >= 4)) begin : g_bad_rw
    $error("sgm_median5x5: RW = %0d: RW must be at least 4 (a 9-row frame and its flush rows)", RW);
  end
`endif

  localparam int LATENCY_ROWS /*verilator public*/ = 2;
  localparam int LATENCY      /*verilator public*/ = 2 * DW + 6;

  localparam int AW = $clog2(MAX_WIDTH);
  localparam int EW = DW + 2;            // line-buffer entry {frame pixel, valid, disp}
  localparam int N  = 25;                // window entries, e = 5 * column + row
  localparam int CENTRE = 12;
  localparam int KW = 5;                 // m = 2 k + 1 <= 25
  localparam int SW = DW + 2 + CW + RW;  // side word {men, centre valid, centre disp, col, row}
  localparam int PB = N * DW * (DW + 1) / 2;  // bit planes of all bit stages

  // Bit stage i (deciding bit DW-1-i) holds planes 0 .. DW-1-i from offset plane_off(i).
  function automatic integer plane_off(input integer i);
    plane_off = N * (i * DW - i * (i - 1) / 2);
  endfunction

  function automatic [4:0] popcount25(input [N-1:0] bits);
    popcount25 = '0;
    for (int e = 0; e < N; e++) popcount25 = popcount25 + {4'b0, bits[e]};
  endfunction

  // ------------------------------------------------------------ stage 0: line buffers
  logic [4*EW-1:0] lines_mem [0:MAX_WIDTH-1];
  logic [4*EW-1:0] lines_q;  // rows y-1 (bits EW-1:0) .. y-4 at column x
  logic [EW-1:0]   pix_q;    // pixel (x, y)
  logic [AW-1:0]   addr_q;
  logic [CW-1:0]   x0_q, w0_q;
  logic [RW-1:0]   y0_q, h0_q;
  logic [RW:0]     h1_q, h2_q, h3_q;  // height + 1, + 2, + 3
  logic            wrap0_q;           // x0_q < 2: the window centre is in the row above
  logic            men0_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lines_q           <= lines_mem[col_i[AW-1:0]];
      lines_mem[addr_q] <= {lines_q[3*EW-1:0], pix_q};
      pix_q             <= {in_valid_i, valid_i & in_valid_i, disp_i};
      addr_q            <= col_i[AW-1:0];
      x0_q              <= col_i;
      y0_q              <= row_i;
      w0_q              <= width_i;
      h0_q              <= height_i;
      h1_q              <= {1'b0, height_i} + (RW+1)'(1);
      h2_q              <= {1'b0, height_i} + (RW+1)'(2);
      h3_q              <= {1'b0, height_i} + (RW+1)'(3);
      wrap0_q           <= col_i < CW'(2);
      men0_q            <= median_en_i;
    end
  end

  // Stage 0b: the line buffers' words and stage 0 registered once more, so
  // that the block RAM's clock-to-out (4.3 ns on the ECP5, no output register)
  // is not followed by the live flags' comparisons (a critical path of the
  // five-lane core on the LFE5U-85F). The write-back above keeps stage 0.
  logic [4*EW-1:0] lines_r;
  logic [EW-1:0]   pix_r;
  logic [CW-1:0]   x0_r, w0_r;
  logic [RW-1:0]   y0_r, h0_r;
  logic [RW:0]     h1_r, h2_r, h3_r;
  logic            wrap0_r, men0_r;
  always_ff @(posedge clk_i) begin
    if (en_i) {lines_r, pix_r, x0_r, w0_r, y0_r, h0_r, h1_r, h2_r, h3_r, wrap0_r, men0_r} <=
                {lines_q, pix_q, x0_q, w0_q, y0_q, h0_q, h1_q, h2_q, h3_q, wrap0_q, men0_q};
  end

  // The new column, entry r = row y-4+r; live = valid and that row inside.
  wire  [5*EW-1:0] new_ent = {pix_r, lines_r[EW-1:0], lines_r[2*EW-1:EW], lines_r[3*EW-1:2*EW],
                              lines_r[4*EW-1:3*EW]};
  wire  [RW:0]     y1      = {1'b0, y0_r};
  logic [5*DW-1:0] new_val;
  logic [4:0]      new_live;
  for (genvar r = 0; r < 5; r++) begin : g_newcol
    wire [RW:0] yr4 = y1 + (RW+1)'(r);  // row y-4+r, plus 4
    assign new_val[r*DW +: DW] = new_ent[r*EW +: DW];
    assign new_live[r]         = new_ent[r*EW + DW] && yr4 >= (RW+1)'(4) && yr4 < {1'b0, h0_r} + (RW+1)'(4);
  end

  // ------------------------------------------------------------ stage A: window
  logic [N*DW-1:0] val_q;
  logic [N-1:0]    live_q;
  logic [4:0]      colok_q;
  logic [CW-1:0]   cxa_q;
  logic [RW-1:0]   cya_q;
  logic            mena_q;

  // Centre of the shifted window and its column masks.
  // The wrap test and height + k are registered in stage 0, so the row tests
  // below are comparisons of y0 with registers, no adder in front of them (the
  // wrap test, y0 - wrap and the comparisons behind it would be the LFE5U-85F
  // five-lane core's critical path at 8.4 ns): row ycb = y0 - wrap, so ycb >= 2
  // iff y0 >= 2 + wrap, ycb < height + k iff y0 < height + k + wrap.
  wire             wrap = wrap0_r;
  wire  [CW-1:0]   cx   = wrap ? w0_r + x0_r - CW'(2) : x0_r - CW'(2);
  wire  [RW-1:0]   ycb  = y0_r - RW'(wrap);  // row of the bottom window row
  // Column masks (columns cx - 2 .. cx + 2 inside the frame) from x0 and the
  // width alone, no adder in front of a comparison: off the wrap cx = x0 - 2,
  // so cx - 2 >= 0 iff x0 >= 4, cx + 1 < W iff x0 <= W, cx + 2 < W iff x0 < W;
  // at the wrap (x0 < 2) cx = W + x0 - 2 >= 2 (W >= 16), cx + 1 < W iff x0 == 0,
  // cx + 2 < W never.
  logic [4:0]      col_ok;
  always_comb begin
    col_ok[0] = wrap || x0_r >= CW'(4);
    col_ok[1] = wrap || x0_r >= CW'(3);
    col_ok[2] = 1'b1;
    col_ok[3] = wrap ? x0_r == '0 : x0_r <= w0_r;
    col_ok[4] = !wrap && x0_r < w0_r;
  end
  wire             y1_top  = wrap ? y1 >= (RW+1)'(3) : y1 >= (RW+1)'(2);  // ycb >= 2
  wire             y1_bot  = wrap ? y1 < h3_r : y1 < h2_r;                 // ycb < height + 2
  wire             y1_pass = wrap ? y1 < h1_r : y1 < {1'b0, h0_r};         // ycb < height
  wire centre_in = y1_top && y1_bot && x0_r < w0_r;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      val_q   <= {new_val, val_q[N*DW-1:5*DW]};
      live_q  <= {new_live, live_q[N-1:5]};
      colok_q <= col_ok;
      cxa_q   <= cx;
      cya_q   <= ycb - RW'(2);
      mena_q  <= men0_r && y1_pass;  // centre row < height - 2: the last 2 rows pass through
    end
  end

  // ------------------------------------------------------------ stage S: counted set, k
  logic [N-1:0] counted;
  logic [N*DW-1:0] planes_s;  // plane b (bit b of every entry) at b * N
  for (genvar e = 0; e < N; e++) begin : g_s
    assign counted[e] = live_q[e] && colok_q[e/5];
    for (genvar b = 0; b < DW; b++) begin : g_plane
      assign planes_s[b*N + e] = val_q[e*DW + b];
    end
  end
  wire [4:0] n_counted = popcount25(counted);
  wire [KW-1:0] k_s     = n_counted;  // m = 2 k + 1 = n (n = 0: the centre is not a frame pixel, the result unused)

  // ------------------------------------------------------------ bit stages
  // Bit stage i (deciding bit B = DW-1-i) is two slots (the 25-input count and
  // the decision each have a clock of their own):
  //   count   from cand_q, kk_q, planes_q, res_q: z = #{cand & ~plane B},
  //           registered with the candidates, plane B, k, the result so far and
  //           planes B-1 .. 0 (planes2_q)
  //   decide  bit B = k >= z; the subset cand & (plane B xnor bit B) (one LUT3
  //           per entry), k (- z) and the result for stage i+1
  // Registers of bit stage i: cand_q[i*N +: N], kk_q[i*KW +: KW],
  // planes_q[plane_off(i) +: (DW-i)*N]; res_q[(i-1)*DW +: DW] for i >= 1
  // (bits DW-1 .. DW-i decided, the others 0); of its count half: z_q, cc_q,
  // pb_q, kc_q, rc_q at index i, planes2_q[plane_off(i+1) - N*DW +: B*N].
  logic [DW*N-1:0]  cand_q;
  logic [DW*KW-1:0] kk_q;
  logic [2*DW*SW-1:0] side_q;
  logic [PB-1:0]    planes_q;
  logic [2*DW-1:0]  ok_q;     // the centre is a real pixel

  logic [DW*5-1:0]      z_d, z_q;
  logic [(DW-1)*N-1:0]  cc_d, cc_q, pb_d, pb_q;  // candidates, plane B (the last stage needs only z)
  logic [DW*KW-1:0]     kc_q;
  logic [DW*DW-1:0]     rc_d, rc_q;
  logic [PB-N*DW-1:0]   planes_d, planes2_q;

  logic [(DW-1)*N-1:0]  cand_d;
  logic [(DW-1)*KW-1:0] kk_d;
  logic [(DW-1)*DW-1:0] res_d;
  logic [DW-1:0]        res_last;

  for (genvar i = 0; i < DW; i++) begin : g_bit
    localparam int B = DW - 1 - i;  // the bit decided here
    // count half
    wire [N-1:0]  cand  = cand_q[i*N +: N];
    wire [N-1:0]  plane = planes_q[plane_off(i) + B*N +: N];
    assign z_d[i*5 +: 5]    = popcount25(cand & ~plane);
    if (i < DW - 1) begin : g_sets
      assign cc_d[i*N +: N] = cand;
      assign pb_d[i*N +: N] = plane;
      assign planes_d[plane_off(i+1) - N*DW +: B*N] = planes_q[plane_off(i) +: B*N];
    end
    if (i == 0) begin : g_first
      assign rc_d[i*DW +: DW] = '0;
    end else begin : g_next
      assign rc_d[i*DW +: DW] = res_q[(i-1)*DW +: DW];
    end
    // decide half
    wire [4:0]    z     = z_q[i*5 +: 5];
    wire [KW-1:0] kk    = kc_q[i*KW +: KW];
    wire          one   = {1'b0, kk} > {z, 1'b0};  // bit B of the k-th smallest: k >= z
    wire [DW-1:0] res_n = rc_q[i*DW +: DW] | (DW'(one) << B);
    if (i < DW - 1) begin : g_pass
      assign cand_d[i*N +: N]  = cc_q[i*N +: N] & ~(pb_q[i*N +: N] ^ {N{one}});
      assign kk_d[i*KW +: KW]  = one ? kk - {z[KW-2:0], 1'b0} : kk;  // k - z
      assign res_d[i*DW +: DW] = res_n;
    end else begin : g_out
      assign res_last = res_n;
    end
  end

  logic [(DW-1)*DW-1:0] res_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      // count halves
      z_q       <= z_d;
      cc_q      <= cc_d;
      pb_q      <= pb_d;
      kc_q      <= kk_q;
      rc_q      <= rc_d;
      planes2_q <= planes_d;
      // decide halves
      cand_q   <= {cand_d, counted};
      kk_q     <= {kk_d, k_s};
      res_q    <= res_d;
      planes_q <= {planes2_q, planes_s};
      side_q   <= {side_q[(2*DW-1)*SW-1:0], mena_q, live_q[CENTRE], val_q[CENTRE*DW +: DW], cxa_q, cya_q};
    end
  end

  // Output: the last bit stage.
  wire [SW-1:0] side = side_q[(2*DW-1)*SW +: SW];
  wire          men  = side[SW-1];
  wire          cval = side[SW-2];
  wire [DW-1:0] cdisp = side[CW+RW +: DW];

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      col_o <= side[RW +: CW];
      row_o <= side[RW-1:0];
      if (men && cval) begin
        disp_o  <= res_last;
        valid_o <= 1'b1;
      end else begin
        disp_o  <= cdisp;
        valid_o <= cval;
      end
    end
  end

  // Frame-pixel flags of the middle row of the two previous window columns: the
  // centre of the window shifted in at this slot is the middle entry of the
  // column from two slots ago. The output is a frame pixel only if that
  // pixel's own slot said so (a slot of an earlier frame still in flight after
  // a frame switch may have a position inside the new frame, never the flag).
  logic [1:0] real_q;
  always_ff @(posedge clk_i) begin
    if (en_i) real_q <= {real_q[0], new_ent[2*EW + DW + 1]};
  end

  // armed_q: a frame pixel has entered since reset. Before that, positions in
  // the pipeline and flags in the memories are power-up values, so nothing may
  // come out; after it, every word read for an output was written by the stream.
  logic armed_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) armed_q <= 1'b0;
    else if (en_i && in_valid_i) armed_q <= 1'b1;
  end

  // Control: v0_q / v0b_q mark stages 0 / 0b as loaded since reset; oka_q,
  // ok_q follow the centre.
  logic v0_q, v0b_q, oka_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      v0_q        <= 1'b0;
      v0b_q       <= 1'b0;
      oka_q       <= 1'b0;
      ok_q        <= '0;
      out_valid_o <= 1'b0;
    end else if (en_i) begin
      v0_q        <= 1'b1;
      v0b_q       <= v0_q;
      oka_q       <= v0b_q && armed_q && centre_in && real_q[1];
      ok_q        <= {ok_q[2*DW-2:0], oka_q};
      out_valid_o <= ok_q[2*DW-1];
    end
  end

endmodule
`default_nettype wire
