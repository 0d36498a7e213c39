// SPDX-License-Identifier: Apache-2.0
// sgm_driver: a small bus-agnostic driver of sgm_axi (register map:
// sgm_regs.h, docs/registers.md). The caller supplies the 32-bit register
// read and write functions (a memory-mapped pointer, a UIO device, a
// simulated AXI4-Lite bus); offsets are relative to the slave's base.
//
//   sgm::driver::Driver core(bus);
//   if (!core.identify(&id)) ...;          // magic / version check
//   core.configure(frame);                 // atomic: taken at the next start of frame
//   core.enable(true);
//   uint32_t done = core.framesDone();
//   ... stream the frame ...
//   if (!core.waitFrames(done + 1, polls)) ...;
//   sgm::driver::Errors e = core.errors();  // sticky kinds and counters
#pragma once

#include "sgm_regs.h"

#include <cstdint>
#include <functional>

namespace sgm::driver {

struct Bus {
  std::function<uint32_t(uint32_t offset)> read;
  std::function<void(uint32_t offset, uint32_t value)> write;
};

// The build of the core behind the bus.
struct Identity {
  uint32_t version = 0;  // low byte of ID
  uint32_t disparities = 0, maxWidth = 0, maxHeight = 0;
  uint32_t censusWidth = 0, censusHeight = 0;
  uint32_t minWidth = 0, lanes = 0;  // narrowest frame width, row lanes
  uint32_t features = 0;             // SGM_FEATURES_* bits: the run-time levers the build has
};

// One frame's run-time configuration (the fields of FRAME_SIZE, PENALTY, CONFIG, EDGE_RESET,
// OUTPUT, DEPTH_FOCAL, DEPTH_BASELINE, MIN_DISPARITY, RECTIFY).
struct FrameConfig {
  uint32_t width = 0, height = 0;
  // Defaults: the golden model's, as the registers of a build with every lever reset to
  // (SGM_*_DEFAULT of sgm_regs.h, generated from regmap/sgm_regmap.def); a build without
  // the fifth path, the uniqueness ratio, the AD term or the path restart (FEATURES) resets
  // to fourPath().
  uint32_t p1 = SGM_PENALTY_P1_DEFAULT, p2 = SGM_PENALTY_P2_DEFAULT;
  uint32_t mode = SGM_CONFIG_MODE_DEFAULT;  // SGM_CONFIG_MODE_RT, _RSAD or _UNIFIED
  bool subpixel = SGM_CONFIG_SUBPIXEL_DEFAULT;
  bool lrCheck = SGM_CONFIG_LR_ENABLE_DEFAULT;
  uint32_t lrTolerance = SGM_CONFIG_LR_TOL_DEFAULT;
  bool fill = SGM_CONFIG_FILL_DEFAULT, snap = SGM_CONFIG_SNAP_DEFAULT, median = SGM_CONFIG_MEDIAN_DEFAULT;
  // The paper's P2'/dI and equal path weights.
  bool p2Paper = SGM_CONFIG_P2_PAPER_DEFAULT, weightsEqual = SGM_CONFIG_WEIGHTS_EQUAL_DEFAULT;
  uint32_t uniqueness = SGM_CONFIG_UNIQUENESS_DEFAULT;  // uniqueness ratio in %, 0 (off) .. SGM_CONFIG_UNIQUENESS_MAX
  // The AD term: C += (W min(AD, T)) >> 3, W 0 (off) .. 15.
  uint32_t adWeight = SGM_PENALTY_AD_WEIGHT_DEFAULT, adCap = SGM_PENALTY_AD_CAP_DEFAULT;
  // The fifth path's W5: 0 (off) .. SGM_PENALTY_RIGHT_WEIGHT_MAX, in blocks of the build's (FEATURES).
  uint32_t rightWeight = SGM_PENALTY_RIGHT_WEIGHT_DEFAULT;
  // The path restart at strong edges (EDGE_RESET): threshold T (0 off), length R (1 .. 15),
  // path flags (bit k: path k, 0, 45, 90, 135 degrees, the fifth).
  uint32_t edgeReset = SGM_EDGE_RESET_T_DEFAULT, edgeResetLength = SGM_EDGE_RESET_LEN_DEFAULT;
  uint32_t edgeResetPaths = SGM_EDGE_RESET_PATHS_DEFAULT;
  // The output word: SGM_OUTPUT_MODE_DISPARITY or SGM_OUTPUT_MODE_DEPTH (a build with
  // SGM_FEATURES_DEPTH), the depth from f in 1/256 px and B in micrometres (24 bits each;
  // sgm-eval calib-mesh prints both).
  uint32_t output = SGM_OUTPUT_MODE_DISPARITY;
  uint32_t focalQ8 = 0, baselineUm = 0;
  // The pixel's confidence in bits 23:16 of the output word (a build with
  // SGM_FEATURES_CONFIDENCE, whose word is 24 bits), beside either output.
  bool confidence = false;
  // The minimum disparity dmin, 0 .. 255 (a build with SGM_FEATURES_MIN_DISPARITY): the
  // search covers dmin .. dmin + D - 1 and the output is the true disparity.
  uint32_t minDisparity = 0;
  // Rectification in the stream (a build with SGM_FEATURES_RECTIFY): the frame's raw pair goes
  // through the meshes loaded with loadMeshes; rectifyLag is the calibration's row lag
  // (sgm-eval calib-mesh), at most rectifyRows(id) - 2.
  bool rectify = false;
  uint32_t rectifyLag = 0;

