// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_edge_snap: edge snapping along each row (docs/algorithm.md section 8b).
// With step(k) = |I(k) - I(k-1)| of the left gray image, a drop at e (pixels e
// and e+1 valid, disp(e) > disp(e+1) + 32) has its edge at the k in
// max(1, e-2) .. e+1 with the largest step (ties to the largest k); a valid
// pixel x with a drop e, x <= e <= x+2, edge(e) <= x takes disp(e+1) of the
// nearest such e. Invalid pixels and validity pass through unchanged.
// snap_en_i = 0 passes every pixel through unchanged, with the same latency.
//
// Left gray: written through its own port (gray_we_i at gray_col_i /
// gray_row_i, any time before the disparity of that pixel arrives, at most
// GRAY_ROWS - 1 rows earlier) into a memory of MAX_WIDTH x GRAY_ROWS x 8 bit
// (addressed column-major, {column, row mod GRAY_ROWS}: exactly the words it holds
// at any width), and read back for each disparity slot one slot after it entered.
//
// Pipeline (all stages advance only when en_i):
//   P0    input registers (pixel, position, frame-pixel flag)
//   P1    gray read of the P0 pixel (the block RAM's read register)
//   P2    the gray registered again (the block RAM's clock-to-out, 4.3 ns on
//         ECP5, in front of the step would be the 5-lane core's critical path at
//         108.9 MHz)
//   W     a window along the stream, w[0] the newest; the pixel leaving is
//         x = w[3], with x+1 .. x+3 in w[2] .. w[0]; x-1 and x-2 take part
//         only through the pair maxima pm(n) = max(step(n), step(n-1)), computed
//         a slot after n enters and carried to w[4]. Each pixel's step
//         |I(n) - I(n-1)| and its drop flag (a drop at n-1) are computed once,
//         when it enters; an entry takes part only if it continues the row of
//         x (frame pixels of the same row: positions arrive in raster order).
//   max   the maxima of the step candidates (one compare-select level on the
//         pair maxima), the
//         drops and x's fields, registered (the maxima and the comparison in
//         one slot would be the 5-lane core's critical path at 97.4 MHz)
//   dec   the snapping decision (step comparisons), registered
//   out   the selected disparity, output registers.
// Parameters: DW disparity width (4 fractional bits), MAX_WIDTH, CW column /
// width bits, RW row / height bits, GRAY_ROWS rows of the gray memory (a power
// of two: 4 when the disparities arrive at most three rows after the grays, the
// core with one lane; more with K lanes, whose LR check reads behind the census).
// Positions: every slot carries (col_i, row_i) of a virtual raster. width_i
// and height_i complete the interface the other row stages share; positions
// and in_valid_i say everything this stage needs.
// Latency: LATENCY = 10 slots, LATENCY_ROWS = 0. Throughput: one pixel per slot.
// Reset: control only (frame-pixel flags).
module sgm_edge_snap #(
  parameter int DW        /*verilator public*/ = 8,
  parameter int MAX_WIDTH /*verilator public*/ = 128,
  parameter int CW                             = $clog2(MAX_WIDTH + 1),
  parameter int RW        /*verilator public*/ = 11,
  parameter int GRAY_ROWS /*verilator public*/ = 4
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  input  wire           snap_en_i,
  input  wire  [CW-1:0] width_i,
  input  wire  [RW-1:0] height_i,
  // Left gray of pixel (gray_col_i, gray_row_i).
  input  wire           gray_we_i,
  input  wire  [CW-1:0] gray_col_i,
  input  wire  [RW-1:0] gray_row_i,
  input  wire  [7:0]    gray_i,
  // Disparity stream.
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
    $error("sgm_edge_snap: DW = %0d: DW must be at least 5 (4 fractional bits)", DW);
  end
  if (!(MAX_WIDTH >= 16)) begin : g_bad_max_width
    $error("sgm_edge_snap: MAX_WIDTH = %0d: MAX_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MAX_WIDTH);
  end
  if (!(CW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_cw
    $error("sgm_edge_snap: CW = %0d: CW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", CW, MAX_WIDTH);
  end
  if (!(RW >= 4)) begin : g_bad_rw
    $error("sgm_edge_snap: RW = %0d: RW must be at least 4 (a 9-row frame and its flush rows)", RW);
  end
  if (!(GRAY_ROWS >= 4 && (GRAY_ROWS & (GRAY_ROWS - 1)) == 0)) begin : g_bad_gray_rows
    $error("sgm_edge_snap: GRAY_ROWS = %0d: GRAY_ROWS must be a power of two >= 4", GRAY_ROWS);
  end
`endif

  localparam int LATENCY_ROWS /*verilator public*/ = 0;
  localparam int LATENCY      /*verilator public*/ = 10;

  localparam int AW = $clog2(MAX_WIDTH);
  localparam int GB = $clog2(GRAY_ROWS);  // bank bits (row mod GRAY_ROWS)
  localparam int NW = 4;                  // window entries with the full pixel
  localparam int EW = DW + 1 + CW + RW;   // entry data {valid, disp, col, row}

  // ------------------------------------------------------------ gray memory
  logic [7:0] gray_mem [0:(MAX_WIDTH << GB)-1];
  always_ff @(posedge clk_i) begin
    if (en_i && gray_we_i) gray_mem[{gray_col_i[AW-1:0], gray_row_i[GB-1:0]}] <= gray_i;
  end

  // ------------------------------------------------------------ P0, P1, P2
  logic [EW-1:0] p0_q, p1_q, p2_q;
  logic          p0_real_q, p1_real_q, p2_real_q;
  logic          p0_en_q, p1_en_q, p2_en_q;
  logic [7:0]    p1_gray_q, p2_gray_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      p0_q      <= {valid_i & in_valid_i, disp_i, col_i, row_i};
      p0_en_q   <= snap_en_i;
      p1_q      <= p0_q;
      p1_en_q   <= p0_en_q;
      p1_gray_q <= gray_mem[{p0_q[RW +: AW], p0_q[GB-1:0]}];
      p2_q      <= p1_q;
      p2_en_q   <= p1_en_q;
      p2_gray_q <= p1_gray_q;
    end
  end

  function automatic logic [8:0] max9(input logic [8:0] a, input logic [8:0] b);
    max9 = a > b ? a : b;
  endfunction

  // ------------------------------------------------------------ window
  // Entering pixel n (from P2) against the newest entry, pixel n-1:
  //   cont  n and n-1 are frame pixels of the same row
  //   step  step(n) = |I(n) - I(n-1)| with bit 8 set when cont (0: absent, never wins)
  //   drop  a drop at e = n-1 (cont, both valid, disp(n-1) > disp(n) + 32)
  logic [NW*EW-1:0] win_q;     // {valid, disp, col, row} of w[0] .. w[3]
  logic [3:0]       wcont_q;   // w[0] .. w[3]
  logic [NW*9-1:0] wstep_q;  // w[0] .. w[3]
  logic [2:0]       wdrop_q;   // w[0] .. w[2]
  logic [NW-1:0]    wreal_q;
  logic [NW-1:0]    wen_q;     // snap enable
  logic [7:0]       wgray_q;   // gray of w[0]
  // Pair maxima along the window: pm(n) = max(step(n), step(n-1)) when n
  // continues the row of n-1, else 0 (step(n) is 0 then, and n-1 is another
  // row's). Computed from w[0] and w[1] and shifted with them, so that the
  // maxima of the max stage are one compare-select level each (two levels
  // there would be the 5-lane core's critical path on ECP5, 8.0 ns at 124.5 MHz).
  // wpm_q[j] is pm of w[j + 1].
  logic [4*9-1:0]   wpm_q;

  wire [DW-1:0] prev_disp = win_q[CW + RW +: DW];
  wire          prev_vld  = win_q[EW - 1];
  wire          new_vld   = p2_q[EW - 1];
  wire [DW-1:0] new_disp  = p2_q[CW + RW +: DW];
  wire          new_cont  = p2_real_q && wreal_q[0] && p2_q[0 +: RW] == win_q[0 +: RW];
  wire [7:0]    new_mag   = p2_gray_q >= wgray_q ? p2_gray_q - wgray_q : wgray_q - p2_gray_q;
  wire          new_drop  = new_cont && prev_vld && new_vld &&
                            {1'b0, prev_disp} > {1'b0, new_disp} + (DW+1)'(32);

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      win_q   <= {win_q[(NW-1)*EW-1:0], p2_q};
      wcont_q <= {wcont_q[2:0], new_cont};
      wstep_q <= {wstep_q[(NW-1)*9-1:0], new_cont ? {1'b1, new_mag} : 9'd0};
      wdrop_q <= {wdrop_q[1:0], new_drop};
      wgray_q <= p2_gray_q;
      wen_q   <= {wen_q[NW-2:0], p2_en_q};
      wpm_q   <= {wpm_q[3*9-1:0], wcont_q[0] ? max9(wstep_q[0*9 +: 9], wstep_q[1*9 +: 9]) : 9'd0};
    end
  end

  // Pixel x = w[3]; w[j] holds x + 3 - j.
  wire [DW-1:0] d_x   = win_q[3*EW + CW + RW +: DW];
  wire          v_x   = win_q[3*EW + EW - 1];
  wire          c1    = wcont_q[2], c2 = wcont_q[1];      // x+1 / x+2 continue the row
  // Drops e = x, x+1, x+2 (stored with e+1), inside the row of x.
  wire [2:0]    drop  = {wdrop_q[0] && c1 && c2, wdrop_q[1] && c1, wdrop_q[2]};
  // Steps: right of x present whenever their drop is; left of x masked to the row.
  wire [8:0] st_p3 = wstep_q[0*9 +: 9], st_p1 = wstep_q[2*9 +: 9];
  wire [8:0] st_0  = wstep_q[3*9 +: 9];

  // edge(e) <= x iff the best left candidate (max(1, e-2) .. x) beats every
  // right one (x+1 .. e+1) strictly (ties go to the larger k). An absent left
  // step is 0 and never beats. By the pair maxima: max(st_m1, st_0) = pm(x);
  // max(st_m2, st_m1, st_0) = max(st_0, pm(x-1)) when x continues its row,
  // else 0 like every left step; max(st_p1, st_p2) = pm(x+2) where it matters
  // (the drop at x+1 is only a drop when x+2 continues the row).
  wire [8:0] pm_p2  = wpm_q[0*9 +: 9], pm_0 = wpm_q[2*9 +: 9], pm_m1 = wpm_q[3*9 +: 9];
  wire [8:0] left1  = pm_0;
  wire [8:0] left0  = wcont_q[3] ? max9(st_0, pm_m1) : 9'd0;
  wire [8:0] left2  = st_0;
  wire [8:0] right0 = st_p1;
  wire [8:0] right1 = pm_p2;
  wire [8:0] right2 = max9(pm_p2, st_p3);

  // max: the maxima and the drops registered; x's fields {disp(x+1), disp(x+2),
  // disp(x+3), disp(x), valid(x), snap enable, col, row} ride along in one
  // bundle through max and dec.
  localparam int XF = 4 * DW + 2 + CW + RW;
  wire  [XF-1:0]   xf = {win_q[0*EW + CW + RW +: DW], win_q[1*EW + CW + RW +: DW], win_q[2*EW + CW + RW +: DW],
                         d_x, v_x, wen_q[3], win_q[3*EW + RW +: CW], win_q[3*EW +: RW]};
  logic [6*9-1:0]  mx_q;     // {left2, left1, left0, right2, right1, right0}
  logic [2:0]      mdrop_q;
  logic [2*XF-1:0] xf_q;     // x's fields at max (low half) and at dec (high half)
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mx_q    <= {left2, left1, left0, right2, right1, right0};
      mdrop_q <= drop;
      xf_q    <= {xf_q[0 +: XF], xf};
    end
  end

  wire [8:0] ml2 = mx_q[5*9 +: 9], ml1 = mx_q[4*9 +: 9], ml0 = mx_q[3*9 +: 9];
  wire [8:0] mr2 = mx_q[2*9 +: 9], mr1 = mx_q[1*9 +: 9], mr0 = mx_q[0*9 +: 9];
  wire [2:0] hit = mdrop_q & {ml2 > mr2, ml1 > mr1, ml0 > mr0};

  // dec: the decision registered (the step comparisons in one slot, the
  // selection of the snapped disparity in the next).
  logic [2:0]      hit_q;
  always_ff @(posedge clk_i) begin
    if (en_i) hit_q <= hit;
  end
  wire  [3*DW-1:0] cand_q;   // disp(x+1), disp(x+2), disp(x+3)
  wire  [DW-1:0]   dx_q;
  wire             vx_q, wen_x_q;
  wire  [CW-1:0]   colx_q;
  wire  [RW-1:0]   rowx_q;
  assign {cand_q, dx_q, vx_q, wen_x_q, colx_q, rowx_q} = xf_q[XF +: XF];

  logic [DW-1:0] snapped;
  always_comb begin
    if (hit_q[0])      snapped = cand_q[0*DW +: DW];
    else if (hit_q[1]) snapped = cand_q[1*DW +: DW];
    else               snapped = cand_q[2*DW +: DW];
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      col_o   <= colx_q;
      row_o   <= rowx_q;
      valid_o <= vx_q;
      disp_o  <= wen_x_q && vx_q && hit_q != '0 ? snapped : dx_q;
    end
  end

  // ------------------------------------------------------------ control
  logic max_real_q, dec_real_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      p0_real_q   <= 1'b0;
      p1_real_q   <= 1'b0;
      p2_real_q   <= 1'b0;
      wreal_q     <= '0;
      max_real_q  <= 1'b0;
      dec_real_q  <= 1'b0;
      out_valid_o <= 1'b0;
    end else if (en_i) begin
      p0_real_q   <= in_valid_i;
      p1_real_q   <= p0_real_q;
      p2_real_q   <= p1_real_q;
      wreal_q     <= {wreal_q[NW-2:0], p2_real_q};
      max_real_q  <= wreal_q[3];
      dec_real_q  <= max_real_q;
      out_valid_o <= dec_real_q;
    end
  end

endmodule
`default_nettype wire
