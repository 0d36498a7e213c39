// SPDX-License-Identifier: Apache-2.0
// The slot order of K row lanes (docs/lanes.md): slot K n + k belongs to
// lane k; lane k holds the rows y with (y + leadRows) mod K == k, each lane a
// virtual raster of its own rows (consecutive slots of a lane are consecutive
// positions, rows < 0 and >= height carry no pixel), and lane k runs `skew`
// columns behind lane k - 1. With K = 1 this is the plain raster, leadRows
// rows before row 0.
#pragma once

namespace sgm::tb {

struct SlotPosition {
  int col;
  int row;  // may be negative (before the frame) or >= height (after it)
};

class LaneSchedule {
 public:
  LaneSchedule(int width, int lanes, int skew, int leadRows)
      : width_(width), lanes_(lanes), skew_(skew), leadRows_(leadRows) {}

  SlotPosition at(long slot) const {
    const long lane = slot % lanes_, round = slot / lanes_;
    const long index = round - lane * skew_;  // position in the lane's own raster
    const long laneRow = floorDiv(index, width_);
    return {int(index - laneRow * width_), int(laneRow * lanes_ + lane - leadRows_)};
  }

  // The slot of position (col, row), row >= -leadRows.
  long slotOf(int col, int row) const {
    const long lane = (row + leadRows_) % lanes_, laneRow = (row + leadRows_) / lanes_;
    return ((laneRow * width_ + col) + lane * skew_) * lanes_ + lane;
  }

  // The first slot after which every position of rows < `rows` has had its slot.
  long slotsToCover(int rows) const {
    long last = 0;
    for (int row = rows - 1; row >= 0 && row >= rows - lanes_; --row)
      if (slotOf(width_ - 1, row) + 1 > last) last = slotOf(width_ - 1, row) + 1;
    return last;
  }

 private:
  static long floorDiv(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  int width_, lanes_, skew_, leadRows_;
};

}  // namespace sgm::tb
