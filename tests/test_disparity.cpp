// SPDX-License-Identifier: Apache-2.0
// Disparity selection and refinement (docs/algorithm.md sections 6 to 9):
// WTA, sub-pixel, right disparity, LR check, hole filling, edge snapping, 5x5 median.
#include "sgm/disparity.hpp"
#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <vector>

namespace {

using sgm::DisparityMap;
using sgm::PathVolume;

// A W x H x D volume from rows of per-pixel disparity vectors.
PathVolume makeVolume(const std::vector<std::vector<std::vector<int>>>& rows) {
  const int h = int(rows.size()), w = int(rows[0].size()), nd = int(rows[0][0].size());
  PathVolume v(w, h, nd);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = 0; d < nd; ++d) v.at(x, y)[d] = uint16_t(rows[y][x][d]);
  return v;
}

DisparityMap makeMap(const std::vector<std::vector<int>>& disp, const std::vector<std::vector<int>>& valid) {
  const int h = int(disp.size()), w = int(disp[0].size());
  DisparityMap m{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      m.disp.at<uint16_t>(y, x) = uint16_t(disp[y][x]);
      m.valid.at<uint8_t>(y, x) = uint8_t(valid[y][x]);
    }
  return m;
}

std::vector<int> dispRow(const DisparityMap& m, int y) {
  std::vector<int> r;
  for (int x = 0; x < m.disp.cols; ++x) r.push_back(m.disp.at<uint16_t>(y, x));
  return r;
}

std::vector<int> validRow(const DisparityMap& m, int y) {
  std::vector<int> r;
  for (int x = 0; x < m.valid.cols; ++x) r.push_back(m.valid.at<uint8_t>(y, x));
  return r;
}

using V = std::vector<int>;

// ------------------------------------------------------------------ WTA

TEST(WinnerTakeAll, TiesGoToTheSmallestDisparity) {
  const uint16_t a[] = {5, 3, 3, 7};
  EXPECT_EQ(sgm::winnerTakeAll(a, 4), 1);
  const uint16_t b[] = {2, 2, 2};
  EXPECT_EQ(sgm::winnerTakeAll(b, 3), 0);
  const uint16_t c[] = {9, 8, 7, 7};
  EXPECT_EQ(sgm::winnerTakeAll(c, 4), 2);
  const uint16_t d[] = {4, 4, 4, 1};
  EXPECT_EQ(sgm::winnerTakeAll(d, 4), 3);
  const uint16_t e[] = {60000, 0, 65535};
  EXPECT_EQ(sgm::winnerTakeAll(e, 3), 1);
  // Only the first `disparities` entries count.
  EXPECT_EQ(sgm::winnerTakeAll(d, 3), 0);
}

// ------------------------------------------------------------------ sub-pixel

TEST(SubpixelOffset, HandExamples) {
  EXPECT_EQ(sgm::subpixelOffset(5, 0, 5), 0);   // symmetric
  EXPECT_EQ(sgm::subpixelOffset(4, 4, 4), 0);   // den = 0
  EXPECT_EQ(sgm::subpixelOffset(10, 0, 0), 8);  // vertex half a pixel towards b
  EXPECT_EQ(sgm::subpixelOffset(0, 0, 10), -8);
  // a > b: the vertex lies towards d+1 -> positive. (6-4)/(2*6)*16 = 2.67 -> 3.
  EXPECT_EQ(sgm::subpixelOffset(6, 2, 4), 3);
  EXPECT_EQ(sgm::subpixelOffset(4, 2, 6), -3);
  // 3 / (2*17) * 16 = 1.41 -> 1.
  EXPECT_EQ(sgm::subpixelOffset(10, 0, 7), 1);
  EXPECT_EQ(sgm::subpixelOffset(7, 0, 10), -1);
}

