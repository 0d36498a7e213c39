// SPDX-License-Identifier: Apache-2.0
// sgm_wta against the golden sgm::winnerTakeAll / sgm::subpixelOffset
// (docs/algorithm.md section 6). S volumes are streamed slot by slot in raster
// order, each frame followed by flush slots (rows >= height), back to back
// without reset, with en_i toggled by a seeded random pattern (inputs are junk
// while en_i = 0). Every enabled slot's outputs are checked against the latency
// contract (position, valid_o), every pixel's d and disp against the golden
// model, and the outputs must hold while en_i = 0 (the slot driver of
// tb/slot_driver.hpp). D / SW / LATENCY come from the model (public
// parameters), so the same file serves every build. A build with CONFIDENCE = 1 also has
// every pixel's conf_o checked against sgm::confidence (docs/algorithm.md section 7b).
#include "Vsgm_wta.h"
#include "Vsgm_wta_sgm_wta.h"
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

using Top = sgm::tb::VerilatedTop<Vsgm_wta>;
using Rtl = Vsgm_wta_sgm_wta;  // public parameters of the build

constexpr int kD = int(Rtl::D);
constexpr int kSW = int(Rtl::SW);
constexpr int kCW = int(Rtl::CW);
constexpr int kRW = int(Rtl::RW);
constexpr int kLatency = int(Rtl::LATENCY);
// UNIQUENESS = 0 (the lean build, rtl-wta-d16-lean): no uniqueness test, every winner is
// unique whatever uniq_i says; the frames still drive their ratios and expect that.
constexpr bool kUniqueness = Rtl::UNIQUENESS != 0;
constexpr bool kConfidence = Rtl::CONFIDENCE != 0;  // conf_o built (else 0)
constexpr int kMaxS = (1 << kSW) - 1;

static_assert(kLatency == sgm::tb::wtaLatency(kD) + (kConfidence ? 4 : 0),
              "sgm_wta latency: T0 + log2(D) - 1 tree stages + 5, and C3 .. C0 with the confidence");

struct Frame {
  sgm::PathVolume s;
  bool subpixel = true;
  std::string name;
  int flush = kLatency - 1;  // slots after the last pixel (the minimum that drains the pipeline)
  int uniqueness = 0;        // uniq_i: ratio in % (0 .. 99)
};

std::string describe(const Frame& f) {
  std::ostringstream o;
  o << "frame '" << f.name << "' " << f.s.width << "x" << f.s.height << " sub-pixel " << (f.subpixel ? "on" : "off")
    << " uniqueness " << f.uniqueness << " (D=" << kD << ", SW=" << kSW << ", LATENCY=" << kLatency
    << (kUniqueness ? "" : ", UNIQUENESS=0: always unique") << (kConfidence ? ", CONFIDENCE=1" : "") << ")";
  return o.str();
}

sgm::tb::WtaResult golden(const uint16_t* s, bool subpixel, int uniqueness = 0) {
  return sgm::tb::goldenWta(s, kD, subpixel, uniqueness);
}

