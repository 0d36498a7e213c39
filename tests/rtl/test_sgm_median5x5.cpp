// sgm_median5x5 against the golden sgm::median5x5 (docs/algorithm.md section 9).
// Frames are streamed slot by slot in raster order, each followed by flush slots
// until its last output has left, back to back without reset, with en_i toggled
// by a seeded random pattern (inputs are random junk while en_i = 0). Every
// output slot is checked against the latency contract (position and
// out_valid_o), every pixel's disp and valid against the golden model, and the
// outputs must hold while en_i = 0. The build's DW / MAX_WIDTH / LATENCY come
// from the model (public parameters), so the same file serves every config.
#include "Vsgm_median5x5.h"
#include "Vsgm_median5x5_sgm_median5x5.h"
#include "verilated_top.hpp"

#include "sgm/disparity.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_median5x5>;
using Rtl = Vsgm_median5x5_sgm_median5x5;  // public parameters of the build
using sgm::DisparityMap;

constexpr int kDW = int(Rtl::DW);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kMaxDisp = (1 << kDW) - 1;
constexpr int kRowMask = (1 << int(Rtl::RW)) - 1;
const char* const kStage = "5x5 median (sgm_median5x5)";

// Total latency in slots for a frame of width w.
int latency(int w) { return int(Rtl::LATENCY_ROWS) * w + int(Rtl::LATENCY); }

struct Frame {
  DisparityMap map;
  bool enable = true;
  std::string name;
};

DisparityMap blankMap(int w, int h) {
  return DisparityMap{cv::Mat(h, w, CV_16UC1, cv::Scalar(0)), cv::Mat(h, w, CV_8UC1, cv::Scalar(0))};
}

// Random disparities (full DW range, also under invalid pixels) with validity
// probability `density`.
DisparityMap randomMap(int w, int h, double density, std::mt19937& rng) {
  DisparityMap m = blankMap(w, h);
  std::uniform_int_distribution<int> value(0, kMaxDisp);
  std::bernoulli_distribution valid(density);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      m.disp.at<uint16_t>(y, x) = uint16_t(value(rng));
      m.valid.at<uint8_t>(y, x) = valid(rng);
    }
  return m;
}

