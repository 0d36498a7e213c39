// SPDX-License-Identifier: Apache-2.0
// Adaptive P2 table, one step of eq. (1), the four path costs and their sum
// (docs/algorithm.md sections 4 and 5).
#include "sgm/aggregate.hpp"
#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <random>

namespace {

using sgm::CostVolume;
using sgm::PathVolume;
constexpr uint16_t S = sgm::kPathSentinel;

std::vector<int> lrAt(const PathVolume& v, int x, int y) { return std::vector<int>(v.at(x, y), v.at(x, y) + v.depth); }

void setCost(CostVolume& v, int x, int y, std::initializer_list<int> c) {
  int d = 0;
  for (int value : c) v.at(x, y)[d++] = uint8_t(value);
}

cv::Mat randomGray(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  return img;
}

CostVolume randomCost(int w, int h, int d, int cmax, std::mt19937& rng) {
  CostVolume v(w, h, d);
  for (auto& c : v.data) c = uint8_t(rng() % (cmax + 1));
  return v;
}

// ------------------------------------------------------------------ P2 table

TEST(P2Table, DocumentedExample) {
  // P2r(k) = max(P1, floor(4 P2' / (k + 4))).
  const sgm::P2Table t = sgm::makeP2Table(7, 100);
  EXPECT_EQ(t[0], 100);
  EXPECT_EQ(t[1], 80);
  EXPECT_EQ(t[2], 66);  // floor(400 / 6)
  EXPECT_EQ(t[3], 57);  // floor(400 / 7)
  EXPECT_EQ(t[53], 7);  // floor(400 / 57) = 7
  EXPECT_EQ(t[54], 7);  // max(P1, 6)
  EXPECT_EQ(t[255], 7);
}

TEST(P2Table, ClampedAtP1AndMonotone) {
  const sgm::P2Table t = sgm::makeP2Table(20, 100);
  EXPECT_EQ(t[0], 100);
  EXPECT_EQ(t[12], 25);
  EXPECT_EQ(t[16], 20);
  EXPECT_EQ(t[17], 20);  // 19 < P1
  for (int k = 1; k < 256; ++k) {
    EXPECT_LE(t[k], t[k - 1]);
    EXPECT_GE(t[k], 20);
  }
  // P1 = P2' = 0: everything 0.
  const sgm::P2Table z = sgm::makeP2Table(0, 0);
  for (int k = 0; k < 256; ++k) EXPECT_EQ(z[k], 0);
}

// ------------------------------------------------------------------ pathStep

TEST(PathStep, EachBranchOfEquationOne) {
  // P1 = 5, P2r = 20; prev = [10, 30, 40, 12, 60, 70] with sentinels around it;
  // minPrev = 10, so the jump term is 30.
  const uint16_t prevBuf[] = {S, 10, 30, 40, 12, 60, 70, S};
  const uint8_t cost[] = {1, 2, 3, 4, 5, 6};
  uint16_t out[6] = {};
  const uint16_t m = sgm::pathStep(cost, prevBuf + 1, 10, 6, 5, 20, out);
  // d=0: min(10, S+5, 35, 30) = 10  prev[d]       -> 1 + 10 - 10 = 1
  // d=1: min(30, 15, 45, 30)   = 15  prev[d-1]+P1  -> 2 + 15 - 10 = 7
  // d=2: min(40, 35, 17, 30)   = 17  prev[d+1]+P1  -> 3 + 17 - 10 = 10
  // d=3: min(12, 45, 65, 30)   = 12  prev[d]       -> 4 + 12 - 10 = 6
  // d=4: min(60, 17, 75, 30)   = 17  prev[d-1]+P1  -> 5 + 17 - 10 = 12
  // d=5: min(70, 65, S+5, 30)  = 30  minPrev+P2r   -> 6 + 30 - 10 = 26
  const std::vector<int> expected = {1, 7, 10, 6, 12, 26};
  EXPECT_EQ(std::vector<int>(out, out + 6), expected);
  EXPECT_EQ(m, 1);
  // The inputs are not modified (sentinels included).
  EXPECT_EQ(prevBuf[0], S);
  EXPECT_EQ(prevBuf[7], S);
}

TEST(PathStep, SentinelsNeverWinAtTheEnds) {
  // prev = [500, 100, 500], minPrev 100, P1 3, P2r at kMaxPenalty: the ends can only come
  // from prev[d] or the inner neighbour (100 + 3). Were prev[-1] / prev[D] read
  // as anything small (e.g. 0), out[0] / out[2] would wrap below zero.
  const uint16_t prevBuf[] = {S, 500, 100, 500, S};
  const uint8_t cost[] = {0, 0, 0};
  uint16_t out[3];
  const uint16_t m = sgm::pathStep(cost, prevBuf + 1, 100, 3, 3, sgm::kMaxPenalty, out);
  EXPECT_EQ(out[0], 3);  // prev[1] + P1 - minPrev
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(out[2], 3);
  EXPECT_EQ(m, 0);
  // Sentinel + max penalty still fits in 16 bits (no wrap to a small value).
  EXPECT_LT(int(sgm::kPathSentinel) + sgm::kMaxPenalty, 65536);
}

TEST(PathStep, SubtractsMinPrevAndReturnsMinimum) {
  // prev = [1000, 1003, 1020], minPrev 1000, P1 2, P2r 8 (jump 1008).
  const uint16_t prevBuf[] = {S, 1000, 1003, 1020, S};
  const uint8_t cost[] = {9, 4, 0};
  uint16_t out[3];
  const uint16_t m = sgm::pathStep(cost, prevBuf + 1, 1000, 3, 2, 8, out);
  // d0: min(1000, 1005, 1008) = 1000 -> 9; d1: min(1003, 1002, 1022, 1008) = 1002 -> 6;
  // d2: min(1020, 1005, 1008) = 1005 -> 5.
  EXPECT_EQ(out[0], 9);
  EXPECT_EQ(out[1], 6);
  EXPECT_EQ(out[2], 5);
  EXPECT_EQ(m, 5);
}

TEST(PathStep, SingleDisparityUsesOnlyPrevAndJump) {
  const uint16_t prevBuf[] = {S, 40, S};
  const uint8_t cost[] = {7};
  uint16_t out[1];
  EXPECT_EQ(sgm::pathStep(cost, prevBuf + 1, 40, 1, 1, 2, out), 7);
  EXPECT_EQ(out[0], 7);
}

TEST(PathStart, CopiesCostAndReturnsMin) {
  const uint8_t cost[] = {9, 4, 160, 4, 80};
  uint16_t out[5];
  EXPECT_EQ(sgm::pathStart(cost, 5, out), 4);
  const std::vector<int> expected = {9, 4, 160, 4, 80};
  EXPECT_EQ(std::vector<int>(out, out + 5), expected);
}

// ------------------------------------------------------------------ pathCost

TEST(PathCost, HandExampleOneRow) {
  // Gray [10, 10, 30], D = 3, P1 = 3, P2' = 100: P2r(0) = 100, P2r(20) = max(3, 5) = 5.
  const cv::Mat gray = (cv::Mat_<uint8_t>(1, 3) << 10, 10, 30);
  CostVolume c(3, 1, 3);
  setCost(c, 0, 0, {0, 5, 9});
  setCost(c, 1, 0, {6, 0, 8});
  setCost(c, 2, 0, {4, 7, 1});
  const PathVolume l0 = sgm::pathCost(c, gray, 0, 3, 100);
  EXPECT_EQ(lrAt(l0, 0, 0), (std::vector<int>{0, 5, 9}));  // path start
  // x=1, m=0, jump 100: d0 min(0, 8) = 0 -> 6; d1 min(5, 3, 12) = 3 -> 3; d2 min(9, 8) = 8 -> 16.
  EXPECT_EQ(lrAt(l0, 1, 0), (std::vector<int>{6, 3, 16}));
  // x=2, m=3, dI=20, jump 3+5=8: d0 min(6, 6, 8) = 6 -> 4+6-3 = 7; d1 min(3, ...) = 3 -> 7;
  // d2 min(16, 3+3, 8) = 6 -> 1+6-3 = 4.
  EXPECT_EQ(lrAt(l0, 2, 0), (std::vector<int>{7, 7, 4}));
  // In a single row every other direction starts at every pixel.
  for (int path : {1, 2, 3}) {
    const PathVolume lr = sgm::pathCost(c, gray, path, 3, 100);
    for (int x = 0; x < 3; ++x)
      EXPECT_EQ(lrAt(lr, x, 0), std::vector<int>(c.at(x, 0), c.at(x, 0) + 3)) << "path " << path;
  }
}

TEST(PathCost, HandExampleOneColumn) {
  // The same numbers down a column: the 90-degree path reproduces the row result.
  const cv::Mat gray = (cv::Mat_<uint8_t>(3, 1) << 10, 10, 30);
  CostVolume c(1, 3, 3);
  setCost(c, 0, 0, {0, 5, 9});
  setCost(c, 0, 1, {6, 0, 8});
  setCost(c, 0, 2, {4, 7, 1});
  const PathVolume l90 = sgm::pathCost(c, gray, 2, 3, 100);
  EXPECT_EQ(lrAt(l90, 0, 0), (std::vector<int>{0, 5, 9}));
  EXPECT_EQ(lrAt(l90, 0, 1), (std::vector<int>{6, 3, 16}));
  EXPECT_EQ(lrAt(l90, 0, 2), (std::vector<int>{7, 7, 4}));
  // With one column, 0, 45 and 135 degrees start at every pixel.
  for (int path : {0, 1, 3}) {
    const PathVolume lr = sgm::pathCost(c, gray, path, 3, 100);
    for (int y = 0; y < 3; ++y)
      EXPECT_EQ(lrAt(lr, 0, y), std::vector<int>(c.at(0, y), c.at(0, y) + 3)) << "path " << path;
  }
}

TEST(PathCost, HandExampleTwoByTwoAllPathsAndSum) {
  // Gray all 10 (P2r = P2' = 100), P1 = 3. Costs: row 0 = [0,5,9], row 1 = [6,0,8].
  const cv::Mat gray(2, 2, CV_8UC1, cv::Scalar(10));
  CostVolume c(2, 2, 3);
  setCost(c, 0, 0, {0, 5, 9});
  setCost(c, 1, 0, {0, 5, 9});
  setCost(c, 0, 1, {6, 0, 8});
  setCost(c, 1, 1, {6, 0, 8});
  using V = std::vector<int>;
  const V row0 = {0, 5, 9}, row1 = {6, 0, 8};
  // [6,0,8] after [0,5,9] (m = 0): d0 min(0, 8) -> 6; d1 min(5, 3, 12) -> 3; d2 min(9, 8) -> 16.
  const V afterRow0 = {6, 3, 16};

  const PathVolume l0 = sgm::pathCost(c, gray, 0, 3, 100);  // from the left
  EXPECT_EQ(lrAt(l0, 0, 0), row0);
  EXPECT_EQ(lrAt(l0, 0, 1), row1);
  // [0,5,9] after [0,5,9]: d0 0; d1 min(5, 3) = 3 -> 8; d2 min(9, 8) = 8 -> 17.
  EXPECT_EQ(lrAt(l0, 1, 0), (V{0, 8, 17}));
  // [6,0,8] after [6,0,8] (m = 0): d0 min(6, 3) -> 9; d1 0; d2 min(8, 3) -> 11.
  EXPECT_EQ(lrAt(l0, 1, 1), (V{9, 0, 11}));

  const PathVolume l45 = sgm::pathCost(c, gray, 1, 3, 100);  // from the upper left
  EXPECT_EQ(lrAt(l45, 0, 0), row0);
  EXPECT_EQ(lrAt(l45, 1, 0), row0);
  EXPECT_EQ(lrAt(l45, 0, 1), row1);
  EXPECT_EQ(lrAt(l45, 1, 1), afterRow0);

  const PathVolume l90 = sgm::pathCost(c, gray, 2, 3, 100);  // from above
  EXPECT_EQ(lrAt(l90, 0, 0), row0);
  EXPECT_EQ(lrAt(l90, 1, 0), row0);
  EXPECT_EQ(lrAt(l90, 0, 1), afterRow0);
  EXPECT_EQ(lrAt(l90, 1, 1), afterRow0);

  const PathVolume l135 = sgm::pathCost(c, gray, 3, 3, 100);  // from the upper right
  EXPECT_EQ(lrAt(l135, 0, 0), row0);
  EXPECT_EQ(lrAt(l135, 1, 0), row0);
  EXPECT_EQ(lrAt(l135, 1, 1), row1);  // x = W-1: path start
  EXPECT_EQ(lrAt(l135, 0, 1), afterRow0);

  // S = 3 L0 + 2 L45 + 3 L90 + 2 L135 (section 5).
  const PathVolume s = sgm::aggregateCost(c, gray, 3, 100);
  EXPECT_EQ(lrAt(s, 0, 0), (V{0, 50, 90}));    // (3+2+3+2) x row0
  EXPECT_EQ(lrAt(s, 1, 0), (V{0, 59, 114}));   // 3 x [0,8,17] + (2+3+2) x row0
  EXPECT_EQ(lrAt(s, 0, 1), (V{60, 15, 120}));  // (3+2) x row1 + (3+2) x afterRow0
  // 3 x [9,0,11] + 2 x afterRow0 + 3 x afterRow0 + 2 x row1 = [27,0,33] + [30,15,80] + [12,0,16];
  // four different Lr here, so a weight on the wrong path shows.
  EXPECT_EQ(lrAt(s, 1, 1), (V{69, 15, 129}));
}

TEST(PathCost, PathStartsAtTheDocumentedBorders) {
  std::mt19937 rng(7);
  const int w = 7, h = 6, nd = 5;
  const cv::Mat gray = randomGray(w, h, rng);
  const CostVolume c = randomCost(w, h, nd, 160, rng);
  auto isStart = [&](int path, int x, int y) {
    switch (path) {
      case 0: return x == 0;
      case 1: return x == 0 || y == 0;
      case 2: return y == 0;
      default: return x == w - 1 || y == 0;
    }
  };
  for (int path = 0; path < 4; ++path) {
    const PathVolume lr = sgm::pathCost(c, gray, path, 7, 100);
    EXPECT_EQ(lr.width, w);
    EXPECT_EQ(lr.height, h);
    EXPECT_EQ(lr.depth, nd);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!isStart(path, x, y)) continue;
        EXPECT_EQ(lrAt(lr, x, y), std::vector<int>(c.at(x, y), c.at(x, y) + nd))
            << "path " << path << " x=" << x << " y=" << y;
      }
  }
}

