// SPDX-License-Identifier: Apache-2.0
// sgm_right_path against the golden fifth path in blocks (docs/algorithm.md
// section 12, sgm::addRightPath with block B): the L5 vector of every pixel of
// every frame, its costs and its side bundle LATENCY slots later, LANES row
// lanes interleaved slot by slot (slot K t + k belongs to lane k, lane k runs
// the rows y = k mod K), frames of many widths back to back (narrower than a
// block, between one and two blocks, multiples of a block and not), random idle
// cycles, and random costs and grays in the rows around each frame (outside the
// frame: they must not reach a pixel of it). Builds with EDGE_RESET = 1 restart
// the passes at strong edges as the golden Params::edgeReset does (random T, R
// and flag per frame); builds without ignore that configuration.
#include "Vsgm_right_path.h"
#include "Vsgm_right_path_sgm_right_path.h"
#include "idle_slot.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/aggregate.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <deque>
#include <random>
#include <sstream>
#include <vector>

#ifndef SGM_D
#define SGM_D 16
#endif

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_right_path>;
using sgm::tb::getBits;
using sgm::tb::setBits;

constexpr int kD = SGM_D;
constexpr int kLanes = int(Vsgm_right_path_sgm_right_path::LANES);
constexpr int kBlock = int(Vsgm_right_path_sgm_right_path::BLOCK);
constexpr int kLatency = int(Vsgm_right_path_sgm_right_path::LATENCY);
constexpr int kL5Lag = int(Vsgm_right_path_sgm_right_path::L5_LAG);
constexpr bool kEdgeReset = int(Vsgm_right_path_sgm_right_path::EDGE_RESET) != 0;
constexpr int kCostBits = 7, kPathBits = 9, kWeightedBits = kPathBits + 4;
constexpr int kDelayLaneSlots = (kLatency - 1) / kLanes;  // DLY

struct Frame {
  int width = 0, height = 0;
  cv::Mat gray;                       // height x width
  std::vector<uint8_t> cost;          // height x width x D
  int p1 = 20, p2 = 200, weight = 1;  // W5
  sgm::P2Mode p2Mode = sgm::P2Mode::kKnee;
  sgm::EdgeReset edgeReset{0};  // the pass restart (paths[4]: the fifth path's flag)
  std::vector<uint16_t> l5;     // expected W5 L5, height x width x D
};

Frame randomFrame(int w, int h, int p1, int p2, sgm::P2Mode mode, int weight, std::mt19937& rng,
                  const sgm::EdgeReset& edgeReset = sgm::EdgeReset{0}) {
  Frame f;
  f.width = w, f.height = h, f.p1 = p1, f.p2 = p2, f.p2Mode = mode, f.weight = weight, f.edgeReset = edgeReset;
  f.gray = cv::Mat(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)  // runs of equal grays (dI = 0) beside random ones
      f.gray.at<uint8_t>(y, x) = rng() % 3 == 0 && x > 0 ? f.gray.at<uint8_t>(y, x - 1) : uint8_t(rng() % 256);
  f.cost.resize(size_t(w) * h * kD);
  for (auto& c : f.cost) c = uint8_t(rng() % 89);  // anything a hardware cost mode can produce (0 .. 88)
  const sgm::P2Table table = sgm::makeP2Table(p1, p2, mode);
  f.l5.assign(f.cost.size(), 0);
  for (int y = 0; y < h; ++y)
    sgm::addRightPath(f.cost.data() + size_t(y) * w * kD, f.gray.ptr<uint8_t>(y), w, kD, p1, table, weight,
                      f.l5.data() + size_t(y) * w * kD, kBlock, kEdgeReset ? edgeReset : sgm::EdgeReset{0});
  return f;
}

struct Entered {
  int frame = -1, x = 0, y = -1;  // y < 0: no pixel of a frame
  uint32_t side = 0;
  std::vector<uint8_t> cost;
};

class Bench {
 public:
  Bench(Top& top, std::mt19937& rng, double idle) : top_(top), rng_(rng), idle_(idle) {}

