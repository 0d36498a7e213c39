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

// sum = Lr of path a + Lr of path b over row y.
void twoPaths(PathState& a, PathState& b, int y, int width, int nd, const uint8_t* cost, uint16_t* sum) {
  for (int x = 0; x < width; ++x) {
    const uint8_t* c = cost + size_t(x) * nd;
    const uint16_t* la = a.step(x, y, c);
    const uint16_t* lb = b.step(x, y, c);
    uint16_t* s = sum + size_t(x) * nd;
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
  // Row y lives in ring slot y % kSlots. Worker w computes half w of C two rows
  // ahead (so it rarely waits for the other worker's half), then two of the four paths of the current row into its own partial
  // sum; the worker that finishes a row second adds the two partial sums and
  // hands S on. Counters say how far each worker got; every wait is on work
  // the other worker does without waiting for this one, so nothing deadlocks.
  constexpr int kSlots = 4;
  const size_t rowSize = size_t(width) * nd;
  std::vector<uint8_t> costRing(rowSize * kSlots);
  std::vector<uint16_t> sumRing[2] = {std::vector<uint16_t>(rowSize * kSlots), std::vector<uint16_t>(rowSize * kSlots)};
  std::atomic<int> costRows[2] = {0, 0};  // rows whose C half w is written
  std::atomic<int> pathRows[2] = {0, 0};  // rows whose paths of worker w are done
  std::atomic<int> arrivals[kSlots] = {0, 0, 0, 0};
  std::atomic<int> slotFreeFrom[kSlots] = {0, 1, 2, 3};  // first row that may use the slot
  auto worker = [&](int w) {
    PathState a(width, nd, gray, w == 0 ? 0 : 1, p1, table), b(width, nd, gray, w == 0 ? 2 : 3, p1, table);
    const int x0 = w == 0 ? 0 : width / 2, x1 = w == 0 ? width / 2 : width;
    auto costHalf = [&](int y) {
      if (y >= height) return;
      waitUntil(pathRows[0], y - kSlots + 1);  // slot no longer read by either worker's paths
      waitUntil(pathRows[1], y - kSlots + 1);
      costRow(y, x0, x1, costRing.data() + rowSize * (y % kSlots));
      costRows[w].store(y + 1, std::memory_order_release);
    };
    costHalf(0);
    costHalf(1);
    for (int y = 0; y < height; ++y) {
      costHalf(y + 2);
      waitUntil(costRows[1 - w], y + 1);
      waitUntil(slotFreeFrom[y % kSlots], y);  // S of row y - kSlots handed on
      const uint8_t* cost = costRing.data() + rowSize * (y % kSlots);
      uint16_t* mine = sumRing[w].data() + rowSize * (y % kSlots);
      twoPaths(a, b, y, width, nd, cost, mine);
      pathRows[w].store(y + 1, std::memory_order_release);
      if (arrivals[y % kSlots].fetch_add(1, std::memory_order_acq_rel) == 1) {  // second to finish row y
        arrivals[y % kSlots].store(0, std::memory_order_relaxed);
        const uint16_t* other = sumRing[1 - w].data() + rowSize * (y % kSlots);
        for (size_t i = 0; i < rowSize; ++i) mine[i] = uint16_t(mine[i] + other[i]);
        sink(w, y, mine);
        slotFreeFrom[y % kSlots].store(y + kSlots, std::memory_order_release);
      }
    }
  };
  runConcurrently({[&] { worker(0); }, [&] { worker(1); }});
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
      [&](int y, int x0, int x1, uint8_t* row) {
        std::copy(cost.at(x0, y), cost.at(x0, y) + size_t(x1 - x0) * cost.depth, row + size_t(x0) * cost.depth);
      },
      [&](int, int y, const uint16_t* row) { std::copy_n(row, rowSize, sum.at(0, y)); });
  return sum;
}

}  // namespace sgm
