// sgm_lr_check against the golden sgm::selectDisparity (its disp and valid
// planes; docs/algorithm.md section 7). S volumes are streamed slot by slot in
// raster order on the S side; the WTA side carries the golden winnerTakeAll /
// subpixelOffset result of the same pixel `lag` enabled slots later (as
// sgm_wta delivers it). Frames follow each other without reset, each with
// flush slots (rows >= height) until its last output has left; en_i is toggled
// by a seeded random pattern (all inputs are junk while en_i = 0). Every
// enabled slot's outputs are checked against the latency contract (one row +
// LATENCY: position, out_valid_o), every pixel's disp and valid against the
// golden model, and the outputs must hold while en_i = 0. The build's D / SW /
// DW / MAX_WIDTH / LATENCY come from the model (public parameters).
#include "Vsgm_lr_check.h"
#include "Vsgm_lr_check_sgm_lr_check.h"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/disparity.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_lr_check>;
using Rtl = Vsgm_lr_check_sgm_lr_check;  // public parameters of the build

constexpr int kD = int(Rtl::D);
constexpr int kSW = int(Rtl::SW);
constexpr int kDW = int(Rtl::DW);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kCW = int(Rtl::CW);
constexpr int kRW = int(Rtl::RW);
constexpr int kLatency = int(Rtl::LATENCY);
constexpr int kMaxS = (1 << kSW) - 1;
constexpr int kMinWidth = kD > 16 ? kD : 16;

constexpr int log2Ceil(int n) { return n <= 1 ? 0 : 1 + log2Ceil((n + 1) / 2); }
constexpr int kWtaLatency = (log2Ceil(kD) + 1) / 2 + 3;  // sgm_wta's LATENCY for this D

struct Frame {
  sgm::PathVolume s;
  int tol = 1;  // < 0: check off
  bool subpixel = true;
  std::string name;
  int flushRows = 0;  // flush slots = width + LATENCY - 1 (the minimum) + flushRows * width
};

std::string describe(const Frame& f) {
  std::ostringstream o;
  o << "frame '" << f.name << "' " << f.s.width << "x" << f.s.height << " tolerance "
    << (f.tol < 0 ? std::string("off") : std::to_string(f.tol)) << " sub-pixel " << (f.subpixel ? "on" : "off")
    << " (D=" << kD << ", MAX_WIDTH=" << kMaxWidth << ", LATENCY=1 row + " << kLatency << ")";
  return o.str();
}

sgm::Params paramsOf(const Frame& f) {
  sgm::Params p;
  p.disparities = kD;
  p.subpixel = f.subpixel;
  p.lrTolerance = f.tol;
  return p;
}

// Golden WTA result (the WTA-side input) of every pixel of a frame.
struct Wta {
  std::vector<int> d, disp;
};
Wta goldenWta(const Frame& f) {
  Wta w;
  for (int y = 0; y < f.s.height; ++y)
    for (int x = 0; x < f.s.width; ++x) {
      const uint16_t* s = f.s.at(x, y);
      const int d = sgm::winnerTakeAll(s, kD);
      int disp = d * sgm::kSubpixelOne;
      if (f.subpixel && d > 0 && d < kD - 1) disp += sgm::subpixelOffset(s[d - 1], s[d], s[d + 1]);
      w.d.push_back(d);
      w.disp.push_back(disp);
    }
  return w;
}

template <typename Port>
void packS(Port& port, const uint16_t* s) {
  uint32_t words[(kD * kSW + 31) / 32 + 1] = {};
  for (int d = 0; d < kD; ++d) {
    const int bit = d * kSW;
    const uint64_t v = uint64_t(s[d]) << (bit % 32);
    words[bit / 32] |= uint32_t(v);
    words[bit / 32 + 1] |= uint32_t(v >> 32);
  }
  for (int w = 0; w < (kD * kSW + 31) / 32; ++w) sgm::tb::setWord(port, w, words[w]);
}

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