  // Fills the P2 table for the frame (idle), then streams it: each lane `pre`
  // rows outside the frame, its rows, then enough rows outside the frame for
  // every pixel of it to leave (the core's flush does the same).
  void run(const Frame& f, int pre) {
    frames_.push_back(&f);
    top_->en_i = 0;
    top_->width_i = f.width;
    top_->p1_i = f.p1;
    top_->weight_i = f.weight;
    top_->reset_t_i = f.edgeReset.threshold;
    top_->reset_len_i = f.edgeReset.length;
    top_->reset_en_i = f.edgeReset.paths[4] != 0;
    top_->p2_i = f.p2;
    top_->p2_mode_i = f.p2Mode == sgm::P2Mode::kPaper;
    top_->lut_ready_i = 1;
    top_->lut_start_i = 1;
    top_.tick();
    top_->lut_start_i = 0;
    for (int i = 0; i < 600 && !top_->lut_ready_o; ++i) top_.tick();
    ASSERT_TRUE(top_->lut_ready_o);
    top_->lut_ready_i = 0;  // the other tables' ready gates this one's
    top_.tick();
    EXPECT_FALSE(top_->lut_ready_o) << "lut_ready_o with lut_ready_i low";
    top_->lut_ready_i = 1;
    top_.tick();
    ASSERT_TRUE(top_->lut_ready_o);
    const int w = f.width;
    const int laneRows = (f.height + kLanes - 1) / kLanes;
    const int post = (kDelayLaneSlots + 2 * kBlock) / w + 2;
    for (int i = 0; i < pre + laneRows + post; ++i)
      for (int x = 0; x < w; ++x)
        for (int k = 0; k < kLanes; ++k) {
          const int y = (i - pre) * kLanes + k;
          const bool pixel = i >= pre && y < f.height;
          slot(int(frames_.size()) - 1, x, pixel ? y : -1, f);
        }
  }

  std::string mismatch() const { return mismatch_; }
  long checked() const { return checked_; }

 private:
  void slot(int frame, int x, int y, const Frame& f) {
    Entered e;
    e.frame = frame, e.x = x, e.y = y;
    e.side = uint32_t(rng_() & 0xffff);
    e.cost.resize(kD);
    for (int d = 0; d < kD; ++d)
      e.cost[size_t(d)] = y >= 0 ? f.cost[(size_t(y) * f.width + x) * kD + d] : uint8_t(rng_() % 128);
    for (int d = 0; d < kD; ++d) setBits(top_->cost_i, d * kCostBits, kCostBits, e.cost[size_t(d)]);
    top_->gray_i = y >= 0 ? f.gray.at<uint8_t>(y, x) : uint8_t(rng_() % 256);
    top_->col_i = x;
    top_->side_i = e.side;
    sgm::tb::slotAfterIdle(top_, rng_, idle_);
    entered_.push_back(std::move(e));
    if (entered_.size() >= size_t(kLatency)) checkCosts(entered_[entered_.size() - kLatency]);
    if (entered_.size() < size_t(kLatency + kL5Lag)) return;
    checkL5(entered_.front());
    entered_.pop_front();
  }

  std::string stage() const {
    return "stage sgm_right_path (LANES=" + std::to_string(kLanes) + ", BLOCK=" + std::to_string(kBlock) +
           "): first mismatch at ";
  }

  // The costs and the side bundle, LATENCY slots after the pixel entered.
  void checkCosts(const Entered& e) {
    if (!mismatch_.empty()) return;
    std::ostringstream where;
    where << stage();
    if (int(top_->side_o) != int(e.side)) {
      where << "slot of (x=" << e.x << ", y=" << e.y << ") side: expected " << e.side << ", got " << top_->side_o;
      mismatch_ = where.str();
      return;
    }
    for (int d = 0; d < kD; ++d)
      if (int(getBits(top_->cost_o, d * kCostBits, kCostBits)) != e.cost[size_t(d)]) {
        where << "slot of (x=" << e.x << ", y=" << e.y << ") cost d=" << d << ": expected " << int(e.cost[size_t(d)])
              << ", got " << getBits(top_->cost_o, d * kCostBits, kCostBits);
        mismatch_ = where.str();
        return;
      }
  }

  // W5 L5, L5_LAG slots after the costs.
  void checkL5(const Entered& e) {
    if (!mismatch_.empty() || e.y < 0) return;
    std::ostringstream where;
    where << stage();
    const Frame& f = *frames_[size_t(e.frame)];
    const uint16_t* want = f.l5.data() + (size_t(e.y) * f.width + e.x) * kD;
    for (int d = 0; d < kD; ++d) {
      const int got = int(getBits(top_->l5w_o, d * kWeightedBits, kWeightedBits));
      if (got != want[d]) {
        where << "(x=" << e.x << ", y=" << e.y << ") W5 L5 d=" << d << ": expected " << want[d] << ", got " << got
              << " (frame " << e.frame << ", " << f.width << "x" << f.height << ", P1=" << f.p1 << ", P2'=" << f.p2
              << ", W5=" << f.weight << ", restart T=" << f.edgeReset.threshold << " R=" << f.edgeReset.length << " on "
              << f.edgeReset.paths[4] << (kEdgeReset ? "" : " not built") << ")";
        mismatch_ = where.str();
        return;
      }
    }
    ++checked_;
  }