TEST(SubpixelOffset, ExactHalvesRoundAwayFromZero) {
  // 2 / (2*32) * 16 = 0.5 -> 1; 6 / 64 * 16 = 1.5 -> 2.
  EXPECT_EQ(sgm::subpixelOffset(17, 0, 15), 1);
  EXPECT_EQ(sgm::subpixelOffset(15, 0, 17), -1);
  EXPECT_EQ(sgm::subpixelOffset(19, 0, 13), 2);
  EXPECT_EQ(sgm::subpixelOffset(13, 0, 19), -2);
  // Offsets do not depend on a common additive constant.
  EXPECT_EQ(sgm::subpixelOffset(1019, 1000, 1013), 2);
}

// ------------------------------------------------------------------ right disparity

// Row 0 (W = 5, D = 3):
//   x=0 [9, 2, 50]   x=1 [8, 3, 50]   x=2 [7, 5, 1]   x=3 [6, 2, 4]   x=4 [90, 1, 2]
// dR(xr) = argmin_d S(xr + d, d), d <= min(D-1, W-1-xr):
//   dR(0) = argmin(9, 3, 1) = 2   dR(1) = argmin(8, 5, 4) = 2   dR(2) = argmin(7, 2, 2) = 1 (tie)
//   dR(3) = argmin(6, 1) = 1      dR(4) = argmin(90) = 0 (right border)
const std::vector<std::vector<int>> kRow0 = {{9, 2, 50}, {8, 3, 50}, {7, 5, 1}, {6, 2, 4}, {90, 1, 2}};

TEST(RightDisparity, HandVolumeIncludingRightBorder) {
  // Row 1 starts with zeros at d = 1, 2: an implementation that read past the
  // end of row 0 (x = 5 is row 1's x = 0) would pick d = 1 at xr = 4.
  const std::vector<std::vector<int>> row1 = {{5, 0, 0}, {0, 9, 9}, {0, 9, 9}, {0, 9, 9}, {0, 9, 9}};
  const PathVolume s = makeVolume({kRow0, row1});
  EXPECT_EQ(sgm::rightDisparity(s, 0, 0), 2);
  EXPECT_EQ(sgm::rightDisparity(s, 1, 0), 2);
  EXPECT_EQ(sgm::rightDisparity(s, 2, 0), 1);
  EXPECT_EQ(sgm::rightDisparity(s, 3, 0), 1);
  EXPECT_EQ(sgm::rightDisparity(s, 4, 0), 0);
  // Row 1: S(0,0) = 5 vs S(1,1) = 9, S(2,2) = 9 -> 0; xr = 4 -> 0.
  EXPECT_EQ(sgm::rightDisparity(s, 0, 1), 0);
  EXPECT_EQ(sgm::rightDisparity(s, 4, 1), 0);
}

TEST(RightDisparity, MoreDisparitiesThanColumns) {
  // W = 3, D = 5: d is limited to W-1-xr.
  const PathVolume s = makeVolume({{{9, 9, 9, 9, 9}, {9, 5, 9, 9, 9}, {9, 9, 1, 0, 0}}});
  EXPECT_EQ(sgm::rightDisparity(s, 0, 0), 2);  // S(0,0)=9, S(1,1)=5, S(2,2)=1
  EXPECT_EQ(sgm::rightDisparity(s, 1, 0), 0);  // S(1,0)=9, S(2,1)=9 -> tie -> 0
  EXPECT_EQ(sgm::rightDisparity(s, 2, 0), 0);
}

// ------------------------------------------------------------------ selectDisparity

sgm::Params selectParams(bool subpixel, int lrTolerance) {
  sgm::Params p;
  p.disparities = 3;
  p.subpixel = subpixel;
  p.lrTolerance = lrTolerance;
  return p;
}

