// SPDX-License-Identifier: Apache-2.0
#include "sgm/aggregate.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <cstdlib>
#include <vector>

namespace sgm {

P2Table makeP2Table(int p1, int p2, P2Mode mode) {
  P2Table table{};
  for (int k = 0; k < 256; ++k) {
    const int adapted = mode == P2Mode::kPaper ? (k == 0 ? p2 : p2 / k) : kP2Knee * p2 / (k + kP2Knee);
    table[k] = uint16_t(std::max(p1, adapted));
  }
  return table;
}

namespace {

// Eq. (1) for one pixel; inlined into the path loops below.
inline __attribute__((always_inline)) uint16_t pathStepInline(const uint8_t* cost, const uint16_t* prev,
                                                              uint16_t minPrev, int disparities, int p1, int p2r,
                                                              uint16_t* out) {
  const uint16_t jump = uint16_t(minPrev + p2r);
  const uint16_t step = uint16_t(p1);
  uint16_t minOut = 0xffff;
  for (int d = 0; d < disparities; ++d) {
    uint16_t best = std::min<uint16_t>(prev[d], jump);
    best = std::min<uint16_t>(best, uint16_t(prev[d - 1] + step));
    best = std::min<uint16_t>(best, uint16_t(prev[d + 1] + step));
    const uint16_t value = uint16_t(cost[d] + best - minPrev);
    out[d] = value;
    minOut = std::min(minOut, value);
  }
  return minOut;
}

}  // namespace

uint16_t pathStep(const uint8_t* cost, const uint16_t* prev, uint16_t minPrev, int disparities, int p1, int p2r,
                  uint16_t* out) {
  return pathStepInline(cost, prev, minPrev, disparities, p1, p2r, out);
}

uint16_t pathStart(const uint8_t* cost, int disparities, uint16_t* out) {
  uint16_t minOut = 0xffff;
  for (int d = 0; d < disparities; ++d) {
    out[d] = cost[d];
    minOut = std::min<uint16_t>(minOut, cost[d]);
  }
  return minOut;
}

namespace {

// The path restart at strong edges (Params::edgeReset; in the core: sgm_top EDGE_RESET):
// the steps since the path last crossed a strong edge, 0 at the step across it, saturating
// at `length` (also at a path start); the pixel restarts (Lr = C) while the count is below
// `length`.
inline int stepsSinceEdge(const EdgeReset& reset, int dI, int previous) {
  return dI >= reset.threshold ? 0 : std::min(reset.length, previous + 1);
}

// Lr of one path for the last few rows (a ring of kRows rows), each pixel's D
// values framed by two sentinels. step() may be called for different pixels
// from different threads as long as the pixels it reads are already written.
class PathState {
 public:
  static constexpr int kRows = 4;

  PathState(int width, int disparities, const cv::Mat& gray, int pathIndex, int p1, const P2Table& p2Table,
            bool mgm = false, const EdgeReset& edgeReset = EdgeReset{}, int lrStoreBits = 0)
      : width_(width),
        disparities_(disparities),
        gray_(gray),
        dir_(kPathDirections[pathIndex]),
        perpendicular_(kMgmPerpendicular[pathIndex]),
        mgm_(mgm),
        p1_(p1),
        p2Table_(p2Table),
        reset_(edgeReset.on(pathIndex) ? edgeReset : EdgeReset{0}),
        stride_(disparities + 2),
        rows_(size_t(kRows) * width * stride_, kPathSentinel),
        mins_(size_t(kRows) * width, 0),
        since_(reset_.threshold ? size_t(kRows) * width : 0, 0),
        storeCap_(lrStoreBits > 0 && kPathDirections[pathIndex].dy != 0 ? uint16_t((1 << lrStoreBits) - 1) : 0) {}

