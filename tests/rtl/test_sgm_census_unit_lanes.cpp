// SPDX-License-Identifier: Apache-2.0
// sgm_census_unit with K row lanes (LANES, docs/lanes.md) against the golden
// sgm::censusTransform (docs/algorithm.md section 2). Frames are streamed slot by
// slot in the lane order of tb/lane_schedule.hpp (slot K n + k of a frame belongs
// to lane k, lane k holds the rows y with (y + lead) mod K == k and starts `skew`
// columns behind lane k - 1): lane k's first k * skew rounds of a frame are
// waiting slots, driven with active_i = 0 and either the lane deal's values
// (column 0, the lane's first row) or random junk (a column the earlier lanes
// have just written, any row, any pixel), which must neither reach the line
// buffer nor give a valid output. Rows outside the frame carry random pixels.
// Frames of several sizes (the narrowest, max(K skew + 2, 16), and odd heights
// among them), leads and skews run back to back without reset, each followed by
// a random number of extra slots of its schedule (none: the next frame starts
// right after the slot of the last centre), with en_i toggled by the seeded
// enable pattern of tb/slot_driver.hpp (junk inputs while en_i = 0, outputs
// held). Every output slot is checked LATENCY slots after its input: valid_o,
// and for valid centres the position, census, rank, centre pixel and the four
// neighbours; every frame pixel must come out exactly once. The build's
// LANES, CENSUS_H, MAX_WIDTH and LATENCY are read from the model.
#include "Vsgm_census_unit.h"
#include "Vsgm_census_unit_sgm_census_unit.h"
#include "lane_schedule.hpp"
#include "port_bits.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"

#include "sgm/census.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_census_unit>;
using Rtl = Vsgm_census_unit_sgm_census_unit;  // public parameters of the build

constexpr int kLanes = int(Rtl::LANES);
constexpr int kCensusH = int(Rtl::CENSUS_H);
constexpr int kLatency = int(Rtl::LATENCY);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kRy = (kCensusH - 1) / 2;  // window rows above and below the centre
constexpr int kBits = 9 * kCensusH - 1;  // census bits
constexpr uint32_t kRowMask = 0xff;      // the builds' RW = 8 (rows wrap)
const sgm::CensusWindow kWindow = kCensusH == 9 ? sgm::CensusWindow::k9x9 : sgm::CensusWindow::k9x5;

// The narrowest frame of a skew: the lanes' line-buffer order needs
// width > (K - 1) skew + 1; the core asks for K skew + 1 and at least 16.
int minWidth(int skew) { return std::max(kLanes * skew + 2, 16); }

// How the waiting lanes' slots (active_i = 0) are driven.
enum class Waiting { kLaneDeal, kJunk };

struct Frame {
  cv::Mat img;
  int skew = 3;
  int lead = 0;   // rows before row 0 (lane k starts at row k - lead)
  int extra = 0;  // slots of the schedule after the last centre's
  Waiting waiting = Waiting::kJunk;
};

// One enabled slot as driven, and what it stands for.
struct Slot {
  int frame;
  long index;  // slot of the frame's schedule
  bool active;
  int col, row;  // the position (active) or the driven junk
  uint8_t pix;
};

// The slot whose census is the centre (cx, cy), in the lane order of the frame:
// the input position 4 columns right and RY rows down, or, for the last four
// columns, column cx + 4 - w of the lane's next row (K rows further).
long slotOfCentre(const sgm::tb::LaneSchedule& lanes, int w, int cx, int cy) {
  return cx + 4 < w ? lanes.slotOf(cx + 4, cy + kRy) : lanes.slotOf(cx + 4 - w, cy + kRy + kLanes);
}

