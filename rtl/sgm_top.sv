// SPDX-License-Identifier: Apache-2.0
`default_nettype none
`include "sgm_cfg.svh"
// sgm_top: Semi-Global Matching stereo core with the refined rank cost of
// Yao & Cheng, one pixel per clock (docs/algorithm.md defines every bit,
// docs/rtl.md the architecture).
//
//   s_axis (left + right gray) [-> sgm_rectify, RECTIFY = 1] -> sgm_stream_ctrl [-> sgm_lane_deal, LANES > 1]
//   -> 2 x sgm_census_unit
//   -> sgm_cost_volume (D PEs) -> sgm_path_engine (4 paths, S) -> sgm_wta
//   -> sgm_lr_check -> sgm_hole_fill -> sgm_edge_snap -> sgm_median5x5 [-> sgm_depth, DEPTH = 1]
//   -> sgm_stream_ctrl -> m_axis
//   [sgm_wta -> sgm_lr_check -> sgm_confidence_rows -> the output word's bits 23:16, CONFIDENCE = 1]
//
// Parameters: D disparities (a power of two from 16 to 256; built and tested at 16, 32,
// 64, 128), MAX_WIDTH (>= MIN_FRAME_WIDTH), MAX_HEIGHT (>= 9) (public to
// the Verilator testbenches, which read the build's limits from the model),
// CENSUS_H census window height: 5 (9x5, ours, the default) or 9 (9x9, the
// paper's); every dependent width follows from it (census bits NB 44 / 80,
// line buffers 4 / 8 lines per image, rank, popcounts, Cmax 88 / 160, costs
// CBITS 7 / 8 bits, LW, SW, the path-buffer word). LANES = K row lanes
// (docs/lanes.md, docs/rtl.md "Lanes"): 1 is the raster schedule; K > 1
// deals the input's gray pairs to K row lanes that share the census units, the
// cost volume, the path engine (K cycles for the 0 degree loop), the WTA and
// the LR check's S side, and the LR check's memories restore raster order for
// the stages behind it (fill, snap, median, output), LR_LAG rows behind the
// raster census position. UNIQUENESS and AD_TERM (1, the default, or 0) build the
// two run-time levers that cost area, the uniqueness ratio (sgm_wta, the unique
// flag in sgm_lr_check) and the AD term (sgm_cost_volume's PEs and the gray in its
// delay line); with 0 the logic is not built, the latencies are the same, and a
// frame that asks for the missing lever (CONFIG.UNIQUENESS or PENALTY.AD_WEIGHT not 0)
// is dropped with error_o[3] (sgm_axi's FEATURES register reports the build).
// RIGHT_BLOCK = B > 0 builds the fifth path, 0 degrees from the right, in blocks of
// B pixels with one block of look-ahead (sgm_right_path, docs/algorithm.md section 5;
// run-time weight PENALTY.RIGHT_WEIGHT, 0 = off): it sits between the cost volume and
// the path engine and delays everything behind the census by its latency
// (K (4B + 1 + ceil(5 / K)) + 1 slots); 0 leaves it out (the default: 64).
// EDGE_RESET = 1 builds the path restart at strong edges (docs/rtl.md; run-time
// EDGE_RESET.T, 0 = off, LEN and PATHS; the default); 0 leaves it out, and a frame
// with T != 0 is dropped with error_o[3].
// DEPTH = 1 builds the depth output (sgm_depth, docs/algorithm.md section 10b): run-time
// OUTPUT.MODE selects the output word, the disparity or the depth in mm from
// DEPTH_FOCAL.F and DEPTH_BASELINE.B, exact to the LSB; it adds its LATENCY (20 slots)
// behind the median. 0 leaves it out (the default), and a frame that asks for depth is
// dropped with error_o[3].
// MIN_DISPARITY = 1 builds the minimum disparity (docs/algorithm.md section 3): run-time
// MIN_DISPARITY.DMIN = dmin, 0 .. 255; the search covers dmin .. dmin + D - 1 (the right
// image enters sgm_cost_volume's delay line dmin pixels late, a memory of 256 K entries),
// the LR check's bound is x - dmin - d >= 0, and the disparity is the true one from the WTA
// on (DW = ceil(log2(D + 256)) + 4 bits in the stages behind it). 0 leaves it out (the
// default), and a frame with dmin != 0 is dropped with error_o[3].
// RECTIFY = 1 builds the rectification in the stream (sgm_rectify, docs/algorithm.md section
// 13; docs/rtl.md "Rectification in the stream"): the input is a raw pair, each image resampled
// through its mesh (RECTIFY_GRID_LOG2: the mesh step; the meshes through the mesh port, one
// node a cycle into the copy not in use, then mesh_swap_i) from a line buffer of RECTIFY_ROWS
// rows; run-time RECTIFY.ENABLE (0: the pair passes) and RECTIFY.LAG (at most RECTIFY_ROWS -
// 2). cfg_i is then sampled with the raw frame's first beat and travels with the frame to the
// stream controller; sgm_rectify_join makes the word of a pixel whose left source lies
// outside the raw image 0 and counts the raw framing errors (sgm_rectify checks them) for the
// frame. 0 leaves it out (the default), and a frame with RECTIFY.ENABLE or LAG not 0 is
// dropped with error_o[3].
// CONFIDENCE = 1 builds the confidence (docs/algorithm.md section 7b): sgm_wta divides the
// second best cost by the best (4 slots more of latency), sgm_lr_check keeps the result
// beside the left word and zeroes it where the pixel is invalid, sgm_confidence_rows carries
// it past the fill, the snap and the median (a memory of 8 rows x MAX_WIDTH x 8 bit), and
// run-time OUTPUT.CONFIDENCE puts it in bits 23:16 of the output word, which is then 24 bits
// wide (OUT_W; 0 there when the field is 0); the output stage waits 3 slots more for the
// memory's read (without DEPTH; sgm_depth's latency covers it). 0 leaves it out (the
// default; OUT_W = 16), and a frame with OUTPUT.CONFIDENCE = 1 is dropped with error_o[3].
// MIN_WIDTH: the narrowest frame the build accepts; 0 (the default) is the least the build
// allows, max(D, 16, K SKEW + 1). With lanes a larger value is a memory lever: the LR check
// runs LR_LAG = 2K - 3 + ceil(LR_WAIT / W) rows behind the census, so a wider narrowest frame
// bounds the lag lower, and the LR check's word memories and the edge snap's gray rows (a
// power of two above the lag) shrink with it; at D = 64, six lanes, MIN_WIDTH 128 halves both.
// A frame narrower than MIN_FRAME_WIDTH is dropped with error_o[3] (sgm_axi: MIN_WIDTH).
// Configuration: cfg_i, the frame configuration word (rtl/sgm_cfg.svh, generated from
// regmap/sgm_regmap.def; its fields are the read-write fields of sgm_axi's FRAME_SIZE,
// PENALTY, CONFIG, EDGE_RESET, OUTPUT, DEPTH_FOCAL, DEPTH_BASELINE, MIN_DISPARITY and RECTIFY,
// docs/registers.md), taken at each start of frame by
// sgm_stream_ctrl, which checks it and latches it whole; this module slices the latched
// word for the stages by the generated CFG_<REGISTER>_<FIELD>_LSB / _W.
// Frame constraints: MIN_FRAME_WIDTH (max(D, 16); with many lanes at least the
// engine's K SKEW + 1) <= width <= MAX_WIDTH, 9 <= height <= MAX_HEIGHT
// (frames outside are dropped and flagged in error_o[3], as are P2' < P1, cost mode 3,
// a field above its legal range and a lever the build lacks).
// Throughput: one pixel per clock while a frame streams; after its last input
// pixel a frame needs about 6 more lines of flush (8 with the 9x9 census; K lanes add LR_LAG,
// about 2K - 2 lines; input stalled) and, at its start, the P2 table fill (about 2 x 256 cycles).
// Latency: about 6 lines + D + a few tens of pixels from a pixel in to its
// disparity out.
module sgm_top #(
  parameter int D          /*verilator public*/ = 64,
  parameter int MAX_WIDTH  /*verilator public*/ = 1280,
  parameter int MAX_HEIGHT /*verilator public*/ = 1024,
  parameter int CENSUS_H   /*verilator public*/ = 5,
  parameter int LANES      /*verilator public*/ = 1,
  parameter int UNIQUENESS /*verilator public*/ = 1,  // the uniqueness ratio is built (0: not)
  parameter int AD_TERM    /*verilator public*/ = 1,  // the AD term is built (0: not)
  parameter int RIGHT_BLOCK /*verilator public*/ = 64,  // the fifth path's block B (a power of two >= 2), 0: not built
  parameter int EDGE_RESET /*verilator public*/ = 1,  // the path restart at strong edges is built (0: not)
  parameter int DEPTH      /*verilator public*/ = 0,  // the depth output is built (0: not)
  parameter int MIN_DISPARITY /*verilator public*/ = 0,  // the minimum disparity is built (0: not)
  parameter int RECTIFY    /*verilator public*/ = 0,  // the rectification in the stream is built (0: not)
  parameter int RECTIFY_ROWS /*verilator public*/ = 32,  // its line buffer rows R (a power of two, 4 .. 256)
  parameter int RECTIFY_GRID_LOG2 /*verilator public*/ = 4,  // its mesh step G = 2^RECTIFY_GRID_LOG2 px (2 .. 6)
  parameter int CONFIDENCE /*verilator public*/ = 0,  // the confidence is built (0: not)
  parameter int MIN_WIDTH  /*verilator public*/ = 0,  // the narrowest frame accepted (0: the least the build allows)
  localparam int OUT_W     /*verilator public*/ = CONFIDENCE != 0 ? 24 : 16,  // the output word's bits
  localparam int XW        = $clog2(MAX_WIDTH + 1),
  // Lanes (docs/lanes.md "The top's wiring at K lanes"). The engine's
  // SKEW (sgm_path_engine owns the formula; mirrored here for the deal, checked
  // by every lane build's whole-core test) and the narrowest frame it allows.
  localparam int SKEW       = 1 + (5 + ($clog2(D) + 1) / 2 + LANES - 1) / LANES,
  localparam int MIN_WIDTH_BOUND = (LANES * SKEW + 1 > D && LANES * SKEW + 1 > 16) ? LANES * SKEW + 1 : (D > 16 ? D : 16),
  localparam int MIN_FRAME_WIDTH /*verilator public*/ = MIN_WIDTH > MIN_WIDTH_BOUND ? MIN_WIDTH : MIN_WIDTH_BOUND,
  // The LR check's read side runs LR_LAG whole rows behind the raster census
  // position (where a census unit in raster order would be): every word the
  // read of left pixel (x, y) needs (its WTA result, dR of the diagonal, or of
  // the row tail the lane writes during the first D columns of its next row) is
  // written (2K - 3) W + LR_WAIT slots or less after that position passed
  // (x, y + 1) (derivation in docs/lanes.md; the lanes' census outputs come
  // 4K slots later than a census behind the deal would give them: its 4 columns
  // of lag cost K slots each in a lane); LR_LAG = 2K - 3 + ceil(LR_WAIT / W) per
  // frame, at most LR_LAG_MAX. LR_WAIT's constant is the cost volume's latency
  // (4, with the AD term's stage: each slot more there is a slot later for every
  // write).
  localparam int COST_LATENCY = 4,  // sgm_cost_volume LATENCY
  // The fifth path: RP_LATENCY bounds sgm_right_path's LATENCY (K (4B + 1 +
  // ceil(5 / K)) + 1 <= K (4B + 6) + 1) for the row counts below.
  localparam int RIGHT_PATH = RIGHT_BLOCK != 0 ? 1 : 0,
  localparam int RP_LATENCY = RIGHT_PATH != 0 ? LANES * (4 * RIGHT_BLOCK + 6) + 1 : 0,
  localparam int LR_WAIT    = (D + 4) * LANES + COST_LATENCY,
  localparam int LR_LAG_MAX = LANES == 1 ? 0 :
                              2 * LANES - 3 + (LR_WAIT + MIN_FRAME_WIDTH - 1) / MIN_FRAME_WIDTH,
  localparam int YW        = $clog2(MAX_HEIGHT + 16),  // the frame height output
  // Row positions inside the core: rows before a frame's row 0 (negative,
  // RW-bit wrap) and after its last (flush) must not alias: 16 with one lane,
  // LR_LAG_MAX and the lanes' lead more, and the rows the fifth path's delay adds to the flush.
  localparam int RW        = $clog2(MAX_HEIGHT + 16 + (LANES == 1 ? 0 : 2 * LR_LAG_MAX + 2 * LANES + 4) +
                                    (RIGHT_PATH != 0 ? RP_LATENCY / MIN_FRAME_WIDTH + 2 : 0)),
  localparam int LD        = $clog2(D),
  localparam int DW        = (MIN_DISPARITY != 0 ? $clog2(D + 256) : LD) + 4,  // the true disparity, 1/16 px
  localparam int NB        = 9 * CENSUS_H - 1,            // census bits: 44 (9x5), 80 (9x9)
  localparam int RKW       = $clog2(NB + 1),              // rank 0 .. NB
  localparam int CBITS     = $clog2(2 * NB + 1),          // matching cost: Cmax = 2 NB (unified)
  localparam int LW        = $clog2(2 * NB + 255 + 1),    // path cost: Cmax + P2'max (343 / 415 < 512)
  localparam int SW        = LW + 4 + RIGHT_PATH  // S = 3 L0 + 2 L45 + 3 L90 + 2 L135 (+ W5 L5) < 10 (+ 15) x 2^LW
) (
  input  wire          clk_i,
  input  wire          rst_ni,
  // Input stream: one left and one right gray pixel per beat.
  input  wire  [15:0]  s_tdata_i,   // {right, left}
  input  wire          s_tuser_i,   // start of frame
  input  wire          s_tlast_i,   // end of line
  input  wire          s_tvalid_i,
  output logic         s_tready_o,
  // Output stream: one word per beat, same framing.
  output logic [OUT_W-1:0] m_tdata_o,  // [15:0] {valid, zeros, disparity x 16}, or the depth in mm
                                       // (OUTPUT.MODE); [23:16] the confidence (OUTPUT.CONFIDENCE)
  output logic         m_tuser_o,
  output logic         m_tlast_o,
  output logic         m_tvalid_o,
  input  wire          m_tready_i,
  // Configuration: the frame configuration word (rtl/sgm_cfg.svh), latched at start of frame.
  input  wire [CFG_W-1:0] cfg_i,
  // The rectification's meshes (RECTIFY = 1; sgm_rectify: a node (u, v) of image channel 0
  // (left) or 1 (right), written into the copy not in use while mesh_swap_pending_o is low,
  // then mesh_swap_i; tie to 0 without it).
  input  wire          mesh_we_i,
  input  wire          mesh_channel_i,
  input  wire  [11:0]  mesh_row_i,
  input  wire  [11:0]  mesh_col_i,
  input  wire  [17:0]  mesh_u_i,       // 1/32 px, signed
  input  wire  [17:0]  mesh_v_i,
  input  wire          mesh_swap_i,
  output logic         mesh_swap_pending_o,
  output logic         rect_row_miss_o,  // the frame's calibration reads a row the buffer no longer holds
  // Status.
  output logic         busy_o,
  output logic         frame_done_o,
  output logic [3:0]   error_o,        // sticky per frame (sgm_stream_ctrl)
  output logic [3:0]   error_event_o,  // one-cycle pulse per error event (the bits error_o sets)
  // The configuration of the frame in flight (taken at its start of frame;
  // still the finished frame's in the cycle of frame_done_o).
  output logic [XW-1:0] frame_width_o,
  output logic [YW-1:0] frame_height_o,
  // The build's narrowest frame (MIN_FRAME_WIDTH, a constant): sgm_axi's MIN_WIDTH.
  output logic [XW-1:0] min_width_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(D >= 16 && D <= 256 && (D & (D - 1)) == 0)) begin : g_bad_d
    $error("sgm_top: D = %0d: D must be a power of two from 16 to 256", D);
  end
  if (!(MIN_WIDTH == 0 || MIN_WIDTH >= MIN_WIDTH_BOUND)) begin : g_bad_min_width
    $error("sgm_top: MIN_WIDTH = %0d: MIN_WIDTH must be 0 or at least the build's narrowest frame, max(D, 16, LANES SKEW + 1) = %0d", MIN_WIDTH, MIN_WIDTH_BOUND);
  end
  if (!(MAX_WIDTH >= MIN_FRAME_WIDTH)) begin : g_bad_max_width
    $error("sgm_top: MAX_WIDTH = %0d: MAX_WIDTH must be at least the narrowest frame, MIN_FRAME_WIDTH = %0d (MIN_WIDTH, or max(D, 16, LANES SKEW + 1))", MAX_WIDTH, MIN_FRAME_WIDTH);
  end
  if (!(MAX_HEIGHT >= 9)) begin : g_bad_max_height
    $error("sgm_top: MAX_HEIGHT = %0d: MAX_HEIGHT must be at least 9 (the narrowest frame has 9 rows)", MAX_HEIGHT);
  end
  if (!(CENSUS_H == 5 || CENSUS_H == 9)) begin : g_bad_census_h
    $error("sgm_top: CENSUS_H = %0d: CENSUS_H must be 5 (the 9x5 census) or 9 (the 9x9)", CENSUS_H);
  end
  if (!(LANES >= 1)) begin : g_bad_lanes
    $error("sgm_top: LANES = %0d: LANES must be at least 1", LANES);
  end
  if (!(UNIQUENESS == 0 || UNIQUENESS == 1)) begin : g_bad_uniqueness
    $error("sgm_top: UNIQUENESS = %0d: UNIQUENESS must be 0 or 1", UNIQUENESS);
  end
  if (!(AD_TERM == 0 || AD_TERM == 1)) begin : g_bad_ad_term
    $error("sgm_top: AD_TERM = %0d: AD_TERM must be 0 or 1", AD_TERM);
  end
  if (!(EDGE_RESET == 0 || EDGE_RESET == 1)) begin : g_bad_edge_reset
    $error("sgm_top: EDGE_RESET = %0d: EDGE_RESET must be 0 or 1", EDGE_RESET);
  end
  if (!(DEPTH == 0 || DEPTH == 1)) begin : g_bad_depth
    $error("sgm_top: DEPTH = %0d: DEPTH must be 0 or 1", DEPTH);
  end
  if (!(MIN_DISPARITY == 0 || MIN_DISPARITY == 1)) begin : g_bad_min_disparity
    $error("sgm_top: MIN_DISPARITY = %0d: MIN_DISPARITY must be 0 or 1", MIN_DISPARITY);
  end
  if (!(CONFIDENCE == 0 || CONFIDENCE == 1)) begin : g_bad_confidence
    $error("sgm_top: CONFIDENCE = %0d: CONFIDENCE must be 0 or 1", CONFIDENCE);
  end
  if (!(RECTIFY == 0 || RECTIFY == 1)) begin : g_bad_rectify
    $error("sgm_top: RECTIFY = %0d: RECTIFY must be 0 or 1", RECTIFY);
  end
  if (RECTIFY != 0 && !(RECTIFY_ROWS >= 4 && RECTIFY_ROWS <= 256 && (RECTIFY_ROWS & (RECTIFY_ROWS - 1)) == 0)) begin : g_bad_rectify_rows
    $error("sgm_top: RECTIFY_ROWS = %0d: RECTIFY_ROWS must be a power of two from 4 to 256", RECTIFY_ROWS);
  end
  if (RECTIFY != 0 && !(RECTIFY_GRID_LOG2 >= 2 && RECTIFY_GRID_LOG2 <= 6)) begin : g_bad_rectify_grid
    $error("sgm_top: RECTIFY_GRID_LOG2 = %0d: RECTIFY_GRID_LOG2 must be 2 .. 6 (mesh steps of 4 .. 64 px)", RECTIFY_GRID_LOG2);
  end
  if (!(RIGHT_BLOCK == 0 || (RIGHT_BLOCK >= 2 && (RIGHT_BLOCK & (RIGHT_BLOCK - 1)) == 0))) begin : g_bad_right_block
    $error("sgm_top: RIGHT_BLOCK = %0d: RIGHT_BLOCK must be 0 (no fifth path) or a power of two >= 2", RIGHT_BLOCK);
  end