// Few distinct values (many ties, the extremes 0 and 2^DW - 1) under a
// validity pattern with structure: invalid blocks, an invalid column band,
// isolated valid pixels, checkerboards, invalid first / valid last row.
DisparityMap patternMap(int w, int h, std::mt19937& rng) {
  DisparityMap m = randomMap(w, h, 0.7, rng);
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

DisparityMap expected(const Frame& f) { return f.enable ? sgm::median5x5(f.map) : f.map; }

std::string describe(const Frame& f) {
  std::ostringstream s;
  s << "frame '" << f.name << "' " << f.map.disp.cols << "x" << f.map.disp.rows << " median " << (f.enable ? "on" : "off")
    << " (DW=" << kDW << ", MAX_WIDTH=" << kMaxWidth << ")";
  return s.str();
}

// Snapshot of every output port, to check that en_i = 0 holds them.
struct Outputs {
  uint32_t disp, valid, col, row, outValid;
  bool operator==(const Outputs& o) const {
    return disp == o.disp && valid == o.valid && col == o.col && row == o.row && outValid == o.outValid;
  }
};
Outputs outputs(Top& top) {
  return {uint32_t(top->disp_o), uint32_t(top->valid_o), uint32_t(top->col_o), uint32_t(top->row_o),
          uint32_t(top->out_valid_o)};
}

// Enable pattern: mostly on, single-cycle gaps and occasional long stalls.
class EnablePattern {
 public:
  EnablePattern(uint32_t seed, double onRate) : rng_(seed), on_(onRate) {}
  bool next() {
    if (stall_ > 0) return --stall_, false;
    if (std::bernoulli_distribution(0.002)(rng_)) stall_ = int(rng_() % 40);
    return on_(rng_);
  }

 private:
  std::mt19937 rng_;
  std::bernoulli_distribution on_;
  int stall_ = 0;
};

// Streams the frames back to back on one model and checks everything. Before
// each frame's first slot come, as in the core, (1) slots of the previous frame
// still in flight upstream: they continue its flush raster (not real) but
// arrive after the switch, with the new frame's width / height / enable, and
// (2) the new frame's lead-in: the raster slots just before (0, 0), negative
// rows wrapped to RW bits, not real.
void runFrames(Top& top, const std::vector<Frame>& frames, uint32_t seed, double onRate = 0.7) {
  std::mt19937 junk(seed ^ 0x9e3779b9u);
  EnablePattern en(seed, onRate);
  auto randomInputs = [&] {
    top->disp_i = junk() & kMaxDisp;
    top->valid_i = junk() & 1;
    top->in_valid_i = junk() & 1;
    top->col_i = junk() % (kMaxWidth + 1);
    top->row_i = junk() & kRowMask;
    top->width_i = junk() % (kMaxWidth + 1);
    top->height_i = junk() & kRowMask;
    top->median_en_i = junk() & 1;
  };
  // Input position of every enabled slot: frame index and (x, y).
  struct Slot {
    int frame, x, y;
    bool real;
  };
  std::vector<Slot> history;
  top->en_i = 0;
  randomInputs();
  top.reset();
  Outputs held = outputs(top);

  // State of the frame being streamed.
  int fi = 0, w = 0, h = 0, lat = 0, received = 0;
  DisparityMap got;
  cv::Mat seen;

  // One enabled slot (after the disabled cycles the pattern asks for), then the output checks.
  auto slot = [&](int x, int y, bool real, int disp, int valid) {
    const Frame& f = frames[fi];
    while (!en.next()) {
      randomInputs();
      top->en_i = 0;
      top.tick();
      ASSERT_TRUE(outputs(top) == held) << describe(f) << ": outputs changed while en_i = 0";
    }
    top->en_i = 1;
    top->col_i = x;
    top->row_i = y & kRowMask;
    top->width_i = w;
    top->height_i = h;
    top->median_en_i = f.enable;
    top->in_valid_i = real;
    top->disp_i = disp;
    top->valid_i = valid;
    top.tick();
    history.push_back({fi, x, y, real});
    held = outputs(top);

    // The output after slot s belongs to the input of slot s - (latency - 1).
    const long src = long(history.size()) - lat;
    const bool expectOut = src >= 0 && history[src].frame == fi && history[src].real;
    ASSERT_EQ(bool(top->out_valid_o), expectOut)
        << describe(f) << ": out_valid_o at slot " << history.size() - 1 << " (latency " << lat << ")";
    if (!expectOut) return;
    const int ox = history[src].x, oy = history[src].y;
    ASSERT_EQ(int(top->col_o), ox) << describe(f) << ": col_o of pixel (" << ox << ", " << oy << ")";
    ASSERT_EQ(int(top->row_o), oy) << describe(f) << ": row_o of pixel (" << ox << ", " << oy << ")";
    ASSERT_FALSE(seen.at<uint8_t>(oy, ox)) << describe(f) << ": pixel (" << ox << ", " << oy << ") output twice";
    seen.at<uint8_t>(oy, ox) = 1;
    got.disp.at<uint16_t>(oy, ox) = uint16_t(top->disp_o);
    got.valid.at<uint8_t>(oy, ox) = uint8_t(top->valid_o);
    ++received;
  };

  int prevX = 0, prevY = 0, prevW = 0;  // next raster position of the previous frame
  for (; fi < int(frames.size()); ++fi) {
    const Frame& f = frames[fi];
    w = f.map.disp.cols, h = f.map.disp.rows, lat = latency(w), received = 0;
    ASSERT_LE(w, kMaxWidth) << describe(f);
    ASSERT_GE(w, 16) << describe(f);
    ASSERT_GE(h, 9) << describe(f);
    const DisparityMap want = expected(f);
    got = blankMap(w, h);
    seen = cv::Mat(h, w, CV_8UC1, cv::Scalar(0));

    if (fi > 0) {  // the previous frame's slots still in flight upstream
      for (int n = int(junk() % (3 * prevW + 1)); n > 0; --n) {
        slot(prevX, prevY, false, junk() & kMaxDisp, junk() & 1);
        if (::testing::Test::HasFatalFailure()) return;
        if (++prevX == prevW) prevX = 0, ++prevY;
      }
    }
    for (int p = -int(junk() % (2 * w + 1)); p < 0; ++p) {  // lead-in, negative rows
      const int y = -((-p + w - 1) / w), x = p - y * w;
      slot(x, y, false, junk() & kMaxDisp, junk() & 1);
      if (::testing::Test::HasFatalFailure()) return;
    }
    int x = 0, y = 0;
    for (; received < w * h; x = x + 1 == w ? 0 : x + 1, y += x == 0) {
      ASSERT_LT(y, h + 4) << describe(f) << ": outputs missing after " << y - h << " flush rows (" << received << " of "
                          << w * h << " received)";
      const bool real = y < h;  // flush slots carry junk the module must ignore
      slot(x, y, real, real ? f.map.disp.at<uint16_t>(y, x) : junk() & kMaxDisp,
           real ? f.map.valid.at<uint8_t>(y, x) : junk() & 1);
      if (::testing::Test::HasFatalFailure()) return;
    }
    prevX = x, prevY = y, prevW = w;

    // First mismatch in raster order.
    int mismatches = 0;
    std::ostringstream first;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int ed = want.disp.at<uint16_t>(y, x), ev = want.valid.at<uint8_t>(y, x);
        const int gd = got.disp.at<uint16_t>(y, x), gv = got.valid.at<uint8_t>(y, x);
        if (ed == gd && ev == gv) continue;
        if (mismatches++ == 0)
          first << "first mismatch at (x, y) = (" << x << ", " << y << "): expected disp " << ed << " valid " << ev
                << ", got disp " << gd << " valid " << gv << " (input disp " << f.map.disp.at<uint16_t>(y, x)
                << " valid " << int(f.map.valid.at<uint8_t>(y, x)) << ")";
      }
    EXPECT_EQ(mismatches, 0) << kStage << ", " << describe(f) << ": " << first.str() << "; " << mismatches
                             << " mismatching pixels";
  }
}

