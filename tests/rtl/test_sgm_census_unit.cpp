// sgm_census_unit against the golden sgm::censusTransform (docs/algorithm.md
// section 2, docs/rtl.md "Window and census"). Frames are streamed slot by slot
// in raster order, each followed by flush slots (rows height, height+1, ...,
// pixel 0) until its last centre has entered, back to back without reset, with
// en_i toggled by a seeded random pattern (pix/col/row are random junk while
// en_i = 0, and every output must hold). Every output slot is checked against
// the latency contract (LATENCY from the model): valid_o, the centre position,
// and for valid centres census, rank, centre pixel and the four neighbours.
#include "Vsgm_census_unit.h"
#include "Vsgm_census_unit_sgm_census_unit.h"
#include "verilated_top.hpp"

#include "sgm/census.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_census_unit>;
using Rtl = Vsgm_census_unit_sgm_census_unit;  // public parameters of the build

constexpr int kLatency = int(Rtl::LATENCY);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);

// How a frame's flush ends: right after the slot of its last centre, (3, H+4)
// (the next frame enters while this one is still in the pipeline), or after
// complete flush rows H .. H+4.
enum class Flush { kMinimal, kFullRows };

struct Slot {
  int frame;  // index into the frame list
  int x, y;   // position in the virtual raster
  uint8_t pix;
};

// Centre of the slot at input (x, y): docs/rtl.md.
struct Centre {
  int x, y;
};
Centre centreOf(int x, int y, int w) { return x >= 4 ? Centre{x - 4, y - 4} : Centre{w + x - 4, y - 5}; }

std::vector<Slot> buildSlots(const std::vector<cv::Mat>& frames, Flush flush, int trailing) {
  std::vector<Slot> slots;
  for (int f = 0; f < int(frames.size()); ++f) {
    const cv::Mat& img = frames[f];
    const int w = img.cols, h = img.rows;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) slots.push_back({f, x, y, img.at<uint8_t>(y, x)});
    // Flush slots: rows h, h+1, ... with pixel 0 until the flush policy is met,
    // then (after the last frame only) `trailing` more so the last outputs leave.
    int extra = f + 1 == int(frames.size()) ? trailing : 0;
    for (int x = 0, y = h;;) {
      const bool done = y > h + 4 || (y == h + 4 && flush == Flush::kMinimal && x > 3);
      if (done && extra-- <= 0) break;
      slots.push_back({f, x, y, 0});
      if (++x == w) x = 0, ++y;
    }
  }
  return slots;
}

struct Outputs {
  uint32_t census[3];
  uint32_t rank, centre, nbr, col, row, valid;
  bool operator==(const Outputs& o) const {
    return census[0] == o.census[0] && census[1] == o.census[1] && census[2] == o.census[2] && rank == o.rank &&
           centre == o.centre && nbr == o.nbr && col == o.col && row == o.row && valid == o.valid;
  }
};

Outputs outputsOf(Top& top) {
  Outputs o;
  for (int i = 0; i < 3; ++i) o.census[i] = top->census_o[i];
  o.rank = top->rank_o;
  o.centre = top->centre_o;
  o.nbr = top->nbr_o;
  o.col = top->col_o;
  o.row = top->row_o;
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
  int idlePercent = 30;    // probability of an idle cycle before a slot
  int burstPermille = 5;   // probability of a long idle burst (up to 40 cycles)
};

struct StreamStats {
  long slots = 0, cycles = 0, validOutputs = 0;
};