// Streams the frames back to back on one model (reset once) and checks every
// output slot. Stops at the first mismatch, naming pixel, expected, got, stage.
void runFrames(Top& top, const std::vector<Frame>& frames, uint32_t seed, double onRate = 0.7) {
  struct Slot {
    int frame, x, y;
    bool real;
  };
  std::vector<uint16_t> junkS(kD);
  sgm::tb::SlotDriver<Vsgm_wta, Slot> driver(
      top, sgm::tb::EnablePattern(seed, onRate),
      [&](Vsgm_wta& m, std::mt19937& junk) {
        sgm::tb::packFields(m.s_i, sgm::tb::junkVector(junkS, kMaxS, junk), kD, kSW);
        m.col_i = junk() & ((1u << kCW) - 1);
        m.row_i = junk() & ((1u << kRW) - 1);
        m.valid_i = junk() & 1;
        m.subpixel_i = junk() & 1;
        m.uniq_i = junk() & 127;
      },
      [](Vsgm_wta& m) {
        return sgm::tb::portWords(m.d_o, m.disp_o, m.unique_o, m.conf_o, m.col_o, m.row_o, m.valid_o);
      });
  driver.reset();
  ASSERT_EQ(int(top->valid_o), 0) << "valid_o after reset";

  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const Frame& f = frames[fi];
    const int w = f.s.width, h = f.s.height;
    ASSERT_EQ(f.s.depth, kD) << describe(f);
    ASSERT_LT(w, 1 << kCW) << describe(f);
    ASSERT_LT(h + (f.flush + w - 1) / w, 1 << kRW) << describe(f);
    ASSERT_LE(*std::max_element(f.s.data.begin(), f.s.data.end()), kMaxS) << describe(f) << ": S exceeds SW bits";
    for (long n = 0; n < long(w) * h + f.flush; ++n) {
      const int x = int(n % w), y = int(n / w);
      const bool real = y < h;
      const bool ok = driver.slot(
          {int(fi), x, y, real},
          [&](Vsgm_wta& m) {
            // flush slots: junk the module must not mistake for a pixel
            sgm::tb::packFields(m.s_i, real ? f.s.at(x, y) : sgm::tb::junkVector(junkS, kMaxS, driver.junk()), kD, kSW);
            m.col_i = x;
            m.row_i = y;
            m.valid_i = real;
            // Flush slots carry junk settings too: each setting must travel with its own slot.
            m.subpixel_i = real ? f.subpixel : driver.junk()() & 1;
            m.uniq_i = real ? f.uniqueness : driver.junk()() & 127;
          },
          [&] { return describe(f); });
      if (!ok) return;

      // The outputs after enabled slot t belong to the input of slot t - (LATENCY - 1).
      const Slot* src = driver.source(kLatency);
      if (!src) {
        ASSERT_EQ(int(top->valid_o), 0) << describe(f) << ": valid_o before the first pixel reached the output";
        continue;
      }
      const Slot& s = *src;
      const Frame& sf = frames[s.frame];
      ASSERT_EQ(bool(top->valid_o), s.real)
          << describe(sf) << ": valid_o of slot (" << s.x << ", " << s.y << ") [stage: position pipeline]";
      ASSERT_EQ(int(top->col_o), s.x) << describe(sf) << ": col_o of slot (" << s.x << ", " << s.y << ")";
      ASSERT_EQ(int(top->row_o), s.y) << describe(sf) << ": row_o of slot (" << s.x << ", " << s.y << ")";
      if (!s.real) continue;
      const uint16_t* sp = sf.s.at(s.x, s.y);
      const sgm::tb::WtaResult want = golden(sp, sf.subpixel, kUniqueness ? sf.uniqueness : 0);
      const int gd = int(top->d_o), gdisp = int(top->disp_o);
      const bool gunique = top->unique_o;
      if (gd == want.d && gdisp == want.disp && gunique != want.unique) {
        // The second minimum away from d* +- 1, for the message.
        int sec = -1;
        for (int k = 0; k < kD; ++k)
          if (std::abs(k - gd) > 1 && (sec < 0 || sp[k] < sec)) sec = sp[k];
        std::ostringstream ctx;
        ctx << "uniqueness (tree's second minimum, product); S(d*) = " << int(sp[gd])
            << ", min S(k), |k - d*| > 1 = " << sec << ", U = " << sf.uniqueness;
        FAIL() << sgm::tb::firstMismatch(s.x, s.y, describe(sf), "unique " + std::to_string(want.unique),
                                         "unique " + std::to_string(gunique), ctx.str());
      }
      if (gd != want.d || gdisp != want.disp) {
        std::ostringstream ctx;
        const int d = want.d;
        ctx << (gd != want.d ? "winner-take-all tree" : "sub-pixel division")
            << "; S(d-1, d, d+1) = " << (d > 0 ? int(sp[d - 1]) : -1) << ", " << int(sp[d]) << ", "
            << (d < kD - 1 ? int(sp[d + 1]) : -1);
        auto result = [](int d, int disp) { return "d " + std::to_string(d) + " disp " + std::to_string(disp); };
        FAIL() << sgm::tb::firstMismatch(s.x, s.y, describe(sf), result(want.d, want.disp), result(gd, gdisp),
                                         ctx.str());
      }
      const int wantConf = kConfidence ? sgm::confidence(sp, kD, want.d) : 0;
      if (int(top->conf_o) != wantConf) {
        int sec = -1;
        for (int k = 0; k < kD; ++k)
          if (std::abs(k - want.d) > 1 && (sec < 0 || sp[k] < sec)) sec = sp[k];
        std::ostringstream ctx;
        ctx << "confidence division (C7 .. C0); S(d*) = " << int(sp[want.d]) << ", min S(k), |k - d*| > 1 = " << sec;
        FAIL() << sgm::tb::firstMismatch(s.x, s.y, describe(sf), "conf " + std::to_string(wantConf),
                                         "conf " + std::to_string(int(top->conf_o)), ctx.str());
      }
    }
  }
}