TEST(SelectDisparity, LeftRightCheckTolerance) {
  // Row 0 = kRow0: WTA d = [1, 1, 2, 1, 1].
  //   x=0: x - d = -1 -> invalid whatever the tolerance.
  //   x=1: dR(0) = 2 vs 1 -> |diff| = 1.   x=2: dR(0) = 2 vs 2 -> 0.
  //   x=3: dR(2) = 1 vs 1 -> 0.            x=4: dR(3) = 1 vs 1 -> 0.
  // Row 1: every pixel [0, 5, 9] -> d = 0, dR = 0 everywhere -> valid.
  const std::vector<std::vector<int>> row1(5, {0, 5, 9});
  const PathVolume s = makeVolume({kRow0, row1});

  DisparityMap m = sgm::selectDisparity(s, selectParams(false, 0));
  EXPECT_EQ(dispRow(m, 0), (V{16, 16, 32, 16, 16}));
  EXPECT_EQ(validRow(m, 0), (V{0, 0, 1, 1, 1}));
  EXPECT_EQ(dispRow(m, 1), (V{0, 0, 0, 0, 0}));
  EXPECT_EQ(validRow(m, 1), (V{1, 1, 1, 1, 1}));

  m = sgm::selectDisparity(s, selectParams(false, 1));
  EXPECT_EQ(validRow(m, 0), (V{0, 1, 1, 1, 1}));
  m = sgm::selectDisparity(s, selectParams(false, 3));
  EXPECT_EQ(validRow(m, 0), (V{0, 1, 1, 1, 1}));  // x - d < 0 stays invalid

  // LR check off: every pixel valid, including x - d < 0.
  m = sgm::selectDisparity(s, selectParams(false, -1));
  EXPECT_EQ(validRow(m, 0), (V{1, 1, 1, 1, 1}));
  EXPECT_EQ(validRow(m, 1), (V{1, 1, 1, 1, 1}));
  EXPECT_EQ(dispRow(m, 0), (V{16, 16, 32, 16, 16}));
}

TEST(Confidence, RatioOfTheSecondBestBeyondTheNeighbours) {
  // S1 = 10 at d = 2; d = 1 and 3 are its neighbours (not counted); S2 = 30 at d = 5.
  const uint16_t s[] = {40, 11, 10, 12, 50, 30};
  EXPECT_EQ(sgm::confidence(s, 6, 2), (20 << 8) / 31);  // floor(5120 / 31) = 165
  EXPECT_EQ(sgm::confidence(s, 6, 2), 165);
  const uint16_t flat[] = {7, 7, 7, 7};
  EXPECT_EQ(sgm::confidence(flat, 4, 0), 0);
  const uint16_t peak[] = {0, 900, 65535, 65535};  // the largest: 255 at S1 = 0, S2 = 65535
  EXPECT_EQ(sgm::confidence(peak, 4, 0), 255);
  const uint16_t three[] = {5, 9, 8};  // no k with |k - d| > 1 for d = 1: 0
  EXPECT_EQ(sgm::confidence(three, 3, 1), 0);
}

TEST(Confidence, SelectionGivesZeroWhereInvalid) {
  const std::vector<std::vector<int>> row1(5, {0, 5, 9});
  const PathVolume s = makeVolume({kRow0, row1});
  cv::Mat confidence;
  const DisparityMap m = sgm::selectDisparity(s, selectParams(false, 0), &confidence);
  ASSERT_EQ(confidence.type(), CV_8UC1);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 5; ++x) {
      const uint16_t* sp = s.at(x, y);
      const int d = sgm::winnerTakeAll(sp, s.depth);
      EXPECT_EQ(confidence.at<uint8_t>(y, x), m.valid.at<uint8_t>(y, x) ? sgm::confidence(sp, s.depth, d) : 0)
          << x << "," << y;
    }
  EXPECT_EQ(confidence.at<uint8_t>(0, 0), 0);              // x - d < 0: invalid
  EXPECT_EQ(confidence.at<uint8_t>(1, 2), (9 << 8) / 10);  // S = [0, 5, 9] at d = 0: S2 = 9
}