// ------------------------------------------------------------------ synthetic

TEST(SgmMedian5x5, SmallestFrameAllDensities) {
  Top top("sgm_median5x5_densities");
  std::mt19937 rng(1);
  std::vector<Frame> frames;
  for (double d : {0.0, 0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 1.0})
    frames.push_back({randomMap(16, 9, d, rng), true, "16x9 " + std::to_string(int(d * 100 + 0.5)) + "% valid"});
  runFrames(top, frames, 101);
}

TEST(SgmMedian5x5, TiesAndValidityPatterns) {
  Top top("sgm_median5x5_patterns");
  std::mt19937 rng(2);
  runFrames(top,
            {{patternMap(16, 9, rng), true, "patterns 16x9"},
             {patternMap(16, 12, rng), true, "patterns 16x12"},
             {patternMap(37, 24, rng), true, "patterns 37"},
             {patternMap(kMaxWidth, 36, rng), true, "patterns max width"},
             {patternMap(kMaxWidth - 1, 13, rng), true, "patterns max width - 1"}},
            202);
}

TEST(SgmMedian5x5, OddSizes) {
  Top top("sgm_median5x5_odd");
  std::mt19937 rng(3);
  std::vector<Frame> frames;
  for (auto [w, h] : {std::pair{17, 9}, {23, 11}, {31, 15}, {45, 13}, {kMaxWidth - 3, 9}})
    for (double d : {0.1, 0.6})
      frames.push_back({randomMap(w, h, d, rng), true, std::to_string(w) + "x" + std::to_string(h)});
  runFrames(top, frames, 303);
}

TEST(SgmMedian5x5, PassThroughWhenDisabled) {
  Top top("sgm_median5x5_off");
  std::mt19937 rng(4);
  runFrames(top,
            {{randomMap(16, 9, 0.3, rng), false, "off 16x9"},
             {patternMap(41, 12, rng), false, "off patterns"},
             {randomMap(kMaxWidth, 10, 0.0, rng), false, "off all invalid"}},
            404);
}

