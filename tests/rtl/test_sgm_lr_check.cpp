// SPDX-License-Identifier: Apache-2.0
// sgm_lr_check against the golden sgm::selectDisparity (its disp and valid
// planes; docs/algorithm.md section 7). S volumes are streamed slot by slot in
// raster order on the S side; the WTA side carries the golden winnerTakeAll /
// subpixelOffset result of the same pixel `lag` enabled slots later (as
// sgm_wta delivers it). Frames follow each other without reset, each with
// flush slots (rows >= height) until its last output has left; en_i is toggled
// by a seeded random pattern (all inputs are junk while en_i = 0). Every
// enabled slot's outputs are checked against the latency contract (one row +
// LATENCY: position, out_valid_o), every pixel's disp and valid against the
// golden model, and the outputs must hold while en_i = 0 (the slot driver of
// tb/slot_driver.hpp). The build's D / SW / DW / MAX_WIDTH / LATENCY come from
// the model (public parameters).
#include "Vsgm_lr_check.h"
#include "Vsgm_lr_check_sgm_lr_check.h"
#include "cones.hpp"
#include "port_bits.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"
#include "wta_model.hpp"

#include "sgm/disparity.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
// UNIQUENESS = 0 (a lean build): unique_i is not stored and does not gate valid_o; the
// frames still drive the golden unique flags of their ratio and expect them ignored.
constexpr bool kUniqueness = Rtl::UNIQUENESS != 0;
constexpr int kMaxS = (1 << kSW) - 1;
constexpr int kMinWidth = kD > 16 ? kD : 16;

constexpr int kWtaLatency = sgm::tb::wtaLatency(kD);

struct Frame {
  sgm::PathVolume s;
  int tol = 1;  // < 0: check off
  bool subpixel = true;
  std::string name;
  int flushRows = 0;   // flush slots = width + LATENCY - 1 (the minimum) + flushRows * width
  int uniqueness = 0;  // the ratio of the WTA side's unique flag (golden isUnique)
};

std::string describe(const Frame& f) {
  std::ostringstream o;
  o << "frame '" << f.name << "' " << f.s.width << "x" << f.s.height << " tolerance "
    << (f.tol < 0 ? std::string("off") : std::to_string(f.tol)) << " sub-pixel " << (f.subpixel ? "on" : "off")
    << " uniqueness " << f.uniqueness << " (D=" << kD << ", MAX_WIDTH=" << kMaxWidth << ", LATENCY=1 row + " << kLatency
    << ")";
  return o.str();
}

sgm::Params paramsOf(const Frame& f) {
  sgm::Params p;
  p.disparities = kD;
  p.subpixel = f.subpixel;
  p.lrTolerance = f.tol;
  p.uniqueness = kUniqueness ? f.uniqueness : 0;
  return p;
}

// Golden WTA result (the WTA-side input) of every pixel of a frame.
struct Wta {
  std::vector<int> d, disp;
  std::vector<bool> unique;
};
Wta goldenWta(const Frame& f) {
  Wta w;
  for (int y = 0; y < f.s.height; ++y)
    for (int x = 0; x < f.s.width; ++x) {
      const sgm::tb::WtaResult r = sgm::tb::goldenWta(f.s.at(x, y), kD, f.subpixel, f.uniqueness);
      w.d.push_back(r.d);
      w.disp.push_back(r.disp);
      w.unique.push_back(r.unique);
    }
  return w;
}

