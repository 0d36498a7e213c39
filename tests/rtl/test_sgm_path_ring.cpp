// SPDX-License-Identifier: Apache-2.0
// sgm_path_ring against the golden 0 degree path costs (docs/algorithm.md
// section 5, sgm::pathCost path 0): Lr(p, d) and its minimum for every pixel,
// LANES row lanes interleaved slot by slot as the re-scheduled core deals them
// (slot K t + k belongs to lane k, lane k runs the rows y = k mod K), with
// random idle cycles and random inputs in the slots of a lane that has run out
// of rows (they must not reach any other lane).
#include "Vsgm_path_ring.h"
#include "Vsgm_path_ring_sgm_path_ring.h"
#include "idle_slot.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/aggregate.hpp"
#include "sgm/volume.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <sstream>

#ifndef SGM_D
#define SGM_D 16
#endif

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_path_ring>;
using sgm::tb::getBits;
using sgm::tb::setBits;

constexpr int kD = SGM_D;
constexpr int kLanes = int(Vsgm_path_ring_sgm_path_ring::LANES);
constexpr int kCostBits = 7, kPathBits = 9;

struct Frame {
  cv::Mat gray;
  sgm::CostVolume cost;
  int p1 = 20, p2 = 200;
  sgm::P2Mode p2Mode = sgm::P2Mode::kKnee;
};

Frame randomFrame(int w, int h, int p1, int p2, sgm::P2Mode mode, std::mt19937& rng) {
  Frame f;
  f.gray = cv::Mat(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)  // runs of equal grays (dI = 0) beside random ones
      f.gray.at<uint8_t>(y, x) = rng() % 3 == 0 && x > 0 ? f.gray.at<uint8_t>(y, x - 1) : uint8_t(rng() % 256);
  f.cost = sgm::CostVolume(w, h, kD);
  for (auto& c : f.cost.data) c = uint8_t(rng() % 89);  // anything a hardware cost mode can produce (0 .. 88)
  f.p1 = p1, f.p2 = p2, f.p2Mode = mode;
  return f;
}

// Streams one frame through the ring, lanes interleaved; returns the first mismatch or "".
std::string runFrame(Top& top, const Frame& f, std::mt19937& rng, double idle) {
  const int w = f.cost.width, h = f.cost.height;
  const sgm::PathVolume expected = sgm::pathCost(f.cost, f.gray, 0, f.p1, f.p2, f.p2Mode);
  const sgm::P2Table p2Table = sgm::makeP2Table(f.p1, f.p2, f.p2Mode);
  const int rowsPerLane = (h + kLanes - 1) / kLanes;
  const long slots = long(kLanes) * rowsPerLane * w;
  top->p1_i = f.p1;
  struct Slot {
    int x, y;  // y < 0: no pixel
  };
  std::vector<Slot> entered;
  long checked = 0;
  for (long t = 0; t < slots + kLanes; ++t) {
    const int lane = int(t % kLanes);
    const long j = t / kLanes;
    const int y = t < slots ? lane + kLanes * int(j / w) : h, x = int(j % w);
    const bool pixel = y < h;
    for (int d = 0; d < kD; ++d)
      setBits(top->cost_i, d * kCostBits, kCostBits, pixel ? f.cost.at(x, y)[d] : rng() % 128);
    if (pixel) {
      const int dI = x > 0 ? std::abs(f.gray.at<uint8_t>(y, x) - f.gray.at<uint8_t>(y, x - 1)) : int(rng() % 256);
      top->p2r_i = p2Table[dI];
      top->start_i = x == 0;
    } else {
      top->p2r_i = rng() % 256;
      top->start_i = rng() % 2;
    }
    sgm::tb::slotAfterIdle(top, rng, idle);
    entered.push_back(pixel ? Slot{x, y} : Slot{0, -1});
    if (entered.size() < size_t(kLanes)) continue;
    const Slot out = entered[entered.size() - kLanes];
    if (out.y < 0) continue;
    const uint16_t* lr = expected.at(out.x, out.y);
    const int minLr = *std::min_element(lr, lr + kD);
    for (int d = 0; d <= kD; ++d) {
      const int want = d < kD ? lr[d] : minLr;
      const int got = d < kD ? int(getBits(top->lr_o, d * kPathBits, kPathBits)) : int(top->min_o);
      if (got != want) {
        std::ostringstream msg;
        msg << "stage sgm_path_ring (LANES=" << kLanes << "): first mismatch at (x=" << out.x << ", y=" << out.y << ") "
            << (d < kD ? "Lr d=" + std::to_string(d) : std::string("min Lr")) << ": expected " << want << ", got "
            << got << " (" << w << "x" << h << ", P1=" << f.p1 << ", P2'=" << f.p2 << ")";
        return msg.str();
      }
    }
    ++checked;
  }
  if (checked != long(w) * h)
    return "checked " + std::to_string(checked) + " pixels, expected " + std::to_string(long(w) * h);
  return "";
}

TEST(SgmPathRing, RandomFramesBackToBack) {
  Top top("sgm_path_ring");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(5);
  const int sizes[][2] = {{1, 5}, {2, 7}, {16, 9}, {37, 11}, {kD + 3, 6}};
  int k = 0;
  for (const auto& s : sizes) {
    const int p2 = int(rng() % 256), p1 = int(rng() % (p2 + 1));
    const auto mode = k++ % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee;
    EXPECT_EQ(runFrame(top, randomFrame(s[0], s[1], p1, p2, mode, rng), rng, 0.3), "") << sgm::p2ModeName(mode);
  }
}

TEST(SgmPathRing, PenaltyExtremes) {
  Top top("sgm_path_ring_extremes");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(6);
  for (auto [p1, p2] : {std::pair{0, 0}, {0, 255}, {255, 255}, {20, 200}})
    EXPECT_EQ(runFrame(top, randomFrame(40, 2 * kLanes + 1, p1, p2, sgm::P2Mode::kKnee, rng), rng, 0.0), "");
}

}  // namespace