// ------------------------------------------------------------------ volumes

sgm::PathVolume randomVolume(int w, int h, int maxValue, std::mt19937& rng) {
  return sgm::tb::randomVolume(w, h, kD, maxValue, rng);
}

// Hand-picked cost vectors, one per pixel (cycled through the frame), around
// the cases the datapath must get right; the rest of each vector is random
// above the minimum.
sgm::PathVolume edgeCaseVolume(int w, int h, std::mt19937& rng) {
  sgm::PathVolume v(w, h, kD);
  std::uniform_int_distribution<int> above(0, kMaxS);
  int k = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x, ++k) {
      uint16_t* s = v.at(x, y);
      const int m = int(rng() % 200);  // the minimum
      for (int d = 0; d < kD; ++d) s[d] = uint16_t(m + 1 + above(rng) % (kMaxS - m));
      const int dm = 1 + int(rng() % (kD - 2));  // an interior winner
      switch (k % 17) {
        case 0: std::fill(s, s + kD, uint16_t(m)); break;    // all equal: d = 0
        case 1: s[0] = uint16_t(m); break;                   // winner at 0
        case 2: s[kD - 1] = uint16_t(m); break;              // winner at D-1
        case 3: s[kD - 1] = s[kD - 2] = uint16_t(m); break;  // tie D-2 / D-1
        case 4: s[1] = uint16_t(m); break;                   // first refined d
        case 5: s[kD - 2] = uint16_t(m); break;              // last refined d
        case 6: s[dm] = s[dm + 1] = uint16_t(m); break;      // b = m: offset +8
        case 7:                                              // many equal minima
          for (int d = 0; d < kD; ++d)
            if (rng() % 3 == 0 && d >= dm) s[d] = uint16_t(m);
          s[dm] = uint16_t(m);
          break;
        case 8: s[dm] = 0, s[dm - 1] = s[dm + 1] = uint16_t(kMaxS); break;      // widest den, num = 0
        case 9: s[dm] = 0, s[dm - 1] = uint16_t(kMaxS), s[dm + 1] = 0; break;   // tie to the right
        case 10: s[dm] = 0, s[dm - 1] = uint16_t(kMaxS), s[dm + 1] = 1; break;  // q near 8
        case 11: s[dm] = 0, s[dm - 1] = 1, s[dm + 1] = uint16_t(kMaxS); break;  // q near -8
        case 12:
          s[dm] = uint16_t(m), s[dm - 1] = uint16_t(m + 1), s[dm + 1] = uint16_t(m + 3);
          break;  // half-way rounding
        case 13: s[dm] = uint16_t(m), s[dm - 1] = uint16_t(m + 3), s[dm + 1] = uint16_t(m + 1); break;
        case 14: std::fill(s, s + kD, uint16_t(kMaxS)), s[dm] = uint16_t(kMaxS - 1); break;  // all at the top
        case 15: std::fill(s, s + kD, uint16_t(kMaxS)), s[dm] = 0; break;  // confidence 255: sec = max, m = 0
        default: s[dm] = uint16_t(m); break;
      }
    }
  return v;
}