  // The four-path defaults (golden preset "four-path"), for builds without those levers.
  static FrameConfig fourPath() {
    FrameConfig f;
    f.p1 = SGM_PENALTY_P1_FOUR_PATH, f.p2 = SGM_PENALTY_P2_FOUR_PATH;
    f.adCap = SGM_PENALTY_AD_CAP_FOUR_PATH, f.adWeight = SGM_PENALTY_AD_WEIGHT_FOUR_PATH;
    f.rightWeight = SGM_PENALTY_RIGHT_WEIGHT_FOUR_PATH;
    f.mode = SGM_CONFIG_MODE_FOUR_PATH, f.subpixel = SGM_CONFIG_SUBPIXEL_FOUR_PATH;
    f.lrCheck = SGM_CONFIG_LR_ENABLE_FOUR_PATH, f.lrTolerance = SGM_CONFIG_LR_TOL_FOUR_PATH;
    f.fill = SGM_CONFIG_FILL_FOUR_PATH, f.snap = SGM_CONFIG_SNAP_FOUR_PATH, f.median = SGM_CONFIG_MEDIAN_FOUR_PATH;
    f.p2Paper = SGM_CONFIG_P2_PAPER_FOUR_PATH, f.weightsEqual = SGM_CONFIG_WEIGHTS_EQUAL_FOUR_PATH;
    f.uniqueness = SGM_CONFIG_UNIQUENESS_FOUR_PATH;
    f.edgeReset = SGM_EDGE_RESET_T_FOUR_PATH, f.edgeResetLength = SGM_EDGE_RESET_LEN_FOUR_PATH;
    f.edgeResetPaths = SGM_EDGE_RESET_PATHS_FOUR_PATH;
    return f;
  }
};

// One image's rectification mesh: nodesX x nodesY source positions (u, v) in 1/32 px, row by
// row (node (i, j) at index i nodesX + j), as sgm-eval calib-mesh's mesh file holds them
// (docs/algorithm.md section 13).
struct MeshImage {
  uint32_t nodesX = 0, nodesY = 0;
  const int32_t* u = nullptr;
  const int32_t* v = nullptr;
};

struct Errors {
  uint32_t sticky = 0;                    // SGM_ERROR_* bits (SGM_ERROR_LAST_EARLY ...)
  uint32_t counts[SGM_ERROR_KINDS] = {};  // events per kind (saturate at 255)
};

class Driver {
 public:
  explicit Driver(Bus bus) : bus_(std::move(bus)) {}