// Streams the frames back to back on one model (reset once); the WTA side lags
// the S side by `lag` enabled slots. Stops at the first mismatch.
void runFrames(Top& top, const std::vector<Frame>& frames, uint32_t seed, int lag, double onRate = 0.7) {
  std::mt19937 junk(seed ^ 0x9e3779b9u);
  EnablePattern en(seed, onRate);
  std::vector<uint16_t> junkS(kD);
  auto junkVector = [&] {
    for (auto& v : junkS) v = uint16_t(junk() & kMaxS);
    return junkS.data();
  };
  auto randomInputs = [&] {
    packS(top->s_i, junkVector());
    top->col_i = junk() & ((1u << kCW) - 1);
    top->row_i = junk() & ((1u << kRW) - 1);
    top->valid_i = junk() & 1;
    top->width_i = junk() & ((1u << kCW) - 1);
    top->height_i = junk() & ((1u << kRW) - 1);
    top->tol_i = junk() & 7;
    top->check_en_i = junk() & 1;
    top->d_i = junk() % kD;
    top->disp_i = junk() & ((1u << kDW) - 1);
    top->wta_col_i = junk() & ((1u << kCW) - 1);
    top->wta_row_i = junk() & ((1u << kRW) - 1);
    top->wta_valid_i = junk() & 1;
  };
  std::vector<Wta> wta;
  std::vector<sgm::DisparityMap> want;
  std::vector<int> received(frames.size(), 0);
  for (const Frame& f : frames) {
    ASSERT_EQ(f.s.depth, kD) << describe(f);
    ASSERT_LE(f.s.width, kMaxWidth) << describe(f);
    ASSERT_GE(f.s.width, kMinWidth) << describe(f);
    ASSERT_LT(f.s.height + 2 + f.flushRows, 1 << kRW) << describe(f);
    ASSERT_LE(lag, f.s.width - 1) << describe(f) << ": the WTA side may lag by at most width - 1 slots";
    ASSERT_LE(*std::max_element(f.s.data.begin(), f.s.data.end()), kMaxS) << describe(f) << ": S exceeds SW bits";
    wta.push_back(goldenWta(f));
    want.push_back(sgm::selectDisparity(f.s, paramsOf(f)));
  }

  struct Slot {
    int frame, x, y;
    bool real;
  };
  std::vector<Slot> history;  // every enabled S-side slot, in order
  top->en_i = 0;
  randomInputs();
  top.reset();
  ASSERT_EQ(int(top->out_valid_o), 0) << "out_valid_o after reset";
  Outputs held = outputs(top);

  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const Frame& f = frames[fi];
    const int w = f.s.width, h = f.s.height;
    const long slots = long(w) * h + w + kLatency - 1 + long(f.flushRows) * w;
    for (long n = 0; n < slots;) {
      if (!en.next()) {
        randomInputs();
        top->en_i = 0;
        top.tick();
        ASSERT_TRUE(outputs(top) == held) << describe(f) << ": outputs changed while en_i = 0";
        continue;
      }
      const int x = int(n % w), y = int(n / w);
      const bool real = y < h;
      top->en_i = 1;
      packS(top->s_i, real ? f.s.at(x, y) : junkVector());  // flush slots: junk S
      top->col_i = x;
      top->row_i = y;
      top->valid_i = real;
      top->width_i = w;
      top->height_i = h;
      top->tol_i = f.tol < 0 ? junk() & 7 : f.tol;
      top->check_en_i = f.tol >= 0;
      history.push_back({int(fi), x, y, real});
      // WTA side: the slot `lag` enabled slots earlier.
      const long ws = long(history.size()) - 1 - lag;
      if (ws >= 0 && history[ws].real) {
        const Slot& s = history[ws];
        const size_t i = size_t(s.y) * frames[s.frame].s.width + s.x;
        top->d_i = wta[s.frame].d[i];
        top->disp_i = wta[s.frame].disp[i];
        top->wta_col_i = s.x;
        top->wta_row_i = s.y;
        top->wta_valid_i = 1;
      } else {
        top->d_i = junk() % kD;
        top->disp_i = junk() & ((1u << kDW) - 1);
        top->wta_col_i = ws >= 0 ? history[ws].x : 0;
        top->wta_row_i = ws >= 0 ? history[ws].y : 0;
        top->wta_valid_i = 0;
      }
      top.tick();
      held = outputs(top);
      ++n;

      // The outputs after enabled slot t belong to the S slot t - (LATENCY - 1),
      // which carries left pixel (x, y - 1) of its frame when 1 <= y <= height.
      const long src = long(history.size()) - kLatency;
      const bool expectOut =
          src >= 0 && history[src].y >= 1 && history[src].y <= frames[history[src].frame].s.height;
      ASSERT_EQ(bool(top->out_valid_o), expectOut)
          << describe(f) << ": out_valid_o at S slot " << history.size() - 1 << " [stage: output framing]";
      if (!expectOut) continue;
      const Slot& s = history[src];
      const Frame& sf = frames[s.frame];
      const int ox = s.x, oy = s.y - 1;
      ASSERT_EQ(int(top->col_o), ox) << describe(sf) << ": col_o of pixel (" << ox << ", " << oy << ")";
      ASSERT_EQ(int(top->row_o), oy) << describe(sf) << ": row_o of pixel (" << ox << ", " << oy << ")";
      ++received[s.frame];
      const sgm::DisparityMap& m = want[s.frame];
      const int ed = m.disp.at<uint16_t>(oy, ox), ev = m.valid.at<uint8_t>(oy, ox);
      const int gd = int(top->disp_o), gv = int(top->valid_o);
      if (ed != gd || ev != gv) {
        const int d = wta[s.frame].d[size_t(oy) * sf.s.width + ox];
        std::ostringstream ctx;
        ctx << "d* = " << d << ", x - d* = " << ox - d;
        if (ox - d >= 0) ctx << ", golden dR(x - d*) = " << sgm::rightDisparity(sf.s, ox - d, oy);
        FAIL() << "first mismatch at (x, y) = (" << ox << ", " << oy << ") of " << describe(sf)
               << ": expected disp " << ed << " valid " << ev << ", got disp " << gd << " valid " << gv
               << " [stage: " << (ed != gd ? "left result memory (disp)" : "left-right check (valid)") << "; "
               << ctx.str() << "]";
      }
    }
  }
  for (size_t fi = 0; fi < frames.size(); ++fi)
    EXPECT_EQ(received[fi], frames[fi].s.width * frames[fi].s.height) << describe(frames[fi]) << ": pixels output";
}