// Streams the frames through the unit and checks every output slot; stops at the
// first mismatch with frame, pixel, stage, expected and got.
void runStream(Top& top, const std::vector<cv::Mat>& frames, const StreamOptions& opt, StreamStats* stats = nullptr) {
  for (const cv::Mat& f : frames) {
    ASSERT_GE(f.cols, 16);
    ASSERT_GE(f.rows, 9);
    ASSERT_LE(f.cols, kMaxWidth);
  }
  std::vector<std::vector<sgm::Census>> golden;
  for (const cv::Mat& f : frames) golden.push_back(sgm::censusTransform(f));
  const std::vector<Slot> slots = buildSlots(frames, opt.flush, kLatency);

  std::mt19937 rng(opt.seed);
  std::uniform_int_distribution<int> percent(0, 99), permille(0, 999), burst(1, 40), junk(0, 1 << 30);
  long validCount = 0;
  std::vector<long> perFrame(frames.size(), 0);

  for (long s = 0; s < long(slots.size()); ++s) {
    const Slot& in = slots[s];
    const cv::Mat& img = frames[in.frame];
    // Idle cycles: junk inputs, nothing may change.
    int idle = 0;
    while (percent(rng) < opt.idlePercent) ++idle;
    if (permille(rng) < opt.burstPermille) idle += burst(rng);
    for (int i = 0; i < idle; ++i) {
      const Outputs before = outputsOf(top);
      top->en_i = 0;
      top->pix_i = junk(rng) & 0xff;
      top->col_i = junk(rng) & 0xff;
      top->row_i = junk(rng) & 0xff;
      top.tick();
      ASSERT_TRUE(outputsOf(top) == before) << "outputs changed during an idle cycle before slot " << s << " (frame "
                                            << in.frame << ", input (" << in.x << ", " << in.y << "))";
    }
    top->en_i = 1;
    top->pix_i = in.pix;
    top->col_i = in.x;
    top->row_i = in.y;
    top->width_i = img.cols;
    top->height_i = img.rows;
    top.tick();

    // The outputs now belong to the slot LATENCY - 1 slots back (the input
    // just sampled is one of the LATENCY stages).
    const long o = s - (kLatency - 1);
    const Outputs got = outputsOf(top);
    if (o < 0) {
      ASSERT_EQ(got.valid, 0u) << "valid_o set at slot " << s << ", before any centre could arrive";
      continue;
    }
    const Slot& src = slots[o];
    const cv::Mat& src_img = frames[src.frame];
    const int w = src_img.cols, h = src_img.rows;
    const Centre c = centreOf(src.x, src.y, w);
    const bool inside = c.y >= 0 && c.y < h;
    std::ostringstream where;
    where << "frame " << src.frame << " (" << w << "x" << h << ") centre (" << c.x << ", " << c.y
          << ") from input slot " << o << " (" << src.x << ", " << src.y << "), output slot " << s;
    ASSERT_EQ(got.valid, uint32_t(inside)) << "stage valid: " << where.str();
    if (!inside) continue;
    ++validCount;
    ++perFrame[src.frame];
    ASSERT_EQ(got.col, uint32_t(c.x)) << "stage position (col_o): " << where.str();
    ASSERT_EQ(got.row, uint32_t(c.y)) << "stage position (row_o): " << where.str();
    const sgm::Census& g = golden[src.frame][size_t(c.y) * w + c.x];
    const uint64_t lo = uint64_t(got.census[0]) | uint64_t(got.census[1]) << 32;
    const uint32_t hi = got.census[2] & 0xffff;
    ASSERT_TRUE(lo == g.lo && hi == g.hi)
        << "stage census: " << where.str() << ": expected " << hexCensus(g.lo, g.hi) << " got " << hexCensus(lo, hi);
    ASSERT_EQ(int(got.rank), g.rank()) << "stage rank: " << where.str();
    ASSERT_EQ(int(got.centre), int(src_img.at<uint8_t>(c.y, c.x))) << "stage centre: " << where.str();
    // Neighbours 0, 45, 90, 135 degrees; only those inside the frame are defined.
    const int nx[4] = {c.x - 1, c.x - 1, c.x, c.x + 1}, ny[4] = {c.y, c.y - 1, c.y - 1, c.y - 1};
    static const char* const kNames[4] = {"0 deg (x-1, y)", "45 deg (x-1, y-1)", "90 deg (x, y-1)",
                                          "135 deg (x+1, y-1)"};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || nx[k] >= w || ny[k] < 0) continue;
      ASSERT_EQ(int((got.nbr >> (8 * k)) & 0xff), int(src_img.at<uint8_t>(ny[k], nx[k])))
          << "stage neighbour " << kNames[k] << ": " << where.str();
    }
  }
  for (size_t f = 0; f < frames.size(); ++f)
    ASSERT_EQ(perFrame[f], long(frames[f].total())) << "frame " << f << ": valid centres";
  if (stats) {
    stats->slots += long(slots.size());
    stats->cycles = long(top.cycles());
    stats->validOutputs += validCount;
  }
}