// Two frames of different sizes (and then more) with no reset in between.
TEST(SgmMedian5x5, BackToBackFramesOfDifferentSizes) {
  Top top("sgm_median5x5_b2b");
  std::mt19937 rng(5);
  runFrames(top,
            {{randomMap(kMaxWidth, 14, 0.4, rng), true, "first"},
             {patternMap(19, 11, rng), true, "second"},
             {randomMap(16, 9, 0.2, rng), false, "third (off)"},
             {randomMap(50, 10, 0.7, rng), true, "fourth"},
             {randomMap(16, 9, 0.5, rng), true, "fifth (smallest)"},
             {randomMap(kMaxWidth, 30, 0.5, rng), true, "sixth (wider and taller)"}},
            505);
}

// A long seeded sequence of frames of random size, density, structure and
// enable, back to back on one model.
TEST(SgmMedian5x5, RandomFrameSequence) {
  Top top("sgm_median5x5_sequence");
  std::mt19937 rng(7);
  std::vector<Frame> frames;
  for (int i = 0; i < 40; ++i) {
    const int w = 16 + int(rng() % (kMaxWidth - 15)), h = 9 + int(rng() % 24);
    const bool structured = rng() % 3 == 0, enable = rng() % 5 != 0;
    const double density = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    frames.push_back({structured ? patternMap(w, h, rng) : randomMap(w, h, density, rng), enable,
                      "sequence #" + std::to_string(i)});
  }
  runFrames(top, frames, 707);
}

TEST(SgmMedian5x5, EnablePatterns) {
  std::mt19937 rng(6);
  for (double rate : {0.05, 0.5, 1.0}) {
    Top top("sgm_median5x5_en");
    runFrames(top, {{patternMap(29, 12, rng), true, "en rate " + std::to_string(int(rate * 100 + 0.5)) + "%"}}, 606, rate);
  }
}

// ------------------------------------------------------------------ Middlebury cones

std::string conesDir() {
  const char* root = std::getenv("SGM_DATA");
  return std::string(root ? root : "") + "/cones";
}

// runPipelineStages on cones (default parameters, D disparities), once per D.
const sgm::PipelineStages* conesStages(int d, std::string& why) {
  static std::map<int, sgm::PipelineStages> cache;
  const std::string dir = conesDir();
  if (!std::getenv("SGM_DATA") || !std::filesystem::exists(dir + "/left.png") ||
      !std::filesystem::exists(dir + "/right.png")) {
    why = "Middlebury cones not found at '" + dir + "' (set SGM_DATA, e.g. via make rtl-tests DATA=...)";
    return nullptr;
  }
  auto it = cache.find(d);
  if (it == cache.end()) {
    sgm::Params params;
    params.disparities = d;
    it = cache.emplace(d, sgm::runPipelineStages(sgm::readGray(dir + "/left.png"), sgm::readGray(dir + "/right.png"),
                                                 params)).first;
  }
  return &it->second;
}

// The map itself when it fits MAX_WIDTH, else full-height tiles (left, middle, right).
std::vector<Frame> tiles(const DisparityMap& m, const std::string& name) {
  const int w = m.disp.cols;
  if (w <= kMaxWidth) return {{m, true, name}};
  std::vector<Frame> out;
  for (int x0 : {0, (w - kMaxWidth) / 2, w - kMaxWidth}) {
    const cv::Rect r(x0, 0, kMaxWidth, m.disp.rows);
    out.push_back({{m.disp(r).clone(), m.valid(r).clone()}, true, name + " columns " + std::to_string(x0) + ".."});
  }
  return out;
}

void runCones(int d) {
  if (d * 16 > kMaxDisp + 1) {
    int need = 0;
    while ((1 << need) < d * 16) ++need;
    GTEST_SKIP() << "D=" << d << " disparities need DW >= " << need << "; this build has DW=" << kDW
                 << " (the DW=" << need << " build runs it)";
  }
  std::string why;
  const sgm::PipelineStages* st = conesStages(d, why);
  if (!st) GTEST_SKIP() << why;
  Top top("sgm_median5x5_cones");
  runFrames(top, tiles(st->filled, "cones D=" + std::to_string(d) + " filled"), 700 + d);
}

TEST(SgmMedian5x5, ConesD16) { runCones(16); }
TEST(SgmMedian5x5, ConesD64) { runCones(64); }

}  // namespace