// ------------------------------------------------------------------ volumes

sgm::PathVolume randomVolume(int w, int h, int maxValue, std::mt19937& rng) {
  sgm::PathVolume v(w, h, kD);
  std::uniform_int_distribution<int> value(0, maxValue);
  for (auto& s : v.data) s = uint16_t(value(rng));
  return v;
}

// A scene-like S: per row, runs of constant true disparity (foreground runs
// over a background, so that pixels are occluded and the check fails there),
// S(x, d) = slope * |d - dt(x)| + noise, clipped to SW bits. The true
// disparities include 0 and D-1; `flat` >= 0 gives every pixel dt = flat.
sgm::PathVolume sceneVolume(int w, int h, std::mt19937& rng, int flat = -1) {
  sgm::PathVolume v(w, h, kD);
  std::uniform_int_distribution<int> noise(0, 24);
  for (int y = 0; y < h; ++y) {
    std::vector<int> dt(w);
    const int background = int(rng() % (kD / 2));
    for (int x = 0; x < w;) {
      const int len = 3 + int(rng() % (w / 3));
      const int pick = int(rng() % 8);
      const int d = pick == 0 ? 0 : pick == 1 ? kD - 1 : pick < 5 ? background : int(rng() % kD);
      for (int i = 0; i < len && x < w; ++i, ++x) dt[x] = flat >= 0 ? flat : d;
    }
    for (int x = 0; x < w; ++x)
      for (int d = 0; d < kD; ++d)
        v.at(x, y)[d] = uint16_t(std::min(kMaxS, 30 * std::abs(d - dt[x]) + noise(rng)));
  }
  return v;
}

// ------------------------------------------------------------------ synthetic

