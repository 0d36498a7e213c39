// SPDX-License-Identifier: Apache-2.0
// sgm_cost_volume (with its sgm_cost_pe) against the golden sgm::computeCost
// (docs/algorithm.md section 3), through the wrapper tb/tops/tb_cost_front.sv:
// two sgm_census_unit (left, right) feeding the cost volume, as in the core.
// A gray pair is streamed slot by slot in the census raster of
// tb/census_stream.hpp (each frame followed by flush slots until its last
// centre has entered), frames back to back without reset (each with its own
// cost mode), with en_i toggled by the seeded enable pattern of
// tb/slot_driver.hpp (inputs are random junk while en_i = 0, and every output
// must hold). Every output slot is checked against the latency contract: the
// census stage (left/right census and rank, left position and valid) at
// CENSUS_LATENCY and the cost stage (valid, column and C(p, d) for every d) at
// CENSUS_LATENCY + COST_LATENCY. D, MAX_WIDTH and the latencies come from the
// model, so the file serves every build.
#include "Vtb_cost_front.h"
#include "Vtb_cost_front_tb_cost_front.h"
#include "census_stream.hpp"
#include "cones.hpp"
#include "port_bits.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"

#include "sgm/census.hpp"
#include "sgm/cost.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vtb_cost_front>;
using Rtl = Vtb_cost_front_tb_cost_front;  // public parameters of the build
using sgm::CostMode;
using sgm::tb::Flush;
using StreamOptions = sgm::tb::CensusStreamOptions;

constexpr int kD = int(Rtl::D);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kCensusLatency = int(Rtl::CENSUS_LATENCY);
constexpr int kLatency = int(Rtl::CENSUS_LATENCY) + int(Rtl::COST_LATENCY);
// AD_TERM = 0 (the lean build, rtl-cost-volume-d16-lean): the volume has no AD term, so
// frames that drive a weight expect the census cost alone.
constexpr bool kAdTerm = Rtl::AD_TERM != 0;

struct Frame {
  cv::Mat left, right;
  CostMode mode;
  int adWeight = 0, adCap = 0;  // the AD term (weight 0: off)
};

struct Golden {
  std::vector<sgm::Census> left, right;
  sgm::CostVolume cost;
};

