// SPDX-License-Identifier: Apache-2.0
// sgm_census_unit against the golden sgm::censusTransform (docs/algorithm.md
// section 2, docs/rtl.md "Window and census"). Frames are streamed slot by slot
// in the census raster of tb/census_stream.hpp (each frame followed by flush
// slots until its last centre has entered), back to back without reset, with
// en_i toggled by the seeded enable pattern of tb/slot_driver.hpp (pix/col/row
// are random junk while en_i = 0, and every output must hold). Every output
// slot is checked against the latency contract (LATENCY from the model):
// valid_o, the centre position, and for valid centres census, rank, centre
// pixel and the four neighbours.
#include "Vsgm_census_unit.h"
#include "Vsgm_census_unit_sgm_census_unit.h"
#include "census_stream.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"

#include "sgm/census.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_census_unit>;
using Rtl = Vsgm_census_unit_sgm_census_unit;  // public parameters of the build
using sgm::tb::Flush;
using StreamOptions = sgm::tb::CensusStreamOptions;

constexpr int kLatency = int(Rtl::LATENCY);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);

// Streams the frames through the unit and checks every output slot; stops at the
// first mismatch with frame, pixel, stage, expected and got.
void runStream(Top& top, const std::vector<cv::Mat>& frames, const StreamOptions& opt) {
  std::vector<cv::Size> sizes;
  for (const cv::Mat& f : frames) {
    ASSERT_GE(f.cols, 16);
    ASSERT_GE(f.rows, 9);
    ASSERT_LE(f.cols, kMaxWidth);
    sizes.push_back(f.size());
  }
  std::vector<std::vector<sgm::Census>> golden;
  for (const cv::Mat& f : frames) golden.push_back(sgm::censusTransform(f));
  const std::vector<sgm::tb::RasterSlot> slots = sgm::tb::censusRaster(sizes, opt.flush, kLatency);

  sgm::tb::SlotDriver<Vsgm_census_unit, long> driver(
      top, opt.enablePattern(),
      [](Vsgm_census_unit& m, std::mt19937& junk) {
        m.pix_i = junk() & 0xff;
        m.active_i = junk() & 1;
        m.col_i = junk() & 0xff;
        m.row_i = junk() & 0xff;
      },
      [](Vsgm_census_unit& m) {
        return sgm::tb::portWords(m.census_o, m.rank_o, m.centre_o, m.nbr_o, m.col_o, m.row_o, m.valid_o);
      });
  if (opt.reset) driver.reset();
  std::vector<long> perFrame(frames.size(), 0);

  for (long s = 0; s < long(slots.size()); ++s) {
    const sgm::tb::RasterSlot& in = slots[s];
    const cv::Mat& img = frames[in.frame];
    const bool ok = driver.slot(
        s,
        [&](Vsgm_census_unit& m) {
          m.pix_i = sgm::tb::pixelOf(img, in);
          m.active_i = 1;  // the raster of one lane: every slot has a position
          m.col_i = in.x;
          m.row_i = in.y;
          m.width_i = img.cols;
          m.height_i = img.rows;
        },
        [&] {
          std::ostringstream os;
          os << "before slot " << s << " (frame " << in.frame << ", input (" << in.x << ", " << in.y << "))";
          return os.str();
        });
    if (!ok) return;

    // The outputs now belong to the slot LATENCY - 1 slots back (the input
    // just sampled is one of the LATENCY stages).
    const long* o = driver.source(kLatency);
    if (!o) {
      ASSERT_EQ(uint32_t(top->valid_o), 0u) << "valid_o set at slot " << s << ", before any centre could arrive";
      continue;
    }
    const sgm::tb::RasterSlot& src = slots[*o];
    const cv::Mat& src_img = frames[src.frame];
    const int w = src_img.cols, h = src_img.rows;
    const sgm::tb::Centre c = sgm::tb::centreOf(src.x, src.y, w);
    const bool inside = c.y >= 0 && c.y < h;
    std::ostringstream where;
    where << "frame " << src.frame << " (" << w << "x" << h << ") centre (" << c.x << ", " << c.y
          << ") from input slot " << *o << " (" << src.x << ", " << src.y << "), output slot " << s;
    ASSERT_EQ(uint32_t(top->valid_o), uint32_t(inside)) << "stage valid: " << where.str();
    if (!inside) continue;
    ++perFrame[src.frame];
    ASSERT_EQ(uint32_t(top->col_o), uint32_t(c.x)) << "stage position (col_o): " << where.str();
    ASSERT_EQ(uint32_t(top->row_o), uint32_t(c.y)) << "stage position (row_o): " << where.str();
    const sgm::Census& g = golden[src.frame][size_t(c.y) * w + c.x];
    const std::string census = sgm::tb::censusMismatch(top->census_o, g);
    ASSERT_TRUE(census.empty()) << "stage census: " << where.str() << ": " << census;
    ASSERT_EQ(int(top->rank_o), g.rank()) << "stage rank: " << where.str();
    ASSERT_EQ(int(top->centre_o), int(src_img.at<uint8_t>(c.y, c.x))) << "stage centre: " << where.str();
    // Neighbours 0, 45, 90, 135 degrees; only those inside the frame are defined.
    const int nx[4] = {c.x - 1, c.x - 1, c.x, c.x + 1}, ny[4] = {c.y, c.y - 1, c.y - 1, c.y - 1};
    static const char* const kNames[4] = {"0 deg (x-1, y)", "45 deg (x-1, y-1)", "90 deg (x, y-1)",
                                          "135 deg (x+1, y-1)"};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || nx[k] >= w || ny[k] < 0) continue;
      ASSERT_EQ(int((top->nbr_o >> (8 * k)) & 0xff), int(src_img.at<uint8_t>(ny[k], nx[k])))
          << "stage neighbour " << kNames[k] << ": " << where.str();
    }
  }
  for (size_t f = 0; f < frames.size(); ++f)
    ASSERT_EQ(perFrame[f], long(frames[f].total())) << "frame " << f << ": valid centres";
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
  EXPECT_EQ(kLatency, 5);
}