// Streams the frames back to back on one model (reset once); the WTA side lags
// the S side by `lag` enabled slots. Stops at the first mismatch.
void runFrames(Top& top, const std::vector<Frame>& frames, uint32_t seed, int lag, double onRate = 0.7) {
  struct Slot {
    int frame, x, y;
    bool real;
  };
  std::vector<uint16_t> junkS(kD);
  sgm::tb::SlotDriver<Vsgm_lr_check, Slot> driver(
      top, sgm::tb::EnablePattern(seed, onRate),
      [&](Vsgm_lr_check& m, std::mt19937& junk) {
        sgm::tb::packFields(m.s_i, sgm::tb::junkVector(junkS, kMaxS, junk), kD, kSW);
        m.col_i = junk() & ((1u << kCW) - 1);
        m.row_i = junk() & ((1u << kRW) - 1);
        m.valid_i = junk() & 1;
        m.last_i = junk() & 1;
        m.width_i = junk() & ((1u << kCW) - 1);
        m.height_i = junk() & ((1u << kRW) - 1);
        m.tol_i = junk() & 7;
        m.dmin_i = 0;  // the minimum disparity: whole-core tests (MIN_DISPARITY builds)
        m.check_en_i = junk() & 1;
        m.d_i = junk() % kD;
        m.disp_i = junk() & ((1u << kDW) - 1);
        m.unique_i = 0;
        m.wta_col_i = junk() & ((1u << kCW) - 1);
        m.wta_row_i = junk() & ((1u << kRW) - 1);
        m.wta_valid_i = junk() & 1;
        m.rd_col_i = junk() & ((1u << kCW) - 1);
        m.rd_row_i = junk() & ((1u << kRW) - 1);
      },
      [](Vsgm_lr_check& m) { return sgm::tb::portWords(m.disp_o, m.valid_o, m.col_o, m.row_o, m.out_valid_o); });
  std::mt19937& junk = driver.junk();
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

  driver.reset();
  ASSERT_EQ(int(top->out_valid_o), 0) << "out_valid_o after reset";

  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const Frame& f = frames[fi];
    const int w = f.s.width, h = f.s.height;
    const long slots = long(w) * h + w + kLatency - 1 + long(f.flushRows) * w;
    for (long n = 0; n < slots; ++n) {
      const int x = int(n % w), y = int(n / w);
      const bool real = y < h;
      const bool ok = driver.slot(
          {int(fi), x, y, real},
          [&](Vsgm_lr_check& m) {
            sgm::tb::packFields(m.s_i, real ? f.s.at(x, y) : sgm::tb::junkVector(junkS, kMaxS, junk), kD,
                                kSW);  // flush slots: junk S
            m.col_i = x;
            m.row_i = y;
            m.last_i = x == w - 1;
            m.valid_i = real;
            m.rd_col_i = x;  // one lane: the read side is the S side
            m.rd_row_i = y;
            m.width_i = w;
            m.height_i = h;
            m.tol_i = f.tol < 0 ? junk() & 7 : f.tol;
            m.dmin_i = 0;
            m.check_en_i = f.tol >= 0;
            // WTA side: the slot `lag` enabled slots earlier.
            const Slot* ws = driver.source(lag + 1);
            if (ws && ws->real) {
              const size_t i = size_t(ws->y) * frames[ws->frame].s.width + ws->x;
              m.d_i = wta[ws->frame].d[i];
              m.disp_i = wta[ws->frame].disp[i];
              m.unique_i = wta[ws->frame].unique[i];
              m.wta_col_i = ws->x;
              m.wta_row_i = ws->y;
              m.wta_valid_i = 1;
            } else {
              m.d_i = junk() % kD;
              m.disp_i = junk() & ((1u << kDW) - 1);
              m.unique_i = junk() & 1;
              m.wta_col_i = ws ? ws->x : 0;
              m.wta_row_i = ws ? ws->y : 0;
              m.wta_valid_i = 0;
            }
          },
          [&] { return describe(f); });
      if (!ok) return;

      // The outputs after enabled slot t belong to the S slot t - (LATENCY - 1),
      // which carries left pixel (x, y - 1) of its frame when 1 <= y <= height.
      const Slot* src = driver.source(kLatency);
      const bool expectOut = src && src->y >= 1 && src->y <= frames[src->frame].s.height;
      ASSERT_EQ(bool(top->out_valid_o), expectOut)
          << describe(f) << ": out_valid_o at S slot " << driver.slots() - 1 << " [stage: output framing]";
      if (!expectOut) continue;
      const Slot& s = *src;
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
        ctx << (ed != gd ? "left result memory (disp)" : "left-right check (valid)") << "; d* = " << d << ", unique "
            << wta[s.frame].unique[size_t(oy) * sf.s.width + ox] << ", x - d* = " << ox - d;
        if (ox - d >= 0) ctx << ", golden dR(x - d*) = " << sgm::rightDisparity(sf.s, ox - d, oy);
        auto result = [](int disp, int valid) {
          return "disp " + std::to_string(disp) + " valid " + std::to_string(valid);
        };
        FAIL() << sgm::tb::firstMismatch(ox, oy, describe(sf), result(ed, ev), result(gd, gv), ctx.str());
      }
    }
  }
  for (size_t fi = 0; fi < frames.size(); ++fi)
    EXPECT_EQ(received[fi], frames[fi].s.width * frames[fi].s.height) << describe(frames[fi]) << ": pixels output";
}

