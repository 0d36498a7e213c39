// SPDX-License-Identifier: Apache-2.0
// Census transform and rank (docs/algorithm.md section 2): bit order, border
// rule, rank and Hamming distance, on hand-made images.
#include "sgm/census.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <random>
#include <set>

namespace {

using sgm::Census;
using sgm::censusBitIndex;
using sgm::censusTransform;

// The set bits of a census signature, ascending.
std::vector<int> setBits(const Census& c) {
  std::vector<int> bits;
  for (int k = 0; k < 64; ++k)
    if (c.bit(k)) bits.push_back(k);
  return bits;
}

const Census& at(const std::vector<Census>& cs, const cv::Mat& img, int x, int y) {
  return cs[size_t(y) * img.cols + x];
}

TEST(CensusBitIndex, DocumentedCorners) {
  EXPECT_EQ(censusBitIndex(-4, -2), 0);
  EXPECT_EQ(censusBitIndex(4, 2), 43);
  EXPECT_EQ(censusBitIndex(0, 0), -1);
  EXPECT_EQ(censusBitIndex(1, 0), 22);
  EXPECT_EQ(censusBitIndex(-1, 0), 21);
}

TEST(CensusBitIndex, RowMajorOrder) {
  // Row dy = -2: dx = -4..4 -> 0..8; next row starts at 9.
  EXPECT_EQ(censusBitIndex(-3, -2), 1);
  EXPECT_EQ(censusBitIndex(4, -2), 8);
  EXPECT_EQ(censusBitIndex(-4, -1), 9);
  EXPECT_EQ(censusBitIndex(0, -2), 4);
  // Centre row dy = 0: 2*9 = 18 is (-4, 0); after the centre one less than 9(dy+2)+(dx+4).
  EXPECT_EQ(censusBitIndex(-4, 0), 18);
  EXPECT_EQ(censusBitIndex(4, 0), 25);   // 26 - 1
  EXPECT_EQ(censusBitIndex(-4, 1), 26);  // 27 - 1
  EXPECT_EQ(censusBitIndex(-4, 2), 35);  // 36 - 1
  EXPECT_EQ(censusBitIndex(0, 2), 39);   // 40 - 1
  EXPECT_EQ(censusBitIndex(-2, -1), 11);
  EXPECT_EQ(censusBitIndex(3, 1), 33);  // 34 - 1
}

TEST(CensusBitIndex, BijectionOntoZeroTo43) {
  std::set<int> seen;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -4; dx <= 4; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const int k = censusBitIndex(dx, dy);
      EXPECT_GE(k, 0);
      EXPECT_LT(k, 44);
      seen.insert(k);
    }
  EXPECT_EQ(seen.size(), 44u);
}

TEST(CensusStruct, SetBitRank) {
  Census c;
  EXPECT_EQ(c.rank(), 0);
  c.set(0);
  c.set(31);
  c.set(32);
  c.set(43);
  EXPECT_TRUE(c.bit(0));
  EXPECT_TRUE(c.bit(31));
  EXPECT_TRUE(c.bit(32));
  EXPECT_TRUE(c.bit(43));
  EXPECT_FALSE(c.bit(1));
  EXPECT_FALSE(c.bit(33));
  EXPECT_EQ(c.bits, (uint64_t(1) << 43) | (uint64_t(3) << 31) | 1u);
  EXPECT_EQ(c.rank(), 4);
  c.set(43);  // setting twice changes nothing
  EXPECT_EQ(c.rank(), 4);
}

TEST(CensusStruct, HammingDistance) {
  Census a, b;
  EXPECT_EQ(sgm::hammingDistance(a, b), 0);
  for (int k : {0, 1, 2, 40}) a.set(k);
  for (int k : {1, 2, 3, 4, 43}) b.set(k);
  // Symmetric difference {0, 3, 4, 40, 43}.
  EXPECT_EQ(sgm::hammingDistance(a, b), 5);
  EXPECT_EQ(sgm::hammingDistance(b, a), 5);
  EXPECT_EQ(sgm::hammingDistance(a, a), 0);
  Census all;
  for (int k = 0; k < 44; ++k) all.set(k);
  EXPECT_EQ(all.rank(), 44);
  EXPECT_EQ(sgm::hammingDistance(all, Census{}), 44);
  EXPECT_EQ(sgm::hammingDistance(all, a), 40);
}

