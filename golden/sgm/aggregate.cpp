#include "sgm/aggregate.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
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

// Adds Lr of one path to acc (a W x H x D volume), row by row. Each row keeps
// its Lr with one sentinel on each side of every pixel's disparity vector.
void accumulatePath(const CostVolume& cost, const cv::Mat& gray, int pathIndex, int p1,
                    const P2Table& p2Table, PathVolume& acc) {
  const int w = cost.width, h = cost.height, nd = cost.depth, stride = nd + 2;
  const PathDirection dir = kPathDirections[pathIndex];
  std::vector<uint16_t> prevRow(size_t(w) * stride, kPathSentinel), curRow(prevRow);
  std::vector<uint16_t> prevMin(w, 0), curMin(w, 0);
  for (int y = 0; y < h; ++y) {
    const uint8_t* grayRow = gray.ptr<uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      uint16_t* out = curRow.data() + size_t(x) * stride + 1;
      const int px = x + dir.dx, py = y + dir.dy;
      if (px < 0 || px >= w || py < 0) {
        curMin[x] = pathStart(cost.at(x, y), nd, out);
      } else {
        const bool sameRow = dir.dy == 0;
        const uint16_t* prev = (sameRow ? curRow : prevRow).data() + size_t(px) * stride + 1;
        const uint16_t minPrev = sameRow ? curMin[px] : prevMin[px];
        const int dI = std::abs(int(grayRow[x]) - int(gray.at<uint8_t>(py, px)));
        curMin[x] = pathStep(cost.at(x, y), prev, minPrev, nd, p1, p2Table[dI], out);
      }
      uint16_t* s = acc.at(x, y);
      for (int d = 0; d < nd; ++d) s[d] = uint16_t(s[d] + out[d]);
    }
    std::swap(prevRow, curRow);
    std::swap(prevMin, curMin);
  }
}

}  // namespace

PathVolume pathCost(const CostVolume& cost, const cv::Mat& grayLeft, int pathIndex, int p1, int p2) {
  PathVolume lr(cost.width, cost.height, cost.depth);
  accumulatePath(cost, grayLeft, pathIndex, p1, makeP2Table(p1, p2), lr);
  return lr;
}

PathVolume aggregateCost(const CostVolume& cost, const cv::Mat& grayLeft, int p1, int p2) {
  const P2Table table = makeP2Table(p1, p2);
  PathVolume sum(cost.width, cost.height, cost.depth), other(sum);
  // Two workers: paths 0 and 90 degrees into sum, 45 and 135 degrees into other.
  runConcurrently({[&] {
                     accumulatePath(cost, grayLeft, 0, p1, table, sum);
                     accumulatePath(cost, grayLeft, 2, p1, table, sum);
                   },
                   [&] {
                     accumulatePath(cost, grayLeft, 1, p1, table, other);
                     accumulatePath(cost, grayLeft, 3, p1, table, other);
                   }});
  for (size_t i = 0; i < sum.data.size(); ++i) sum.data[i] = uint16_t(sum.data[i] + other.data[i]);
  return sum;
}

}  // namespace sgm
