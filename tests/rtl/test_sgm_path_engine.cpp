// SPDX-License-Identifier: Apache-2.0
// sgm_path_engine against the golden path aggregation (docs/algorithm.md
// section 5): S(p, d) for every pixel and disparity, slots streamed in the
// engine's lane order (raster order at LANES = 1; tb/lane_schedule.hpp) with
// random idle cycles, several frames back to back without reset. Builds with
// EDGE_RESET = 1 restart the paths at strong edges as the golden
// Params::edgeReset does; builds without ignore the restart configuration.
#include "Vsgm_path_engine.h"
#include "Vsgm_path_engine_sgm_path_engine.h"
#include "idle_slot.hpp"
#include "lane_schedule.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/aggregate.hpp"
#include "sgm/cost.hpp"
#include "sgm/image_io.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <random>
#include <sstream>

#ifndef SGM_D
#define SGM_D 16
#endif
#ifndef SGM_YW
#define SGM_YW 8
#endif

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_path_engine>;
using sgm::tb::getBits;
using sgm::tb::setBits;

constexpr int kD = SGM_D;
// The row and grays of a pixel lead its costs by GRAY_LEAD slots (0 or 1, a parameter of the build).
constexpr int kGrayLead = int(Vsgm_path_engine_sgm_path_engine::GRAY_LEAD);
// The column leads the costs by COL_LEAD slots (the previous-row reads run ahead).
constexpr int kColLead = int(Vsgm_path_engine_sgm_path_engine::COL_LEAD);
// K row lanes, each SKEW columns behind the one before (the build's LANES).
constexpr int kLanes = int(Vsgm_path_engine_sgm_path_engine::LANES);
constexpr int kSkew = int(Vsgm_path_engine_sgm_path_engine::SKEW);
// The narrowest frame that schedule supports (frames here are widened to it).
constexpr int kMinWidth = int(Vsgm_path_engine_sgm_path_engine::MIN_WIDTH);
// 1: the build has the path restart at strong edges (EDGE_RESET).
constexpr bool kEdgeReset = int(Vsgm_path_engine_sgm_path_engine::EDGE_RESET) != 0;
constexpr int kCostBits = 7, kSumBits = 13;

struct Frame {
  cv::Mat gray;          // left gray image (P2 gradients)
  sgm::CostVolume cost;  // C(p, d)
  int p1 = 20, p2 = 200;
  sgm::P2Mode p2Mode = sgm::P2Mode::kKnee;                 // run-time P2 form
  sgm::PathWeighting weights = sgm::PathWeighting::k3232;  // run-time path weights
  sgm::EdgeReset edgeReset{};  // run-time path restart (threshold 0: off); paths 0 .. 3 only
};

cv::Mat randomImage(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  cv::GaussianBlur(img, img, cv::Size(3, 3), 0);  // some structure, many small gradients
  return img;
}

Frame syntheticFrame(int w, int h, int p1, int p2, std::mt19937& rng) {
  Frame f;
  f.gray = randomImage(w, h, rng);
  f.cost = sgm::CostVolume(w, h, kD);
  for (auto& c : f.cost.data) c = uint8_t(rng() % 89);  // anything a hardware mode can produce (0 .. 88)
  f.p1 = p1, f.p2 = p2;
  return f;
}

class PathEngine {
 public:
  explicit PathEngine(const std::string& name, uint32_t seed, double idle) : top_(name), rng_(seed), idle_(idle) {
    top_->en_i = 0;
    top_->lut_start_i = 0;
    top_.reset();
  }

