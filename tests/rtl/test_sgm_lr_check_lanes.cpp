// SPDX-License-Identifier: Apache-2.0
// sgm_lr_check with K lanes (docs/lanes.md) against the golden
// sgm::selectDisparity (docs/algorithm.md section 7): the S side and the WTA side (its golden result,
// `lag` slots later) in the slot order of K row lanes (tb/lane_schedule.hpp),
// the read side in raster order far enough behind that every word of a row is
// written before the row is read (computed here from the schedule: the left
// word, the diagonal's dR, the row tail written during the lane's next row).
// Every output slot is checked: position, out_valid_o, disp and the check's
// valid of every pixel; frames of different sizes and settings back to back
// without reset, random idle cycles. Rows outside the frame carry junk S.
#include "Vsgm_lr_check.h"
#include "Vsgm_lr_check_sgm_lr_check.h"
#include "idle_slot.hpp"
#include "lane_schedule.hpp"
#include "port_bits.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"
#include "wta_model.hpp"

#include "sgm/disparity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_lr_check>;
using Rtl = Vsgm_lr_check_sgm_lr_check;  // public parameters of the build

constexpr int kD = int(Rtl::D);
constexpr int kSW = int(Rtl::SW);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kRW = int(Rtl::RW);
constexpr int kLanes = int(Rtl::LANES);
constexpr int kBanks = int(Rtl::ROW_BANKS);
constexpr int kLatency = int(Rtl::LATENCY);
constexpr int kDrRead = int(Rtl::RAM_LATENCY);  // the dR read, slots after the left word's
// UNIQUENESS = 0 (a lean build): unique_i is not stored and does not gate valid_o; the
// frames still drive the golden unique flags of their ratio and expect them ignored.
constexpr bool kUniqueness = Rtl::UNIQUENESS != 0;
constexpr int kMaxS = (1 << kSW) - 1;
constexpr int kMinWidth = kD > 16 ? kD : 16;
constexpr int kSkew = 3;
constexpr int kLeadRows = 2;

struct Frame {
  sgm::PathVolume s;
  int tol = 1;  // < 0: check off
  bool subpixel = true;
  int uniqueness = 0;  // the ratio of the WTA side's unique flag (golden isUnique)
};

class LrLanes {
 public:
  LrLanes(const std::string& name, uint32_t seed, double idle, int initialState = 2)
      : top_(name, initialState), rng_(seed), idle_(idle) {
    top_->en_i = 0;
    top_.reset();
  }

  std::string run(const Frame& f, int lag) {
    const int w = f.s.width, h = f.s.height;
    sgm::Params p;
    p.disparities = kD;
    p.subpixel = f.subpixel;
    p.lrTolerance = f.tol;
    p.uniqueness = kUniqueness ? f.uniqueness : 0;
    const sgm::DisparityMap want = sgm::selectDisparity(f.s, p);
    const sgm::tb::LaneSchedule lanes(w, kLanes, kSkew, kLeadRows);
    // The last slot that writes a word of row y (+1 for the registered dR port):
    // left words at their slot + lag, dR of the diagonal at column xr + D - 1, the
    // row tail during the first D columns of the lane's next row.
    auto lastWrite = [&](int y) {
      long last = lanes.slotOf(w - 1, y) + lag;
      last = std::max(last, lanes.slotOf(w - 1, y) + 1);
      last = std::max(last, lanes.slotOf(std::min(kD, w - 1), y + kLanes) + 1);
      return last;
    };
    auto firstWrite = [&](int y) { return lanes.slotOf(0, y); };
    // The read side: raster index q (rows from -kLeadRows) at slot q + delay; row y
    // is read at rows y + 1 from (0, y + 1) to (W - 1, y + 1) + kDrRead (the dR read).
    auto rasterIndex = [&](int col, int row) { return long(row + kLeadRows) * w + col; };
    long delay = 0;
    for (int y = 0; y < h; ++y) delay = std::max(delay, lastWrite(y) + 1 - rasterIndex(0, y + 1));
    // Row y + ROW_BANKS overwrites row y's words only after their last reads: the
    // left word (x, y) is read at (x, y + 1), dR(xr) by left pixels up to xr + D - 1.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int xl = std::min(x + kD - 1, w - 1);
        if (lanes.slotOf(x, y + kBanks) + lag <= rasterIndex(x, y + 1) + delay ||
            lanes.slotOf(xl, y + kBanks) + 1 <= rasterIndex(xl, y + 1) + delay + kDrRead)
          return "ROW_BANKS = " + std::to_string(kBanks) + " too few for " + std::to_string(kLanes) +
                 " lanes at width " + std::to_string(w) + " (pixel " + std::to_string(x) + ", " + std::to_string(y) +
                 ")";
      }
    const long slots = rasterIndex(w - 1, h) + delay + kLatency + 1;