TEST(SelectDisparity, SubpixelOnlyInsideTheRange) {
  const std::vector<std::vector<int>> row1(5, {0, 5, 9});
  const PathVolume s = makeVolume({kRow0, row1});
  const DisparityMap m = sgm::selectDisparity(s, selectParams(true, 1));
  // x=0: a=9, m=2, b=50: -41 * 8 / 55 = -5.96 -> -6 -> 16 - 6 = 10
  // x=1: a=8, m=3, b=50: -42 * 8 / 52 = -6.46 -> -6 -> 10
  // x=2: d = D-1 -> no refinement -> 32
  // x=3: a=6, m=2, b=4: 2 * 8 / 6 = 2.67 -> 3 -> 19
  // x=4: a=90, m=1, b=2: 88 * 8 / 90 = 7.82 -> 8 -> 24
  EXPECT_EQ(dispRow(m, 0), (V{10, 10, 32, 19, 24}));
  EXPECT_EQ(validRow(m, 0), (V{0, 1, 1, 1, 1}));  // LR check uses the integer d
  EXPECT_EQ(dispRow(m, 1), (V{0, 0, 0, 0, 0}));   // d = 0 -> no refinement
}

// ------------------------------------------------------------------ fillHoles

TEST(FillHoles, BackgroundSideBordersAndEmptyRows) {
  const int X = 999;  // value of an invalid pixel, far from every neighbour: background rule
  const DisparityMap in = makeMap(
      {
          {X, 48, X, X, 32, X},   // both sides -> smaller; borders -> the one side
          {X, X, X, X, X, X},     // no valid pixel: stays invalid
          {1, 2, 3, 4, 5, 6},     // all valid: unchanged
          {X, X, X, X, X, 80},    // only a right neighbour
          {16, X, 64, X, X, 16},  // left 16 / right 64 -> 16; left 64 / right 16 -> 16
          {0, X, 40, X, X, X},    // a valid d = 0 is a real neighbour (0 < 40)
      },
      {
          {0, 1, 0, 0, 1, 0},
          {0, 0, 0, 0, 0, 0},
          {1, 1, 1, 1, 1, 1},
          {0, 0, 0, 0, 0, 1},
          {1, 0, 1, 0, 0, 1},
          {1, 0, 1, 0, 0, 0},
      });
  const DisparityMap out = sgm::fillHoles(in);
  EXPECT_EQ(dispRow(out, 0), (V{48, 48, 32, 32, 32, 32}));
  EXPECT_EQ(validRow(out, 0), (V{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(dispRow(out, 1), (V{X, X, X, X, X, X}));
  EXPECT_EQ(validRow(out, 1), (V{0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(dispRow(out, 2), (V{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(dispRow(out, 3), (V{80, 80, 80, 80, 80, 80}));
  EXPECT_EQ(validRow(out, 3), (V{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(dispRow(out, 4), (V{16, 16, 64, 16, 16, 16}));
  EXPECT_EQ(dispRow(out, 5), (V{0, 0, 40, 40, 40, 40}));
  EXPECT_EQ(validRow(out, 5), (V{1, 1, 1, 1, 1, 1}));
  // The input is not modified.
  EXPECT_EQ(validRow(in, 0), (V{0, 1, 0, 0, 1, 0}));
}

TEST(FillHoles, UsesOnlyOriginallyValidNeighbours) {
  // x=1 and x=2 are both holes between 80 (left) and 20 (right): both take 20,
  // i.e. x=2 does not take the value just filled into x=1 as its left neighbour.
  const DisparityMap in = makeMap({{80, 0, 0, 20}}, {{1, 0, 0, 1}});
  EXPECT_EQ(dispRow(sgm::fillHoles(in), 0), (V{80, 20, 20, 20}));
}

TEST(FillHoles, KeepsAnOwnDisparityThatAgreesWithANeighbour) {
  // Invalid pixels keep their own disparity when it is within 16 (1 px) of the
  // nearest valid pixel on either side, else they take the smaller neighbour.
  const DisparityMap in = makeMap(
      {
          {160, 176, 150, 320},  // 176: 16 from 160 (kept); 150: 10 from 160 (kept)
          {160, 177, 143, 320},  // 177: 17 from 160, far from 320 -> 160; 143 likewise
          {160, 310, 336, 320},  // 310 / 336: within 16 of the right neighbour 320
          {160, 304, 90, 320},   // 304 is 16 from 320 (kept), 90 agrees with neither
          {999, 40, 999, 999},   // no left neighbour for x=0; 999 agrees with nothing
          {30, 999, 999, 999},   // only a left neighbour
      },
      {
          {1, 0, 0, 1},
          {1, 0, 0, 1},
          {1, 0, 0, 1},
          {1, 0, 0, 1},
          {0, 1, 0, 0},
          {1, 0, 0, 0},
      });
  const DisparityMap out = sgm::fillHoles(in);
  EXPECT_EQ(dispRow(out, 0), (V{160, 176, 150, 320}));
  EXPECT_EQ(dispRow(out, 1), (V{160, 160, 160, 320}));
  EXPECT_EQ(dispRow(out, 2), (V{160, 310, 336, 320}));
  EXPECT_EQ(dispRow(out, 3), (V{160, 304, 160, 320}));
  EXPECT_EQ(dispRow(out, 4), (V{40, 40, 40, 40}));
  EXPECT_EQ(dispRow(out, 5), (V{30, 30, 30, 30}));
  for (int y = 0; y < 6; ++y) EXPECT_EQ(validRow(out, y), (V{1, 1, 1, 1})) << "row " << y;
}

// ------------------------------------------------------------------ snapEdges

cv::Mat grayRow(const std::vector<std::vector<int>>& rows) {
  cv::Mat g(int(rows.size()), int(rows[0].size()), CV_8UC1);
  for (int y = 0; y < g.rows; ++y)
    for (int x = 0; x < g.cols; ++x) g.at<uint8_t>(y, x) = uint8_t(rows[y][x]);
  return g;
}

TEST(SnapEdges, MovesADropOntoTheStrongestIntensityStep) {
  // Drop 640 -> 160 between x=5 and x=6 (more than 2 px). Candidate steps
  // k = 3 .. 6 (|I(k) - I(k-1)|): the strongest one decides the new edge.
  const std::vector<int> d = {640, 640, 640, 640, 640, 640, 160, 160};
  const std::vector<int> ones(8, 1);
  const DisparityMap in = makeMap({d, d, d, d}, {ones, ones, ones, ones});
  const cv::Mat g = grayRow({
      {10, 10, 10, 90, 90, 90, 90, 90},  // step at k=3 (80): pixels 3..5 take 160
      {10, 10, 10, 10, 50, 50, 50, 50},  // step at k=4: pixels 4..5
      {10, 10, 10, 10, 10, 10, 90, 90},  // step at k=6 = e+1: nothing moves
      {90, 10, 10, 10, 10, 10, 10, 10},  // step at k=1 is out of reach: all steps 0 -> k=6
  });
  const DisparityMap out = sgm::snapEdges(in, g);
  EXPECT_EQ(dispRow(out, 0), (V{640, 640, 640, 160, 160, 160, 160, 160}));
  EXPECT_EQ(dispRow(out, 1), (V{640, 640, 640, 640, 160, 160, 160, 160}));
  EXPECT_EQ(dispRow(out, 2), d);
  EXPECT_EQ(dispRow(out, 3), d);
  EXPECT_EQ(validRow(out, 0), ones);
  EXPECT_EQ(dispRow(in, 0), d);  // the input is not modified
}

TEST(SnapEdges, TiesGoToTheSmallestMove) {
  // Equal steps at k=4 and k=5: the edge goes to k=5 (one pixel moves).
  const std::vector<int> ones(8, 1);
  const DisparityMap in = makeMap({{640, 640, 640, 640, 640, 640, 160, 160}}, {ones});
  const DisparityMap out = sgm::snapEdges(in, grayRow({{0, 0, 0, 0, 40, 80, 80, 80}}));
  EXPECT_EQ(dispRow(out, 0), (V{640, 640, 640, 640, 640, 160, 160, 160}));
}

TEST(SnapEdges, OnlyDropsOfMoreThanTwoPixelsBetweenValidPixels) {
  const cv::Mat g = grayRow(std::vector<std::vector<int>>(6, {0, 0, 0, 200, 200, 200}));  // step at k=3
  const DisparityMap in = makeMap(
      {
          {200, 200, 200, 200, 200, 168},  // drop of exactly 32: not an edge
          {200, 200, 200, 200, 200, 167},  // 33: edge, pixels 3..4 take 167
          {200, 200, 200, 200, 200, 100},  // e+1 invalid: not an edge
          {200, 200, 200, 200, 200, 100},  // e invalid: not an edge
          {200, 200, 200, 200, 200, 100},  // pixel 3 invalid: keeps its value
          {100, 100, 100, 200, 200, 200},  // a rise: untouched
      },
      {{1, 1, 1, 1, 1, 1},
       {1, 1, 1, 1, 1, 1},
       {1, 1, 1, 1, 1, 0},
       {1, 1, 1, 1, 0, 1},
       {1, 1, 1, 0, 1, 1},
       {1, 1, 1, 1, 1, 1}});
  const DisparityMap out = sgm::snapEdges(in, g);
  EXPECT_EQ(dispRow(out, 0), (V{200, 200, 200, 200, 200, 168}));
  EXPECT_EQ(dispRow(out, 1), (V{200, 200, 200, 167, 167, 167}));
  EXPECT_EQ(dispRow(out, 2), (V{200, 200, 200, 200, 200, 100}));
  EXPECT_EQ(dispRow(out, 3), (V{200, 200, 200, 200, 200, 100}));
  EXPECT_EQ(dispRow(out, 4), (V{200, 200, 200, 200, 100, 100}));
  EXPECT_EQ(validRow(out, 4), (V{1, 1, 1, 0, 1, 1}));
  EXPECT_EQ(dispRow(out, 5), (V{100, 100, 100, 200, 200, 200}));
}

TEST(SnapEdges, NearestDropWinsAndStepsNeedAPixelOnTheLeft) {
  // Drops at e=2 (800 -> 480) and e=3 (480 -> 160). The step at k=1 is the
  // strongest for both, so pixels 1..2 are under both drops and take the
  // nearest one's value (480); pixel 3 takes 160. Column 0 is never moved.
  const DisparityMap in = makeMap({{800, 800, 800, 480, 160, 160}}, {{1, 1, 1, 1, 1, 1}});
  const DisparityMap out = sgm::snapEdges(in, grayRow({{0, 100, 100, 100, 100, 100}}));
  EXPECT_EQ(dispRow(out, 0), (V{800, 480, 480, 160, 160, 160}));
}

// ------------------------------------------------------------------ median

TEST(Median5x5, FullWindowAndClippedBorders) {
  // 5x5, values 16 * ((7 i) mod 25), i = 5y + x: a permutation of 0..24 (x16).
  std::vector<std::vector<int>> disp(5, std::vector<int>(5)), valid(5, std::vector<int>(5, 1));
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) disp[y][x] = 16 * ((7 * (5 * y + x)) % 25);
  const DisparityMap out = sgm::median5x5(makeMap(disp, valid));
  // Centre: all 25 values -> 12.
  EXPECT_EQ(out.disp.at<uint16_t>(2, 2), 16 * 12);
  // (0,0): i in {0,1,2,5,6,7,10,11,12} -> {0,7,14,10,17,24,20,2,9}, sorted element 4 = 10.
  EXPECT_EQ(out.disp.at<uint16_t>(0, 0), 16 * 10);
  // (4,4) lies in one of the last two rows (window clipped by the bottom edge):
  // passed through, i = 24 -> 7 * 24 mod 25 = 18 (its clipped median would be 11).
  EXPECT_EQ(out.disp.at<uint16_t>(4, 4), 16 * 18);
  // Likewise row 3: (x=0, y=3), i = 15 -> 105 mod 25 = 5.
  EXPECT_EQ(out.disp.at<uint16_t>(3, 0), 16 * 5);
  // (x=2, y=0): rows 0..2, i = 0..14 -> 15 values, element 7 of
  // {0,2,3,6,7,9,10,13,14,16,17,20,21,23,24} = 13.
  EXPECT_EQ(out.disp.at<uint16_t>(0, 2), 16 * 13);
  // (x=3, y=1): columns 1..4, rows 0..3: 16 values, lower median = element 7 = 12.
  EXPECT_EQ(out.disp.at<uint16_t>(1, 3), 16 * 12);
  for (int y = 0; y < 5; ++y) EXPECT_EQ(validRow(out, y), (V{1, 1, 1, 1, 1}));
}

// The one-row cases below get two invalid rows underneath, so that row 0 is
// not one of the last two rows (which pass through); invalid pixels never count.
TEST(Median5x5, EvenCountTakesTheLowerMedian) {
  const DisparityMap out = sgm::median5x5(
      makeMap({{10, 40, 20, 30}, {0, 0, 0, 0}, {0, 0, 0, 0}}, {{1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}}));
  // x=0: {10,40,20} -> 20; x=1: {10,20,30,40} -> 20; x=2: same -> 20; x=3: {40,20,30} -> 30.
  EXPECT_EQ(dispRow(out, 0), (V{20, 20, 20, 30}));
}

TEST(Median5x5, OnlyValidPixelsCountAndInvalidCentreStays) {
  const DisparityMap out = sgm::median5x5(makeMap({{100, 0, 50, 60, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}},
                                                  {{1, 0, 1, 1, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}));
  // x=0: valid {100, 50} -> 50; x=2: valid {100, 50, 60} -> 60 (with the two
  // invalid zeros counted it would be 50); x=3: valid {50, 60} -> 50.
  EXPECT_EQ(dispRow(out, 0), (V{50, 0, 60, 50, 0}));
  EXPECT_EQ(validRow(out, 0), (V{1, 0, 1, 1, 0}));
}

TEST(Median5x5, InvalidCentreValuePassesThrough) {
  std::vector<std::vector<int>> disp(6, std::vector<int>(6, 32)), valid(6, std::vector<int>(6, 1));
  disp[3][3] = 777;
  valid[3][3] = 0;
  const DisparityMap out = sgm::median5x5(makeMap(disp, valid));
  EXPECT_EQ(out.disp.at<uint16_t>(3, 3), 777);
  EXPECT_EQ(out.valid.at<uint8_t>(3, 3), 0);
  EXPECT_EQ(out.disp.at<uint16_t>(3, 2), 32);  // 777 is not part of its neighbours' windows
  EXPECT_EQ(out.disp.at<uint16_t>(5, 5), 32);
}

TEST(Median5x5, LastTwoRowsPassThrough) {
  // 9 rows of 16, one outlier 800 in each row: every row above the last two
  // loses its outlier to the median, the last two keep it (docs/algorithm.md 9).
  std::vector<std::vector<int>> disp(9, std::vector<int>(7, 16)), valid(9, std::vector<int>(7, 1));
  for (int y = 0; y < 9; ++y) disp[y][y % 7] = 800;
  const DisparityMap out = sgm::median5x5(makeMap(disp, valid));
  for (int y = 0; y < 9; ++y) {
    EXPECT_EQ(out.disp.at<uint16_t>(y, y % 7), y < 7 ? 16 : 800) << "y=" << y;
    EXPECT_EQ(validRow(out, y), (V{1, 1, 1, 1, 1, 1, 1})) << "y=" << y;
  }
}

}  // namespace
