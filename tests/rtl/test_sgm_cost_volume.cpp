// sgm_cost_volume (with its sgm_cost_pe) against the golden sgm::computeCost
// (docs/algorithm.md section 3), through the wrapper tb/tops/tb_cost_front.sv:
// two sgm_census_unit (left, right) feeding the cost volume, as in the core.
// A gray pair is streamed slot by slot in raster order, each frame followed by
// flush slots (rows height, height+1, ..., pixel 0) until its last centre has
// entered, frames back to back without reset (each with its own cost mode),
// with en_i toggled by a seeded random pattern (inputs are random junk while
// en_i = 0, and every output must hold). Every output slot is checked against
// the latency contract: the census stage (left/right census and rank, left
// position and valid) at CENSUS_LATENCY and the cost stage (valid, column and
// C(p, d) for every d) at CENSUS_LATENCY + COST_LATENCY. D, MAX_WIDTH and the
// latencies come from the model, so the file serves every build.
#include "Vtb_cost_front.h"
#include "Vtb_cost_front_tb_cost_front.h"
#include "verilated_top.hpp"

#include "sgm/census.hpp"
#include "sgm/cost.hpp"
#include "sgm/image_io.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vtb_cost_front>;
using Rtl = Vtb_cost_front_tb_cost_front;  // public parameters of the build
using sgm::CostMode;

constexpr int kD = int(Rtl::D);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kCensusLatency = int(Rtl::CENSUS_LATENCY);
constexpr int kLatency = int(Rtl::CENSUS_LATENCY) + int(Rtl::COST_LATENCY);
constexpr int kCostWords = kD * 8 / 32;

struct Frame {
  cv::Mat left, right;
  CostMode mode;
};

// How a frame's flush ends: right after the slot of its last centre, (3, H+4)
// (the next frame enters while this one is still in the pipeline), or after
// complete flush rows H .. H+4.
enum class Flush { kMinimal, kFullRows };

struct Slot {
  int frame;
  int x, y;
  uint8_t l, r;
};

struct Centre {
  int x, y;
};
Centre centreOf(int x, int y, int w) { return x >= 4 ? Centre{x - 4, y - 4} : Centre{w + x - 4, y - 5}; }

std::vector<Slot> buildSlots(const std::vector<Frame>& frames, Flush flush, int trailing) {
  std::vector<Slot> slots;
  for (int f = 0; f < int(frames.size()); ++f) {
    const cv::Mat &l = frames[f].left, &r = frames[f].right;
    const int w = l.cols, h = l.rows;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) slots.push_back({f, x, y, l.at<uint8_t>(y, x), r.at<uint8_t>(y, x)});
    // Flush slots: rows h, h+1, ... with pixel 0 until the flush policy is met,
    // then (after the last frame only) `trailing` more so the last outputs leave.
    int extra = f + 1 == int(frames.size()) ? trailing : 0;
    for (int x = 0, y = h;;) {
      const bool done = y > h + 4 || (y == h + 4 && flush == Flush::kMinimal && x > 3);
      if (done && extra-- <= 0) break;
      slots.push_back({f, x, y, 0, 0});
      if (++x == w) x = 0, ++y;
    }
  }
  return slots;
}

struct Outputs {
  uint32_t lcensus[3], rcensus[3], cost[kCostWords];
  uint32_t lrank, rrank, lcol, lrow, lvalid, col, valid;
  bool operator==(const Outputs& o) const {
    for (int i = 0; i < 3; ++i)
      if (lcensus[i] != o.lcensus[i] || rcensus[i] != o.rcensus[i]) return false;
    for (int i = 0; i < kCostWords; ++i)
      if (cost[i] != o.cost[i]) return false;
    return lrank == o.lrank && rrank == o.rrank && lcol == o.lcol && lrow == o.lrow && lvalid == o.lvalid &&
           col == o.col && valid == o.valid;
  }
  int costOf(int d) const { return int((cost[d / 4] >> (8 * (d % 4))) & 0xff); }
};

Outputs outputsOf(Top& top) {
  Outputs o;
  for (int i = 0; i < 3; ++i) o.lcensus[i] = top->lcensus_o[i], o.rcensus[i] = top->rcensus_o[i];
  for (int i = 0; i < kCostWords; ++i) o.cost[i] = top->cost_o[i];
  o.lrank = top->lrank_o;
  o.rrank = top->rrank_o;
  o.lcol = top->lcol_o;
  o.lrow = top->lrow_o;
  o.lvalid = top->lvalid_o;
  o.col = top->col_o;
  o.valid = top->valid_o;
  return o;
}

std::string hexCensus(uint64_t lo, uint32_t hi) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04x%016llx", unsigned(hi & 0xffff), static_cast<unsigned long long>(lo));
  return buf;
}