TEST(PathCost, DirectionTable) {
  EXPECT_EQ(sgm::kPathDirections[0].degrees, 0);
  EXPECT_EQ(sgm::kPathDirections[0].dx, -1);
  EXPECT_EQ(sgm::kPathDirections[0].dy, 0);
  EXPECT_EQ(sgm::kPathDirections[1].degrees, 45);
  EXPECT_EQ(sgm::kPathDirections[1].dx, -1);
  EXPECT_EQ(sgm::kPathDirections[1].dy, -1);
  EXPECT_EQ(sgm::kPathDirections[2].degrees, 90);
  EXPECT_EQ(sgm::kPathDirections[2].dx, 0);
  EXPECT_EQ(sgm::kPathDirections[2].dy, -1);
  EXPECT_EQ(sgm::kPathDirections[3].degrees, 135);
  EXPECT_EQ(sgm::kPathDirections[3].dx, 1);
  EXPECT_EQ(sgm::kPathDirections[3].dy, -1);
}

// Straightforward int implementation of eq. (1) for one path, for cross-checking.
std::vector<int> referencePath(const CostVolume& c, const cv::Mat& gray, int dx, int dy, int p1, int p2) {
  const int w = c.width, h = c.height, nd = c.depth;
  std::vector<int> lr(size_t(w) * h * nd);
  auto L = [&](int x, int y, int d) -> int& { return lr[(size_t(y) * w + x) * nd + d]; };
  // Paths only come from the left, above or the upper right: row-major order
  // is a valid evaluation order for every direction.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || px >= w || py < 0 || py >= h) {
        for (int d = 0; d < nd; ++d) L(x, y, d) = c.at(x, y)[d];
        continue;
      }
      int m = 1 << 30;
      for (int d = 0; d < nd; ++d) m = std::min(m, L(px, py, d));
      const int di = std::abs(int(gray.at<uint8_t>(y, x)) - int(gray.at<uint8_t>(py, px)));
      const int p2r = std::max(p1, 4 * p2 / (di + 4));
      for (int d = 0; d < nd; ++d) {
        int best = std::min(L(px, py, d), m + p2r);
        if (d > 0) best = std::min(best, L(px, py, d - 1) + p1);
        if (d < nd - 1) best = std::min(best, L(px, py, d + 1) + p1);
        L(x, y, d) = c.at(x, y)[d] + best - m;
      }
    }
  return lr;
}