std::vector<Slot> laneSlots(const std::vector<Frame>& frames, std::mt19937& rng) {
  std::vector<Slot> slots;
  for (int f = 0; f < int(frames.size()); ++f) {
    const Frame& fr = frames[f];
    const int w = fr.img.cols, h = fr.img.rows;
    const sgm::tb::LaneSchedule lanes(w, kLanes, fr.skew, fr.lead);
    long last = 0;
    for (int cy = 0; cy < h; ++cy)
      for (int cx = 0; cx < w; ++cx) last = std::max(last, slotOfCentre(lanes, w, cx, cy));
    long count = last + 1 + fr.extra;
    if (f + 1 == int(frames.size())) count += kLatency;  // the last outputs leave the pipeline
    for (long n = 0; n < count; ++n) {
      const long lane = n % kLanes, round = n / kLanes;
      Slot s{f, n, round >= lane * fr.skew, 0, 0, uint8_t(rng())};
      if (s.active) {
        const sgm::tb::SlotPosition p = lanes.at(n);
        s.col = p.col;
        s.row = p.row;
        if (p.row >= 0 && p.row < h) s.pix = fr.img.at<uint8_t>(p.row, p.col);
      } else if (fr.waiting == Waiting::kLaneDeal) {
        s.row = int(lane) - fr.lead;
      } else {
        // Mostly a column the earlier lanes have just written: a write of this
        // slot would overwrite a line-buffer word before its next row reads it.
        const int recent = std::min(w, kLanes * fr.skew + 1);
        const bool fresh = rng() % 4 != 0;
        s.col = int(rng() % uint32_t(fresh ? recent : w));
        s.row = int(rng() & kRowMask);
      }
      slots.push_back(s);
    }
  }
  return slots;
}

// The census port and the golden signature as hex strings (bit kBits - 1 first).
template <typename Port>
std::pair<std::string, std::string> censusHex(const Port& port, const sgm::Census& want) {
  const uint32_t expected[3] = {uint32_t(want.bits), uint32_t(want.bits >> 32), uint32_t(want.high)};
  uint32_t got[3] = {0, 0, 0};
  for (int i = 0; i * 32 < kBits; ++i) got[i] = sgm::tb::getBits(port, 32 * i, std::min(32, kBits - 32 * i));
  auto hex = [](const uint32_t* w) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%04x%08x%08x", w[2] & 0xffffu, w[1], w[0]);
    return std::string(buf);
  };
  return {hex(expected), hex(got)};
}

sgm::tb::EnablePattern enablePattern(uint32_t seed, int idlePercent) {
  if (idlePercent < 0) return sgm::tb::EnablePattern(seed, 0.7, 0.0035);  // the census fixture's default
  return sgm::tb::EnablePattern(seed, 1.0 - idlePercent / 100.0, idlePercent ? 0.015 : 0.0);
}

