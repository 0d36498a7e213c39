// SPDX-License-Identifier: Apache-2.0
// Matching costs (docs/algorithm.md section 3): the three hardware modes on
// census pairs, the out-of-image cost, and the software modes sad, bt, sad+rt
// on hand-made images.
#include "sgm/census.hpp"
#include "sgm/cost.hpp"
#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <random>

namespace {

using sgm::Census;
using sgm::CostMode;
using sgm::CostVolume;

Census censusOf(std::initializer_list<int> bits) {
  Census c;
  for (int k : bits) c.set(k);
  return c;
}

std::vector<int> costsAt(const CostVolume& v, int x, int y) {
  return std::vector<int>(v.at(x, y), v.at(x, y) + v.depth);
}

cv::Mat randomImage(int w, int h, unsigned seed, int lo = 0, int hi = 255) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> dist(lo, hi);
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(dist(rng));
  return img;
}

TEST(CensusCost, ModesOnHandPairs) {
  // Bits 0..43 of the 44-bit signature; 43 (offset (4,2)) is the last one.
  const Census left = censusOf({0, 1, 2, 40});                     // rank 4
  const Census right = censusOf({1, 2, 3, 4, 43});                 // rank 5; xor = {0,3,4,40,43}
  EXPECT_EQ(sgm::censusCost(CostMode::kRt, left, right), 1);       // |4 - 5|
  EXPECT_EQ(sgm::censusCost(CostMode::kRsad, left, right), 5);     // |xor|
  EXPECT_EQ(sgm::censusCost(CostMode::kUnified, left, right), 6);  // 1 + 5
  // Same rank, different bits: rt is blind to it, rsad is not (xor = {5,6,42,43}).
  const Census a = censusOf({5, 42}), b = censusOf({6, 43});
  EXPECT_EQ(sgm::censusCost(CostMode::kRt, a, b), 0);
  EXPECT_EQ(sgm::censusCost(CostMode::kRsad, a, b), 4);
  EXPECT_EQ(sgm::censusCost(CostMode::kUnified, a, b), 4);
}

TEST(CensusCost, ExtremesReachMaxCost) {
  // All 44 bits against none: rank 44 vs 0, Hamming 44; unified adds both.
  Census all;
  for (int k = 0; k < 44; ++k) all.set(k);
  const Census none;
  EXPECT_EQ(sgm::censusCost(CostMode::kRt, all, none), 44);
  EXPECT_EQ(sgm::censusCost(CostMode::kRsad, none, all), 44);
  EXPECT_EQ(sgm::censusCost(CostMode::kUnified, all, none), 88);
  EXPECT_EQ(sgm::censusCost(CostMode::kUnified, all, all), 0);
}

TEST(CensusCost, SoftwareModesThrow) {
  const Census c;
  for (CostMode m : {CostMode::kSad, CostMode::kBt, CostMode::kSadRt})
    EXPECT_THROW(sgm::censusCost(m, c, c), sgm::Error) << sgm::costModeName(m);
}

TEST(MaxCost, DocumentedValues) {
  // 9x5 census: 44 bits, so rank differences and Hamming distances are 0..44;
  // unified is their sum (0..88); sad+rt is rescaled to the rank scale (0..44).
  EXPECT_EQ(sgm::maxCost(CostMode::kRt, sgm::CensusWindow::k9x5), 44);
  EXPECT_EQ(sgm::maxCost(CostMode::kRsad, sgm::CensusWindow::k9x5), 44);
  EXPECT_EQ(sgm::maxCost(CostMode::kUnified, sgm::CensusWindow::k9x5), 88);
  EXPECT_EQ(sgm::maxCost(CostMode::kSad, sgm::CensusWindow::k9x5), 255);
  EXPECT_EQ(sgm::maxCost(CostMode::kBt, sgm::CensusWindow::k9x5), 255);
  EXPECT_EQ(sgm::maxCost(CostMode::kSadRt, sgm::CensusWindow::k9x5), 44);
}

TEST(ComputeCost, MatchOutsideRightImageCostsMax) {
  const cv::Mat l = randomImage(14, 11, 1), r = randomImage(14, 11, 2);
  const struct {
    CostMode mode;
    int expected;
  } cases[] = {{CostMode::kRt, 44},   {CostMode::kRsad, 44}, {CostMode::kUnified, 88},
               {CostMode::kSad, 255}, {CostMode::kBt, 255},  {CostMode::kSadRt, 44}};
  for (const auto& c : cases) {
    const CostVolume v = sgm::computeCost(l, r, c.mode, 9);
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < 8; ++x)
        for (int d = x + 1; d < 9; ++d)
          ASSERT_EQ(v.at(x, y)[d], c.expected) << sgm::costModeName(c.mode) << " x=" << x << " y=" << y << " d=" << d;
  }
}