cv::Mat randomImage(int w, int h, std::mt19937& rng, int levels = 256) {
  cv::Mat img(h, w, CV_8UC1);
  std::uniform_int_distribution<int> v(0, levels - 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(levels == 256 ? v(rng) : v(rng) * 255 / (levels - 1));
  return img;
}

TEST(SgmCensusUnit, LatencyConstant) {
  // The top aligns the other signals with this value (docs/rtl.md pipeline table).
  EXPECT_EQ(kLatency, 4);
}

TEST(SgmCensusUnit, RandomImagesSeveralSizes) {
  std::mt19937 rng(20240611);
  const std::pair<int, int> sizes[] = {{16, 9}, {17, 10}, {23, 9}, {37, 21}, {100, 13}, {kMaxWidth, 11}, {61, 40}};
  uint32_t seed = 1;
  for (auto [w, h] : sizes) {
    if (w > kMaxWidth) continue;
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    Top top("sgm_census_unit_random_" + std::to_string(w) + "x" + std::to_string(h));
    top->en_i = 0;
    top.reset();
    StreamOptions opt;
    opt.seed = seed++;
    ASSERT_NO_FATAL_FAILURE(runStream(top, {randomImage(w, h, rng)}, opt));
  }
}

TEST(SgmCensusUnit, FewGrayLevelsTies) {
  // Many equal neighbours: bit = I(q) < I(p) is strict.
  std::mt19937 rng(77);
  Top top("sgm_census_unit_ties");
  top->en_i = 0;
  top.reset();
  StreamOptions opt;
  opt.seed = 99;
  ASSERT_NO_FATAL_FAILURE(runStream(top, {randomImage(29, 14, rng, 2), randomImage(31, 12, rng, 3)}, opt));
}

TEST(SgmCensusUnit, BackToBackFramesNoReset) {
  // Different sizes, no reset: the rows of the previous frame in the line buffer
  // and the previous frame's slots in the pipeline must not leak. Large after
  // small and small after large, with minimal and full-row flushes.
  std::mt19937 rng(4242);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    SCOPED_TRACE(flush == Flush::kMinimal ? "minimal flush" : "full-row flush");
    Top top("sgm_census_unit_b2b");
    top->en_i = 0;
    top.reset();
    std::vector<cv::Mat> frames = {randomImage(std::min(90, kMaxWidth), 20, rng), randomImage(16, 9, rng),
                                   randomImage(std::min(57, kMaxWidth), 13, rng), randomImage(40, 25, rng),
                                   randomImage(40, 9, rng)};
    StreamOptions opt;
    opt.flush = flush;
    opt.seed = flush == Flush::kMinimal ? 5 : 6;
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCensusUnit, RandomSizesBackToBack) {
  // 12 frames of random size (16 .. MAX_WIDTH x 9 .. 40) in one stream, once
  // per flush policy.
  std::mt19937 rng(555);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    Top top("sgm_census_unit_sizes");
    top->en_i = 0;
    top.reset();
    std::uniform_int_distribution<int> wd(16, kMaxWidth), hd(9, 40);
    std::vector<cv::Mat> frames;
    for (int i = 0; i < 12; ++i) frames.push_back(randomImage(wd(rng), hd(rng), rng));
    StreamOptions opt;
    opt.flush = flush;
    opt.seed = flush == Flush::kMinimal ? 61 : 62;
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCensusUnit, FlatAndSaturatedImages) {
  Top top("sgm_census_unit_flat");
  top->en_i = 0;
  top.reset();
  std::vector<cv::Mat> frames = {cv::Mat(9, 16, CV_8UC1, cv::Scalar(255)), cv::Mat(10, 20, CV_8UC1, cv::Scalar(0)),
                                 cv::Mat(12, 18, CV_8UC1, cv::Scalar(128))};
  cv::Mat checker(11, 24, CV_8UC1), stripes(9, 33, CV_8UC1);
  for (int y = 0; y < checker.rows; ++y)
    for (int x = 0; x < checker.cols; ++x) checker.at<uint8_t>(y, x) = (x + y) % 2 ? 255 : 0;
  for (int y = 0; y < stripes.rows; ++y)
    for (int x = 0; x < stripes.cols; ++x) stripes.at<uint8_t>(y, x) = x % 3 == 0 ? 255 : x % 3 == 1 ? 254 : 0;
  frames.push_back(checker);
  frames.push_back(stripes);
  frames.push_back(cv::Mat(9, 16, CV_8UC1, cv::Scalar(255)));  // all-zero census after the others
  StreamOptions opt;
  opt.seed = 3;
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
}

TEST(SgmCensusUnit, HeavyStallsAndNoStalls) {
  std::mt19937 rng(8);
  const cv::Mat img = randomImage(33, 15, rng);
  for (int idle : {0, 70}) {
    SCOPED_TRACE("idle " + std::to_string(idle) + "%");
    Top top("sgm_census_unit_stalls");
    top->en_i = 0;
    top.reset();
    StreamOptions opt;
    opt.idlePercent = idle;
    opt.burstPermille = idle ? 50 : 0;
    opt.seed = 11 + idle;
    ASSERT_NO_FATAL_FAILURE(runStream(top, {img, img}, opt));
  }
}

TEST(SgmCensusUnit, ResetMidFrame) {
  // A frame abandoned half way by a reset leaves stale rows in the line buffer
  // and no valid output; the next frame is exact.
  std::mt19937 rng(31);
  Top top("sgm_census_unit_reset");
  top->en_i = 0;
  top.reset();
  const cv::Mat first = randomImage(40, 20, rng);
  top->width_i = first.cols;
  top->height_i = first.rows;
  top->en_i = 1;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < first.cols; ++x) {
      top->pix_i = first.at<uint8_t>(y, x);
      top->col_i = x;
      top->row_i = y;
      top.tick();
    }
  top->en_i = 0;
  top.reset();
  EXPECT_EQ(top->valid_o, 0);
  StreamOptions opt;
  opt.seed = 12;
  ASSERT_NO_FATAL_FAILURE(runStream(top, {randomImage(37, 18, rng)}, opt));
}

}  // namespace