// ------------------------------------------------------------------ volumes

sgm::PathVolume randomVolume(int w, int h, int maxValue, std::mt19937& rng) {
  return sgm::tb::randomVolume(w, h, kD, maxValue, rng);
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
      for (int d = 0; d < kD; ++d) v.at(x, y)[d] = uint16_t(std::min(kMaxS, 30 * std::abs(d - dt[x]) + noise(rng)));
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
             {sceneVolume(kMaxWidth, 12, rng), 7, true, "scene tol 7"},
             {sceneVolume(kMaxWidth, 12, rng), 1, true, "scene tol 1 uniqueness 10", 0, 10},
             {sceneVolume(kMaxWidth, 12, rng), -1, false, "scene check off uniqueness 30", 0, 30}},
            211, kWtaLatency);
}

// The first frame after reset from registers and memories that start all zeros
// (an FPGA after configuration) or all ones, instead of random: no state the
// reset leaves alone may reach a pixel (a stale row-end register equal to the
// first slot's column 0 once started a row tail and lost dR(0)).
TEST(SgmLrCheck, FirstFrameFromZeroOrOnesPowerUpState) {
  for (int state : {0, 1}) {
    Top top("sgm_lr_check_power_up_" + std::to_string(state), state);
    std::mt19937 rng(28);
    runFrames(top,
              {{sceneVolume(kMaxWidth, 9, rng), 1, true, "power-up state " + std::to_string(state)},
               {sceneVolume(kMinWidth + 5, 9, rng), 0, true, "second frame", 0, 10}},
              228, kWtaLatency);
  }
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
      f.uniqueness = rng() % 3 ? 0 : int(rng() % 100);
      frames.push_back(std::move(f));
    }
    Top top("sgm_lr_check_soak");
    runFrames(top, frames, 217 + lag, lag);
  }
}

// ------------------------------------------------------------------ Middlebury cones

// Columns x0 .. x0 + w - 1, rows y0 .. y0 + h - 1 of a volume.
sgm::PathVolume crop(const sgm::PathVolume& v, int x0, int y0, int w, int h) {
  sgm::PathVolume c(w, h, v.depth);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) std::copy(v.at(x0 + x, y0 + y), v.at(x0 + x, y0 + y) + v.depth, c.at(x, y));
  return c;
}

// The aggregated cones volume of this build's D, cut into MAX_WIDTH-wide
// tiles (left border, middle, right border), through the check with tolerance
// 1, 0 and off; the full-frame golden selection (four-path preset) must
// also agree with selectDisparity on the whole volume.
TEST(SgmLrCheck, Cones) {
  if (const std::string why = sgm::tb::conesMissing(); !why.empty()) GTEST_SKIP() << why;
  const sgm::PipelineStages& st = sgm::tb::conesStages(kD);
  const sgm::PathVolume& s = st.aggregated;
  {
    sgm::Params p = sgm::presetParams("four-path");  // conesStages' parameters
    p.disparities = kD;
    const sgm::DisparityMap whole = sgm::selectDisparity(s, p);
    ASSERT_EQ(cv::countNonZero(whole.disp != st.selected.disp), 0) << "golden selection stage disagreement";
    ASSERT_EQ(cv::countNonZero(whole.valid != st.selected.valid), 0) << "golden selection stage disagreement";
  }
  const int w = std::min(kMaxWidth, s.width), h = s.height;
  std::vector<Frame> frames;
  const int tols[] = {1, 0, -1};
  int k = 0;
  for (int x0 : {0, (s.width - w) / 2, s.width - w}) {
    const int y0 = (k * 97) % (s.height - h + 1);
    const int tol = tols[k++ % 3];
    frames.push_back(
        {crop(s, x0, y0, w, h), tol, true,
         "cones D=" + std::to_string(kD) + " columns " + std::to_string(x0) + ".., rows " + std::to_string(y0) + ".."});
  }
  frames.push_back({crop(s, s.width - w, s.height - h, w, h), 0, false, "cones bottom right, integer"});
  frames.push_back({crop(s, 0, 0, w, h), 1, true, "cones left, uniqueness 15", 0, 15});
  Top top("sgm_lr_check_cones");
  runFrames(top, frames, 700 + kD, kWtaLatency, 0.8);
}

}  // namespace