TEST(SgmCensusUnit, RandomImagesSeveralSizes) {
  std::mt19937 rng(20240611);
  const std::pair<int, int> sizes[] = {{16, 9}, {17, 10}, {23, 9}, {37, 21}, {100, 13}, {kMaxWidth, 11}, {61, 40}};
  uint32_t seed = 1;
  for (auto [w, h] : sizes) {
    if (w > kMaxWidth) continue;
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    Top top("sgm_census_unit_random_" + std::to_string(w) + "x" + std::to_string(h));
    ASSERT_NO_FATAL_FAILURE(runStream(top, {randomImage(w, h, rng)}, StreamOptions::seeded(seed++)));
  }
}

TEST(SgmCensusUnit, FewGrayLevelsTies) {
  // Many equal neighbours: bit = I(q) < I(p) is strict.
  std::mt19937 rng(77);
  Top top("sgm_census_unit_ties");
  ASSERT_NO_FATAL_FAILURE(
      runStream(top, {randomImage(29, 14, rng, 2), randomImage(31, 12, rng, 3)}, StreamOptions::seeded(99)));
}

TEST(SgmCensusUnit, BackToBackFramesNoReset) {
  // Different sizes, no reset: the rows of the previous frame in the line buffer
  // and the previous frame's slots in the pipeline must not leak. Large after
  // small and small after large, with minimal and full-row flushes.
  std::mt19937 rng(4242);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    SCOPED_TRACE(flush == Flush::kMinimal ? "minimal flush" : "full-row flush");
    Top top("sgm_census_unit_b2b");
    std::vector<cv::Mat> frames = {randomImage(std::min(90, kMaxWidth), 20, rng), randomImage(16, 9, rng),
                                   randomImage(std::min(57, kMaxWidth), 13, rng), randomImage(40, 25, rng),
                                   randomImage(40, 9, rng)};
    const StreamOptions opt = StreamOptions::seeded(flush == Flush::kMinimal ? 5 : 6, flush);
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCensusUnit, RandomSizesBackToBack) {
  // 12 frames of random size (16 .. MAX_WIDTH x 9 .. 40) in one stream, once
  // per flush policy.
  std::mt19937 rng(555);
  for (Flush flush : {Flush::kMinimal, Flush::kFullRows}) {
    Top top("sgm_census_unit_sizes");
    std::uniform_int_distribution<int> wd(16, kMaxWidth), hd(9, 40);
    std::vector<cv::Mat> frames;
    for (int i = 0; i < 12; ++i) frames.push_back(randomImage(wd(rng), hd(rng), rng));
    const StreamOptions opt = StreamOptions::seeded(flush == Flush::kMinimal ? 61 : 62, flush);
    ASSERT_NO_FATAL_FAILURE(runStream(top, frames, opt));
  }
}

TEST(SgmCensusUnit, FlatAndSaturatedImages) {
  Top top("sgm_census_unit_flat");
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
  ASSERT_NO_FATAL_FAILURE(runStream(top, frames, StreamOptions::seeded(3)));
}

TEST(SgmCensusUnit, HeavyStallsAndNoStalls) {
  std::mt19937 rng(8);
  const cv::Mat img = randomImage(33, 15, rng);
  for (int idle : {0, 70}) {
    SCOPED_TRACE("idle " + std::to_string(idle) + "%");
    Top top("sgm_census_unit_stalls");
    const StreamOptions opt = StreamOptions::idle(11 + idle, idle);
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
  top->active_i = 1;
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
  StreamOptions opt = StreamOptions::seeded(12);
  opt.reset = false;  // straight on from the reset above
  ASSERT_NO_FATAL_FAILURE(runStream(top, {randomImage(37, 18, rng)}, opt));
}

}  // namespace
