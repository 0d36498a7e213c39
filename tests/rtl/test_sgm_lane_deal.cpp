// SPDX-License-Identifier: Apache-2.0
// sgm_lane_deal against the lane schedule of tb/lane_schedule.hpp: a raster
// stream that starts like the stream controller's (the frame's first slot at
// (0, 0), rows on past the frame as flush) carries a tag of its frame,
// row and column; every lane-side output slot must carry the position the
// schedule gives for it (K lanes, SKEW, LANE_LEAD of the build) and, when
// valid, the tag of that position: a read before the raster wrote it, or after
// the ring overwrote it, gives another position's tag; active_o must say
// whether the slot's lane has started. Frames of different widths back to
// back, random idle cycles, the build's parameters from the model.
#include "Vsgm_lane_deal.h"
#include "Vsgm_lane_deal_sgm_lane_deal.h"
#include "idle_slot.hpp"
#include "lane_schedule.hpp"
#include "verilated_top.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_lane_deal>;
using Rtl = Vsgm_lane_deal_sgm_lane_deal;

constexpr int kLanes = int(Rtl::LANES);
constexpr int kSkew = int(Rtl::SKEW);
constexpr int kLaneLead = int(Rtl::LANE_LEAD);
constexpr uint32_t kRowMask = 0xff;  // YW = 8

uint16_t tagOf(int frame, int row, int col) {
  uint32_t h = uint32_t(frame) * 0x9e3779b1u ^ uint32_t(row + 16) * 0x85ebca6bu ^ uint32_t(col) * 0xc2b2ae35u;
  h ^= h >> 15;
  return uint16_t(h * 0x2c1b3c6du >> 16);
}

// One frame: returns the first mismatch or "".
std::string runFrame(Top& top, int frame, int w, int h, std::mt19937& rng, double idle) {
  const sgm::tb::LaneSchedule lanes(w, kLanes, kSkew, kLaneLead);
  const long slots = lanes.slotsToCover(h) + 2;
  long received = 0;
  for (long m = 0; m < slots; ++m) {
    const int rcol = int(m % w), rrow = int(m / w);  // the raster slot m
    top->sof_i = m == 0;
    top->col_i = rcol;
    top->row_i = uint32_t(rrow) & kRowMask;
    top->data_i = tagOf(frame, rrow, rcol);
    top->width_i = w;
    top->height_i = h;
    sgm::tb::slotAfterIdle(top, rng, idle);
    // The outputs now belong to lane slot m.
    const sgm::tb::SlotPosition want = lanes.at(m);
    const bool inside = want.row >= 0 && want.row < h;
    const std::string where = "stage sgm_lane_deal (" + std::to_string(kLanes) + " lanes, width " + std::to_string(w) +
                              ") lane slot " + std::to_string(m) + " (x=" + std::to_string(want.col) +
                              ", y=" + std::to_string(want.row) + ")";
    if (bool(top->valid_o) != inside) return where + ": valid_o " + std::to_string(top->valid_o);
    const bool started = m / kLanes >= (m % kLanes) * kSkew;
    if (bool(top->active_o) != started) return where + ": active_o " + std::to_string(top->active_o);
    if (!inside) continue;
    if (int(top->col_o) != want.col || int(top->row_o) != want.row)
      return where + ": position (" + std::to_string(top->col_o) + ", " + std::to_string(top->row_o) + ")";
    if (top->data_o != tagOf(frame, want.row, want.col))
      return where + ": expected tag " + std::to_string(tagOf(frame, want.row, want.col)) + ", got " +
             std::to_string(top->data_o);
    ++received;
  }
  if (received != long(w) * h)
    return "received " + std::to_string(received) + " pixels, expected " + std::to_string(long(w) * h);
  return "";
}

TEST(SgmLaneDeal, FramesOfDifferentWidthsBackToBack) {
  Top top("sgm_lane_deal");
  top->en_i = 0;
  top.reset();
  std::mt19937 rng(99);
  const int sizes[][2] = {{16, 9}, {40, 12}, {128, 10}, {23, 13}, {77, 9}};
  int frame = 0;
  for (const auto& s : sizes) {
    EXPECT_EQ(runFrame(top, frame, s[0], s[1], rng, frame % 2 ? 0.3 : 0.0), "") << "frame " << frame;
    ++frame;
  }
}

}  // namespace