TEST(ComputeCost, VolumeShapeAndLayout) {
  const cv::Mat l = randomImage(13, 11, 3), r = randomImage(13, 11, 4);
  const CostVolume v = sgm::computeCost(l, r, CostMode::kUnified, 7);
  EXPECT_EQ(v.width, 13);
  EXPECT_EQ(v.height, 11);
  EXPECT_EQ(v.depth, 7);
  EXPECT_EQ(v.data.size(), size_t(13 * 11 * 7));
  EXPECT_EQ(v.at(1, 0) - v.at(0, 0), 7);  // pixel-major, disparities adjacent
  EXPECT_EQ(v.at(0, 1) - v.at(0, 0), 13 * 7);
}

TEST(ComputeCost, IdenticalImagesCostZeroAtZeroDisparity) {
  const cv::Mat img = randomImage(16, 12, 5);
  for (CostMode m : sgm::allCostModes()) {
    const CostVolume v = sgm::computeCost(img, img, m, 4);
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) ASSERT_EQ(v.at(x, y)[0], 0) << sgm::costModeName(m);
  }
}

TEST(ComputeCost, CensusModesOnShiftedDarkPixel) {
  // Left: constant 100 with a dark pixel at (5,5); right: the same pixel at (3,5),
  // i.e. a true disparity of 2.
  cv::Mat l(10, 12, CV_8UC1, cv::Scalar(100)), r(10, 12, CV_8UC1, cv::Scalar(100));
  l.at<uint8_t>(5, 5) = 50;
  r.at<uint8_t>(5, 3) = 50;
  // At p = (7,6) the left census has the single bit of offset (-2,-1):
  // k = 9(dy+2) + (dx+4) = 9 + 2 = 11; the right census at (7-d, 6) has the
  // single bit of offset (-4+d, -1) = 9 + d for d = 0..7 (the dark pixel stays
  // in the window). So rsad = 2 except at d = 2, rt = 0 (both ranks 1), and
  // d = 8, 9 fall outside the right image: Cmax = 44 (rt, rsad), 88 (unified).
  const std::vector<int> rt = {0, 0, 0, 0, 0, 0, 0, 0, 44, 44};
  const std::vector<int> rsad = {2, 2, 0, 2, 2, 2, 2, 2, 44, 44};
  const std::vector<int> unified = {2, 2, 0, 2, 2, 2, 2, 2, 88, 88};
  EXPECT_EQ(costsAt(sgm::computeCost(l, r, CostMode::kRt, 10), 7, 6), rt);
  EXPECT_EQ(costsAt(sgm::computeCost(l, r, CostMode::kRsad, 10), 7, 6), rsad);
  EXPECT_EQ(costsAt(sgm::computeCost(l, r, CostMode::kUnified, 10), 7, 6), unified);
  // At p = (5,5), d = 0: left census is empty (the dark centre), the right
  // census has the bit of offset (-2,0) = 9*2 + 2 = 20: ranks 0 vs 1, Hamming 1.
  EXPECT_EQ(sgm::computeCost(l, r, CostMode::kRt, 4).at(5, 5)[0], 1);
  EXPECT_EQ(sgm::computeCost(l, r, CostMode::kRsad, 4).at(5, 5)[0], 1);
  EXPECT_EQ(sgm::computeCost(l, r, CostMode::kUnified, 4).at(5, 5)[0], 2);
}

TEST(ComputeCost, CensusModesEqualCensusCostOfTheTransforms) {
  // Wiring check: C(x, y, d) is censusCost(left census at x, right census at x - d).
  const cv::Mat l = randomImage(15, 12, 6), r = randomImage(15, 12, 7);
  const auto cl = sgm::censusTransform(l), cr = sgm::censusTransform(r);
  for (CostMode m : {CostMode::kRt, CostMode::kRsad, CostMode::kUnified}) {
    const CostVolume v = sgm::computeCost(l, r, m, 6);
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 15; ++x)
        for (int d = 0; d <= std::min(x, 5); ++d) {
          const Census &a = cl[size_t(y) * 15 + x], &b = cr[size_t(y) * 15 + x - d];
          int expected = std::abs(a.rank() - b.rank());
          if (m == CostMode::kRsad) expected = sgm::hammingDistance(a, b);
          if (m == CostMode::kUnified) expected += sgm::hammingDistance(a, b);
          ASSERT_EQ(v.at(x, y)[d], expected) << sgm::costModeName(m);
        }
  }
}