TEST(CensusTransform, ConstantImageHasNoBits) {
  // Equal neighbours give 0 (strict I(q) < I(p)).
  cv::Mat img(10, 12, CV_8UC1, cv::Scalar(100));
  const auto cs = censusTransform(img);
  ASSERT_EQ(cs.size(), size_t(120));
  for (const Census& c : cs) EXPECT_EQ(c.bits, 0u);
}

TEST(CensusTransform, BrightPixelInteriorAndCorner) {
  // 10x10 constant 100; (5,5) = 200 and (0,0) = 200.
  cv::Mat img(10, 10, CV_8UC1, cv::Scalar(100));
  img.at<uint8_t>(5, 5) = 200;
  img.at<uint8_t>(0, 0) = 200;
  const auto cs = censusTransform(img);
  // (5,5): the whole window is inside the image, every neighbour is darker.
  EXPECT_EQ(at(cs, img, 5, 5).rank(), 44);
  // (0,0): only offsets dx in 0..4, dy in 0..2 are inside; window pixels outside give 0.
  // k = 9(dy+2) + (dx+4) - 1 after the centre.
  std::vector<int> expected = {22, 23, 24, 25};  // dy = 0, dx = 1..4
  for (int base : {30, 39})                      // dy = 1..2, dx = 0..4
    for (int dx = 0; dx <= 4; ++dx) expected.push_back(base + dx);
  EXPECT_EQ(setBits(at(cs, img, 0, 0)), expected);
  EXPECT_EQ(at(cs, img, 0, 0).rank(), 14);
  // (1,1) = 100: neighbours (0,0) and (5,5) are brighter, the rest equal -> no bits.
  EXPECT_EQ(at(cs, img, 1, 1).rank(), 0);
}

TEST(CensusTransform, DarkPixelSetsOneBitPerNeighbour) {
  // 12x10 constant 100 with one dark pixel at (x=3, y=2): the census of p has
  // exactly the bit of offset (3 - x, 2 - y) when that offset is in the window.
  cv::Mat img(10, 12, CV_8UC1, cv::Scalar(100));
  img.at<uint8_t>(2, 3) = 50;
  const auto cs = censusTransform(img);
  using V = std::vector<int>;
  EXPECT_EQ(setBits(at(cs, img, 5, 3)), V{11});  // offset (-2,-1): 9*1 + 2
  EXPECT_EQ(setBits(at(cs, img, 0, 0)), V{42});  // offset (3,2): 9*4 + 7 - 1
  EXPECT_EQ(setBits(at(cs, img, 7, 4)), V{0});   // offset (-4,-2)
  EXPECT_EQ(setBits(at(cs, img, 3, 4)), V{4});   // offset (0,-2)
  EXPECT_EQ(setBits(at(cs, img, 2, 2)), V{22});  // offset (1,0)
  EXPECT_EQ(setBits(at(cs, img, 4, 2)), V{21});  // offset (-1,0)
  EXPECT_EQ(setBits(at(cs, img, 8, 2)), V{});    // offset (-5,0): outside the window
  EXPECT_EQ(setBits(at(cs, img, 3, 5)), V{});    // offset (0,-3): outside the window (9x5)
  EXPECT_EQ(setBits(at(cs, img, 3, 2)), V{});    // the dark pixel itself
  EXPECT_EQ(setBits(at(cs, img, 11, 9)), V{});   // far corner
}

TEST(CensusTransform, MatchesNaiveDefinitionOnRandomImage) {
  // Independent straightforward implementation of section 2, incl. the border rule.
  std::mt19937 rng(1234);
  cv::Mat img(11, 13, CV_8UC1);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 8 * 32);  // many ties
  const auto cs = censusTransform(img);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      int k = 0, rank = 0;
      const Census& c = at(cs, img, x, y);
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
          if (dx == 0 && dy == 0) continue;
          const int qx = x + dx, qy = y + dy;
          const bool inside = qx >= 0 && qy >= 0 && qx < img.cols && qy < img.rows;
          const bool expected = inside && img.at<uint8_t>(qy, qx) < img.at<uint8_t>(y, x);
          EXPECT_EQ(c.bit(k), expected) << "x=" << x << " y=" << y << " dx=" << dx << " dy=" << dy;
          rank += expected;
          ++k;
        }
      EXPECT_EQ(c.rank(), rank);
      EXPECT_EQ(c.bits >> 44, 0u);
    }
}

}  // namespace
