// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_census_unit: CENSUS_H-line buffer, 9 x CENSUS_H window (9x5 or the paper's
// 9x9), census and rank of ONE image (docs/algorithm.md section 2, docs/rtl.md
// "Window and census"). The core instantiates it twice (left, right).
//
// Input: one slot per enabled cycle, (col_i, row_i) = (x, y) the slot's position
// and pix_i its gray pixel (any value on rows outside 0 .. height-1), active_i = 1;
// active_i = 0 marks a slot without a position (a lane still waiting for its start
// at a frame's beginning): it writes nothing and gives valid_o = 0 (pix_i, col_i,
// row_i don't care).
// Slot order: K = LANES row lanes (docs/lanes.md, tb/lane_schedule.hpp): slot
// K n + k belongs to lane k, each lane a virtual raster of its own rows (consecutive
// active slots of a lane are consecutive positions of its rows; the row after y in
// a lane is y + K), and every column is visited in row order with the slots of
// (x, y - 1) and (x, y) at least 2 slots apart (lane k running `skew` >= 1 columns
// behind lane k - 1 and width > (K - 1) skew + 1). K = 1 is the plain raster of
// the core (sgm_stream_ctrl's step stream). A frame may start at any slot.
// Output: the census of the centre of that slot,
//   (cx, cy) = (x - 4, y - RY)             if x >= 4
//            = (width + x - 4, y - RY - K) otherwise,     RY = (CENSUS_H - 1) / 2
// (the centre column of x < 4 is in the lane's previous row, K rows up),
// with census bit k = I(q) < I(p) in golden censusBitIndex order (row-major over
// dy = -RY..RY, dx = -4..4, centre skipped), 0 for window pixels outside the frame;
// rank = popcount; centre = I(cx, cy); nbr = I of the four path predecessors,
// 8 bits each LSB first: 0 deg (cx-1, cy), 45 deg (cx-1, cy-1), 90 deg (cx, cy-1),
// 135 deg (cx+1, cy-1) (don't care outside the frame); valid_o = the slot was
// active, came through the pipeline since reset and 0 <= cy < height (0 <= cx <
// width holds by construction). col_o/row_o = (cx, cy) (row_o meaningless when
// !valid_o).
//
// Structure (stage = one enabled cycle):
//   s1  line buffer read mem[x] (rows y-2RY .. y-1 of column x), input registers;
//       width/height are captured here and travel with the slot, so a new frame
//       may enter while the previous one is still in the pipeline.
//   s2  window: the new column (column x, rows y-2RY .. y) enters a register, the
//       other 8 columns are the lane's previous slot's newest 8 (K slots earlier,
//       an sgm_delay_ram of DEPTH = K: one register at K = 1, else K - 1 words of
//       distributed RAM and a register); line buffer write-back of {rows y-2RY+1 ..
//       y} to mem[x] (the address read one slot earlier; read and write addresses
//       of one cycle differ because the two visits of a column are 2 slots apart),
//       active slots only; centre position and the CENSUS_H + 9 row/column masks.
//   s3  census: NB (44 / 80) masked compares, centre and neighbours.
//   s4  rank's two weighted counts (the popcount tree without its final adder).
//   s5  rank = their sum; all outputs registered.
// Rows of an earlier frame or of flush slots still in the buffer are never
// used: every such window pixel is masked by the centre position (rows above 0
// of a new frame are negative, columns of another virtual row lie outside
// 0 .. width-1). If one column arrives in two consecutive slots (possible only
// across a frame boundary) the second read misses the first write-back; the
// missed rows are the previous frame's and masked. Likewise the window columns a
// lane's first slots of a frame take from the slots K earlier (another frame or
// an inactive slot) are masked.
//
// Memory: one MAX_WIDTH x 8 (CENSUS_H - 1) bit simple dual-port RAM (32 bits for
// 9x5, 64 for 9x9: the paper's 9-line buffer; synchronous read with enable,
// write with enable, no same-address read and write) + 9 CENSUS_H x 8 bit window
// registers, and at K > 1 a (K - 1) x 8 CENSUS_H x 8 bit delay memory (the other
// lanes' windows).
//
// Parameters: CENSUS_H window height (5 or 9; the width is 9); NB = 9 CENSUS_H - 1
// census bits, RKW = $clog2(NB + 1) rank bits; MAX_WIDTH largest frame width; CW
// column/width bits (2^CW > MAX_WIDTH); RW row/height bits, rows wrap (row_i must
// hold the last flush row the census needs, height + RY + K - 1, and a row -m < 0
// must satisfy 2^RW - m >= height + 2 RY + K); LANES = K row lanes (>= 1).
// Frame: width_i >= 16, height_i >= 9, constant during a frame (sampled with
// every slot).
// Latency: LATENCY = 5 slots for every parameter value (s1 .. s5): the outputs
// during slot t belong to the input of slot t - 5. The top mirrors it as its own
// localparam (hierarchical parameter references are not portable).
// Throughput: one slot per enabled cycle.
module sgm_census_unit #(
  parameter int CENSUS_H  /*verilator public*/ = 5,
  parameter int MAX_WIDTH /*verilator public*/ = 1280,
  parameter int CW        = 11,
  parameter int RW        = 11,
  parameter int LANES     /*verilator public*/ = 1,
  localparam int NB       = 9 * CENSUS_H - 1,     // census bits (44 / 80)
  localparam int RKW      = $clog2(NB + 1)        // rank bits (6 / 7)
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              en_i,
  input  wire              active_i,
  input  wire  [7:0]       pix_i,
  input  wire  [CW-1:0]    col_i,
  input  wire  [RW-1:0]    row_i,
  input  wire  [CW-1:0]    width_i,
  input  wire  [RW-1:0]    height_i,
  output logic [NB-1:0]    census_o,
  output logic [RKW-1:0]   rank_o,
  output logic [7:0]       centre_o,
  output logic [31:0]      nbr_o,
  output logic [CW-1:0]    col_o,
  output logic [RW-1:0]    row_o,
  output logic             valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(CENSUS_H == 5 || CENSUS_H == 9)) begin : g_bad_census_h
    $error("sgm_census_unit: CENSUS_H = %0d: CENSUS_H must be 5 (the 9x5 census) or 9 (the 9x9)", CENSUS_H);
  end
  if (!(MAX_WIDTH >= 16)) begin : g_bad_max_width
    $error("sgm_census_unit: MAX_WIDTH = %0d: MAX_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MAX_WIDTH);
  end
  if (!(CW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_cw
    $error("sgm_census_unit: CW = %0d: CW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", CW, MAX_WIDTH);
  end
  if (!(RW >= $clog2(10 + CENSUS_H - 1 + LANES))) begin : g_bad_rw
    $error("sgm_census_unit: RW = %0d: RW must hold the rows of a 9-row frame, its census flush rows and a row before it (at least $clog2(10 + CENSUS_H - 1 + LANES) = %0d bits)", RW, $clog2(10 + CENSUS_H - 1 + LANES));
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_census_unit: LANES = %0d: LANES must be at least 1", LANES);
  end
`endif

  localparam int LATENCY /*verilator public*/ = 5;
  localparam int RX = 4;                // window columns dx = -RX .. RX
  localparam int RY = (CENSUS_H - 1) / 2;  // window rows dy = -RY .. RY (2 / 4)
  localparam int WC = 2 * RX + 1;       // 9 columns
  localparam int WR = 2 * RY + 1;       // CENSUS_H rows
  localparam int MID = RY * WC + RX;    // window index of the centre (22 / 40)
  localparam int LB = 8 * (WR - 1);     // line buffer word: WR - 1 rows of 8 bits
  localparam int AW = MAX_WIDTH > 1 ? $clog2(MAX_WIDTH) : 1;  // line buffer address bits (<= CW)
  // Bottom-border constants height + k, k = 0 .. 2RY (x >= 4) and K .. 2RY + K (x < 4):
  // NH entries, entry e = HIDX(k) holds k = HOFF(e) (e <= 2RY: e, else e + HSHIFT).
  localparam int HSHIFT = LANES > 2 * RY + 1 ? LANES - 2 * RY - 1 : 0;
  localparam int NH     = 2 * RY + LANES + 1 - HSHIFT;

  // ------------------------------------------------------------ s1: line buffer read
  // mem_q[c][8k +: 8] = row y-2RY+k of column c (k = 2RY-1 the newest), seen from the next
  // slot y of that column (the previous row's slot; with lanes another lane's).
  logic [LB-1:0] mem_q [0:MAX_WIDTH-1];
  logic [LB-1:0] rd_q;
  logic [7:0]    pix1_q;
  logic [CW-1:0] col1_q, wm4_q;
  logic          wrap1_q;        // col1_q < RX (the centre wraps to the previous row)
  logic [RW-1:0] row1_q;
  logic [NH*(RW+1)-1:0] hgt1_q;  // hgt1_q[e (RW + 1) +: RW + 1] = height + HOFF(e)
  logic          v1_q;           // the slot came through the pipeline since reset
  logic          act1_q;         // the slot is active (a position of its lane)

  always_ff @(posedge clk_i) begin
    if (en_i) rd_q <= mem_q[col_i[AW-1:0]];
  end

  // An inactive slot (a lane waiting for its start) writes nothing.
  always_ff @(posedge clk_i) begin
    if (en_i && v1_q && act1_q) mem_q[col1_q[AW-1:0]] <= {pix1_q, rd_q[LB-1:8]};
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      act1_q    <= active_i;
      pix1_q    <= pix_i;
      col1_q    <= col_i;
      wrap1_q   <= col_i < CW'(RX);
      row1_q    <= row_i;
      wm4_q     <= width_i - CW'(RX);
      for (int k = 0; k <= 2 * RY; k++) hgt1_q[k*(RW+1) +: RW+1] <= {1'b0, height_i} + (RW+1)'(k);
      for (int e = 2 * RY + 1; e < NH; e++) hgt1_q[e*(RW+1) +: RW+1] <= {1'b0, height_i} + (RW+1)'(e + HSHIFT);
    end
  end

  // ------------------------------------------------------------ s2: window, position, masks
  // The window by age: column j (dx = j - RX) of a slot is age a = WC - 1 - j, the new
  // column of the lane's slot a K slots earlier. age0_q (age 0) is loaded with the new
  // column; ages 1 .. WC-1 are ages 0 .. WC-2 of the lane's previous slot, K slots
  // earlier: an sgm_delay_ram of DEPTH = LANES (K = 1: one register, the shift).
  // win[(WC i + j) * 8 +: 8]: window row i (dy = i - RY, i = 0 the oldest row),
  // column j (j = WC - 1 the newest column).
  localparam int CB = WR * 8;            // one window column
  wire  [CB-1:0]        new_col = {pix1_q, rd_q};  // byte i = row y-2RY+i
  logic [CB-1:0]        age0_q;          // age 0
  logic [(WC-1)*CB-1:0] ages_q;          // ages 1 .. WC-1
  wire  [WC*CB-1:0]     ages = {ages_q, age0_q};
  wire  [WR*WC*8-1:0]   win;

  always_ff @(posedge clk_i) begin
    if (en_i) age0_q <= new_col;
  end

  sgm_delay_ram #(.WIDTH((WC - 1) * CB), .DEPTH(LANES)) u_ages (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .en_i   (en_i),
    .d_i    (ages[0 +: (WC-1)*CB]),
    .q_o    (ages_q)
  );

  for (genvar i = 0; i < WR; i++) begin : g_win_row
    for (genvar j = 0; j < WC; j++) begin : g_win_col
      assign win[(WC*i+j)*8 +: 8] = ages[(WC-1-j)*CB + i*8 +: 8];
    end
  end

  // Centre of the slot: x >= 4 -> (x - 4, y - RY), else (width + x - 4, y - RY - K).
  // Window row i holds row y - 2RY + i (x >= 4) or y - 2RY - K + i (x < 4: the
  // centre column and every column left of it are in the lane's previous row,
  // K rows up; the columns of row y in the window are masked), i.e. row cy + i - RY,
  // inside the frame when off <= y + i < height + off with off = 2RY or 2RY + K,
  // that is y >= off - i and y < height + (off - i): hgt1_q holds height + k for
  // every k = off - i needed (0 .. 2RY for x >= 4, K .. 2RY + K for x < 4; entry
  // HIDX(k)), registered in s1, so each row test is one comparison. Rows wrap in
  // RW bits: a row -m < 0 reads as 2^RW - m, outside every test as long as
  // 2^RW - m >= height + 2RY + K.
  // Window column j holds cx + j - 4, inside when 4 <= cx + j < width + 4; since
  // 0 <= x < width and width >= 16 that is x + j >= 8 when x >= 4 (cx = x - 4; the
  // upper bound holds) and x + j < 8 when x < 4 (cx = width + x - 4; the lower
  // bound holds): a comparison of x with a constant, no adder on the path. The
  // wrap test itself is registered in s1 (wrap1_q: it selects every mask, and
  // the comparison in front of that fan-out was the five-lane core's critical
  // path on the LFE5U-85F, 8.3 ns).
  wire             wrap   = wrap1_q;
  wire  [CW-1:0]   cx     = wrap ? wm4_q + col1_q : col1_q - CW'(RX);
  wire  [RW-1:0]   cy     = row1_q - (wrap ? RW'(RY + LANES) : RW'(RY));
  logic [WR-1:0]   row_ok;
  logic [WC-1:0]   col_ok;

  for (genvar i = 0; i < WR; i++) begin : g_row_mask
    localparam int OFF0 = 2 * RY - i;          // off - i, x >= 4
    localparam int OFF1 = 2 * RY + LANES - i;  // off - i, x < 4 (>= K)
    localparam int IDX1 = OFF1 > 2 * RY ? OFF1 - HSHIFT : OFF1;  // HIDX(OFF1); HIDX(OFF0) = OFF0
    wire below0 = {1'b0, row1_q} < hgt1_q[OFF0*(RW+1) +: RW+1];
    wire below1 = {1'b0, row1_q} < hgt1_q[IDX1*(RW+1) +: RW+1];
    wire ok1    = row1_q >= RW'(OFF1) && below1;
    if (OFF0 == 0) begin : g_top
      assign row_ok[i] = wrap ? ok1 : below0;
    end else begin : g_above
      assign row_ok[i] = wrap ? ok1 : row1_q >= RW'(OFF0) && below0;
    end
  end
  for (genvar j = 0; j < WC; j++) begin : g_col_mask
    if (j == 2 * RX) begin : g_right
      assign col_ok[j] = !wrap;
    end else begin : g_inner
      assign col_ok[j] = wrap ? col1_q < CW'(2 * RX - j) : col1_q >= CW'(2 * RX - j);
    end
  end

  logic [WR-1:0] row_ok2_q;
  logic [WC-1:0] col_ok2_q;
  logic [CW-1:0] cx2_q;
  logic [RW-1:0] cy2_q;
  logic          v2_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      row_ok2_q <= row_ok;
      col_ok2_q <= col_ok;
      cx2_q     <= cx;
      cy2_q     <= cy;
    end
  end

  // ------------------------------------------------------------ s3: census
  wire  [7:0]    centre = win[MID*8 +: 8];
  logic [NB-1:0] census;

  for (genvar i = 0; i < WR; i++) begin : g_cen_row
    for (genvar j = 0; j < WC; j++) begin : g_cen_col
      if (WC * i + j < MID) begin : g_before
        assign census[WC*i+j] = row_ok2_q[i] && col_ok2_q[j] && win[(WC*i+j)*8 +: 8] < centre;
      end else if (WC * i + j > MID) begin : g_after
        assign census[WC*i+j-1] = row_ok2_q[i] && col_ok2_q[j] && win[(WC*i+j)*8 +: 8] < centre;
      end
    end
  end

  logic [NB-1:0] census3_q;
  logic [7:0]    centre3_q;
  logic [31:0]   nbr3_q;
  logic [CW-1:0] cx3_q;
  logic [RW-1:0] cy3_q;
  logic          v3_q;

  // Path predecessors: 0 deg (row RY, column RX-1), 45 / 90 / 135 deg (row RY-1,
  // columns RX-1, RX, RX+1).
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      census3_q <= census;
      centre3_q <= centre;
      nbr3_q    <= {win[(MID-WC+1)*8 +: 8], win[(MID-WC)*8 +: 8], win[(MID-WC-1)*8 +: 8],
                    win[(MID-1)*8 +: 8]};
      cx3_q     <= cx2_q;
      cy3_q     <= cy2_q;
    end
  end

  // ------------------------------------------------------------ s4: rank's two weighted counts
  // rank = ones1 + 2 ones2 (sgm_popcount): the popcount with its final adder
  // in one slot would be the 5-lane core's critical path (9.4 ns on ECP5).
  logic [RKW-1:0] ones1, ones1_4q;
  logic [RKW-2:0] ones2, ones2_4q;
  logic [6*(((NB + 2) / 3 + 5) / 6)-1:0] rank_groups;  // sgm_popcount's group counts: not used here
  sgm_popcount #(.N(NB)) u_rank (
    .bits_i   (census3_q),
    .ones1_o  (ones1),
    .ones2_o  (ones2),
    .groups_o (rank_groups)
  );
  wire unused_groups = ^rank_groups;

  logic [NB-1:0] census4_q;
  logic [7:0]    centre4_q;
  logic [31:0]   nbr4_q;
  logic [CW-1:0] cx4_q;
  logic [RW-1:0] cy4_q;
  logic          v4_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ones1_4q  <= ones1;
      ones2_4q  <= ones2;
      census4_q <= census3_q;
      centre4_q <= centre3_q;
      nbr4_q    <= nbr3_q;
      cx4_q     <= cx3_q;
      cy4_q     <= cy3_q;
    end
  end

  // ------------------------------------------------------------ s5: rank, outputs
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      census_o <= census4_q;
      rank_o   <= ones1_4q + {ones2_4q, 1'b0};
      centre_o <= centre4_q;
      nbr_o    <= nbr4_q;
      col_o    <= cx4_q;
      row_o    <= cy4_q;
    end
  end

  // Control: slot-valid chain (reset).
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      v1_q    <= 1'b0;
      v2_q    <= 1'b0;
      v3_q    <= 1'b0;
      v4_q    <= 1'b0;
      valid_o <= 1'b0;
    end else if (en_i) begin
      v1_q    <= 1'b1;
      v2_q    <= v1_q && act1_q && row_ok[RY];
      v3_q    <= v2_q;
      v4_q    <= v3_q;
      valid_o <= v4_q;
    end
  end

endmodule
`default_nettype wire