struct StreamOptions {
  Flush flush = Flush::kMinimal;
  uint32_t seed = 1;
  int idlePercent = 30;   // probability of an idle cycle before a slot
  int burstPermille = 5;  // probability of a long idle burst (up to 40 cycles)
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
    golden.push_back(
        {sgm::censusTransform(f.left), sgm::censusTransform(f.right), sgm::computeCost(f.left, f.right, f.mode, kD)});
  }
  const std::vector<Slot> slots = buildSlots(frames, opt.flush, kLatency);

  std::mt19937 rng(opt.seed);
  std::uniform_int_distribution<int> percent(0, 99), permille(0, 999), burst(1, 40), junk(0, 1 << 30);
  std::vector<long> perFrame(frames.size(), 0);

  // Expected centre of input slot o, and whether it is a frame pixel.
  auto centre = [&](long o, Centre& c) {
    const Slot& src = slots[o];
    const cv::Mat& img = frames[src.frame].left;
    c = centreOf(src.x, src.y, img.cols);
    return c.y >= 0 && c.y < img.rows;
  };
  auto where = [&](long o, const Centre& c, long s) {
    const Slot& src = slots[o];
    std::ostringstream os;
    os << "frame " << src.frame << " (" << frames[src.frame].left.cols << "x" << frames[src.frame].left.rows << ", "
       << sgm::costModeName(frames[src.frame].mode) << ") pixel (" << c.x << ", " << c.y << ") from input slot " << o
       << " (" << src.x << ", " << src.y << "), output slot " << s;
    return os.str();
  };

  for (long s = 0; s < long(slots.size()); ++s) {
    const Slot& in = slots[s];
    const Frame& fr = frames[in.frame];
    int idle = 0;
    while (percent(rng) < opt.idlePercent) ++idle;
    if (permille(rng) < opt.burstPermille) idle += burst(rng);
    for (int i = 0; i < idle; ++i) {
      const Outputs before = outputsOf(top);
      top->en_i = 0;
      top->lpix_i = junk(rng) & 0xff;
      top->rpix_i = junk(rng) & 0xff;
      top->col_i = junk(rng) & 0xff;
      top->row_i = junk(rng) & 0xff;
      top->mode_i = junk(rng) & 3;
      top.tick();
      ASSERT_TRUE(outputsOf(top) == before) << "outputs changed during an idle cycle before slot " << s;
    }
    top->en_i = 1;
    top->lpix_i = in.l;
    top->rpix_i = in.r;
    top->col_i = in.x;
    top->row_i = in.y;
    top->width_i = fr.left.cols;
    top->height_i = fr.left.rows;
    top->mode_i = int(fr.mode);
    top.tick();
    const Outputs got = outputsOf(top);

    // Census stage: the slot CENSUS_LATENCY - 1 back.
    if (const long o = s - (kCensusLatency - 1); o < 0) {
      ASSERT_EQ(got.lvalid, 0u) << "stage census: lvalid_o set at slot " << s << " before any centre";
    } else {
      Centre c;
      const bool inside = centre(o, c);
      ASSERT_EQ(got.lvalid, uint32_t(inside)) << "stage census (valid): " << where(o, c, s);
      if (inside) {
        const Golden& g = golden[slots[o].frame];
        const int w = frames[slots[o].frame].left.cols;
        ASSERT_EQ(got.lcol, uint32_t(c.x)) << "stage census (col): " << where(o, c, s);
        ASSERT_EQ(got.lrow, uint32_t(c.y)) << "stage census (row): " << where(o, c, s);
        for (int side = 0; side < 2; ++side) {
          const sgm::Census& e = (side ? g.right : g.left)[size_t(c.y) * w + c.x];
          const uint32_t* cw = side ? got.rcensus : got.lcensus;
          const uint64_t lo = uint64_t(cw[0]) | uint64_t(cw[1]) << 32;
          const uint32_t hi = cw[2] & 0xffff;
          ASSERT_TRUE(lo == e.lo && hi == e.hi) << "stage census (" << (side ? "right" : "left")
                                                << "): " << where(o, c, s) << ": expected " << hexCensus(e.lo, e.hi)
                                                << " got " << hexCensus(lo, hi);
          ASSERT_EQ(int(side ? got.rrank : got.lrank), e.rank())
              << "stage rank (" << (side ? "right" : "left") << "): " << where(o, c, s);
        }
      }
    }

    // Cost stage: the slot LATENCY - 1 back.
    const long o = s - (kLatency - 1);
    if (o < 0) {
      ASSERT_EQ(got.valid, 0u) << "stage cost: valid_o set at slot " << s << " before any centre";
      continue;
    }
    Centre c;
    const bool inside = centre(o, c);
    ASSERT_EQ(got.valid, uint32_t(inside)) << "stage cost (valid): " << where(o, c, s);
    if (!inside) continue;
    ++perFrame[slots[o].frame];
    ASSERT_EQ(got.col, uint32_t(c.x)) << "stage cost (col): " << where(o, c, s);
    const uint8_t* e = golden[slots[o].frame].cost.at(c.x, c.y);
    for (int d = 0; d < kD; ++d)
      ASSERT_EQ(got.costOf(d), int(e[d])) << "stage cost d=" << d << ": " << where(o, c, s);
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
  EXPECT_EQ(kCensusLatency, 4);
  EXPECT_EQ(int(Rtl::COST_LATENCY), 3);
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
    top->en_i = 0;
    top.reset();
    std::vector<Frame> frames;
    for (CostMode m : kModes) frames.push_back(randomFrame(w, h, m, rng));
    StreamOptions opt;
    opt.seed = seed++;
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
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
    top->en_i = 0;
    top.reset();
    const std::vector<Frame> frames = {
        randomFrame(std::min(90, kMaxWidth), 14, CostMode::kUnified, rng), randomFrame(16, 9, CostMode::kRt, rng),
        randomFrame(std::min(61, kMaxWidth), 11, CostMode::kRsad, rng), randomFrame(33, 20, CostMode::kUnified, rng),
        randomFrame(33, 9, CostMode::kRt, rng)};
    StreamOptions opt;
    opt.flush = flush;
    opt.seed = flush == Flush::kMinimal ? 7 : 8;
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCostVolume, RandomSizesAndModesBackToBack) {
  // 8 frames of random size (16 .. min(MAX_WIDTH, 160) x 9 .. 24) and mode in
  // one stream, once per flush policy.
  std::mt19937 rng(8080);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    Top top("tb_cost_front_sizes");
    top->en_i = 0;
    top.reset();
    std::uniform_int_distribution<int> wd(16, std::min(kMaxWidth, 160)), hd(9, 24), md(0, 2);
    std::vector<Frame> frames;
    for (int i = 0; i < 8; ++i) frames.push_back(randomFrame(wd(rng), hd(rng), kModes[md(rng)], rng));
    StreamOptions opt;
    opt.flush = flush;
    opt.seed = flush == Flush::kMinimal ? 71 : 72;
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCostVolume, FlatAndSaturatedPairs) {
  // Extreme costs: equal flat images (all costs 0 inside), saturated left vs
  // black right, a checkerboard against its inverse (rsad up to 80, unified up
  // to 160 inside the image as well as at the border).
  Top top("tb_cost_front_flat");
  top->en_i = 0;
  top.reset();
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
  StreamOptions opt;
  opt.seed = 4;
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
}