  // Computes Lr(x, y, .) from C(x, y, .) and returns it (valid for kRows - 1 more rows).
  const uint16_t* step(int x, int y, const uint8_t* cost) {
    if (mgm_) return stepMgm(x, y, cost);
    uint16_t* out = lr(x, y);
    const int px = x + dir_.dx, py = y + dir_.dy;
    if (px < 0 || px >= width_ || py < 0) {
      if (reset_.threshold) since(x, y) = uint8_t(reset_.length);
      minLr(x, y) = pathStart(cost, disparities_, out);
      return out;
    }
    const int dI = std::abs(int(gray_.at<uint8_t>(y, x)) - int(gray_.at<uint8_t>(py, px)));
    if (reset_.threshold) {
      since(x, y) = uint8_t(stepsSinceEdge(reset_, dI, since(px, py)));
      if (since(x, y) < reset_.length) {
        minLr(x, y) = pathStart(cost, disparities_, out);
        return out;
      }
    }
    if (storeCap_ && py != y) {  // golden-only: the row above's Lr as a narrower memory holds it
      thread_local std::vector<uint16_t> stored;
      stored.assign(size_t(disparities_) + 2, kPathSentinel);
      const uint16_t* prev = lr(px, py);
      const uint16_t minPrev = minLr(px, py);
      for (int d = 0; d < disparities_; ++d)
        stored[size_t(d) + 1] = uint16_t(minPrev + std::min<uint16_t>(uint16_t(prev[d] - minPrev), storeCap_));
      minLr(x, y) = pathStepInline(cost, stored.data() + 1, minPrev, disparities_, p1_, p2Table_[dI], out);
      return out;
    }
    minLr(x, y) = pathStepInline(cost, lr(px, py), minLr(px, py), disparities_, p1_, p2Table_[dI], out);
    return out;
  }

 private:
  bool inside(int x, int y) const { return x >= 0 && x < width_ && y >= 0; }

  // Golden-only MGM (Params::mgm): the mean of eq. (1)'s recursion from p - r and
  // from the perpendicular causal neighbour, each with its own dI; one of them
  // alone when the other is outside the image.
  const uint16_t* stepMgm(int x, int y, const uint8_t* cost) {
    uint16_t* out = lr(x, y);
    const int ax = x + dir_.dx, ay = y + dir_.dy, bx = x + perpendicular_.dx, by = y + perpendicular_.dy;
    const bool a = inside(ax, ay), b = inside(bx, by);
    if (!a && !b) {
      minLr(x, y) = pathStart(cost, disparities_, out);
      return out;
    }
    thread_local std::vector<uint8_t> zero;
    thread_local std::vector<uint16_t> partA, partB;
    zero.assign(size_t(disparities_), 0), partA.resize(size_t(disparities_)), partB.resize(size_t(disparities_));
    const auto part = [&](int px, int py, uint16_t* into) {
      const int dI = std::abs(int(gray_.at<uint8_t>(y, x)) - int(gray_.at<uint8_t>(py, px)));
      pathStepInline(zero.data(), lr(px, py), minLr(px, py), disparities_, p1_, p2Table_[dI], into);
    };
    if (a) part(ax, ay, partA.data());
    if (b) part(bx, by, partB.data());
    uint16_t minOut = 0xffff;
    for (int d = 0; d < disparities_; ++d) {
      const int term = a && b ? (partA[size_t(d)] + partB[size_t(d)]) >> 1 : a ? partA[size_t(d)] : partB[size_t(d)];
      out[d] = uint16_t(cost[d] + term);
      minOut = std::min(minOut, out[d]);
    }
    minLr(x, y) = minOut;
    return out;
  }

  uint16_t* lr(int x, int y) { return rows_.data() + (size_t(y % kRows) * width_ + x) * stride_ + 1; }
  uint16_t& minLr(int x, int y) { return mins_[size_t(y % kRows) * width_ + x]; }
  uint8_t& since(int x, int y) { return since_[size_t(y % kRows) * width_ + x]; }