  // Reads the identification registers; false when the magic or version differs.
  bool identify(Identity* id = nullptr);
  // Writes the configuration with CTRL.HOLD set, so that the core takes all of
  // it, or none of it, at its next start of frame; keeps CTRL.ENABLE as it is.
  void configure(const FrameConfig& frame);
  FrameConfig readConfig();
  void enable(bool on);
  // Resets the core (not the registers) and waits until it is out of reset.
  bool softReset(long maxPolls = 1000);
  bool busy();
  uint32_t framesDone();
  // Polls FRAMES until it reaches `target` (wrapping counter); false after maxPolls reads.
  bool waitFrames(uint32_t target, long maxPolls);
  void lastFrameSize(uint32_t* width, uint32_t* height);
  Errors errors();
  // Clears the sticky kinds and the counters.
  void clearErrors();
  void enableInterrupts(uint32_t mask);  // SGM_IRQ_ENABLE_* bits
  uint32_t interrupts();                 // IRQ_STATUS
  void clearInterrupts(uint32_t mask);
  // Loads a calibration's two meshes into the copy the core does not use and swaps them in
  // at the next start of frame: waits (at most maxPolls reads) until MESH_CTRL.PENDING is 0,
  // writes every node, then MESH_CTRL.SWAP. False when PENDING stayed 1 or a mesh is larger
  // than the register fields hold (nothing written then).
  bool loadMeshes(const MeshImage& left, const MeshImage& right, long maxPolls);
  bool meshSwapPending();
  // Whether the frame leaving the rectification read a row its line buffer no longer held.
  bool rectifyRowMiss();

  // Whether the core of this identity takes a frame of this size (the core drops
  // any other and flags ERROR.CONFIG): minWidth <= width <= maxWidth, 9 <= height <= maxHeight.
  static bool sizeFits(const Identity& id, uint32_t width, uint32_t height);
  // Whether the build of this identity has every lever the frame sets (the core drops a
  // frame with uniqueness != 0 without SGM_FEATURES_UNIQUENESS, adWeight != 0 without
  // SGM_FEATURES_AD_TERM, rightWeight != 0 without SGM_FEATURES_RIGHT_PATH, edgeReset != 0
  // without SGM_FEATURES_EDGE_RESET, the depth output without SGM_FEATURES_DEPTH, or
  // minDisparity != 0 without SGM_FEATURES_MIN_DISPARITY, rectify or rectifyLag != 0 without
  // SGM_FEATURES_RECTIFY or a rectifyLag above rectifyRows(id) - 2, the confidence without
  // SGM_FEATURES_CONFIDENCE, and flags ERROR.CONFIG).
  static bool featuresFit(const Identity& id, const FrameConfig& frame);
  // The fifth path's block B of the build (0: the build has no fifth path).
  static uint32_t rightBlock(const Identity& id);
  // The rectification's line buffer rows R and mesh step G of the build (0: no rectification).
  static uint32_t rectifyRows(const Identity& id);
  static uint32_t rectifyGrid(const Identity& id);
  static uint32_t encodeSize(uint32_t width, uint32_t height);
  static uint32_t encodePenalty(const FrameConfig& frame);
  static uint32_t encodeConfig(const FrameConfig& frame);
  static uint32_t encodeEdgeReset(const FrameConfig& frame);
  static uint32_t encodeOutput(const FrameConfig& frame);
  static uint32_t encodeDepthFocal(const FrameConfig& frame);
  static uint32_t encodeDepthBaseline(const FrameConfig& frame);
  static uint32_t encodeMinDisparity(const FrameConfig& frame);
  static uint32_t encodeRectify(const FrameConfig& frame);
  // The configuration the nine registers' values hold (readConfig reads them).
  static FrameConfig decode(uint32_t frameSize, uint32_t penalty, uint32_t config, uint32_t edgeReset, uint32_t output,
                            uint32_t depthFocal, uint32_t depthBaseline, uint32_t minDisparity, uint32_t rectify);

 private:
  uint32_t read(uint32_t offset) { return bus_.read(offset); }
  void write(uint32_t offset, uint32_t value) { bus_.write(offset, value); }
  Bus bus_;
};

}  // namespace sgm::driver