  Top& top_;
  std::mt19937& rng_;
  double idle_;
  std::vector<const Frame*> frames_;
  std::deque<Entered> entered_;
  std::string mismatch_;
  long checked_ = 0;
};

TEST(SgmRightPath, FramesOfManyWidthsBackToBack) {
  Top top("sgm_right_path");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(11);
  // Narrower than a block, one block, between one and two, two, multiples and remainders.
  const int widths[] = {kBlock / 2 + 1, kBlock,         kBlock + 3, 2 * kBlock - 1,          2 * kBlock,
                        3 * kBlock + 1, 5 * kBlock - 2, 4 * kBlock, 2 * kBlock + kBlock / 2, 7 * kBlock + 5};
  std::vector<Frame> frames;
  frames.reserve(std::size(widths));
  for (int w : widths) {
    if (w < 2 || w > 255) continue;
    const int p2 = int(rng() % 256), p1 = int(rng() % (p2 + 1));
    const auto mode = frames.size() % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee;
    const int weights[] = {1, 4, 0, 15, 3, 8};
    frames.push_back(randomFrame(w, 2 * kLanes + 1 + int(rng() % 3), p1, p2, mode,
                                 weights[frames.size() % std::size(weights)], rng));
  }
  Bench bench(top, rng, 0.25);
  long pixels = 0;
  for (const Frame& f : frames) {
    bench.run(f, 1 + int(rng() % 2));
    pixels += long(f.width) * f.height;
  }
  // Each frame's rows after it flush it: every pixel of every frame is checked.
  EXPECT_EQ(bench.mismatch(), "");
  EXPECT_EQ(bench.checked(), pixels);
}

// The pass restart at strong edges: T from many edges to few, R from 1 to 15,
// the flag on and off, frame by frame back to back (the grays' runs of equal
// values give steps of 0 beside random ones).
TEST(SgmRightPath, RestartAtStrongEdges) {
  Top top("sgm_right_path_restart");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(13);
  const int widths[] = {3 * kBlock + 1, kBlock + 3, 2 * kBlock, 5 * kBlock - 2, kBlock / 2 + 1, 4 * kBlock + 7};
  const int thresholds[] = {1, 100, 40, 0, 160, 20};
  std::vector<Frame> frames;
  frames.reserve(std::size(widths));
  for (size_t i = 0; i < std::size(widths); ++i) {
    const int w = widths[i];
    if (w < 2 || w > 255) continue;
    sgm::EdgeReset reset{thresholds[i],
                         i == 0   ? 15
                         : i == 1 ? 1
                                  : 1 + int(rng() % sgm::kMaxEdgeResetLength),
                         {0, 0, 0, 0, i == 5 ? 0 : 1}};
    const int p2 = 40 + int(rng() % 200), p1 = int(rng() % 40);
    frames.push_back(randomFrame(w, 2 * kLanes + 1, p1, p2, i % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee,
                                 1 + int(rng() % 8), rng, reset));
  }
  Bench bench(top, rng, 0.25);
  long pixels = 0;
  for (const Frame& f : frames) bench.run(f, 1), pixels += long(f.width) * f.height;
  EXPECT_EQ(bench.mismatch(), "");
  EXPECT_EQ(bench.checked(), pixels);
}

TEST(SgmRightPath, PenaltyExtremes) {
  Top top("sgm_right_path_extremes");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(12);
  std::vector<Frame> frames;
  for (auto [p1, p2] : {std::pair{0, 0}, {0, 255}, {255, 255}, {20, 200}})
    frames.push_back(randomFrame(3 * kBlock + 2, kLanes + 1, p1, p2, sgm::P2Mode::kKnee, 1, rng));
  Bench bench(top, rng, 0.0);
  long pixels = 0;
  for (const Frame& f : frames) bench.run(f, 1), pixels += long(f.width) * f.height;
  EXPECT_EQ(bench.mismatch(), "");
  EXPECT_EQ(bench.checked(), pixels);
}

}  // namespace