TEST(PathCost, MatchesReferenceRecursionOnRandomInput) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 3; ++trial) {
    const int w = 9 + trial, h = 7 + trial, nd = 4 + 3 * trial;
    // Few gray levels -> many dI = 0 (P2r = P2') next to large dI (P2r = P1).
    cv::Mat gray = randomGray(w, h, rng);
    if (trial == 1) gray = gray / 64 * 64;
    const CostVolume c = randomCost(w, h, nd, 160, rng);
    const int p1 = 5 + trial, p2 = 90 + 40 * trial;
    for (int path = 0; path < 4; ++path) {
      const sgm::PathDirection dir = sgm::kPathDirections[path];
      const std::vector<int> ref = referencePath(c, gray, dir.dx, dir.dy, p1, p2);
      const PathVolume lr = sgm::pathCost(c, gray, path, p1, p2);
      ASSERT_EQ(lr.data.size(), ref.size());
      for (size_t i = 0; i < ref.size(); ++i)
        ASSERT_EQ(int(lr.data[i]), ref[i]) << "trial " << trial << " path " << path << " index " << i;
    }
  }
}

TEST(PathCost, BoundedByMaxCostPlusP2) {
  // Lr <= Cmax + P2r <= Cmax + P2' (section 5), also at the largest penalties.
  std::mt19937 rng(5);
  const int w = 48, h = 32, nd = 32;
  const cv::Mat gray = randomGray(w, h, rng);
  for (int cmax : {44, 88, 255}) {
    const CostVolume c = randomCost(w, h, nd, cmax, rng);
    for (auto [p1, p2] : {std::pair{7, 100}, std::pair{0, 0}, std::pair{6000, 6000}, std::pair{3, 6000}}) {
      int maxSeen = 0;
      for (int path = 0; path < 4; ++path) {
        const PathVolume lr = sgm::pathCost(c, gray, path, p1, p2);
        for (uint16_t v : lr.data) maxSeen = std::max(maxSeen, int(v));
      }
      EXPECT_LE(maxSeen, cmax + p2) << "cmax " << cmax << " P1 " << p1 << " P2 " << p2;
    }
  }
}

