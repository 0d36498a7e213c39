// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_hole_fill: hole filling along each row (docs/algorithm.md section 8).
// An invalid pixel keeps its own disparity when it is within 16 (1 px) of the
// nearest valid disparity to its left or to its right in the same row, else it
// takes the smaller of the two, or the one that exists; a pixel with neither
// stays invalid (value passed through). Filled pixels are valid.
// fill_en_i = 0 passes every pixel through unchanged, with the same latency.
//
// Row y is written while it streams in; it is read back during row y + 1:
//   * pixel memory, 2 banks (row parity) x MAX_WIDTH words of {frame pixel
//     (in_valid_i), disp, valid, nearest valid to the left (exists, value),
//     run index r}:
//     r numbers the runs of invalid pixels of the row from the left;
//   * run table, 2 banks x ceil(MAX_WIDTH / 2) words of {exists, value}:
//     entry r is the right neighbour of run r, written by the valid pixel that
//     ends the run ("none" for a run reaching the end of the row).
// At input slot (x, y + 1): read pixel (x, y); the slot after the next: read
// its run-table entry (the pixel word registered once more in between: the
// pixel memory's clock-to-out in front of the run table's address would be the
// 5-lane core's critical path on ECP5); then the entry is registered again and
// the fill decided. The run table's writes are registered one slot (written at
// the slot after their pixel), so that the read of row y's last pixel, which
// falls in the second slot of row y + 2, comes before row y + 2's first write
// to the same bank. Both memories are simple dual port (one synchronous write,
// one synchronous read with enable, never the same address in the same slot):
// block RAM. With fill_en_i = 0 the left neighbour and the run-table entries
// are written as "none".
//
// Parameters: DW disparity width (4 fractional bits), MAX_WIDTH largest frame
// width (memories are 2^ceil(log2 MAX_WIDTH) deep per bank), CW column/width
// bits, RW row/height bits (must hold height + 1 flush row).
// Positions: every slot carries (col_i, row_i) of a virtual raster (rows >=
// height_i are flush slots); width_i >= 16, height_i, fill_en_i constant per
// frame. The output position is computed from the input position;
// out_valid_o = 1 <= row_i <= height_i and the stored word of (x, y) says its
// own slot was a frame pixel (a slot of an earlier frame still in flight after
// a frame switch may have a row inside the new frame, never the flag).
// Latency: LATENCY_ROWS * width + LATENCY slots (pixel (x, y) leaves LATENCY
// slots after input slot (x, y + 1)). Throughput: one pixel per enabled slot.
// Memory: 2 x MAX_WIDTH x (2 DW + 3 + RIW) + 2 x 2^RIW x (DW + 1) bit,
// RIW = ceil(log2(MAX_WIDTH / 2)). Cost (Yosys 0.23 synth_xilinx, xc7, DW = 8,
// MAX_WIDTH = 128): ~70 LUT + 19 SRL16, ~56 FF, 1 RAMB18 (pixel memory) and
// 6 RAM64M (run table); DW = 10, MAX_WIDTH = 512: RAMB36 + RAMB18.
module sgm_hole_fill #(
  parameter int DW        /*verilator public*/ = 8,
  parameter int MAX_WIDTH /*verilator public*/ = 128,
  parameter int CW                             = $clog2(MAX_WIDTH + 1),
  parameter int RW        /*verilator public*/ = 11
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  input  wire           fill_en_i,
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
    $error("sgm_hole_fill: DW = %0d: DW must be at least 5 (4 fractional bits)", DW);
  end
  if (!(MAX_WIDTH >= 16)) begin : g_bad_max_width
    $error("sgm_hole_fill: MAX_WIDTH = %0d: MAX_WIDTH must be at least 16 (frames are 16 or more pixels wide)", MAX_WIDTH);
  end
  if (!(CW >= $clog2(MAX_WIDTH + 1))) begin : g_bad_cw
    $error("sgm_hole_fill: CW = %0d: CW must hold MAX_WIDTH = %0d (at least $clog2(MAX_WIDTH + 1) bits)", CW, MAX_WIDTH);
  end
  if (!(RW >= 4)) begin : g_bad_rw
    $error("sgm_hole_fill: RW = %0d: RW must be at least 4 (a 9-row frame and its flush row)", RW);
  end