// Streams the frames through the wrapper and checks every output slot; stops at
// the first mismatch with frame, pixel, stage, expected and got.
void runStream(Top& top, const std::vector<Frame>& frames, const StreamOptions& opt) {
  std::vector<Golden> golden;
  for (const Frame& f : frames) {
    ASSERT_EQ(f.left.size(), f.right.size());
    ASSERT_GE(f.left.cols, 16);
    ASSERT_GE(f.left.rows, 9);
    ASSERT_LE(f.left.cols, kMaxWidth);
    sgm::CostVolume cost = sgm::computeCost(f.left, f.right, f.mode, kD);
    if (f.adWeight && kAdTerm) {
      sgm::Params p;  // the contract's range (Cmax + largest term within the cost word)
      p.mode = f.mode, p.disparities = kD, p.adWeight = f.adWeight, p.adCap = f.adCap;
      p.validate();
      for (int y = 0; y < f.left.rows; ++y)
        sgm::addAdTerm(f.left, f.right, y, 0, f.left.cols, kD, f.adWeight, f.adCap, cost.at(0, y));
    }
    golden.push_back({sgm::censusTransform(f.left), sgm::censusTransform(f.right), std::move(cost)});
  }
  std::vector<cv::Size> sizes;
  for (const Frame& f : frames) sizes.push_back(f.left.size());
  const std::vector<sgm::tb::RasterSlot> slots = sgm::tb::censusRaster(sizes, opt.flush, kLatency);

  sgm::tb::SlotDriver<Vtb_cost_front, long> driver(
      top, opt.enablePattern(),
      [](Vtb_cost_front& m, std::mt19937& junk) {
        m.lpix_i = junk() & 0xff;
        m.rpix_i = junk() & 0xff;
        m.col_i = junk() & 0xff;
        m.row_i = junk() & 0xff;
        m.mode_i = junk() & 3;
        m.ad_weight_i = junk() & 15;
        m.ad_cap_i = junk() & 0xff;
      },
      [](Vtb_cost_front& m) {
        return sgm::tb::portWords(m.lcensus_o, m.rcensus_o, m.cost_o, m.lrank_o, m.rrank_o, m.lcol_o, m.lrow_o,
                                  m.lvalid_o, m.col_o, m.valid_o);
      });
  if (opt.reset) driver.reset();
  std::vector<long> perFrame(frames.size(), 0);

  // Expected centre of input slot o, and whether it is a frame pixel.
  auto centre = [&](long o, sgm::tb::Centre& c) {
    const sgm::tb::RasterSlot& src = slots[o];
    const cv::Mat& img = frames[src.frame].left;
    c = sgm::tb::centreOf(src.x, src.y, img.cols);
    return c.y >= 0 && c.y < img.rows;
  };
  auto where = [&](long o, const sgm::tb::Centre& c, long s) {
    const sgm::tb::RasterSlot& src = slots[o];
    std::ostringstream os;
    os << "frame " << src.frame << " (" << frames[src.frame].left.cols << "x" << frames[src.frame].left.rows << ", "
       << sgm::costModeName(frames[src.frame].mode) << ", AD " << frames[src.frame].adWeight << "/"
       << frames[src.frame].adCap << ") pixel (" << c.x << ", " << c.y << ") from input slot " << o << " (" << src.x
       << ", " << src.y << "), output slot " << s;
    return os.str();
  };

  for (long s = 0; s < long(slots.size()); ++s) {
    const sgm::tb::RasterSlot& in = slots[s];
    const Frame& fr = frames[in.frame];
    const bool ok = driver.slot(
        s,
        [&](Vtb_cost_front& m) {
          m.lpix_i = sgm::tb::pixelOf(fr.left, in);
          m.rpix_i = sgm::tb::pixelOf(fr.right, in);
          m.col_i = in.x;
          m.row_i = in.y;
          m.width_i = fr.left.cols;
          m.height_i = fr.left.rows;
          m.mode_i = int(fr.mode);
          m.ad_weight_i = fr.adWeight;
          m.ad_cap_i = fr.adCap;
        },
        [&] { return "before slot " + std::to_string(s); });
    if (!ok) return;

    // Census stage: the slot CENSUS_LATENCY - 1 back.
    if (const long* o = driver.source(kCensusLatency); !o) {
      ASSERT_EQ(uint32_t(top->lvalid_o), 0u) << "stage census: lvalid_o set at slot " << s << " before any centre";
    } else {
      sgm::tb::Centre c;
      const bool inside = centre(*o, c);
      ASSERT_EQ(uint32_t(top->lvalid_o), uint32_t(inside)) << "stage census (valid): " << where(*o, c, s);
      if (inside) {
        const Golden& g = golden[slots[*o].frame];
        const int w = frames[slots[*o].frame].left.cols;
        ASSERT_EQ(uint32_t(top->lcol_o), uint32_t(c.x)) << "stage census (col): " << where(*o, c, s);
        ASSERT_EQ(uint32_t(top->lrow_o), uint32_t(c.y)) << "stage census (row): " << where(*o, c, s);
        for (int side = 0; side < 2; ++side) {
          const sgm::Census& e = (side ? g.right : g.left)[size_t(c.y) * w + c.x];
          const std::string census = sgm::tb::censusMismatch(side ? top->rcensus_o : top->lcensus_o, e);
          ASSERT_TRUE(census.empty()) << "stage census (" << (side ? "right" : "left") << "): " << where(*o, c, s)
                                      << ": " << census;
          ASSERT_EQ(int(side ? top->rrank_o : top->lrank_o), e.rank())
              << "stage rank (" << (side ? "right" : "left") << "): " << where(*o, c, s);
        }
      }
    }

    // Cost stage: the slot LATENCY - 1 back.
    const long* o = driver.source(kLatency);
    if (!o) {
      ASSERT_EQ(uint32_t(top->valid_o), 0u) << "stage cost: valid_o set at slot " << s << " before any centre";
      continue;
    }
    sgm::tb::Centre c;
    const bool inside = centre(*o, c);
    ASSERT_EQ(uint32_t(top->valid_o), uint32_t(inside)) << "stage cost (valid): " << where(*o, c, s);
    if (!inside) continue;
    ++perFrame[slots[*o].frame];
    ASSERT_EQ(uint32_t(top->col_o), uint32_t(c.x)) << "stage cost (col): " << where(*o, c, s);
    const uint8_t* e = golden[slots[*o].frame].cost.at(c.x, c.y);
    for (int d = 0; d < kD; ++d)
      ASSERT_EQ(int(sgm::tb::getBits(top->cost_o, 7 * d, 7)), int(e[d]))
          << "stage cost d=" << d << ": " << where(*o, c, s);
  }
  for (size_t f = 0; f < frames.size(); ++f)
    ASSERT_EQ(perFrame[f], long(frames[f].left.total())) << "frame " << f << ": valid cost outputs";
}