TEST(AggregateCost, EqualsWeightedSumOfTheFourPaths) {
  std::mt19937 rng(11);
  const int w = 40, h = 30, nd = 24;
  const cv::Mat gray = randomGray(w, h, rng);
  for (auto [cmax, p1, p2] : {std::tuple{88, 7, 100}, std::tuple{255, 6000, 6000}}) {
    const CostVolume c = randomCost(w, h, nd, cmax, rng);
    const PathVolume s = sgm::aggregateCost(c, gray, p1, p2);
    ASSERT_EQ(s.width, w);
    ASSERT_EQ(s.height, h);
    ASSERT_EQ(s.depth, nd);
    // Sum in int: a 16-bit wrap in S would show up as a mismatch.
    std::vector<int> sum(s.data.size(), 0);
    for (int path = 0; path < 4; ++path) {
      const PathVolume lr = sgm::pathCost(c, gray, path, p1, p2);
      for (size_t i = 0; i < sum.size(); ++i) sum[i] += sgm::kPathWeights[path] * lr.data[i];
    }
    for (size_t i = 0; i < sum.size(); ++i) {
      ASSERT_EQ(int(s.data[i]), sum[i]) << "index " << i << " P2 " << p2;
      ASSERT_LE(sum[i], sgm::kPathWeightSum * (cmax + p2));
    }
  }
}

}  // namespace