`endif

  assign min_width_o = XW'(MIN_FRAME_WIDTH);

  // ------------------------------------------------------------ control
  logic          en, en_ctrl;  // en: en_ctrl on the clock network where the flow asks for it
  logic [7:0]    pix_l, pix_r;
  logic [XW-1:0] col0, width;
  logic          sof0;  // the slot is the frame's first, (0, 0): a flag of the controller
  logic [RW-1:0] row0, height;
  // The frame's configuration word, latched at its start: the stages take its fields,
  // cfg[CFG_<REGISTER>_<FIELD>_LSB +: CFG_<REGISTER>_<FIELD>_W]; the frame size they take
  // at the positions' widths (width, height).
  logic [CFG_W-1:0] cfg;
  wire  [CFG_FRAME_SIZE_WIDTH_W+CFG_FRAME_SIZE_HEIGHT_W-1:0] unused_cfg_size =
      {cfg[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W], cfg[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W]};
  logic          lut_start, lut_ready, lut_ready_core;
  logic          res_valid;
  logic [OUT_W-1:0] res_word;

  // ------------------------------------------------------------ rectification
  // With RECTIFY = 1 the input pair goes through sgm_rectify (two channels: left in bits 7:0,
  // right in 15:8) before the stream controller, which then sees rectified frames with the
  // configuration word each raw frame came with (sgm_rectify's side band: a frame's word
  // travels with it through the line buffer's lag). The framing of the raw input is checked
  // by sgm_rectify (error kinds 0 .. 2; its output frames are always whole); the left
  // pixel's outside flag rides beside the beat into the stream controller (side_o with the
  // slot) and waits in sgm_rectify_join for that pixel's output word, which it turns into 0
  // (disparity 0, invalid; depth 0): docs/algorithm.md section 13.
  logic [15:0]      ctrl_tdata;
  logic             ctrl_tuser, ctrl_tlast, ctrl_tvalid, ctrl_tready, ctrl_tside;
  logic [CFG_W-1:0] ctrl_cfg;
  logic [3:0]       ctrl_error, ctrl_error_set;
  logic             ctrl_busy;
  logic             side0;
  logic [OUT_W-1:0] res_word_out;
  if (RECTIFY != 0) begin : g_rectify
    localparam int RXW = $clog2(MAX_WIDTH + 1);
    localparam int RYW = $clog2(MAX_HEIGHT + 1);
    localparam int RNX = ((MAX_WIDTH - 1) >> RECTIFY_GRID_LOG2) + 2;
    localparam int RNY = ((MAX_HEIGHT - 1) >> RECTIFY_GRID_LOG2) + 2;
`ifndef __ICARUS__
    if (RNX > 4096 || RNY > 4096) begin : g_bad_mesh
      $error("sgm_top: the mesh of %0d x %0d nodes exceeds the 12-bit mesh_col_i / mesh_row_i", RNX, RNY);
    end