`endif

  localparam int LATENCY_ROWS /*verilator public*/ = 1;
  localparam int LATENCY      /*verilator public*/ = 5;

  localparam int AW  = $clog2(MAX_WIDTH);            // column address bits
  localparam int RIW = $clog2((MAX_WIDTH + 1) / 2);  // run index bits
  localparam int PW  = 2 * DW + 3 + RIW;             // pixel word {frame pixel, disp, valid, left, run}
  localparam int TW  = DW + 1;                       // run-table word

  // ------------------------------------------------------------ write side (row y)
  logic [PW-1:0] pix_mem [0:2*MAX_WIDTH-1];   // {column, row parity}: exactly 2 rows
  logic [TW-1:0] run_mem [0:(2 << RIW)-1];

  logic           prev_valid_q;  // pixel x - 1 of this row was valid
  logic           left_e_q;      // a valid pixel exists left of x in this row
  logic [DW-1:0]  left_q;        // the nearest one
  logic [RIW-1:0] run_q;         // runs ended so far in this row

  wire            first   = col_i == '0;
  wire            last    = col_i == width_i - 1'b1;
  wire            v_in    = valid_i & in_valid_i;
  wire            left_e  = !first && left_e_q && fill_en_i;
  wire  [RIW-1:0] run     = first ? '0 : run_q;
  // A valid pixel after an invalid one ends run r; an invalid last pixel
  // closes run r with no right neighbour.
  wire            run_end = v_in && !first && !prev_valid_q;
  wire            run_we  = run_end || (last && !v_in);
  wire  [TW-1:0]  run_wd  = {run_end && fill_en_i, disp_i};

  // The run-table write, one slot late (see above).
  logic           run_we_q;
  logic [RIW:0]   run_wa_q;
  logic [TW-1:0]  run_wd_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) run_we_q <= 1'b0;
    else if (en_i) run_we_q <= run_we;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      pix_mem[{col_i[AW-1:0], row_i[0]}] <= {in_valid_i, disp_i, v_in, left_e, left_q, run};
      if (run_we_q) run_mem[run_wa_q] <= run_wd_q;
      run_wa_q <= {row_i[0], run};
      run_wd_q <= run_wd;
      prev_valid_q <= v_in;
      if (v_in) begin
        left_e_q <= 1'b1;
        left_q   <= disp_i;
      end else if (first) begin
        left_e_q <= 1'b0;
      end
      run_q <= run + RIW'(run_end);
    end
  end

  // ------------------------------------------------------------ read side (row y + 1)
  // Stage 1: pixel word of (x, y); stage 1o: the same registered again.
  logic [PW-1:0] word1_q, word1o_q;
  logic [CW-1:0] col1_q, col1o_q;
  logic [RW-1:0] row1_q, row1o_q;
  logic          bank1_q, bank1o_q, ok1_q, ok1o_q;
  // Stage 2: run-table entry of its run.
  logic [PW-1:0] word2_q;
  logic [TW-1:0] right2_q;
  logic [CW-1:0] col2_q;
  logic [RW-1:0] row2_q;
  logic          ok2_q, ok2o_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      word1_q  <= pix_mem[{col_i[AW-1:0], ~row_i[0]}];
      col1_q   <= col_i;
      row1_q   <= row_i - 1'b1;
      bank1_q  <= ~row_i[0];
      word1o_q <= word1_q;
      col1o_q  <= col1_q;
      row1o_q  <= row1_q;
      bank1o_q <= bank1_q;
      right2_q <= run_mem[{bank1o_q, word1o_q[RIW-1:0]}];
      word2_q  <= word1o_q;
      col2_q   <= col1o_q;
      row2_q   <= row1o_q;
    end
  end

  // Output pixel (x, y) is real when 1 <= row_i <= height_i and its stored word
  // says its own slot was a frame pixel (a slot of an earlier frame still in
  // flight after a frame switch may have a row inside the new frame, never the flag).
  // armed_q: a frame pixel has entered since reset. Before that, positions in
  // the pipeline and flags in the memories are power-up values, so nothing may
  // come out; after it, every word read for an output was written by the stream.
  logic armed_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) armed_q <= 1'b0;
    else if (en_i && in_valid_i) armed_q <= 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      ok1_q       <= 1'b0;
      ok1o_q      <= 1'b0;
      ok2_q       <= 1'b0;
      ok2o_q      <= 1'b0;
      out_valid_o <= 1'b0;
    end else if (en_i) begin
      ok1_q       <= armed_q && row_i != '0 && row_i <= height_i && col_i < width_i;
      ok1o_q      <= ok1_q;
      ok2_q       <= ok1o_q && word1o_q[PW-1];
      ok2o_q      <= ok2_q;
      out_valid_o <= ok2o_q;
    end
  end

  // Stage 2o: the run-table entry registered again (the block RAM's clock-to-out
  // in front of stage 3's comparisons).
  logic [PW-1:0] word2o_q;
  logic [TW-1:0] right2o_q;
  logic [CW-1:0] col2o_q;
  logic [RW-1:0] row2o_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      word2o_q  <= word2_q;
      right2o_q <= right2_q;
      col2o_q   <= col2_q;
      row2o_q   <= row2_q;
    end
  end

  // Stage 3: own disparity if it agrees with a neighbour, else min of the existing neighbours.
  wire [DW-1:0] disp2   = word2o_q[PW-2 -: DW];
  wire          valid2  = word2o_q[PW-2-DW];
  wire          left_e2 = word2o_q[DW+RIW];
  wire [DW-1:0] left2   = word2o_q[RIW +: DW];
  wire          right_e2 = right2o_q[DW];
  wire [DW-1:0] right2  = right2o_q[DW-1:0];

  // |own - n| <= 16 (1 px), on DW + 1 bits.
  function automatic logic agrees(input logic [DW-1:0] own, input logic [DW-1:0] n);
    logic [DW:0] diff;
    diff   = own >= n ? {1'b0, own} - {1'b0, n} : {1'b0, n} - {1'b0, own};
    agrees = diff <= (DW+1)'(16);
  endfunction

  wire          keep_own = (left_e2 && agrees(disp2, left2)) || (right_e2 && agrees(disp2, right2));
  logic [DW-1:0] fill;
  always_comb begin
    if (keep_own)                                       fill = disp2;
    else if (left_e2 && (!right_e2 || left2 <= right2)) fill = left2;
    else                                                fill = right2;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      col_o <= col2o_q;
      row_o <= row2o_q;
      if (!valid2 && (left_e2 || right_e2)) begin
        disp_o  <= fill;
        valid_o <= 1'b1;
      end else begin
        disp_o  <= disp2;
        valid_o <= valid2;
      end
    end
  end

endmodule
`default_nettype wire