TEST(SgmLrCheck, SceneTolerances) {
  Top top("sgm_lr_check_scene");
  std::mt19937 rng(21);
  runFrames(top,
            {{sceneVolume(kMaxWidth, 12, rng), 1, true, "scene tol 1"},
             {sceneVolume(kMaxWidth, 12, rng), 0, true, "scene tol 0"},
             {sceneVolume(kMaxWidth, 12, rng), -1, true, "scene check off"},
             {sceneVolume(kMaxWidth, 12, rng), 3, false, "scene tol 3 integer"},
             {sceneVolume(kMaxWidth, 12, rng), 7, true, "scene tol 7"}},
            211, kWtaLatency);
}

TEST(SgmLrCheck, RandomCostsManyTies) {
  Top top("sgm_lr_check_ties");
  std::mt19937 rng(22);
  runFrames(top,
            {{randomVolume(kMaxWidth, 9, 1, rng), 0, true, "values 0..1 tol 0"},
             {randomVolume(std::min(kMaxWidth, kMinWidth + 45), 11, 3, rng), 1, true, "values 0..3 tol 1"},
             {randomVolume(kMinWidth + 3, 9, 2, rng), 1, false, "values 0..2 tol 1"},
             {randomVolume(kMaxWidth - 1, 9, kMaxS, rng), 1, true, "full range tol 1"},
             {randomVolume(kMaxWidth, 7, 3, rng), 2, true, "values 0..3 tol 2"}},
            212, kWtaLatency);
}

// Width = max(D, 16), the narrowest frame: with d* = 0 the right-border
// (tail) dR words are read exactly one slot after they are written.
TEST(SgmLrCheck, NarrowestWidthRightBorder) {
  Top top("sgm_lr_check_narrow");
  std::mt19937 rng(23);
  runFrames(top,
            {{sceneVolume(kMinWidth, 10, rng, 0), 0, true, "narrow, all d = 0"},
             {sceneVolume(kMinWidth, 10, rng, kD - 1), 0, true, "narrow, all d = D-1"},
             {sceneVolume(kMinWidth, 10, rng), 1, true, "narrow scene"},
             {randomVolume(kMinWidth, 10, 3, rng), 0, true, "narrow ties"}},
            213, kWtaLatency);
}

// Frames of one and two rows, and the WTA-side lag from 0 to width - 1.
TEST(SgmLrCheck, ShortFramesAndWtaLag) {
  std::mt19937 rng(24);
  for (int lag : {0, 1, kWtaLatency, kMinWidth - 1}) {
    Top top("sgm_lr_check_lag");
    runFrames(top,
              {{sceneVolume(kMinWidth, 1, rng), 1, true, "one row, lag " + std::to_string(lag)},
               {sceneVolume(kMinWidth + 5, 2, rng), 0, true, "two rows, lag " + std::to_string(lag)},
               {sceneVolume(kMaxWidth, 6, rng), 1, true, "wide, lag " + std::to_string(lag)}},
              214 + lag, lag);
  }
}

// Two frames (then more) of different sizes and settings, no reset between
// them, minimal and generous flushes.
TEST(SgmLrCheck, BackToBackFramesOfDifferentSizes) {
  Top top("sgm_lr_check_b2b");
  std::mt19937 rng(25);
  std::vector<Frame> frames = {{sceneVolume(kMaxWidth, 13, rng), 1, true, "first"},
                               {sceneVolume(kMinWidth + 1, 9, rng), 0, false, "second"},
                               {randomVolume(std::min(kMaxWidth, kMinWidth + 61), 10, 3, rng), -1, true, "third"},
                               {sceneVolume(kMaxWidth - 8, 11, rng), 1, true, "fourth"},
                               {sceneVolume(kMinWidth, 8, rng), 1, true, "fifth"}};
  frames[2].flushRows = 2;
  runFrames(top, frames, 215, kWtaLatency);
}

TEST(SgmLrCheck, EnablePatterns) {
  std::mt19937 rng(26);
  for (double rate : {0.05, 0.5, 1.0}) {
    Top top("sgm_lr_check_en");
    runFrames(top, {{sceneVolume(kMinWidth + 13, 8, rng), 1, true, "en rate " + std::to_string(rate)}}, 216,
              kWtaLatency, rate);
  }
}

