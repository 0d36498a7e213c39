// SPDX-License-Identifier: Apache-2.0
// sgm_median5x5 against the golden sgm::median5x5 (docs/algorithm.md section 9),
// with the disparity-stage fixture of tb/disparity_stage.hpp: frames streamed
// slot by slot back to back without reset, seeded random stalls with junk
// inputs while en_i = 0 (outputs must hold), stale slots after frame switches,
// the latency contract and every pixel against the golden model. The build's
// DW / MAX_WIDTH / LATENCY come from the model, so the file serves every config.
#include "Vsgm_median5x5.h"
#include "Vsgm_median5x5_sgm_median5x5.h"
#include "disparity_stage.hpp"

#include "sgm/disparity.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using sgm::DisparityMap;

struct Median {
  using Model = Vsgm_median5x5;
  using Rtl = Vsgm_median5x5_sgm_median5x5;  // public parameters of the build
  static constexpr const char* kName = "sgm_median5x5";
  static constexpr const char* kStage = "5x5 median (sgm_median5x5)";
  static constexpr const char* kSwitch = "median";
  static constexpr const char* kStructured = "patterns";
  static constexpr DisparityMap sgm::PipelineStages::*kConesInput = &sgm::PipelineStages::snapped;
  static constexpr const char* kConesInputName = "snapped";
  static void setEnable(Model& m, bool on) { m.median_en_i = on; }
  static DisparityMap golden(const DisparityMap& m) { return sgm::median5x5(m); }
  static DisparityMap structured(int w, int h, std::mt19937& rng);
};

class SgmMedian5x5 : public sgm::tb::DisparityStageTest<Median> {};

// Few distinct values (many ties, the extremes 0 and 2^DW - 1) under a
// validity pattern with structure: invalid blocks, an invalid column band,
// isolated valid pixels, checkerboards, invalid first / valid last row.
DisparityMap Median::structured(int w, int h, std::mt19937& rng) {
  constexpr int kMaxDisp = SgmMedian5x5::kMaxDisp;
  DisparityMap m = SgmMedian5x5::randomMap(w, h, 0.7, rng);
  const int levels[] = {0, 1, 16, 17, 100 % (kMaxDisp + 1), kMaxDisp - 1, kMaxDisp};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.disp.at<uint16_t>(y, x) = uint16_t(levels[rng() % 7]);
  auto set = [&](int x, int y, bool v) {
    if (x >= 0 && x < w && y >= 0 && y < h) m.valid.at<uint8_t>(y, x) = v;
  };
  for (int i = 0; i < 3; ++i) {  // invalid blocks
    const int bx = int(rng() % w), by = int(rng() % h), bw = 1 + int(rng() % 7), bh = 1 + int(rng() % 7);
    for (int y = by; y < by + bh; ++y)
      for (int x = bx; x < bx + bw; ++x) set(x, y, false);
  }
  const int band = int(rng() % (w - 4));  // invalid column band
  for (int y = 0; y < h; ++y)
    for (int x = band; x < band + 3; ++x) set(x, y, false);
  for (int x = 0; x < w; ++x) set(x, 0, false), set(x, h - 1, true);
  const int cx = int(rng() % w), cy = 2 + int(rng() % (h - 4));  // a checkerboard patch
  for (int y = cy - 3; y <= cy + 3; ++y)
    for (int x = cx - 3; x <= cx + 3; ++x) set(x, y, (x + y) % 2 == 0);
  const int ix = int(rng() % w), iy = 1 + int(rng() % (h - 3));  // an isolated valid pixel
  for (int y = iy - 2; y <= iy + 2; ++y)
    for (int x = ix - 2; x <= ix + 2; ++x) set(x, y, x == ix && y == iy);
  return m;
}

TEST_F(SgmMedian5x5, SmallestFrameAllDensities) { smallestFrameAllDensities(); }

TEST_F(SgmMedian5x5, TiesAndValidityPatterns) {
  Top top("sgm_median5x5_patterns");
  std::mt19937 rng(2);
  runFrames(top,
            {{Median::structured(16, 9, rng), true, "patterns 16x9"},
             {Median::structured(16, 12, rng), true, "patterns 16x12"},
             {Median::structured(37, 24, rng), true, "patterns 37"},
             {Median::structured(kMaxWidth, 36, rng), true, "patterns max width"},
             {Median::structured(kMaxWidth - 1, 13, rng), true, "patterns max width - 1"}},
            202);
}

TEST_F(SgmMedian5x5, OddSizes) { oddSizes(); }
TEST_F(SgmMedian5x5, PassThroughWhenDisabled) { passThroughWhenDisabled(); }
TEST_F(SgmMedian5x5, BackToBackFramesOfDifferentSizes) { backToBackFramesOfDifferentSizes(); }
TEST_F(SgmMedian5x5, RandomFrameSequence) { randomFrameSequence(); }
TEST_F(SgmMedian5x5, EnablePatterns) { enablePatterns(); }
TEST_F(SgmMedian5x5, ConesD16) { runCones(16); }
TEST_F(SgmMedian5x5, ConesD64) { runCones(64); }

}  // namespace