  // Streams one frame and checks every S vector; returns the mismatch text or "".
  std::string run(const Frame& f) {
    const int w = f.cost.width, h = f.cost.height;
    const sgm::EdgeReset restart = kEdgeReset ? f.edgeReset : sgm::EdgeReset{0};
    const sgm::PathVolume expected = sgm::aggregateCost(f.cost, f.gray, f.p1, f.p2, f.p2Mode, f.weights, 0, false, 0,
                                                        nullptr, restart);
    // Per-frame configuration and the P2 table fill, pipeline held.
    top_->en_i = 0;
    top_->width_i = w;
    top_->p1_i = f.p1;
    top_->p2_i = f.p2;
    top_->p2_mode_i = f.p2Mode == sgm::P2Mode::kPaper;
    top_->weights_eq_i = f.weights == sgm::PathWeighting::kEqual;
    top_->reset_t_i = f.edgeReset.threshold;
    top_->reset_len_i = f.edgeReset.length;
    uint32_t resetPaths = 0;
    for (int r = 0; r < 4; ++r) resetPaths |= uint32_t(f.edgeReset.paths[size_t(r)] != 0) << r;
    top_->reset_paths_i = resetPaths;
    top_->lut_start_i = 1;
    top_.tick();
    top_->lut_start_i = 0;
    while (!top_->lut_ready_o) top_.tick();

    long checked = 0;
    std::string failure;
    const int leadRows = 2;  // slots before row 0 carry no pixel, as behind the census window
    const sgm::tb::LaneSchedule lanes(w, kLanes, kSkew, leadRows);
    // Every pixel's slot, the pipeline and a flush row of every lane.
    const long slots = lanes.slotsToCover(h) + long(kLanes) * (w + kSkew) + 8;
    for (long t = 0; t < slots; ++t) {
      const sgm::tb::SlotPosition pos = lanes.at(t);
      const int row = pos.row, col = pos.col;
      const bool inside = row >= 0 && row < h;
      for (int d = 0; d < kD; ++d) setBits(top_->cost_i, d * kCostBits, kCostBits, inside ? f.cost.at(col, row)[d] : 0);
      top_->col_i = lanes.at(t + kColLead).col;
      top_->valid_i = inside;
      // The row and the grays of slot t + kGrayLead (negative rows wrap; they carry no
      // pixel, and the grays there are random: they must not matter).
      const sgm::tb::SlotPosition gpos = lanes.at(t + kGrayLead);
      const int growIndex = gpos.row, gcol = gpos.col;
      top_->row_i = uint32_t(growIndex) & ((1u << SGM_YW) - 1);
      uint32_t nbr = 0;
      if (growIndex >= 0 && growIndex < h) {
        top_->centre_i = f.gray.at<uint8_t>(growIndex, gcol);
        const int dx[4] = {-1, -1, 0, 1}, dy[4] = {0, -1, -1, -1};
        for (int r = 0; r < 4; ++r) {
          const int x = gcol + dx[r], y = growIndex + dy[r];
          const int v = x >= 0 && x < w && y >= 0 ? f.gray.at<uint8_t>(y, x) : int(rng_() % 256);
          nbr |= uint32_t(v) << (8 * r);
        }
      } else {
        top_->centre_i = rng_() % 256;
        nbr = uint32_t(rng_());
      }
      top_->nbr_i = nbr;
      sgm::tb::slotAfterIdle(top_, rng_, idle_);
      if (top_->valid_o && failure.empty()) {
        const int x = top_->col_o, y = int(top_->row_o);
        if (bool(top_->last_o) != (x == w - 1)) {
          failure = "stage sgm_path_engine: last_o = " + std::to_string(int(top_->last_o)) +
                    " at (x=" + std::to_string(x) + ", y=" + std::to_string(y) + "), width " + std::to_string(w);
          break;
        }
        const uint16_t* s = expected.at(x, y);
        for (int d = 0; d < kD; ++d) {
          const int got = int(getBits(top_->s_o, d * kSumBits, kSumBits));
          if (got != s[d]) {
            std::ostringstream msg;
            msg << "stage sgm_path_engine: first mismatch at (x=" << x << ", y=" << y << ") d=" << d
                << ": expected S=" << s[d] << ", got " << got << " (" << w << "x" << h << ", P1=" << f.p1
                << ", P2'=" << f.p2 << ", " << kLanes << " lanes, restart T=" << f.edgeReset.threshold
                << " R=" << f.edgeReset.length << " paths " << resetPaths << (kEdgeReset ? "" : " not built") << ")";
            failure = msg.str();
            break;
          }
        }
        ++checked;
      }
    }
    if (failure.empty() && checked != long(w) * h)
      failure = "checked " + std::to_string(checked) + " pixels, expected " + std::to_string(long(w) * h);
    return failure;
  }

