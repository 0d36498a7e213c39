// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_confidence_rows: carries each pixel's confidence (docs/algorithm.md section 7b) from
// the LR check's output to the core's output, past hole filling, edge snapping and the
// median, which do not change it. Those stages keep the raster order and every pixel, so
// the confidence goes into a row memory at its pixel's position as the LR check gives the
// pixel, and is read back at the same position as the median gives it.
//
// Rows: ROWS rows of MAX_WIDTH words of 8 bits (ROWS a power of two), column-major
// {column, row slot} (no multiplier in front of the address; ROWS x MAX_WIDTH words
// exactly). The row slot is not the frame's row number: each side counts the rows it
// has seen, a new row at each column 0, continuously across frames, so that the next
// frame's first rows, written while the last rows of a frame are still read, take
// other slots. Both sides see the same rows in the same order, so their counts agree
// (both start at reset). A word is read before its slot is written again as long as the
// reading side runs less than ROWS - 1 rows behind the writing side (sgm_top derives ROWS
// from the fill's, the snap's and the median's latencies).
//
// The output word: the 16-bit word of the same pixel (word_i, word_valid_i: the disparity
// word in the slot of the read, or sgm_depth's word WORD_DELAY slots after it) with the
// confidence in bits 23:16 when conf_en_i (OUTPUT.CONFIDENCE), else 0 there. The memory's
// read takes RAM_LATENCY = 3 slots: a word that comes sooner waits the difference (a reset
// pipeline for its valid flag), one that comes later has the confidence wait for it.
//
// Parameters: MAX_WIDTH (the widest frame), CW column bits (hold MAX_WIDTH - 1), ROWS
// (a power of two, >= 2), WORD_DELAY (>= 0) the slots from a pixel's read to its word_i.
// Latency: word_o max(WORD_DELAY, RAM_LATENCY) enabled slots after the read (rd_valid_i),
// max(0, RAM_LATENCY - WORD_DELAY) after word_i. Throughput: one write, one read and one
// word per slot. Reset: the two row counters and the valid pipeline.
module sgm_confidence_rows #(
  parameter int MAX_WIDTH = 1024,
  parameter int CW        = $clog2(MAX_WIDTH + 1),
  parameter int ROWS      = 8,
  parameter int WORD_DELAY = 0,
  localparam int RAM_LATENCY /*verilator public*/ = 3
) (
  input  wire           clk_i,
  input  wire           rst_ni,
  input  wire           en_i,
  // Write side: the LR check's output pixel (col, its confidence).
  input  wire           wr_valid_i,
  input  wire [CW-1:0]  wr_col_i,
  input  wire [7:0]     conf_i,
  // Read side: the median's output pixel.
  input  wire           rd_valid_i,
  input  wire [CW-1:0]  rd_col_i,
  // The 16-bit word of the pixel read WORD_DELAY slots earlier, and the output word.
  input  wire           conf_en_i,
  input  wire [15:0]    word_i,
  input  wire           word_valid_i,
  output logic [23:0]   word_o,
  output logic          word_valid_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(MAX_WIDTH >= 1)) begin : g_bad_max_width
    $error("sgm_confidence_rows: MAX_WIDTH = %0d: MAX_WIDTH must be at least 1", MAX_WIDTH);
  end
  if (!(CW >= $clog2(MAX_WIDTH))) begin : g_bad_cw
    $error("sgm_confidence_rows: CW = %0d: CW must hold MAX_WIDTH - 1 = %0d", CW, MAX_WIDTH - 1);
  end
  if (!(ROWS >= 2 && (ROWS & (ROWS - 1)) == 0)) begin : g_bad_rows
    $error("sgm_confidence_rows: ROWS = %0d: ROWS must be a power of two >= 2", ROWS);
  end
  if (!(WORD_DELAY >= 0)) begin : g_bad_word_delay
    $error("sgm_confidence_rows: WORD_DELAY = %0d: WORD_DELAY must be at least 0", WORD_DELAY);
  end
`endif

  localparam int BW  = $clog2(ROWS);
  localparam int MW  = ROWS * MAX_WIDTH;
  localparam int MAW = $clog2(MW);

  // The row slot of each side: the next one from a column 0 on (all ones at reset, so
  // that the first row is slot 0 on both sides).
  logic [BW-1:0] wr_slot_q, rd_slot_q;
  wire  [BW-1:0] wr_slot = wr_col_i == '0 ? wr_slot_q + 1'b1 : wr_slot_q;
  wire  [BW-1:0] rd_slot = rd_col_i == '0 ? rd_slot_q + 1'b1 : rd_slot_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_slot_q <= '1;
      rd_slot_q <= '1;
    end else if (en_i) begin
      if (wr_valid_i) wr_slot_q <= wr_slot;
      if (rd_valid_i) rd_slot_q <= rd_slot;
    end
  end

  logic [7:0] conf_read, conf_now;  // the memory's word; its pixel's, beside word
  sgm_bank_ram #(.WIDTH(8), .DEPTH(MW), .AW(MAW), .LATENCY(RAM_LATENCY)) u_mem (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .we_i   (wr_valid_i),
    .waddr_i(MAW'({wr_col_i, wr_slot})),
    .wdata_i(conf_i),
    .raddr_i(MAW'({rd_col_i, rd_slot})),
    .rdata_o(conf_read)
  );

  // ------------------------------------------------------------ the output word
  logic [15:0] word;
  logic        word_valid;
  if (WORD_DELAY < RAM_LATENCY) begin : g_word_waits
    localparam int WAIT = RAM_LATENCY - WORD_DELAY;
    sgm_delay #(.WIDTH(16), .DEPTH(WAIT)) u_word_wait (
      .clk_i(clk_i),
      .en_i (en_i),
      .d_i  (word_i),
      .q_o  (word)
    );
    logic [WAIT-1:0] valid_q;
    if (WAIT == 1) begin : g_one
      always_ff @(posedge clk_i) begin
        if (!rst_ni) valid_q <= '0;
        else if (en_i) valid_q <= word_valid_i;
      end
    end else begin : g_more
      always_ff @(posedge clk_i) begin
        if (!rst_ni) valid_q <= '0;
        else if (en_i) valid_q <= {valid_q[WAIT-2:0], word_valid_i};
      end
    end
    assign word_valid = valid_q[WAIT-1];
    assign conf_now   = conf_read;
  end else if (WORD_DELAY > RAM_LATENCY) begin : g_conf_waits
    sgm_delay #(.WIDTH(8), .DEPTH(WORD_DELAY - RAM_LATENCY)) u_conf_wait (
      .clk_i(clk_i),
      .en_i (en_i),
      .d_i  (conf_read),
      .q_o  (conf_now)
    );
    assign {word, word_valid} = {word_i, word_valid_i};
  end else begin : g_aligned
    assign conf_now = conf_read;
    assign {word, word_valid} = {word_i, word_valid_i};
  end
  // conf_en_i is a constant of the frame (the configuration word's field).
  assign word_o       = {conf_en_i ? conf_now : 8'd0, word};
  assign word_valid_o = word_valid;

endmodule
`default_nettype wire