`endif
    logic [1:0] outside;
    logic [2:0] rect_frame_error, rect_error_set;
    logic       rect_busy;
    wire  [2:0] unused_rect_error_set = rect_error_set;  // the events as the join counts them instead
    sgm_rectify #(
      .MAX_WIDTH (MAX_WIDTH),
      .MAX_HEIGHT(MAX_HEIGHT),
      .ROWS      (RECTIFY_ROWS),
      .GRID_LOG2 (RECTIFY_GRID_LOG2),
      .CHANNELS  (2),
      .INFO_W    (CFG_W)
    ) u_rectify (
      .clk_i              (clk_i),
      .rst_ni             (rst_ni),
      .width_i            (RXW'(cfg_i[CFG_FRAME_SIZE_WIDTH_LSB +: CFG_FRAME_SIZE_WIDTH_W])),
      .height_i           (RYW'(cfg_i[CFG_FRAME_SIZE_HEIGHT_LSB +: CFG_FRAME_SIZE_HEIGHT_W])),
      .lag_i              (cfg_i[CFG_RECTIFY_LAG_LSB +: CFG_RECTIFY_LAG_W]),
      .enable_i           (cfg_i[CFG_RECTIFY_ENABLE_LSB]),
      .info_i             (cfg_i),
      .info_o             (ctrl_cfg),
      .mesh_we_i          (mesh_we_i),
      .mesh_channel_i     (mesh_channel_i),
      .mesh_row_i         ($clog2(RNY)'(mesh_row_i)),
      .mesh_col_i         ($clog2(RNX)'(mesh_col_i)),
      .mesh_u_i           (mesh_u_i),
      .mesh_v_i           (mesh_v_i),
      .mesh_swap_i        (mesh_swap_i),
      .mesh_swap_pending_o(mesh_swap_pending_o),
      .s_tdata_i          (s_tdata_i),
      .s_tvalid_i         (s_tvalid_i),
      .s_tready_o         (s_tready_o),
      .s_tuser_i          (s_tuser_i),
      .s_tlast_i          (s_tlast_i),
      .m_tdata_o          (ctrl_tdata),
      .m_tvalid_o         (ctrl_tvalid),
      .m_tready_i         (ctrl_tready),
      .m_tuser_o          (ctrl_tuser),
      .m_tlast_o          (ctrl_tlast),
      .m_outside_o        (outside),
      .m_error_o          (rect_frame_error),
      .error_set_o        (rect_error_set),
      .busy_o             (rect_busy),
      .row_miss_o         (rect_row_miss_o)
    );
    assign ctrl_tside    = outside[0];
    // The mesh address ports are 12 bits for every build; the build's mesh takes the low bits.
    wire [23:0] unused_mesh_address = {mesh_row_i, mesh_col_i};
    wire unused_outside  = outside[1];  // a right pixel outside only costs its matches
    // The outside flags in flight: at most the slots of a frame's flush, fewer than the rows
    // the row positions keep apart beyond a frame (RW) times the width.
    localparam int SIDE_ROWS = 16 + (LANES == 1 ? 0 : 2 * LR_LAG_MAX + 2 * LANES + 4) +
                               (RIGHT_PATH != 0 ? RP_LATENCY / MIN_FRAME_WIDTH + 2 : 0);
    sgm_rectify_join #(
      .DEPTH_LOG2($clog2(SIDE_ROWS * MAX_WIDTH)),
      .YW        (RW),
      .WORD_W    (OUT_W)
    ) u_join (
      .clk_i           (clk_i),
      .rst_ni          (rst_ni),
      .en_i            (en),
      .row_i           (row0),
      .height_i        (height),
      .side_i          (side0),
      .res_valid_i     (res_valid),
      .res_word_i      (res_word),
      .res_word_o      (res_word_out),
      .ctrl_error_i    (ctrl_error),
      .ctrl_error_set_i(ctrl_error_set),
      .beat_valid_i    (ctrl_tvalid),
      .beat_ready_i    (ctrl_tready),
      .frame_error_i   (rect_frame_error),
      .lut_start_i     (lut_start),
      .ctrl_busy_i     (ctrl_busy),
      .rect_busy_i     (rect_busy),
      .busy_o          (busy_o),
      .error_o         (error_o),
      .error_set_o     (error_event_o)
    );
  end else begin : g_no_rectify
    assign ctrl_tdata          = s_tdata_i;
    assign ctrl_tuser          = s_tuser_i;
    assign ctrl_tlast          = s_tlast_i;
    assign ctrl_tvalid         = s_tvalid_i;
    assign s_tready_o          = ctrl_tready;
    assign ctrl_tside          = 1'b0;
    assign ctrl_cfg            = cfg_i;
    assign error_o             = ctrl_error;
    assign busy_o              = ctrl_busy;
    assign error_event_o       = ctrl_error_set;
    assign res_word_out        = res_word;
    assign mesh_swap_pending_o = 1'b0;
    assign rect_row_miss_o     = 1'b0;
    wire [63:0] unused_mesh = {mesh_we_i, mesh_channel_i, mesh_row_i, mesh_col_i, mesh_u_i, mesh_v_i, mesh_swap_i,
                               side0};
  end

  sgm_stream_ctrl #(
    .MAX_WIDTH (MAX_WIDTH),
    .MIN_WIDTH (MIN_FRAME_WIDTH),
    .MAX_HEIGHT(MAX_HEIGHT),
    .NB        (NB),
    .XW        (XW),
    .YW        (RW),
    .FIFO_DEPTH(4),
    .UNIQUENESS(UNIQUENESS),
    .AD_TERM   (AD_TERM),
    .RIGHT_PATH(RIGHT_PATH),
    .EDGE_RESET(EDGE_RESET),
    .DEPTH     (DEPTH),
    .MIN_DISPARITY(MIN_DISPARITY),
    .RECTIFY   (RECTIFY),
    .RECTIFY_ROWS(RECTIFY_ROWS),
    .CONFIDENCE(CONFIDENCE),
    .WORD_W    (OUT_W)
  ) u_ctrl (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .s_tdata_i     (ctrl_tdata),
    .s_tuser_i     (ctrl_tuser),
    .s_tlast_i     (ctrl_tlast),
    .s_tvalid_i    (ctrl_tvalid),
    .s_tready_o    (ctrl_tready),
    .s_tside_i     (ctrl_tside),
    .m_tdata_o     (m_tdata_o),
    .m_tuser_o     (m_tuser_o),
    .m_tlast_o     (m_tlast_o),
    .m_tvalid_o    (m_tvalid_o),
    .m_tready_i    (m_tready_i),
    .cfg_i         (ctrl_cfg),
    .cfg_o         (cfg),
    .width_o       (width),
    .height_o      (height),
    .lut_start_o   (lut_start),
    .lut_ready_i   (lut_ready),
    .en_o          (en_ctrl),
    .pix_left_o    (pix_l),
    .pix_right_o   (pix_r),
    .col_o         (col0),
    .row_o         (row0),
    .sof_o         (sof0),
    .side_o        (side0),
    .res_valid_i   (res_valid),
    .res_word_i    (res_word_out),
    .busy_o        (ctrl_busy),
    .frame_done_o  (frame_done_o),
    .error_o       (ctrl_error),
    .error_set_o   (ctrl_error_set)
  );

  // The enable reaches every flip-flop of the datapath: on ECP5 it rides a
  // global network (sgm_global_buf, SGM_ECP5_GLOBAL).
  sgm_global_buf u_en_global (
    .sig_i (en_ctrl),
    .sig_o (en)
  );

  // The minimum disparity of the frame (0 in a build without it: the field is 0 in every
  // frame such a build takes, and the LR check's bound then folds away).
  logic [7:0] dmin;
  if (MIN_DISPARITY != 0) begin : g_dmin
    assign dmin = cfg[CFG_MIN_DISPARITY_DMIN_LSB +: CFG_MIN_DISPARITY_DMIN_W];
  end else begin : g_no_dmin
    assign dmin = 8'd0;
    wire [CFG_MIN_DISPARITY_DMIN_W-1:0] unused_cfg_dmin = cfg[CFG_MIN_DISPARITY_DMIN_LSB +: CFG_MIN_DISPARITY_DMIN_W];
  end

  assign frame_width_o  = width;
  assign frame_height_o = height[YW-1:0];

  // ------------------------------------------------------------ lanes
  // The slot stream of the census units: with one lane the stream controller's
  // raster itself; with K lanes sgm_lane_deal deals the raster's gray pairs to
  // the K row lanes (docs/lanes.md "The deal in front of the census"):
  // its frame starts at the frame's first slot (0, 0), lanes LANE_LEAD = K - 1
  // rows ahead of the raster's row 0, its ring DEAL_ROWS >= 2K - 2 rows (a power
  // of two: 2, 4, 16 at K = 2, 3, 6). The
  // census units then run in lane order (their LANES), and their output is the
  // lanes' slot stream for the cost volume, the path engine and the WTA.
  localparam int CENSUS_LATENCY = 5;                  // sgm_census_unit LATENCY
  localparam int CENSUS_RY      = (CENSUS_H - 1) / 2;  // the centre's rows behind the input
  logic [7:0]    cen_pix_l, cen_pix_r;
  logic [XW-1:0] cen_col;
  logic [RW-1:0] cen_row;
  logic          cen_active;
  // The LR check's read position: the path engine's output position (col3,
  // row3) with one lane, with K lanes the raster census position LR_LAG rows back
  // (rdt_*: sgm_lane_timing's, delayed with the census side when the fifth path
  // is built).
  logic [XW-1:0]  col3, rd_col, rdt_col, rdt_col_e;
  logic [RW-1:0]  row3, rd_row, rdt_row, rdt_row_e;

  if (LANES == 1) begin : g_raster
    assign {cen_pix_r, cen_pix_l} = {pix_r, pix_l};
    assign cen_col    = col0;
    assign cen_row    = row0;
    assign cen_active = 1'b1;
    wire unused_sof = sof0;  // only the lanes restart at it
    assign rd_col     = col3;
    assign rd_row     = row3;
    assign rdt_col    = '0;  // no lane timing
    assign rdt_row    = '0;
    wire [XW+RW-1:0] unused_rdt = {rdt_col_e, rdt_row_e};  // wiring only (no logic in the top)
  end else begin : g_lanes
    localparam int LANE_LEAD = LANES - 1;
    localparam int DEAL_ROWS = 1 << $clog2(2 * LANES - 2);
    logic unused_deal_valid;
    sgm_lane_timing #(
      .LANES(LANES), .LR_WAIT(LR_WAIT), .LR_LAG_MAX(LR_LAG_MAX), .MIN_FRAME_WIDTH(MIN_FRAME_WIDTH),
      .CENSUS_LATENCY(CENSUS_LATENCY), .CENSUS_RY(CENSUS_RY), .XW(XW), .RW(RW)
    ) u_timing (
      .clk_i     (clk_i),
      .rst_ni    (rst_ni),
      .en_i      (en),
      .width_i   (width),
      .col_i     (col0),
      .row_i     (row0),
      .sof_i     (sof0),
      .rd_col_o  (rdt_col),
      .rd_row_o  (rdt_row)
    );
    assign rd_col = rdt_col_e;
    assign rd_row = rdt_row_e;
    sgm_lane_deal #(
      .WIDTH(16), .LANES(LANES), .SKEW(SKEW), .LANE_LEAD(LANE_LEAD), .ROWS(DEAL_ROWS),
      .MAX_WIDTH(MAX_WIDTH), .XW(XW), .YW(RW)
    ) u_deal (
      .clk_i    (clk_i),
      .rst_ni   (rst_ni),
      .en_i     (en),
      .width_i  (width),
      .height_i (height),
      .sof_i    (sof0),
      .data_i   ({pix_r, pix_l}),
      .col_i    (col0),
      .row_i    (row0),
      .data_o   ({cen_pix_r, cen_pix_l}),
      .col_o    (cen_col),
      .row_o    (cen_row),
      .valid_o  (unused_deal_valid),
      .active_o (cen_active)
    );
  end

  // ------------------------------------------------------------ census
  logic [NB-1:0]  lane_census_l, lane_census_r;
  logic [RKW-1:0] lane_rank_l, lane_rank_r;
  logic [7:0]     lane_centre;
  logic [31:0]    lane_nbr;
  logic [XW-1:0]  lane_col;
  logic [RW-1:0]  lane_row;
  logic           lane_valid;
  logic [7:0]     lane_centre_r;
  logic [31:0]    unused_nbr_r;
  logic [XW-1:0]  unused_col_r;
  logic [RW-1:0]  unused_row_r;
  logic           unused_valid_r;

  sgm_census_unit #(.CENSUS_H(CENSUS_H), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW), .LANES(LANES)) u_census_l (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .en_i     (en),
    .active_i (cen_active),
    .pix_i    (cen_pix_l),
    .col_i    (cen_col),
    .row_i    (cen_row),
    .width_i  (width),
    .height_i (height),
    .census_o (lane_census_l),
    .rank_o   (lane_rank_l),
    .centre_o (lane_centre),
    .nbr_o    (lane_nbr),
    .col_o    (lane_col),
    .row_o    (lane_row),
    .valid_o  (lane_valid)
  );

  sgm_census_unit #(.CENSUS_H(CENSUS_H), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW), .LANES(LANES)) u_census_r (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .en_i     (en),
    .active_i (cen_active),
    .pix_i    (cen_pix_r),
    .col_i    (cen_col),
    .row_i    (cen_row),
    .width_i  (width),
    .height_i (height),
    .census_o (lane_census_r),
    .rank_o   (lane_rank_r),
    .centre_o (lane_centre_r),
    .nbr_o    (unused_nbr_r),
    .col_o    (unused_col_r),
    .row_o    (unused_row_r),
    .valid_o  (unused_valid_r)
  );

  // ------------------------------------------------------------ costs
  logic [D*CBITS-1:0] cost;
  logic [XW-1:0]      col2;  // the engine takes the column COST_LATENCY slots earlier; the fifth path this one
  logic               valid2;

  sgm_cost_volume #(
    .D(D), .CW(XW), .NB(NB), .LANES(LANES), .AD_TERM(AD_TERM), .MIN_DISPARITY(MIN_DISPARITY)
  ) u_cost (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .en_i      (en),
    .mode_i    (cfg[CFG_CONFIG_MODE_LSB +: CFG_CONFIG_MODE_W]),
    .dmin_i    (dmin),
    .ad_weight_i(cfg[CFG_PENALTY_AD_WEIGHT_LSB +: CFG_PENALTY_AD_WEIGHT_W]),
    .ad_cap_i  (cfg[CFG_PENALTY_AD_CAP_LSB +: CFG_PENALTY_AD_CAP_W]),
    .lgray_i   (lane_centre),
    .rgray_i   (lane_centre_r),
    .lcensus_i (lane_census_l),
    .lrank_i   (lane_rank_l),
    .col_i     (lane_col),
    .rcensus_i (lane_census_r),
    .rrank_i   (lane_rank_r),
    .valid_i   (lane_valid),
    .cost_o    (cost),
    .col_o     (col2),
    .valid_o   (valid2)
  );

  // ------------------------------------------------------------ fifth path
  // With RIGHT_BLOCK > 0, sgm_right_path takes the costs and gives them back
  // RP_LATENCY slots later with the fifth path's W5 L5 LANES + 1 slots behind
  // them (the engine's S stage). Everything the stages behind it take from the
  // census side (the census position, row and grays of the engine, the edge
  // snap's gray writes, the LR check's read position) rides in its side bundle,
  // delayed alike: the schedule behind the census is today's, RP_LATENCY slots
  // later (the LR check's and the snap's row counts unchanged).
  localparam int L5W = LW + 4;
  logic [D*CBITS-1:0] cost_e;      // the engine's costs
  logic               valid2_e;
  logic [XW-1:0]      lane_col_e;  // census-side signals, delayed with the costs
  logic [RW-1:0]      lane_row_e;
  logic [7:0]         lane_centre_e;
  logic [31:0]        lane_nbr_e;
  logic               lane_valid_e;
  logic [D*L5W-1:0]   l5w;
  logic               lut_ready_paths;

  if (RIGHT_PATH != 0) begin : g_right
    logic [7:0] gray2;  // the left gray beside its costs
    sgm_delay #(.WIDTH(8), .DEPTH(COST_LATENCY)) u_gray2 (
      .clk_i (clk_i),
      .en_i  (en),
      .d_i   (lane_centre),
      .q_o   (gray2)
    );
    localparam int SIDE_W = 2 * XW + 2 * RW + 8 + 32 + 2;
    sgm_right_path #(
      .D(D), .CW(CBITS), .LW(LW), .PW(8), .BLOCK(RIGHT_BLOCK), .XW(XW), .LANES(LANES), .SIDE_W(SIDE_W),
      .L5_LAG(LANES + 1), .EDGE_RESET(EDGE_RESET)
    ) u_right (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .en_i        (en),
      .width_i     (width),
      .p1_i        (cfg[CFG_PENALTY_P1_LSB +: CFG_PENALTY_P1_W]),
      .weight_i    (cfg[CFG_PENALTY_RIGHT_WEIGHT_LSB +: CFG_PENALTY_RIGHT_WEIGHT_W]),
      .reset_t_i   (cfg[CFG_EDGE_RESET_T_LSB +: CFG_EDGE_RESET_T_W]),
      .reset_len_i (cfg[CFG_EDGE_RESET_LEN_LSB +: CFG_EDGE_RESET_LEN_W]),
      .reset_en_i  (cfg[CFG_EDGE_RESET_PATHS_LSB + 4]),  // the fifth path's restart flag
      .lut_start_i (lut_start),
      .p2_i        (cfg[CFG_PENALTY_P2_LSB +: CFG_PENALTY_P2_W]),
      .p2_mode_i   (cfg[CFG_CONFIG_P2_PAPER_LSB]),
      .lut_ready_i (lut_ready_paths),
      .lut_ready_o (lut_ready_core),
      .cost_i      (cost),
      .gray_i      (gray2),
      .col_i       (col2),
      .side_i      ({lane_col, lane_row, lane_centre, lane_nbr, lane_valid, valid2, rdt_col, rdt_row}),
      .cost_o      (cost_e),
      .side_o      ({lane_col_e, lane_row_e, lane_centre_e, lane_nbr_e, lane_valid_e, valid2_e, rdt_col_e, rdt_row_e}),
      .l5w_o       (l5w)
    );
  end else begin : g_four
    assign lut_ready_core = lut_ready_paths;
    assign {cost_e, valid2_e} = {cost, valid2};
    assign {lane_col_e, lane_row_e, lane_centre_e, lane_nbr_e, lane_valid_e} =
           {lane_col, lane_row, lane_centre, lane_nbr, lane_valid};
    assign {rdt_col_e, rdt_row_e} = {rdt_col, rdt_row};
    assign l5w = '0;
    wire [XW+4:0] unused_right = {cfg[CFG_PENALTY_RIGHT_WEIGHT_LSB +: CFG_PENALTY_RIGHT_WEIGHT_W], col2,
                                  cfg[CFG_EDGE_RESET_PATHS_LSB + 4]};  // wiring only (no logic in the top)
  end

  // The path engine also needs the row and the left grays of the pixel,
  // GRAY_LEAD slot ahead of the costs (its P2 lookup then runs in the slot
  // before the pixel and P2r is registered behind the table's RAM).
  localparam int GRAY_LEAD = 1;
  logic [RW-1:0] row2;
  logic [7:0]    centre2;
  logic [31:0]   nbr2;
  sgm_delay #(.WIDTH(RW + 8 + 32), .DEPTH(COST_LATENCY - GRAY_LEAD)) u_align_cost (
    .clk_i (clk_i),
    .en_i  (en),
    .d_i   ({lane_row_e, lane_centre_e, lane_nbr_e}),
    .q_o   ({row2, centre2, nbr2})
  );

  // ------------------------------------------------------------ paths
  logic [D*SW-1:0] sum;
  logic            last3;  // col3 is its row's last column
  logic            valid3;

  // Its previous-row reads run three slots or more ahead of the costs: the
  // census unit's column (COST_LATENCY slots ahead) goes straight in.
  sgm_path_engine #(
    .D(D), .CW(CBITS), .LW(LW), .PW(8), .MAX_WIDTH(MAX_WIDTH), .XW(XW), .YW(RW), .GRAY_LEAD(GRAY_LEAD),
    .COL_LEAD(COST_LATENCY), .LANES(LANES), .RIGHT_PATH(RIGHT_PATH), .EDGE_RESET(EDGE_RESET)
  ) u_paths (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en),
    .width_i     (width),
    .p1_i        (cfg[CFG_PENALTY_P1_LSB +: CFG_PENALTY_P1_W]),
    .weights_eq_i(cfg[CFG_CONFIG_WEIGHTS_EQUAL_LSB]),
    .reset_t_i   (cfg[CFG_EDGE_RESET_T_LSB +: CFG_EDGE_RESET_T_W]),
    .reset_len_i (cfg[CFG_EDGE_RESET_LEN_LSB +: CFG_EDGE_RESET_LEN_W]),
    .reset_paths_i(cfg[CFG_EDGE_RESET_PATHS_LSB +: 4]),  // the four paths' restart flags
    .lut_start_i (lut_start),
    .p2_i        (cfg[CFG_PENALTY_P2_LSB +: CFG_PENALTY_P2_W]),
    .p2_mode_i   (cfg[CFG_CONFIG_P2_PAPER_LSB]),
    .lut_ready_o (lut_ready_paths),
    .cost_i      (cost_e),
    .col_i       (lane_col_e),
    .row_i       (row2),
    .valid_i     (valid2_e),
    .centre_i    (centre2),
    .nbr_i       (nbr2),
    .l5w_i       (l5w),
    .s_o         (sum),
    .col_o       (col3),
    .row_o       (row3),
    .last_o      (last3),
    .valid_o     (valid3)
  );

  // ------------------------------------------------------------ WTA
  logic [LD-1:0] win_d;
  logic [DW-1:0] win_disp;
  logic          win_unique;
  logic [7:0]    win_conf;
  logic [XW-1:0] col4;
  logic [RW-1:0] row4;
  logic          valid4;

  sgm_wta #(
    .D(D), .SW(SW), .CW(XW), .RW(RW), .UNIQUENESS(UNIQUENESS), .MIN_DISPARITY(MIN_DISPARITY), .CONFIDENCE(CONFIDENCE)
  ) u_wta (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .en_i       (en),
    .dmin_i     (dmin),
    .subpixel_i (cfg[CFG_CONFIG_SUBPIXEL_LSB]),
    .uniq_i     (cfg[CFG_CONFIG_UNIQUENESS_LSB +: CFG_CONFIG_UNIQUENESS_W]),
    .s_i        (sum),
    .col_i      (col3),
    .row_i      (row3),
    .valid_i    (valid3),
    .d_o        (win_d),
    .disp_o     (win_disp),
    .unique_o   (win_unique),
    .conf_o     (win_conf),
    .col_o      (col4),
    .row_o      (row4),
    .valid_o    (valid4)
  );

  // ------------------------------------------------------------ LR check
  // S side: the path engine's slot stream; WTA side: the winner of the same S,
  // sgm_wta's LATENCY slots later (sgm_lr_check accepts any lag below a row).
  // Read side: with one lane the S side's position; with K lanes the raster
  // census position LR_LAG rows back (sgm_lane_timing; the frame's LR_LAG taken at its
  // first centre, so that slots of the frame before still in flight keep theirs),
  // registered; the memories then hold LR_BANKS rows: the lanes write row y + B
  // after the read side has read row y when B >= LR_LAG + 1 (docs/lanes.md),
  // one row spare.
  localparam int LR_BANKS = LANES == 1 ? 2 : 1 << $clog2(LR_LAG_MAX + 2);
  logic [DW-1:0] lr_disp;
  logic          lr_ok, lr_valid;
  logic [7:0]    lr_conf;
  logic [XW-1:0] col5;
  logic [RW-1:0] row5;
  sgm_lr_check #(
    .D(D), .SW(SW), .DW(DW), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW), .LANES(LANES), .ROW_BANKS(LR_BANKS),
    .UNIQUENESS(UNIQUENESS), .CONFIDENCE(CONFIDENCE)
  ) u_lr (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en),
    .width_i     (width),
    .height_i    (height),
    .tol_i       (cfg[CFG_CONFIG_LR_TOL_LSB +: CFG_CONFIG_LR_TOL_W]),
    .dmin_i      (dmin),
    .check_en_i  (cfg[CFG_CONFIG_LR_ENABLE_LSB]),
    .s_i         (sum),
    .col_i       (col3),
    .row_i       (row3),
    .last_i      (last3),
    .valid_i     (valid3),
    .d_i         (win_d),
    .disp_i      (win_disp),
    .unique_i    (win_unique),
    .conf_i      (win_conf),
    .wta_col_i   (col4),
    .wta_row_i   (row4),
    .wta_valid_i (valid4),
    .rd_col_i    (rd_col),
    .rd_row_i    (rd_row),
    .disp_o      (lr_disp),
    .valid_o     (lr_ok),
    .conf_o      (lr_conf),
    .col_o       (col5),
    .row_o       (row5),
    .out_valid_o (lr_valid)
  );

  // ------------------------------------------------------------ hole filling
  logic [DW-1:0] fill_disp;
  logic          fill_ok, fill_valid;
  logic [XW-1:0] col6;
  logic [RW-1:0] row6;

  sgm_hole_fill #(.DW(DW), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW)) u_fill (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en),
    .fill_en_i   (cfg[CFG_CONFIG_FILL_LSB]),
    .width_i     (width),
    .height_i    (height),
    .disp_i      (lr_disp),
    .valid_i     (lr_ok),
    .in_valid_i  (lr_valid),
    .col_i       (col5),
    .row_i       (row5),
    .disp_o      (fill_disp),
    .valid_o     (fill_ok),
    .col_o       (col6),
    .row_o       (row6),
    .out_valid_o (fill_valid)
  );

  // ------------------------------------------------------------ edge snapping
  // The left gray of each pixel goes into the stage's row memory as it leaves
  // the census unit, about two rows before the pixel's disparity arrives (with
  // K lanes LR_LAG rows more: read about LR_LAG + 2 rows after the raster
  // census position passed it, and the lanes write it later than that position
  // and overwrite its bank no earlier, so GRAY_ROWS >= LR_LAG_MAX + 3).
  localparam int GRAY_ROWS = LANES == 1 ? 4 : 1 << $clog2(LR_LAG_MAX + 3);
  logic [DW-1:0] snap_disp;
  logic          snap_ok, snap_valid;
  logic [XW-1:0] col7;
  logic [RW-1:0] row7;

  sgm_edge_snap #(.DW(DW), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW), .GRAY_ROWS(GRAY_ROWS)) u_snap (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en),
    .snap_en_i   (cfg[CFG_CONFIG_SNAP_LSB]),
    .width_i     (width),
    .height_i    (height),
    .gray_we_i   (lane_valid_e),
    .gray_col_i  (lane_col_e),
    .gray_row_i  (lane_row_e),
    .gray_i      (lane_centre_e),
    .disp_i      (fill_disp),
    .valid_i     (fill_ok),
    .in_valid_i  (fill_valid),
    .col_i       (col6),
    .row_i       (row6),
    .disp_o      (snap_disp),
    .valid_o     (snap_ok),
    .col_o       (col7),
    .row_o       (row7),
    .out_valid_o (snap_valid)
  );

  // ------------------------------------------------------------ median
  logic [DW-1:0] med_disp;
  logic          med_ok, med_valid;
  logic [XW-1:0] col8;
  logic [RW-1:0] unused_row8;

  sgm_median5x5 #(.DW(DW), .MAX_WIDTH(MAX_WIDTH), .CW(XW), .RW(RW)) u_median (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .en_i        (en),
    .median_en_i (cfg[CFG_CONFIG_MEDIAN_LSB]),
    .width_i     (width),
    .height_i    (height),
    .disp_i      (snap_disp),
    .valid_i     (snap_ok),
    .in_valid_i  (snap_valid),
    .col_i       (col7),
    .row_i       (row7),
    .disp_o      (med_disp),
    .valid_o     (med_ok),
    .col_o       (col8),
    .row_o       (unused_row8),
    .out_valid_o (med_valid)
  );

  // ------------------------------------------------------------ output word
  // The 16-bit word (disparity or depth) and, with CONFIDENCE, the confidence above it
  // (sgm_confidence_rows: its memory's read takes 3 slots, which the disparity word waits
  // for; the depth word comes DEPTH_LATENCY slots after the median, the confidence waits).
  // With the depth output the frame's first slot also waits for K = F B (sgm_depth's
  // ready_o: the P2 table's ready and its product's, which takes up to 24 cycles after
  // lut_start). OUTPUT.MODE's upper bit is 0 in every frame the core takes (cfg_below_max).
  localparam int DEPTH_LATENCY = 20;  // sgm_depth LATENCY (which checks it)
  logic [15:0] word16;
  logic        word16_valid;
  if (DEPTH != 0) begin : g_depth
    wire unused_mode_high = cfg[CFG_OUTPUT_MODE_LSB + 1];
    sgm_depth #(.DW(DW), .LATENCY(DEPTH_LATENCY)) u_depth (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .en_i        (en),
      .depth_en_i  (cfg[CFG_OUTPUT_MODE_LSB]),
      .focal_i     (cfg[CFG_DEPTH_FOCAL_F_LSB +: CFG_DEPTH_FOCAL_F_W]),
      .baseline_i  (cfg[CFG_DEPTH_BASELINE_B_LSB +: CFG_DEPTH_BASELINE_B_W]),
      .start_i     (lut_start),
      .ready_i     (lut_ready_core),
      .ready_o     (lut_ready),
      .disp_i      (med_disp),
      .valid_i     (med_ok),
      .in_valid_i  (med_valid),
      .word_o      (word16),
      .out_valid_o (word16_valid)
    );
  end else begin : g_disparity
    assign lut_ready    = lut_ready_core;
    assign word16       = {med_ok, 15'(med_disp)};
    assign word16_valid = med_valid;
    wire [CFG_OUTPUT_MODE_W+CFG_DEPTH_FOCAL_F_W+CFG_DEPTH_BASELINE_B_W-1:0] unused_cfg_depth =
        {cfg[CFG_OUTPUT_MODE_LSB +: CFG_OUTPUT_MODE_W], cfg[CFG_DEPTH_FOCAL_F_LSB +: CFG_DEPTH_FOCAL_F_W],
         cfg[CFG_DEPTH_BASELINE_B_LSB +: CFG_DEPTH_BASELINE_B_W]};
  end
  if (CONFIDENCE != 0) begin : g_confidence
    // A pixel's confidence is read 3 W + 2 DW + 21 slots after it is written (the fill's row
    // and 5 slots, the snap's 10, the median's 2 rows and 2 DW + 6) and its memory read takes
    // 3 more; its row slot is written again (ROWS - 1) W slots or more later (every row has
    // W slots or more): ROWS >= 4 + ceil((2 DW + 24) / W) rows, a power of two (8 for every
    // legal build: W >= 16, DW <= 13).
    localparam int CONF_ROWS = 1 << $clog2(4 + (2 * DW + 24 + MIN_FRAME_WIDTH - 1) / MIN_FRAME_WIDTH);
    sgm_confidence_rows #(
      .MAX_WIDTH(MAX_WIDTH), .CW(XW), .ROWS(CONF_ROWS), .WORD_DELAY(DEPTH != 0 ? DEPTH_LATENCY : 0)
    ) u_conf_rows (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .en_i        (en),
      .wr_valid_i  (lr_valid),
      .wr_col_i    (col5),
      .conf_i      (lr_conf),
      .rd_valid_i  (med_valid),
      .rd_col_i    (col8),
      .conf_en_i   (cfg[CFG_OUTPUT_CONFIDENCE_LSB]),
      .word_i      (word16),
      .word_valid_i(word16_valid),
      .word_o      (res_word),
      .word_valid_o(res_valid)
    );
  end else begin : g_no_confidence
    assign res_word  = word16;
    assign res_valid = word16_valid;
    wire [8+XW:0] unused_conf = {lr_conf, col8, cfg[CFG_OUTPUT_CONFIDENCE_LSB]};
  end

endmodule
`default_nettype wire
