// SPDX-License-Identifier: Apache-2.0
// sgm_hole_fill against the golden sgm::fillHoles (docs/algorithm.md section 8),
// with the disparity-stage fixture of tb/disparity_stage.hpp: frames streamed
// slot by slot back to back without reset, seeded random stalls with junk
// inputs while en_i = 0 (outputs must hold), stale slots after frame switches,
// the latency contract and every pixel against the golden model. The build's
// DW / MAX_WIDTH / LATENCY come from the model, so the file serves every config.
#include "Vsgm_hole_fill.h"
#include "Vsgm_hole_fill_sgm_hole_fill.h"
#include "disparity_stage.hpp"

#include "sgm/disparity.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using sgm::DisparityMap;

struct HoleFill {
  using Model = Vsgm_hole_fill;
  using Rtl = Vsgm_hole_fill_sgm_hole_fill;  // public parameters of the build
  static constexpr const char* kName = "sgm_hole_fill";
  static constexpr const char* kStage = "hole fill (sgm_hole_fill)";
  static constexpr const char* kSwitch = "fill";
  static constexpr const char* kStructured = "runs";
  static constexpr DisparityMap sgm::PipelineStages::*kConesInput = &sgm::PipelineStages::selected;
  static constexpr const char* kConesInputName = "selected";
  static void setEnable(Model& m, bool on) { m.fill_en_i = on; }
  static DisparityMap golden(const DisparityMap& m) { return sgm::fillHoles(m); }
  static DisparityMap structured(int w, int h, std::mt19937& rng);
};

class SgmHoleFill : public sgm::tb::DisparityStageTest<HoleFill> {};

// Rows of hand-picked run structure, then rows of random run lengths (long
// invalid runs, runs touching either end or both).
DisparityMap HoleFill::structured(int w, int h, std::mt19937& rng) {
  DisparityMap m = SgmHoleFill::randomMap(w, h, 0.0, rng);
  auto set = [&](int y, int x, bool v) { m.valid.at<uint8_t>(y, x) = v; };
  for (int y = 0; y < h; ++y) {
    switch (y % 12) {
      case 0: break;  // no valid pixel
      case 1:
        for (int x = 0; x < w; ++x) set(y, x, true);
        break;                             // all valid
      case 2: set(y, 0, true); break;      // run touching the right end
      case 3: set(y, w - 1, true); break;  // run touching the left end
      case 4: set(y, w / 2, true); break;  // runs touching both ends
      case 5:
        for (int x = 0; x < w; x += 2) set(y, x, true);
        break;  // alternating
      case 6:
        for (int x = 1; x < w; x += 2) set(y, x, true);
        break;
      case 7:
        set(y, 0, true);
        set(y, w - 1, true);
        break;  // one long inner run
      case 8:
        set(y, 1, true);
        set(y, w - 2, true);
        break;    // short end runs
      default: {  // random run lengths
        std::geometric_distribution<int> len(0.15);
        bool v = rng() & 1;
        for (int x = 0; x < w;) {
          const int n = 1 + len(rng);
          for (int i = 0; i < n && x < w; ++i, ++x) set(y, x, v);
          v = !v;
        }
      }
    }
  }
  return m;
}

TEST_F(SgmHoleFill, SmallestFrameAllDensities) { smallestFrameAllDensities(); }

TEST_F(SgmHoleFill, StructuredRuns) {
  Top top("sgm_hole_fill_runs");
  std::mt19937 rng(2);
  runFrames(top,
            {{HoleFill::structured(16, 12, rng), true, "runs 16"},
             {HoleFill::structured(37, 24, rng), true, "runs 37"},
             {HoleFill::structured(kMaxWidth, 36, rng), true, "runs max width"},
             {HoleFill::structured(kMaxWidth - 1, 13, rng), true, "runs max width - 1"}},
            202);
}

TEST_F(SgmHoleFill, OddSizes) { oddSizes(); }
TEST_F(SgmHoleFill, PassThroughWhenDisabled) { passThroughWhenDisabled(); }
TEST_F(SgmHoleFill, BackToBackFramesOfDifferentSizes) { backToBackFramesOfDifferentSizes(); }
TEST_F(SgmHoleFill, RandomFrameSequence) { randomFrameSequence(); }
TEST_F(SgmHoleFill, EnablePatterns) { enablePatterns(); }
TEST_F(SgmHoleFill, ConesD16) { runCones(16); }
TEST_F(SgmHoleFill, ConesD64) { runCones(64); }

}  // namespace