 private:
  Top top_;
  std::mt19937 rng_;
  double idle_;
};

TEST(SgmPathEngine, RandomCostsSeveralSizesBackToBack) {
  PathEngine engine("sgm_path_engine", 7, 0.3);
  std::mt19937 rng(1);
  const int sizes[][2] = {{16, 9}, {37, 11}, {64, 20}, {kD + 3, 13}, {100, 7 + 9}};
  int k = 0;
  for (const auto& s : sizes) {
    const int p2 = int(rng() % 256), p1 = int(rng() % (p2 + 1));
    Frame f = syntheticFrame(std::max(s[0], kMinWidth), s[1], p1, p2, rng);
    f.p2Mode = k % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee;                     // both forms and both weightings,
    f.weights = k / 2 % 2 ? sgm::PathWeighting::kEqual : sgm::PathWeighting::k3232;  // changing per frame
    ++k;
    EXPECT_EQ(engine.run(f), "") << sgm::p2ModeName(f.p2Mode) << " " << sgm::pathWeightingName(f.weights);
  }
}

TEST(SgmPathEngine, PenaltyExtremes) {
  PathEngine engine("sgm_path_engine_extremes", 11, 0.0);
  std::mt19937 rng(2);
  for (auto [p1, p2] : {std::pair{0, 0}, {0, 255}, {255, 255}, {20, 200}})
    EXPECT_EQ(engine.run(syntheticFrame(40, 12, p1, p2, rng)), "");
}

// The path restart at strong edges: random T, R and path flags changing frame
// by frame (a threshold that marks many steps, few, none), back to back.
TEST(SgmPathEngine, RestartAtStrongEdges) {
  PathEngine engine("sgm_path_engine_restart", 17, 0.25);
  std::mt19937 rng(5);
  const int sizes[][2] = {{40, 12}, {23, 9}, {64, 14}, {kD + 5, 11}, {50, 10}, {31, 8}};
  int k = 0;
  for (const auto& s : sizes) {
    const int p2 = 40 + int(rng() % 200), p1 = int(rng() % 40);
    Frame f = syntheticFrame(std::max(s[0], kMinWidth), s[1], p1, p2, rng);
    const int thresholds[] = {1, 12, 25, 4, 60, 8};
    f.edgeReset.threshold = thresholds[k];
    f.edgeReset.length = k == 0 ? 15 : k == 1 ? 1 : 1 + int(rng() % sgm::kMaxEdgeResetLength);
    for (int r = 0; r < 4; ++r) f.edgeReset.paths[size_t(r)] = k < 2 ? 1 : int(rng() % 2);
    f.edgeReset.paths[4] = 0;
    f.p2Mode = k % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee;
    ++k;
    EXPECT_EQ(engine.run(f), "");
  }
  // Off again (T = 0 with every path flag set).
  Frame f = syntheticFrame(std::max(33, kMinWidth), 10, 10, 120, rng);
  f.edgeReset = sgm::EdgeReset{0, 7, {1, 1, 1, 1, 0}};
  EXPECT_EQ(engine.run(f), "");
}

TEST(SgmPathEngine, MiddleburyCones) {
  const char* data = std::getenv("SGM_DATA");
  const std::string dir = std::string(data ? data : "") + "/cones";
  if (!data || !std::ifstream(dir + "/left.png"))
    GTEST_SKIP() << "Middlebury data not found at " << dir << "; set DATA=...";
  cv::Mat left = sgm::readGray(dir + "/left.png"), right = sgm::readGray(dir + "/right.png");
  if (left.cols > 128 * (kD / 16)) {  // small builds take a crop that fits MAX_WIDTH
    const cv::Rect crop(0, 0, 120, 60);
    left = left(crop).clone(), right = right(crop).clone();
  }
  Frame f;
  f.gray = left;
  f.cost = sgm::computeCost(left, right, sgm::CostMode::kRsad, kD);
  PathEngine engine("sgm_path_engine_cones", 3, 0.2);
  EXPECT_EQ(engine.run(f), "");
}

}  // namespace