// Cost vectors around the uniqueness test's boundary at ratio u: the winner d
// (anywhere, 0 and D-1 included) with cost m, its neighbours d +- 1 at or just
// above m (excluded from the test, ties included), and the second minimum away
// from them at 100 m / (100 - u) rounded up, minus one, or plus one, placed at
// d +- 2, at an end, or anywhere; the rest high. Large m reaches the top of SW.
sgm::PathVolume uniquenessVolume(int w, int h, int u, std::mt19937& rng) {
  sgm::PathVolume v(w, h, kD);
  int k = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x, ++k) {
      uint16_t* s = v.at(x, y);
      const int top = std::min(kMaxS - 3, (kMaxS * (100 - u)) / 100);  // the largest m whose boundary fits SW bits
      const int m = k % 5 == 0 ? top - int(rng() % 4) : int(rng() % std::min(top + 1, 2000));
      const int d = k % 7 == 0 ? 0 : k % 7 == 1 ? kD - 1 : int(rng() % kD);
      const int boundary = (100 * m + (100 - u) - 1) / (100 - u);  // least sec that passes
      const int sec = std::min(kMaxS, std::max(m, boundary + int(rng() % 3) - 1));
      for (int j = 0; j < kD; ++j) s[j] = uint16_t(std::min(kMaxS, sec + 1 + int(rng() % 50)));
      int at;
      switch (rng() % 4) {
        case 0: at = d >= 2 ? d - 2 : d + 2; break;
        case 1: at = d + 2 < kD ? d + 2 : d - 2; break;
        case 2: at = d < kD / 2 ? kD - 1 : 0; break;
        default:
          do at = int(rng() % kD);
          while (std::abs(at - d) <= 1);
          break;
      }
      s[at] = uint16_t(sec);
      for (int n : {d - 1, d + 1})
        if (n >= 0 && n < kD) s[n] = uint16_t(std::min(kMaxS, m + int(rng() % 3)));
      s[d] = uint16_t(m);
      // A tie at d - 1 would move the winner: keep d the first minimum.
      if (d > 0 && s[d - 1] == m) s[d - 1] = uint16_t(m + 1);  // m <= kMaxS - 3
    }
  return v;
}

// ------------------------------------------------------------------ synthetic

TEST(SgmWta, EdgeCases) {
  Top top("sgm_wta_edges");
  std::mt19937 rng(11);
  runFrames(top,
            {{edgeCaseVolume(32, 16, rng), true, "edge cases, sub-pixel"},
             {edgeCaseVolume(32, 16, rng), false, "edge cases, integer"}},
            111);
}

// The uniqueness flag at its boundary, per frame ratio (0 = off: always unique),
// and on random and tie-heavy costs.
TEST(SgmWta, Uniqueness) {
  Top top("sgm_wta_unique");
  std::mt19937 rng(18);
  std::vector<Frame> frames;
  for (int u : {15, 1, 50, 99, 0, 7, 33}) {
    frames.push_back({uniquenessVolume(37, 9, u, rng), u % 2 == 1, "boundary U " + std::to_string(u)});
    frames.back().uniqueness = u;
  }
  for (int u : {10, 25}) {
    frames.push_back({randomVolume(31, 9, u == 10 ? 7 : kMaxS, rng), true, "random U " + std::to_string(u)});
    frames.back().uniqueness = u;
  }
  runFrames(top, frames, 118);
}

// den = a + b - 2m = 0 cannot occur at the WTA winner: a = S(d*-1) > m, or d*-1
// would have won the tie (golden's "q = 0 when den = 0" is unreachable here).
// The smallest reachable denominators: den = 1 (b = m, a = m + 1: q = 8, the
// half-pixel rounding edge) and den = 2 with num = 0 (q = 0), at every
// interior d.
TEST(SgmWta, SmallestDenominator) {
  Top top("sgm_wta_den");
  sgm::PathVolume v(kD, 4, kD);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      uint16_t* s = v.at(x, y);
      std::fill(s, s + kD, uint16_t(500));
      const int dm = 1 + (x % (kD - 2));
      s[dm] = 100;
      if (y % 2 == 0)
        s[dm - 1] = 101, s[dm + 1] = 100;
      else
        s[dm - 1] = 101, s[dm + 1] = 101;
    }
  runFrames(top, {{v, true, "small den"}}, 112);
}