cv::Mat randomImage(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  std::uniform_int_distribution<int> v(0, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(v(rng));
  return img;
}

// A right view of `left`: shifted by a disparity that varies with the row
// (0 .. D+2), with noise, so that small costs and the Cmax border both occur.
cv::Mat rightView(const cv::Mat& left, std::mt19937& rng) {
  cv::Mat right(left.size(), CV_8UC1);
  std::uniform_int_distribution<int> noise(-6, 6), fill(0, 255);
  for (int y = 0; y < left.rows; ++y) {
    const int d = (y * 5) % (kD + 3);
    for (int x = 0; x < left.cols; ++x) {
      const int v = x + d < left.cols ? left.at<uint8_t>(y, x + d) + noise(rng) : fill(rng);
      right.at<uint8_t>(y, x) = uint8_t(std::clamp(v, 0, 255));
    }
  }
  return right;
}

Frame randomFrame(int w, int h, CostMode mode, std::mt19937& rng) {
  Frame f{randomImage(w, h, rng), cv::Mat(), mode};
  f.right = rightView(f.left, rng);
  return f;
}

constexpr CostMode kModes[] = {CostMode::kRt, CostMode::kRsad, CostMode::kUnified};

TEST(SgmCostVolume, LatencyConstants) {
  // The wrapper mirrors sgm_census_unit / sgm_cost_volume LATENCY; the stream
  // checks below hold the RTL to them slot by slot.
  EXPECT_EQ(kCensusLatency, 5);
  EXPECT_EQ(int(Rtl::COST_LATENCY), 4);
}

// The AD term in every mode, at the edges of its range (the largest term the
// 9x5 cost word leaves each mode, weight 15, cap 255, cap 0), frame after frame
// with other settings and without it.
TEST(SgmCostVolume, AdTerm) {
  std::mt19937 rng(4242);
  Top top("tb_cost_front_ad");
  const int w = std::min(kMaxWidth, 52);
  std::vector<Frame> frames;
  const struct {
    CostMode mode;
    int weight, cap;
  } settings[] = {{CostMode::kRsad, 3, 20},     {CostMode::kRsad, 15, 44},    {CostMode::kRt, 8, 83},
                  {CostMode::kUnified, 15, 21}, {CostMode::kUnified, 1, 255}, {CostMode::kRsad, 7, 0},
                  {CostMode::kRt, 0, 99},       {CostMode::kRsad, 2, 100}};
  for (const auto& s : settings) {
    Frame f = randomFrame(w, 10, s.mode, rng);
    f.adWeight = s.weight, f.adCap = s.cap;
    frames.push_back(std::move(f));
  }
  Frame bright{cv::Mat(9, 20, CV_8UC1, cv::Scalar(255)), cv::Mat(9, 20, CV_8UC1, cv::Scalar(0)), CostMode::kRsad, 15,
               44};
  frames.push_back(bright);
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, StreamOptions::seeded(42)));
}

TEST(SgmCostVolume, RandomPairsAllModes) {
  // Per size, one frame per mode back to back (same size).
  std::mt19937 rng(777);
  const std::pair<int, int> sizes[] = {{16, 9}, {23, 10}, {45, 12}, {kMaxWidth, 9}, {70, 17}};
  uint32_t seed = 100;
  for (auto [w, h] : sizes) {
    if (w > kMaxWidth) continue;
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    Top top("tb_cost_front_random");
    std::vector<Frame> frames;
    for (CostMode m : kModes) frames.push_back(randomFrame(w, h, m, rng));
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, StreamOptions::seeded(seed++)));
  }
}