// Many random frames of random sizes, contents and settings back to back, with
// the WTA side at sgm_wta's latency and at lag 0.
TEST(SgmLrCheck, RandomSoak) {
  std::mt19937 rng(27);
  for (int lag : {kWtaLatency, 0}) {
    std::vector<Frame> frames;
    for (int i = 0; i < 30; ++i) {
      const int w = kMinWidth + int(rng() % (kMaxWidth - kMinWidth + 1)), h = 1 + int(rng() % 12);
      const int tol = int(rng() % 9) - 1;
      Frame f{rng() % 2 ? sceneVolume(w, h, rng) : randomVolume(w, h, int(rng() % 8), rng), tol, bool(rng() % 4 != 0),
              "soak " + std::to_string(i) + " lag " + std::to_string(lag)};
      f.flushRows = int(rng() % 3);
      frames.push_back(std::move(f));
    }
    Top top("sgm_lr_check_soak");
    runFrames(top, frames, 217 + lag, lag);
  }
}

// ------------------------------------------------------------------ Middlebury cones

const sgm::PipelineStages* conesStages(std::string& why) {
  static std::map<int, sgm::PipelineStages> cache;
  const char* root = std::getenv("SGM_DATA");
  const std::string dir = std::string(root ? root : "") + "/cones";
  if (!root || !std::filesystem::exists(dir + "/left.png") || !std::filesystem::exists(dir + "/right.png")) {
    why = "Middlebury cones not found at '" + dir + "' (set SGM_DATA, e.g. via make rtl-tests DATA=...)";
    return nullptr;
  }
  auto it = cache.find(kD);
  if (it == cache.end()) {
    sgm::Params params;
    params.disparities = kD;
    it = cache.emplace(kD, sgm::runPipelineStages(sgm::readGray(dir + "/left.png"), sgm::readGray(dir + "/right.png"),
                                                  params)).first;
  }
  return &it->second;
}

// Columns x0 .. x0 + w - 1, rows y0 .. y0 + h - 1 of a volume.
sgm::PathVolume crop(const sgm::PathVolume& v, int x0, int y0, int w, int h) {
  sgm::PathVolume c(w, h, v.depth);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) std::copy(v.at(x0 + x, y0 + y), v.at(x0 + x, y0 + y) + v.depth, c.at(x, y));
  return c;
}

// The aggregated cones volume of this build's D, cut into MAX_WIDTH-wide
// tiles (left border, middle, right border), through the check with tolerance
// 1, 0 and off; the full-frame golden selection (default parameters) must
// also agree with selectDisparity on the whole volume.
TEST(SgmLrCheck, Cones) {
  std::string why;
  const sgm::PipelineStages* st = conesStages(why);
  if (!st) GTEST_SKIP() << why;
  const sgm::PathVolume& s = st->aggregated;
  {
    sgm::Params p;
    p.disparities = kD;
    const sgm::DisparityMap whole = sgm::selectDisparity(s, p);
    ASSERT_EQ(cv::countNonZero(whole.disp != st->selected.disp), 0) << "golden selection stage disagreement";
    ASSERT_EQ(cv::countNonZero(whole.valid != st->selected.valid), 0) << "golden selection stage disagreement";
  }
  const int w = std::min(kMaxWidth, s.width), h = s.height;
  std::vector<Frame> frames;
  const int tols[] = {1, 0, -1};
  int k = 0;
  for (int x0 : {0, (s.width - w) / 2, s.width - w}) {
    const int y0 = (k * 97) % (s.height - h + 1);
    const int tol = tols[k++ % 3];
    frames.push_back({crop(s, x0, y0, w, h), tol, true,
                      "cones D=" + std::to_string(kD) + " columns " + std::to_string(x0) + ".., rows " +
                          std::to_string(y0) + ".."});
  }
  frames.push_back({crop(s, s.width - w, s.height - h, w, h), 0, false, "cones bottom right, integer"});
  Top top("sgm_lr_check_cones");
  runFrames(top, frames, 700 + kD, kWtaLatency, 0.8);
}

}  // namespace