// Streams the frames back to back (after one reset) and checks every output
// slot; stops at the first mismatch with frame, pixel, field, expected and got.
void runStream(const std::string& name, const std::vector<Frame>& frames, uint32_t seed, int idlePercent = -1) {
  for (const Frame& f : frames) {
    ASSERT_GE(f.img.cols, minWidth(f.skew)) << "frame narrower than the lanes need";
    ASSERT_LE(f.img.cols, kMaxWidth);
    ASSERT_GE(f.img.rows, 9);
    ASSERT_GE(f.skew, 1);
  }
  std::mt19937 rng(seed);
  const std::vector<Slot> slots = laneSlots(frames, rng);
  std::vector<std::vector<sgm::Census>> golden;
  std::vector<std::vector<uint8_t>> seen;
  for (const Frame& f : frames) {
    golden.push_back(sgm::censusTransform(f.img, kWindow));
    seen.emplace_back(f.img.total(), 0);
  }

  Top top(name);
  sgm::tb::SlotDriver<Vsgm_census_unit, long> driver(
      top, enablePattern(seed, idlePercent),
      [](Vsgm_census_unit& m, std::mt19937& junk) {
        m.active_i = junk() & 1;
        m.pix_i = junk() & 0xff;
        m.col_i = junk() & 0xff;
        m.row_i = junk() & kRowMask;
        m.width_i = junk() & 0xff;
        m.height_i = junk() & kRowMask;
      },
      [](Vsgm_census_unit& m) {
        return sgm::tb::portWords(m.census_o, m.rank_o, m.centre_o, m.nbr_o, m.col_o, m.row_o, m.valid_o);
      });
  driver.reset();

  for (long t = 0; t < long(slots.size()); ++t) {
    const Slot& in = slots[t];
    const cv::Mat& img = frames[in.frame].img;
    const bool ok = driver.slot(
        t,
        [&](Vsgm_census_unit& m) {
          m.active_i = in.active;
          m.pix_i = in.pix;
          m.col_i = in.col;
          m.row_i = uint32_t(in.row) & kRowMask;
          m.width_i = img.cols;
          m.height_i = img.rows;
        },
        [&] {
          std::ostringstream os;
          os << "before slot " << t << " (frame " << in.frame << ", slot " << in.index << " of its schedule)";
          return os.str();
        });
    if (!ok) return;

    const long* o = driver.source(kLatency);
    if (!o) {
      ASSERT_EQ(uint32_t(top->valid_o), 0u) << "valid_o set at slot " << t << ", before any centre could arrive";
      continue;
    }
    const Slot& src = slots[*o];
    const Frame& fr = frames[src.frame];
    const cv::Mat& si = fr.img;
    const int w = si.cols, h = si.rows;
    std::ostringstream where;
    where << "frame " << src.frame << " (" << w << "x" << h << ", " << kLanes << " lanes, skew " << fr.skew << ", lead "
          << fr.lead << "), input slot " << src.index << " of lane " << src.index % kLanes;
    if (!src.active) {
      ASSERT_EQ(uint32_t(top->valid_o), 0u)
          << "field valid: " << where.str() << " is a waiting slot (active_i = 0, driven (" << src.col << ", "
          << src.row << ")): expected 0, got 1";
      continue;
    }
    const int cx = src.col >= 4 ? src.col - 4 : w + src.col - 4;
    const int cy = src.col >= 4 ? src.row - kRy : src.row - kRy - kLanes;
    const bool inside = cy >= 0 && cy < h;
    where << " at (" << src.col << ", " << src.row << ") -> centre";
    auto fail = [&](const std::string& field, const std::string& expected, const std::string& got) {
      return sgm::tb::firstMismatch(cx, cy, field, expected, got, where.str());
    };
    ASSERT_EQ(uint32_t(top->valid_o), uint32_t(inside))
        << fail("valid", std::to_string(inside), std::to_string(top->valid_o));
    if (!inside) continue;
    ASSERT_EQ(uint32_t(top->col_o), uint32_t(cx))
        << fail("position (col_o)", std::to_string(cx), std::to_string(top->col_o));
    ASSERT_EQ(uint32_t(top->row_o), uint32_t(cy))
        << fail("position (row_o)", std::to_string(cy), std::to_string(top->row_o));
    const size_t i = size_t(cy) * w + cx;
    ASSERT_EQ(seen[src.frame][i], 0) << fail("valid", "one output per pixel", "a second one");
    seen[src.frame][i] = 1;
    const sgm::Census& g = golden[src.frame][i];
    const auto [censusWant, censusGot] = censusHex(top->census_o, g);
    ASSERT_EQ(censusGot, censusWant) << fail("census", censusWant, censusGot);
    ASSERT_EQ(int(top->rank_o), g.rank()) << fail("rank", std::to_string(g.rank()), std::to_string(top->rank_o));
    ASSERT_EQ(int(top->centre_o), int(si.at<uint8_t>(cy, cx)))
        << fail("centre", std::to_string(si.at<uint8_t>(cy, cx)), std::to_string(top->centre_o));
    // Neighbours 0, 45, 90, 135 degrees; only those inside the frame are defined.
    const int nx[4] = {cx - 1, cx - 1, cx, cx + 1}, ny[4] = {cy, cy - 1, cy - 1, cy - 1};
    static const char* const kNames[4] = {"neighbour 0 deg (x-1, y)", "neighbour 45 deg (x-1, y-1)",
                                          "neighbour 90 deg (x, y-1)", "neighbour 135 deg (x+1, y-1)"};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || nx[k] >= w || ny[k] < 0) continue;
      const int want = si.at<uint8_t>(ny[k], nx[k]), got = int((top->nbr_o >> (8 * k)) & 0xff);
      ASSERT_EQ(got, want) << fail(kNames[k], std::to_string(want), std::to_string(got));
    }
  }
  for (size_t f = 0; f < frames.size(); ++f) {
    const long n = std::count(seen[f].begin(), seen[f].end(), 1);
    ASSERT_EQ(n, long(frames[f].img.total())) << "frame " << f << ": valid centres";
  }
}

cv::Mat randomImage(int w, int h, std::mt19937& rng, int levels = 256) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int v = int(rng() % uint32_t(levels));
      img.at<uint8_t>(y, x) = uint8_t(levels == 256 ? v : v * 255 / (levels - 1));
    }
  return img;
}