TEST(ComputeCost, BirchfieldTomasiHandExample) {
  // One row. Left [10, 21, 60, 60], right [0, 30, 30, 30].
  const cv::Mat l = (cv::Mat_<uint8_t>(1, 4) << 10, 21, 60, 60);
  const cv::Mat r = (cv::Mat_<uint8_t>(1, 4) << 0, 30, 30, 30);
  const CostVolume v = sgm::computeCost(l, r, CostMode::kBt, 3);
  // x=1, d=1: left 21 vs right interval around x=0: [0, 15] -> 6;
  //           right 0 vs left interval around x=1: [15.5, 40.5] -> 15.5; min 6.
  EXPECT_EQ(v.at(1, 0)[1], 6);
  // x=2, d=1: left interval [40.5, 60] vs right 30 -> 10.5; right interval
  //           [15, 30] vs left 60 -> 30; min 10.5, rounded half up -> 11.
  EXPECT_EQ(v.at(2, 0)[1], 11);
  // x=2, d=0: right interval around x=2 is [30, 30]; left interval [40.5, 60] -> 10.5 -> 11.
  EXPECT_EQ(v.at(2, 0)[0], 11);
  // x=3, d=0: both intervals degenerate (60 and 30) -> 30.
  EXPECT_EQ(v.at(3, 0)[0], 30);
  // x=3, d=2: right x=1 interval [15, 30]; left 60, left interval [60, 60] -> 30.
  EXPECT_EQ(v.at(3, 0)[2], 30);
  // x=0, d=0: left interval [10, 15.5], right interval [0, 15]: 10 is inside [0, 15] -> 0.
  EXPECT_EQ(v.at(0, 0)[0], 0);
  EXPECT_EQ(v.at(0, 0)[1], 255);
  EXPECT_EQ(v.at(1, 0)[2], 255);
}

TEST(ComputeCost, SadOnConstantOffsetPair) {
  // right(x) = left(x + 3) + 5: at d = 3 every window difference is exactly 5.
  const int w = 24, h = 16;
  const cv::Mat l = randomImage(w, h, 8, 0, 200);
  cv::Mat r = randomImage(w, h, 9, 0, 250);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x + 3 < w; ++x) r.at<uint8_t>(y, x) = uint8_t(l.at<uint8_t>(y, x + 3) + 5);
  const CostVolume v = sgm::computeCost(l, r, CostMode::kSad, 6);
  for (int y = 0; y < h; ++y)
    for (int x = 3; x < w; ++x) ASSERT_EQ(v.at(x, y)[3], 5) << "x=" << x << " y=" << y;
}

TEST(ComputeCost, SadRoundsTheMeanHalfUp) {
  // |left - right| = 1 on odd columns, 0 on even ones. An interior 9x5 window
  // centred on an odd column holds 5 odd columns: 25 / 45 = 0.56 -> 1; on an
  // even column 4 odd columns: 20 / 45 = 0.44 -> 0.
  cv::Mat l(12, 14, CV_8UC1), r(12, 14, CV_8UC1, cv::Scalar(100));
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 14; ++x) l.at<uint8_t>(y, x) = uint8_t(100 + (x & 1));
  const CostVolume v = sgm::computeCost(l, r, CostMode::kSad, 2);
  for (int y = 4; y < 8; ++y) {
    EXPECT_EQ(v.at(5, y)[0], 1);
    EXPECT_EQ(v.at(6, y)[0], 0);
    EXPECT_EQ(v.at(7, y)[0], 1);
  }
  // Corner (0,0): window clipped to columns 0..4 (2 odd of 5), rows 0..2:
  // 6 / 15 = 0.4 -> 0. Column 1 at row 0: columns 0..5 (3 odd of 6): 9 / 18 = 0.5 -> 1.
  EXPECT_EQ(v.at(0, 0)[0], 0);
  EXPECT_EQ(v.at(1, 0)[0], 1);
}

TEST(ComputeCost, SadRtOnConstantImages) {
  // Constant images: all census signatures empty -> rt = 0; SAD = 100.
  // SADn = (100*44 + 127) / 255 = 4527 / 255 = 17; cost = (2*17 + 0 + 5) / 10 = 3.
  // Outside the right image: Cmax = 44.
  const cv::Mat l(12, 12, CV_8UC1, cv::Scalar(100)), r(12, 12, CV_8UC1, cv::Scalar(200));
  const CostVolume v = sgm::computeCost(l, r, CostMode::kSadRt, 3);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x)
      for (int d = 0; d < 3; ++d) ASSERT_EQ(v.at(x, y)[d], x - d >= 0 ? 3 : 44);
  // SAD 255 (0 vs 255): SADn = (255*44 + 127) / 255 = 44 -> (88 + 5) / 10 = 9.
  const cv::Mat black(12, 12, CV_8UC1, cv::Scalar(0)), white(12, 12, CV_8UC1, cv::Scalar(255));
  EXPECT_EQ(sgm::computeCost(black, white, CostMode::kSadRt, 2).at(6, 6)[0], 9);
  // The rank term: constant 100, one dark pixel (50) at (5,5) on the left and at
  // (3,5) on the right. At p = (5,5), d = 0 the left census is empty (rank 0), the
  // right one holds the dark pixel (rank 1): rt = 1. The 9x5 window (45 pixels,
  // all inside) differs at (5,5) and (3,5) by 50 each: SAD = 100 / 45 = 2.2 -> 2,
  // SADn = (2*44 + 127) / 255 = 0; cost = (0 + 8*1 + 5) / 10 = 1.
  cv::Mat dl(10, 12, CV_8UC1, cv::Scalar(100)), dr(10, 12, CV_8UC1, cv::Scalar(100));
  dl.at<uint8_t>(5, 5) = 50;
  dr.at<uint8_t>(5, 3) = 50;
  EXPECT_EQ(sgm::computeCost(dl, dr, CostMode::kSadRt, 4).at(5, 5)[0], 1);
}

}  // namespace