    const uint32_t rowMask = (1u << kRW) - 1;
    std::vector<uint16_t> junk(kD);
    std::deque<std::pair<int, int>> reads;  // read positions in flight (col, row)
    long received = 0;
    for (long n = 0; n < slots; ++n) {
      // S side.
      const sgm::tb::SlotPosition sp = lanes.at(n);
      const bool real = sp.row >= 0 && sp.row < h;
      sgm::tb::packFields(top_->s_i, real ? f.s.at(sp.col, sp.row) : sgm::tb::junkVector(junk, kMaxS, rng_), kD, kSW);
      top_->col_i = sp.col;
      top_->row_i = uint32_t(sp.row) & rowMask;
      top_->last_i = sp.col == w - 1;
      top_->valid_i = real;
      // WTA side, lag slots later.
      if (n >= lag) {
        const sgm::tb::SlotPosition wp = lanes.at(n - lag);
        const bool wreal = wp.row >= 0 && wp.row < h;
        const sgm::tb::WtaResult r = sgm::tb::goldenWta(wreal ? f.s.at(wp.col, wp.row) : f.s.at(0, 0), kD, f.subpixel,
                                                        f.uniqueness);
        top_->d_i = wreal ? r.d : rng_() % kD;
        top_->disp_i = wreal ? r.disp : rng_() & 0xff;
        top_->unique_i = wreal ? r.unique : rng_() & 1;
        top_->wta_col_i = wp.col;
        top_->wta_row_i = uint32_t(wp.row) & rowMask;
        top_->wta_valid_i = wreal;
      } else {  // before the frame's first WTA slot: a row outside the frame
        top_->d_i = 0;
        top_->disp_i = 0;
        top_->unique_i = 0;
        top_->wta_col_i = 0;
        top_->wta_row_i = uint32_t(-kLeadRows - kLanes) & rowMask;
        top_->wta_valid_i = 0;
      }
      // Read side, raster order.
      const long q = n - delay;
      const int rcol = q >= 0 ? int(q % w) : 0, rrow = q >= 0 ? int(q / w) - kLeadRows : -kLeadRows - 1;
      top_->rd_col_i = rcol;
      top_->rd_row_i = uint32_t(rrow) & rowMask;
      top_->width_i = w;
      top_->height_i = h;
      top_->tol_i = f.tol < 0 ? rng_() & 7 : f.tol;
      top_->dmin_i = 0;  // the minimum disparity: whole-core tests (MIN_DISPARITY builds)
      top_->check_en_i = f.tol >= 0;
      sgm::tb::slotAfterIdle(top_, rng_, idle_);
      reads.emplace_back(rcol, rrow);
      if (int(reads.size()) < kLatency) continue;
      const auto [ox, orow] = reads.front();
      reads.pop_front();
      const int oy = orow - 1;
      const bool expectOut = orow >= 1 && orow <= h;
      std::ostringstream where;
      where << "stage sgm_lr_check (" << kLanes << " lanes, " << w << "x" << h << ", lag " << lag << ") pixel (x=" << ox
            << ", y=" << oy << ")";
      if (bool(top_->out_valid_o) != expectOut)
        return where.str() + ": out_valid_o " + std::to_string(top_->out_valid_o);
      if (!expectOut) continue;
      if (int(top_->col_o) != ox || int(top_->row_o) != oy)
        return where.str() + ": position (" + std::to_string(top_->col_o) + ", " + std::to_string(top_->row_o) + ")";
      const int ed = want.disp.at<uint16_t>(oy, ox), ev = want.valid.at<uint8_t>(oy, ox);
      if (int(top_->disp_o) != ed || int(top_->valid_o) != ev)
        return where.str() + ": expected disp " + std::to_string(ed) + " valid " + std::to_string(ev) + ", got disp " +
               std::to_string(top_->disp_o) + " valid " + std::to_string(top_->valid_o);
      ++received;
    }
    if (received != long(w) * h)
      return "received " + std::to_string(received) + " pixels, expected " + std::to_string(long(w) * h);
    return "";
  }

 private:
  Top top_;
  std::mt19937 rng_;
  double idle_;
};

TEST(SgmLrCheckLanes, RandomVolumesBackToBack) {
  LrLanes lr("sgm_lr_check_lanes", 5, 0.25);
  std::mt19937 rng(41);
  const int widths[] = {kMinWidth, kMinWidth + 7, kMaxWidth, kMinWidth + 30};
  int k = 0;
  for (int w : widths) {
    w = std::min(w, kMaxWidth);
    const int h = 9 + k % 4;
    Frame f{sgm::tb::randomVolume(w, h, kD, k % 2 ? 3 : kMaxS, rng), k % 3 - 1, k % 2 == 0, k % 2 ? 0 : 20};
    EXPECT_EQ(lr.run(f, k % 2 ? sgm::tb::wtaLatency(kD) : 0), "") << "frame " << k;
    ++k;
  }
}

// The first frame after reset from an all-zeros or all-ones power-up state (an
// FPGA after configuration starts at zero) instead of random.
TEST(SgmLrCheckLanes, FirstFrameFromZeroOrOnesPowerUpState) {
  for (int state : {0, 1}) {
    LrLanes lr("sgm_lr_check_lanes_power_up_" + std::to_string(state), 6, 0.2, state);
    std::mt19937 rng(42);
    Frame f{sgm::tb::randomVolume(kMinWidth + 3, 9, kD, kMaxS, rng), 1, true, 10};
    EXPECT_EQ(lr.run(f, sgm::tb::wtaLatency(kD)), "") << "power-up state " << state;
  }
}

}  // namespace