TEST(SgmWta, RandomCostsFullRange) {
  Top top("sgm_wta_random");
  std::mt19937 rng(13);
  runFrames(top,
            {{randomVolume(16, 9, kMaxS, rng), true, "16x9 full range"},
             {randomVolume(61, 13, kMaxS, rng), true, "61x13 full range"},
             {randomVolume(128, 8, kMaxS, rng), false, "128x8 full range, integer"}},
            113);
}

TEST(SgmWta, RandomCostsManyTies) {
  Top top("sgm_wta_ties");
  std::mt19937 rng(14);
  runFrames(top,
            {{randomVolume(40, 12, 1, rng), true, "values 0..1"},
             {randomVolume(40, 12, 3, rng), true, "values 0..3"},
             {randomVolume(23, 9, 7, rng), false, "values 0..7, integer"}},
            114);
}

// Two frames (then more) of different sizes and settings with no reset in
// between and the minimum flush, then a generous one.
TEST(SgmWta, BackToBackFramesOfDifferentSizes) {
  Top top("sgm_wta_b2b");
  std::mt19937 rng(15);
  std::vector<Frame> frames = {{randomVolume(128, 11, kMaxS, rng), true, "first 128x11"},
                               {randomVolume(17, 9, 5, rng), false, "second 17x9"},
                               {edgeCaseVolume(45, 10, rng), true, "third 45x10"},
                               {randomVolume(16, 20, 3, rng), true, "fourth 16x20"}};
  frames[2].flush = 3 * 45;  // three flush rows
  runFrames(top, frames, 115);
}

TEST(SgmWta, EnablePatterns) {
  std::mt19937 rng(16);
  for (double rate : {0.05, 0.5, 1.0}) {
    Top top("sgm_wta_en");
    runFrames(top, {{edgeCaseVolume(29, 12, rng), true, "en rate " + std::to_string(rate)}}, 116, rate);
  }
}

// Many random frames of random sizes, value ranges and settings back to back.
TEST(SgmWta, RandomSoak) {
  Top top("sgm_wta_soak");
  std::mt19937 rng(17);
  std::vector<Frame> frames;
  const int ranges[] = {1, 3, 15, 255, kMaxS};
  for (int i = 0; i < 40; ++i) {
    const int w = 16 + int(rng() % 113), h = 1 + int(rng() % 12);
    Frame f{i % 5 == 4 ? edgeCaseVolume(w, h, rng) : randomVolume(w, h, ranges[rng() % 5], rng), bool(rng() % 4 != 0),
            "soak " + std::to_string(i)};
    f.flush += int(rng() % 3) * w;
    const int ratios[] = {0, 0, 5, 15, 40, 99};
    f.uniqueness = ratios[rng() % 6];
    frames.push_back(std::move(f));
  }
  runFrames(top, frames, 117);
}

// ------------------------------------------------------------------ Middlebury cones

// The whole aggregated cones volume of this build's D through the core, with
// and without sub-pixel; the sub-pixel result must also equal the disp plane of
// the golden pipeline's selection stage.
TEST(SgmWta, Cones) {
  if (const std::string why = sgm::tb::conesMissing(); !why.empty()) GTEST_SKIP() << why;
  const sgm::PipelineStages& st = sgm::tb::conesStages(kD);
  const sgm::PathVolume& s = st.aggregated;
  // The golden selection stage agrees with the per-pixel model used above.
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      ASSERT_EQ(golden(s.at(x, y), true).disp, int(st.selected.disp.at<uint16_t>(y, x)))
          << "golden model disagreement at (" << x << ", " << y << ")";
  Top top("sgm_wta_cones");
  runFrames(top,
            {{s, true, "cones D=" + std::to_string(kD) + " aggregated"},
             {s, false, "cones D=" + std::to_string(kD) + " aggregated, integer", kLatency - 1, 15}},
            700 + kD, 0.8);
}

}  // namespace