Frame frame(cv::Mat img, int skew, int lead, int extra, Waiting waiting) {
  Frame f;
  f.img = std::move(img);
  f.skew = skew;
  f.lead = lead;
  f.extra = extra;
  f.waiting = waiting;
  return f;
}

TEST(SgmCensusUnitLanes, SeveralSizesOneStream) {
  // The narrowest frame of each skew, odd and even heights, the widest frame;
  // leads 0 (lane k starts at row k), 1 and K + 1, no extra
  // slots between frames, then a few.
  std::mt19937 rng(20250301);
  const int skews[] = {1, 3, 2, 4, 3, 1, 3};
  const int heights[] = {9, 10, 11, 13, 9, 17, 12};
  const int leads[] = {0, 1, kLanes + 1, 0, 2, kLanes + 1, 0};
  std::vector<Frame> frames;
  for (int i = 0; i < 7; ++i) {
    const int w = i == 3   ? std::max(minWidth(skews[i]), std::min(37, kMaxWidth))
                  : i == 5 ? kMaxWidth
                           : minWidth(skews[i]);
    if (w > kMaxWidth) continue;
    frames.push_back(frame(randomImage(w, heights[i], rng), skews[i], leads[i], i < 3 ? 0 : int(rng() % 50),
                           i % 2 ? Waiting::kLaneDeal : Waiting::kJunk));
  }
  ASSERT_NO_FATAL_FAILURE(runStream("sgm_census_unit_lanes_sizes", frames, 7));
}

TEST(SgmCensusUnitLanes, RandomFramesBackToBack) {
  // 14 frames of random size, skew, lead and gap in one stream, twice.
  std::mt19937 rng(4711);
  for (uint32_t seed : {21u, 22u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<Frame> frames;
    for (int i = 0; i < 14; ++i) {
      const int skew = 1 + int(rng() % 4);
      if (minWidth(skew) > kMaxWidth) continue;
      const int w = minWidth(skew) + int(rng() % uint32_t(kMaxWidth - minWidth(skew) + 1));
      const int h = 9 + int(rng() % 22);
      const int lead = int(rng() % uint32_t(kLanes + 3));
      const int extra = rng() % 3 ? int(rng() % uint32_t(2 * kLanes * w)) : 0;
      frames.push_back(
          frame(randomImage(w, h, rng), skew, lead, extra, rng() % 2 ? Waiting::kJunk : Waiting::kLaneDeal));
    }
    ASSERT_NO_FATAL_FAILURE(runStream("sgm_census_unit_lanes_random", frames, seed));
  }
}

TEST(SgmCensusUnitLanes, FewGrayLevelsAndFlat) {
  // Ties (bit = I(q) < I(p) is strict), flat and saturated frames after a textured one.
  std::mt19937 rng(99);
  const int w = std::min(kMaxWidth, std::max(minWidth(3), 29));
  std::vector<Frame> frames = {frame(randomImage(w, 14, rng, 2), 3, 0, 0, Waiting::kJunk),
                               frame(randomImage(w, 11, rng, 3), 3, 1, 5, Waiting::kJunk),
                               frame(cv::Mat(9, minWidth(2), CV_8UC1, cv::Scalar(255)), 2, 0, 0, Waiting::kJunk),
                               frame(cv::Mat(10, w, CV_8UC1, cv::Scalar(0)), 3, kLanes + 1, 0, Waiting::kLaneDeal),
                               frame(randomImage(w, 9, rng), 3, 0, 0, Waiting::kJunk)};
  ASSERT_NO_FATAL_FAILURE(runStream("sgm_census_unit_lanes_ties", frames, 5));
}

TEST(SgmCensusUnitLanes, HeavyStallsAndNoStalls) {
  std::mt19937 rng(8);
  const int w = std::min(kMaxWidth, std::max(minWidth(3), 33));
  const cv::Mat a = randomImage(w, 15, rng), b = randomImage(minWidth(3), 9, rng);
  for (int idle : {0, 70}) {
    SCOPED_TRACE("idle " + std::to_string(idle) + "%");
    const std::vector<Frame> frames = {frame(a, 3, 0, 0, Waiting::kJunk), frame(b, 3, 1, 0, Waiting::kJunk),
                                       frame(a, 3, kLanes + 1, 3, Waiting::kLaneDeal)};
    ASSERT_NO_FATAL_FAILURE(runStream("sgm_census_unit_lanes_stalls", frames, 11 + idle, idle));
  }
}

}  // namespace