  const int width_, disparities_;
  const cv::Mat& gray_;
  const PathDirection dir_, perpendicular_;
  const bool mgm_;
  const int p1_;
  const P2Table& p2Table_;
  const EdgeReset reset_;  // threshold 0 when this path does not restart
  const int stride_;
  std::vector<uint16_t> rows_, mins_;
  std::vector<uint8_t> since_;  // stepsSinceEdge per pixel (with a restart only)
  const uint16_t storeCap_;     // golden-only Params::lrStoreBits: Lr - min Lr of the row above, saturated; 0 = off
};

}  // namespace

void addRightPath(const uint8_t* cost, const uint8_t* grayRow, int width, int nd, int p1, const P2Table& table,
                  int weight, uint16_t* sum, int block, const EdgeReset& edgeReset) {
  const bool restarts = edgeReset.on(kPathCount);
  std::vector<uint16_t> buffers(2 * size_t(nd + 2), kPathSentinel);
  // Blocks [jB, (j+1)B) for j = 0 .. m-2 and the last block [(m-1)B, W), m =
  // max(1, W / B): the last takes the remainder (B .. 2B-1 pixels, or the
  // whole row when W < 2B), so that the streaming schedule never has more
  // than two passes in flight (docs/algorithm.md section 12; a partial last
  // block of its own would start at W - 1 too: the same values). Each block's
  // path starts at x0 + 2B - 1 (the next block is its warm-up), the last
  // block's at the row's end; only its values in the block count.
  const int span = block > 0 ? block : width;
  const int blocks = std::max(1, width / span);
  for (int j = 0; j < blocks; ++j) {
    const int x0 = j * span;
    const bool last = j == blocks - 1;
    const int x1 = last ? width : x0 + span;
    const int start = last ? width - 1 : x0 + 2 * span - 1;
    uint16_t* prev = buffers.data() + 1;
    uint16_t* cur = buffers.data() + nd + 3;
    uint16_t minPrev = 0;
    int since = edgeReset.length;
    for (int x = start; x >= x0; --x) {
      const uint8_t* c = cost + size_t(x) * nd;
      const int dI = x == start ? 0 : std::abs(int(grayRow[x]) - int(grayRow[x + 1]));
      if (restarts && x != start) since = stepsSinceEdge(edgeReset, dI, since);
      const uint16_t minCur = x == start || (restarts && since < edgeReset.length)
                                  ? pathStart(c, nd, cur)
                                  : pathStepInline(c, prev, minPrev, nd, p1, table[dI], cur);
      if (x < x1) {
        uint16_t* s = sum + size_t(x) * nd;
        for (int d = 0; d < nd; ++d) s[d] = uint16_t(s[d] + weight * cur[d]);
      }
      std::swap(prev, cur);
      minPrev = minCur;
    }
  }
}

namespace {

void waitUntil(const std::atomic<int>& counter, int value) {
  while (counter.load(std::memory_order_acquire) < value) std::this_thread::yield();
}

}  // namespace

void aggregateRows(int width, int height, int nd, const cv::Mat& gray, int p1, int p2, P2Mode p2Mode,
                   PathWeighting weights, const CostRowFn& costRow, const SumRowFn& sink, int rightPathWeight, bool mgm,
                   int rightPathBlock, const int* p1PathPercent, const EdgeReset& edgeReset, int lrStoreBits) {
  const int* w = pathWeights(weights);
  // Each path's P1 and P2 table (the golden-only per-path P1; one P1 for all in the core).
  int pathP1[kPathCount + 1];
  std::vector<P2Table> tables;
  tables.reserve(kPathCount + 1);  // the paths keep references: no reallocation
  for (int i = 0; i <= kPathCount; ++i) {
    pathP1[i] = p1PathPercent ? p1 * p1PathPercent[i] / 100 : p1;
    tables.push_back(makeP2Table(pathP1[i], p2, p2Mode));
  }
  std::vector<PathState> paths;
  for (int i = 0; i < kPathCount; ++i)
    paths.emplace_back(width, nd, gray, i, pathP1[i], tables[size_t(i)], mgm, edgeReset, lrStoreBits);
  // Two workers split every row at column `split`: the left worker computes
  // C and all four paths of columns 0 .. split-1, the right worker those of
  // split .. W-1 and then hands the whole row of S on. The left worker runs
  // about a row ahead. Dependencies across the split: the right half of row y
  // needs the left half of row y (0 degrees, and 45 degrees from row y-1);
  // the left half of row y+1 needs the first right pixel of row y (135 degrees).
  constexpr int kSlots = PathState::kRows;
  const int split = std::clamp(width * 11 / 20, 1, width);  // the right worker also selects
  const size_t rowSize = size_t(width) * nd;
  std::vector<uint8_t> costRing(rowSize * kSlots);
  std::vector<uint16_t> sumRing(rowSize * kSlots);
  std::atomic<int> leftRows{0}, rightStarted{0}, rightRows{0};
  auto columns = [&](int y, int x0, int x1, const std::function<void()>& afterFirst) {
    uint8_t* cost = costRing.data() + rowSize * (y % kSlots);
    uint16_t* sum = sumRing.data() + rowSize * (y % kSlots);
    costRow(y, x0, x1, cost);
    for (int x = x0; x < x1; ++x) {
      const uint8_t* c = cost + size_t(x) * nd;
      const uint16_t* l0 = paths[0].step(x, y, c);
      const uint16_t* l1 = paths[1].step(x, y, c);
      const uint16_t* l2 = paths[2].step(x, y, c);
      const uint16_t* l3 = paths[3].step(x, y, c);
      uint16_t* s = sum + size_t(x) * nd;
      for (int d = 0; d < nd; ++d) s[d] = uint16_t(w[0] * l0[d] + w[1] * l1[d] + w[2] * l2[d] + w[3] * l3[d]);
      if (x == x0) afterFirst();
    }
  };
  runConcurrently({[&] {
                     for (int y = 0; y < height; ++y) {
                       waitUntil(rightStarted, y);            // pixel (split, y-1) for 135 degrees
                       waitUntil(rightRows, y - kSlots + 2);  // ring slots of row y - kSlots are free
                       columns(y, 0, split, [] {});
                       leftRows.store(y + 1, std::memory_order_release);
                     }
                   },
                   [&] {
                     for (int y = 0; y < height; ++y) {
                       waitUntil(leftRows, y + 1);
                       if (split < width)
                         columns(y, split, width, [&] { rightStarted.store(y + 1, std::memory_order_release); });
                       else
                         rightStarted.store(y + 1, std::memory_order_release);
                       if (rightPathWeight)  // the whole row of C is in its slot now
                         addRightPath(costRing.data() + rowSize * (y % kSlots), gray.ptr<uint8_t>(y), width, nd,
                                      pathP1[kPathCount], tables[kPathCount], rightPathWeight,
                                      sumRing.data() + rowSize * (y % kSlots), rightPathBlock, edgeReset);
                       sink(1, y, sumRing.data() + rowSize * (y % kSlots));
                       rightRows.store(y + 1, std::memory_order_release);
                     }
                   }});
}

PathVolume pathCost(const CostVolume& cost, const cv::Mat& grayLeft, int pathIndex, int p1, int p2, P2Mode p2Mode) {
  const P2Table table = makeP2Table(p1, p2, p2Mode);
  PathState path(cost.width, cost.depth, grayLeft, pathIndex, p1, table);
  PathVolume lr(cost.width, cost.height, cost.depth);
  for (int y = 0; y < cost.height; ++y)
    for (int x = 0; x < cost.width; ++x) std::copy_n(path.step(x, y, cost.at(x, y)), cost.depth, lr.at(x, y));
  return lr;
}

PathVolume aggregateCost(const CostVolume& cost, const cv::Mat& grayLeft, int p1, int p2, P2Mode p2Mode,
                         PathWeighting weights, int rightPathWeight, bool mgm, int rightPathBlock,
                         const int* p1PathPercent, const EdgeReset& edgeReset, int lrStoreBits) {
  PathVolume sum(cost.width, cost.height, cost.depth);
  const size_t rowSize = size_t(cost.width) * cost.depth;
  aggregateRows(
      cost.width, cost.height, cost.depth, grayLeft, p1, p2, p2Mode, weights,
      [&](int y, int x0, int x1, uint8_t* row) {
        std::copy(cost.at(x0, y), cost.at(x0, y) + size_t(x1 - x0) * cost.depth, row + size_t(x0) * cost.depth);
      },
      [&](int, int y, const uint16_t* row) { std::copy_n(row, rowSize, sum.at(0, y)); }, rightPathWeight, mgm,
      rightPathBlock, p1PathPercent, edgeReset, lrStoreBits);
  return sum;
}

}  // namespace sgm