TEST(SgmCostVolume, HeavyStallsAndNoStalls) {
  std::mt19937 rng(9);
  for (int idle : {0, 70}) {
    SCOPED_TRACE("idle " + std::to_string(idle) + "%");
    Top top("tb_cost_front_stalls");
    top->en_i = 0;
    top.reset();
    StreamOptions opt;
    opt.idlePercent = idle;
    opt.burstPermille = idle ? 50 : 0;
    opt.seed = 21 + idle;
    ASSERT_NO_FATAL_FAILURE(
        runStream(top, {randomFrame(40, 11, CostMode::kUnified, rng), randomFrame(40, 11, CostMode::kRsad, rng)}, opt));
  }
}

TEST(SgmCostVolume, MiddleburyCones) {
  // The real pair in the three modes, back to back (the D = 64, MAX_WIDTH = 512 build).
  const char* root = std::getenv("SGM_DATA");
  const std::string dir = std::string(root ? root : "") + "/cones";
  if (!root || !std::filesystem::exists(dir + "/left.png") || !std::filesystem::exists(dir + "/right.png"))
    GTEST_SKIP() << "Middlebury cones not found: set SGM_DATA to the middlebury folder (" << dir << ")";
  const cv::Mat left = sgm::readGray(dir + "/left.png"), right = sgm::readGray(dir + "/right.png");
  if (left.cols > kMaxWidth || kD < 64)
    GTEST_SKIP() << "cones runs in the D >= 64 build with MAX_WIDTH >= " << left.cols << " (this build: D " << kD
                 << ", MAX_WIDTH " << kMaxWidth << ")";
  Top top("tb_cost_front_cones");
  top->en_i = 0;
  top.reset();
  std::vector<Frame> frames;
  for (CostMode m : kModes) frames.push_back({left, right, m});
  StreamOptions opt;
  opt.seed = 2024;
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("cones %dx%d, 3 modes: %llu cycles in %.1f s\n", left.cols, left.rows,
              static_cast<unsigned long long>(top.cycles()), sec);
}

}  // namespace
