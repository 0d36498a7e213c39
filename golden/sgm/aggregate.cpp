#include "sgm/aggregate.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <cstdlib>
#include <vector>

namespace sgm {

P2Table makeP2Table(int p1, int p2) {
  P2Table table{};
  table[0] = uint16_t(p2);
  for (int k = 1; k < 256; ++k) table[k] = uint16_t(std::max(p1, p2 / k));
  return table;
}

uint16_t pathStep(const uint8_t* cost, const uint16_t* prev, uint16_t minPrev, int disparities,
                  int p1, int p2r, uint16_t* out) {
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

uint16_t pathStart(const uint8_t* cost, int disparities, uint16_t* out) {
  uint16_t minOut = 0xffff;
  for (int d = 0; d < disparities; ++d) {
    out[d] = cost[d];
    minOut = std::min<uint16_t>(minOut, cost[d]);
  }
  return minOut;
}

namespace {

// Running state of one path over the image, one row at a time: the Lr of the
// previous and current rows, each pixel's D values framed by two sentinels.
class PathState {
 public:
  PathState(int width, int disparities, const cv::Mat& gray, int pathIndex, int p1, const P2Table& p2Table)
      : width_(width), disparities_(disparities), gray_(gray), dir_(kPathDirections[pathIndex]), p1_(p1),
        p2Table_(p2Table), stride_(disparities + 2), prevRow_(size_t(width) * stride_, kPathSentinel),
        curRow_(prevRow_), prevMin_(width, 0), curMin_(width, 0) {}

  // Computes Lr(x, y, .) from C(x, y, .) and returns it (valid until the row after next).
  const uint16_t* step(int x, int y, const uint8_t* cost) {
    uint16_t* out = curRow_.data() + size_t(x) * stride_ + 1;
    const int px = x + dir_.dx, py = y + dir_.dy;
    if (px < 0 || px >= width_ || py < 0) {
      curMin_[x] = pathStart(cost, disparities_, out);
      return out;
    }
    const bool sameRow = dir_.dy == 0;
    const uint16_t* prev = (sameRow ? curRow_ : prevRow_).data() + size_t(px) * stride_ + 1;
    const uint16_t minPrev = sameRow ? curMin_[px] : prevMin_[px];
    const int dI = std::abs(int(gray_.at<uint8_t>(y, x)) - int(gray_.at<uint8_t>(py, px)));
    curMin_[x] = pathStep(cost, prev, minPrev, disparities_, p1_, p2Table_[dI], out);
    return out;
  }

  void endRow() {
    std::swap(prevRow_, curRow_);
    std::swap(prevMin_, curMin_);
  }

 private:
  const int width_, disparities_;
  const cv::Mat& gray_;
  const PathDirection dir_;
  const int p1_;
  const P2Table& p2Table_;
  const int stride_;
  std::vector<uint16_t> prevRow_, curRow_;
  std::vector<uint16_t> prevMin_, curMin_;
};

// sum (+)= Lr of path a + Lr of path b over row y.
void addTwoPaths(PathState& a, PathState& b, int y, int width, int nd, const uint8_t* cost, bool accumulate,
                 uint16_t* sum) {
  for (int x = 0; x < width; ++x) {
    const uint8_t* c = cost + size_t(x) * nd;
    const uint16_t* la = a.step(x, y, c);
    const uint16_t* lb = b.step(x, y, c);
    uint16_t* s = sum + size_t(x) * nd;
    if (accumulate)
      for (int d = 0; d < nd; ++d) s[d] = uint16_t(s[d] + la[d] + lb[d]);
    else
      for (int d = 0; d < nd; ++d) s[d] = uint16_t(la[d] + lb[d]);
  }
  a.endRow();
  b.endRow();
}

void waitUntil(const std::atomic<int>& counter, int value) {
  while (counter.load(std::memory_order_acquire) < value) std::this_thread::yield();
}

}  // namespace

void aggregateRows(int width, int height, int nd, const cv::Mat& gray, int p1, int p2, const CostRowFn& costRow,
                   const SumRowFn& sink) {
  const P2Table table = makeP2Table(p1, p2);
  // A ring of row slots: the first worker computes C and Lr(0) + Lr(90) into
  // slot y % kSlots; the second adds Lr(45) + Lr(135) and hands the row on.
  constexpr int kSlots = 4;
  const size_t rowSize = size_t(width) * nd;
  std::vector<uint8_t> costRing(rowSize * kSlots);
  std::vector<uint16_t> sumRing(rowSize * kSlots);
  std::atomic<int> rowsFirst{0}, rowsSecond{0};
  runConcurrently({[&] {
                     PathState p0(width, nd, gray, 0, p1, table), p90(width, nd, gray, 2, p1, table);
                     for (int y = 0; y < height; ++y) {
                       waitUntil(rowsSecond, y - kSlots + 1);  // slot free again
                       uint8_t* cost = costRing.data() + rowSize * (y % kSlots);
                       costRow(y, cost);
                       addTwoPaths(p0, p90, y, width, nd, cost, false, sumRing.data() + rowSize * (y % kSlots));
                       rowsFirst.store(y + 1, std::memory_order_release);
                     }
                   },
                   [&] {
                     PathState p45(width, nd, gray, 1, p1, table), p135(width, nd, gray, 3, p1, table);
                     for (int y = 0; y < height; ++y) {
                       waitUntil(rowsFirst, y + 1);
                       const uint8_t* cost = costRing.data() + rowSize * (y % kSlots);
                       uint16_t* sum = sumRing.data() + rowSize * (y % kSlots);
                       addTwoPaths(p45, p135, y, width, nd, cost, true, sum);
                       sink(y, sum);
                       rowsSecond.store(y + 1, std::memory_order_release);
                     }
                   }});
}

PathVolume pathCost(const CostVolume& cost, const cv::Mat& grayLeft, int pathIndex, int p1, int p2) {
  const P2Table table = makeP2Table(p1, p2);
  PathState path(cost.width, cost.depth, grayLeft, pathIndex, p1, table);
  PathVolume lr(cost.width, cost.height, cost.depth);
  for (int y = 0; y < cost.height; ++y) {
    for (int x = 0; x < cost.width; ++x) std::copy_n(path.step(x, y, cost.at(x, y)), cost.depth, lr.at(x, y));
    path.endRow();
  }
  return lr;
}

PathVolume aggregateCost(const CostVolume& cost, const cv::Mat& grayLeft, int p1, int p2) {
  PathVolume sum(cost.width, cost.height, cost.depth);
  const size_t rowSize = size_t(cost.width) * cost.depth;
  aggregateRows(
      cost.width, cost.height, cost.depth, grayLeft, p1, p2,
      [&](int y, uint8_t* row) { std::copy_n(cost.at(0, y), rowSize, row); },
      [&](int y, const uint16_t* row) { std::copy_n(row, rowSize, sum.at(0, y)); });
  return sum;
}

}  // namespace sgm