TEST(SgmCostVolume, BackToBackFramesNoReset) {
  // Different sizes and modes, no reset: stale right census of the previous
  // frame in the delay line and the previous frame's slots in the pipeline (its
  // mode included) must not leak. Minimal and full-row flushes.
  std::mt19937 rng(31337);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    SCOPED_TRACE(flush == Flush::kMinimal ? "minimal flush" : "full-row flush");
    Top top("tb_cost_front_b2b");
    const std::vector<Frame> frames = {
        randomFrame(std::min(90, kMaxWidth), 14, CostMode::kUnified, rng), randomFrame(16, 9, CostMode::kRt, rng),
        randomFrame(std::min(61, kMaxWidth), 11, CostMode::kRsad, rng), randomFrame(33, 20, CostMode::kUnified, rng),
        randomFrame(33, 9, CostMode::kRt, rng)};
    const StreamOptions opt = StreamOptions::seeded(flush == Flush::kMinimal ? 7 : 8, flush);
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCostVolume, RandomSizesAndModesBackToBack) {
  // 8 frames of random size (16 .. min(MAX_WIDTH, 160) x 9 .. 24) and mode in
  // one stream, once per flush policy.
  std::mt19937 rng(8080);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    Top top("tb_cost_front_sizes");
    std::uniform_int_distribution<int> wd(16, std::min(kMaxWidth, 160)), hd(9, 24), md(0, 2);
    std::vector<Frame> frames;
    for (int i = 0; i < 8; ++i) frames.push_back(randomFrame(wd(rng), hd(rng), kModes[md(rng)], rng));
    const StreamOptions opt = StreamOptions::seeded(flush == Flush::kMinimal ? 71 : 72, flush);
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCostVolume, FlatAndSaturatedPairs) {
  // Extreme costs: equal flat images (all costs 0 inside), saturated left vs
  // black right, a checkerboard against its inverse (rsad up to 44, unified up
  // to 88 inside the image as well as at the border).
  Top top("tb_cost_front_flat");
  cv::Mat checker(12, 24, CV_8UC1), inverse(12, 24, CV_8UC1);
  for (int y = 0; y < checker.rows; ++y)
    for (int x = 0; x < checker.cols; ++x) {
      checker.at<uint8_t>(y, x) = (x + y) % 2 ? 255 : 0;
      inverse.at<uint8_t>(y, x) = (x + y) % 2 ? 0 : 255;
    }
  std::vector<Frame> frames;
  for (CostMode m : kModes) {
    frames.push_back({cv::Mat(9, 16, CV_8UC1, cv::Scalar(255)), cv::Mat(9, 16, CV_8UC1, cv::Scalar(255)), m});
    frames.push_back({cv::Mat(10, 20, CV_8UC1, cv::Scalar(255)), cv::Mat(10, 20, CV_8UC1, cv::Scalar(0)), m});
    frames.push_back({checker, inverse, m});
  }
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, StreamOptions::seeded(4)));
}

TEST(SgmCostVolume, HeavyStallsAndNoStalls) {
  std::mt19937 rng(9);
  for (int idle : {0, 70}) {
    SCOPED_TRACE("idle " + std::to_string(idle) + "%");
    Top top("tb_cost_front_stalls");
    const StreamOptions opt = StreamOptions::idle(21 + idle, idle);
    ASSERT_NO_FATAL_FAILURE(
        runStream(top, {randomFrame(40, 11, CostMode::kUnified, rng), randomFrame(40, 11, CostMode::kRsad, rng)}, opt));
  }
}

TEST(SgmCostVolume, MiddleburyCones) {
  // The real pair in the three modes, back to back (the D = 64, MAX_WIDTH = 512 build).
  if (const std::string why = sgm::tb::conesMissing(); !why.empty()) GTEST_SKIP() << why;
  const cv::Mat left = sgm::tb::conesGray("left"), right = sgm::tb::conesGray("right");
  if (left.cols > kMaxWidth || kD < 64)
    GTEST_SKIP() << "cones runs in the D >= 64 build with MAX_WIDTH >= " << left.cols << " (this build: D " << kD
                 << ", MAX_WIDTH " << kMaxWidth << ")";
  Top top("tb_cost_front_cones");
  std::vector<Frame> frames;
  for (CostMode m : kModes) frames.push_back({left, right, m});
  const StreamOptions opt = StreamOptions::seeded(2024);
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("cones %dx%d, 3 modes: %llu cycles in %.1f s\n", left.cols, left.rows,
              static_cast<unsigned long long>(top.cycles()), sec);
}

}  // namespace
