// SPDX-License-Identifier: Apache-2.0
// sgm_cost_volume in lane order (docs/lanes.md) against the golden
// sgm::computeCost (docs/algorithm.md section 3), the module itself (9x5 census):
// the left and right census of the golden model are streamed in the slot order
// of K row lanes (tb/lane_schedule.hpp), with random idle cycles and frames of
// different sizes and modes back to back; every output slot (valid, column and
// C(p, d) for every d) is checked LATENCY slots after its input. Rows outside
// the frame carry random census words, which must not reach a frame pixel's cost.
#include "Vsgm_cost_volume.h"
#include "Vsgm_cost_volume_sgm_cost_volume.h"
#include "idle_slot.hpp"
#include "lane_schedule.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/census.hpp"
#include "sgm/cost.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <sstream>
#include <string>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_cost_volume>;
using Rtl = Vsgm_cost_volume_sgm_cost_volume;  // public parameters of the build

constexpr int kD = int(Rtl::D);
constexpr int kLanes = int(Rtl::LANES);
constexpr int kLatency = int(Rtl::LATENCY);
// AD_TERM = 0 (a lean build): no AD term, the weight and cap driven are ignored.
constexpr bool kAdTerm = Rtl::AD_TERM != 0;
constexpr int kSkew = 3;  // any skew: the volume keeps no state across rows

cv::Mat randomImage(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  return img;
}

void setCensus(QData& port, const sgm::Census& c) { port = c.bits & ((uint64_t(1) << 44) - 1); }

// Streams one frame in lane order and checks every output; returns the first
// mismatch (in output order) or "".
std::string runFrame(Top& top, const cv::Mat& left, const cv::Mat& right, sgm::CostMode mode, std::mt19937& rng,
                     double idle, int adWeight = 0, int adCap = 0) {
  const int w = left.cols, h = left.rows;
  const std::vector<sgm::Census> lc = sgm::censusTransform(left), rc = sgm::censusTransform(right);
  sgm::CostVolume expected = sgm::computeCost(left, right, mode, kD);
  for (int y = 0; adWeight && kAdTerm && y < h; ++y)
    sgm::addAdTerm(left, right, y, 0, w, kD, adWeight, adCap, expected.at(0, y));
  const int leadRows = 2;
  const sgm::tb::LaneSchedule lanes(w, kLanes, kSkew, leadRows);
  const long slots = lanes.slotsToCover(h) + kLatency;
  std::deque<sgm::tb::SlotPosition> inFlight;  // inputs of the last kLatency slots
  long checked = 0;
  for (long t = 0; t < slots; ++t) {
    const sgm::tb::SlotPosition pos = lanes.at(t);
    const bool inside = pos.row >= 0 && pos.row < h;
    const size_t i = inside ? size_t(pos.row) * w + pos.col : 0;
    sgm::Census junkL, junkR;
    junkL.bits = (uint64_t(rng()) << 32) | rng();
    junkR.bits = (uint64_t(rng()) << 32) | rng();
    const sgm::Census& l = inside ? lc[i] : junkL;
    const sgm::Census& r = inside ? rc[i] : junkR;
    setCensus(top->lcensus_i, l);
    setCensus(top->rcensus_i, r);
    top->lrank_i = sgm::Census{l.bits & ((uint64_t(1) << 44) - 1), 0}.rank();
    top->rrank_i = sgm::Census{r.bits & ((uint64_t(1) << 44) - 1), 0}.rank();
    top->col_i = pos.col;
    top->valid_i = inside;
    top->mode_i = int(mode);
    top->ad_weight_i = adWeight;
    top->ad_cap_i = adCap;
    top->lgray_i = inside ? left.at<uint8_t>(pos.row, pos.col) : rng() & 0xff;
    top->rgray_i = inside ? right.at<uint8_t>(pos.row, pos.col) : rng() & 0xff;
    sgm::tb::slotAfterIdle(top, rng, idle);
    inFlight.push_back(pos);
    if (int(inFlight.size()) < kLatency) continue;
    const sgm::tb::SlotPosition src = inFlight.front();
    inFlight.pop_front();
    const bool srcInside = src.row >= 0 && src.row < h;
    std::ostringstream where;
    where << "stage cost (" << kLanes << " lanes, " << w << "x" << h << ", " << sgm::costModeName(mode)
          << ") pixel (x=" << src.col << ", y=" << src.row << ")";
    if (bool(top->valid_o) != srcInside) return where.str() + ": valid_o " + std::to_string(top->valid_o);
    if (!srcInside) continue;
    if (int(top->col_o) != src.col) return where.str() + ": col_o " + std::to_string(top->col_o);
    const uint8_t* e = expected.at(src.col, src.row);
    for (int d = 0; d < kD; ++d) {
      const int got = int(sgm::tb::getBits(top->cost_o, 7 * d, 7));
      if (got != e[d])
        return where.str() + " d=" + std::to_string(d) + ": expected " + std::to_string(e[d]) + ", got " +
               std::to_string(got);
    }
    ++checked;
  }
  if (checked != long(w) * h)
    return "checked " + std::to_string(checked) + " pixels, expected " + std::to_string(long(w) * h);
  return "";
}

TEST(SgmCostVolumeLanes, RandomFramesAllModesBackToBack) {
  Top top("sgm_cost_volume_lanes");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(2026);
  const sgm::CostMode modes[] = {sgm::CostMode::kRt, sgm::CostMode::kRsad, sgm::CostMode::kUnified};
  const int sizes[][2] = {{16, 9}, {kD + 5, 13}, {37, 10}, {90, 12}};
  int k = 0;
  for (const auto& s : sizes) {
    const cv::Mat left = randomImage(s[0], s[1], rng), right = randomImage(s[0], s[1], rng);
    const sgm::CostMode mode = modes[k++ % 3];
    // The AD term on every other frame (weights and caps within the 9x5 cost word).
    EXPECT_EQ(runFrame(top, left, right, mode, rng, k % 2 ? 0.3 : 0.0, k % 2 ? 0 : 5 + k, k % 2 ? 0 : 30), "");
  }
}

}  // namespace
