// SPDX-License-Identifier: Apache-2.0
// sgm_edge_snap against the golden sgm::snapEdges (docs/algorithm.md section 8b),
// with the disparity-stage fixture of tb/disparity_stage.hpp (frames streamed
// back to back without reset, random stalls with junk inputs, stale slots,
// the latency contract, every pixel against the golden model); the fixture
// also writes each pixel's left gray through the gray port in the pixel's own
// slot. The build's DW / MAX_WIDTH / LATENCY come from the model.
#include "Vsgm_edge_snap.h"
#include "Vsgm_edge_snap_sgm_edge_snap.h"
#include "disparity_stage.hpp"

#include "sgm/disparity.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using sgm::DisparityMap;

struct EdgeSnap {
  using Model = Vsgm_edge_snap;
  using Rtl = Vsgm_edge_snap_sgm_edge_snap;  // public parameters of the build
  static constexpr const char* kName = "sgm_edge_snap";
  static constexpr const char* kStage = "edge snap (sgm_edge_snap)";
  static constexpr const char* kSwitch = "snap";
  static constexpr const char* kStructured = "plateaus";
  static constexpr DisparityMap sgm::PipelineStages::*kConesInput = &sgm::PipelineStages::filled;
  static constexpr const char* kConesInputName = "filled";
  static void setEnable(Model& m, bool on) { m.snap_en_i = on; }
  static void setGray(Model& m, bool we, int x, int y, int gray) {
    m.gray_we_i = we;
    m.gray_col_i = x;
    m.gray_row_i = y;
    m.gray_i = gray;
  }
  static DisparityMap golden(const DisparityMap& m, const cv::Mat& gray) { return sgm::snapEdges(m, gray); }
  static DisparityMap structured(int w, int h, std::mt19937& rng);
};

class SgmEdgeSnap : public sgm::tb::DisparityStageTest<EdgeSnap> {};

// Rows of disparity plateaus 1 .. 6 px long: steps up and down of random size
// around the 2 px threshold and far beyond it, drops close together (a pixel
// under several drops), a few invalid pixels; the gray comes from the fixture.
DisparityMap EdgeSnap::structured(int w, int h, std::mt19937& rng) {
  DisparityMap m = SgmEdgeSnap::randomMap(w, h, 1.0, rng);
  std::uniform_int_distribution<int> len(1, 6), jump(-48, 48), big(0, SgmEdgeSnap::kMaxDisp);
  for (int y = 0; y < h; ++y) {
    int v = big(rng);
    for (int x = 0; x < w;) {
      for (int n = len(rng); n > 0 && x < w; --n, ++x) {
        m.disp.at<uint16_t>(y, x) = uint16_t(v);
        m.valid.at<uint8_t>(y, x) = rng() % 10 != 0;
      }
      v = rng() % 3 == 0 ? big(rng) : std::clamp(v + jump(rng), 0, int(SgmEdgeSnap::kMaxDisp));
    }
  }
  return m;
}

TEST_F(SgmEdgeSnap, SmallestFrameAllDensities) { smallestFrameAllDensities(); }

TEST_F(SgmEdgeSnap, StructuredPlateaus) {
  Top top("sgm_edge_snap_plateaus");
  std::mt19937 rng(2);
  runFrames(top,
            {{EdgeSnap::structured(16, 12, rng), true, "plateaus 16"},
             {EdgeSnap::structured(37, 24, rng), true, "plateaus 37"},
             {EdgeSnap::structured(kMaxWidth, 36, rng), true, "plateaus max width"},
             {EdgeSnap::structured(kMaxWidth - 1, 13, rng), true, "plateaus max width - 1"}},
            202);
}

TEST_F(SgmEdgeSnap, OddSizes) { oddSizes(); }
TEST_F(SgmEdgeSnap, PassThroughWhenDisabled) { passThroughWhenDisabled(); }
TEST_F(SgmEdgeSnap, BackToBackFramesOfDifferentSizes) { backToBackFramesOfDifferentSizes(); }
TEST_F(SgmEdgeSnap, RandomFrameSequence) { randomFrameSequence(); }
TEST_F(SgmEdgeSnap, EnablePatterns) { enablePatterns(); }
TEST_F(SgmEdgeSnap, ConesD16) { runCones(16); }
TEST_F(SgmEdgeSnap, ConesD64) { runCones(64); }

}  // namespace
