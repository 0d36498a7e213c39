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
  for (int k = 0; k < 80; ++k)
    if (c.bit(k)) bits.push_back(k);
  return bits;
}

const Census& at(const std::vector<Census>& cs, const cv::Mat& img, int x, int y) {
  return cs[size_t(y) * img.cols + x];
}

TEST(CensusBitIndex, DocumentedCorners) {
  EXPECT_EQ(censusBitIndex(-4, -4), 0);
  EXPECT_EQ(censusBitIndex(4, 4), 79);
  EXPECT_EQ(censusBitIndex(0, 0), -1);
  EXPECT_EQ(censusBitIndex(1, 0), 40);
  EXPECT_EQ(censusBitIndex(-1, 0), 39);
}

TEST(CensusBitIndex, RowMajorOrder) {
  // Row dy = -4: dx = -4..4 -> 0..8; next row starts at 9.
  EXPECT_EQ(censusBitIndex(-3, -4), 1);
  EXPECT_EQ(censusBitIndex(4, -4), 8);
  EXPECT_EQ(censusBitIndex(-4, -3), 9);
  EXPECT_EQ(censusBitIndex(0, -4), 4);
  // Centre row dy = 0: 4*9 = 36 is (-4, 0); after the centre one less than 9(dy+4)+(dx+4).
  EXPECT_EQ(censusBitIndex(-4, 0), 36);
  EXPECT_EQ(censusBitIndex(4, 0), 43);   // 44 - 1
  EXPECT_EQ(censusBitIndex(-4, 1), 44);  // 45 - 1
  EXPECT_EQ(censusBitIndex(-4, 4), 71);  // 72 - 1
  EXPECT_EQ(censusBitIndex(0, 4), 75);   // 76 - 1
  EXPECT_EQ(censusBitIndex(-2, -3), 11);
  EXPECT_EQ(censusBitIndex(3, 2), 60);   // 61 - 1
}

TEST(CensusBitIndex, BijectionOntoZeroTo79) {
  std::set<int> seen;
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const int k = censusBitIndex(dx, dy);
      EXPECT_GE(k, 0);
      EXPECT_LT(k, 80);
      seen.insert(k);
    }
  EXPECT_EQ(seen.size(), 80u);
}

TEST(CensusStruct, SetBitRank) {
  Census c;
  EXPECT_EQ(c.rank(), 0);
  c.set(0);
  c.set(63);
  c.set(64);
  c.set(79);
  EXPECT_TRUE(c.bit(0));
  EXPECT_TRUE(c.bit(63));
  EXPECT_TRUE(c.bit(64));
  EXPECT_TRUE(c.bit(79));
  EXPECT_FALSE(c.bit(1));
  EXPECT_FALSE(c.bit(65));
  EXPECT_EQ(c.lo, (uint64_t(1) << 63) | 1u);
  EXPECT_EQ(c.hi, uint16_t(0x8001));
  EXPECT_EQ(c.rank(), 4);
  c.set(79);  // setting twice changes nothing
  EXPECT_EQ(c.rank(), 4);
}

TEST(CensusStruct, HammingDistance) {
  Census a, b;
  EXPECT_EQ(sgm::hammingDistance(a, b), 0);
  for (int k : {0, 1, 2, 70}) a.set(k);
  for (int k : {1, 2, 3, 4, 79}) b.set(k);
  // Symmetric difference {0, 3, 4, 70, 79}.
  EXPECT_EQ(sgm::hammingDistance(a, b), 5);
  EXPECT_EQ(sgm::hammingDistance(b, a), 5);
  EXPECT_EQ(sgm::hammingDistance(a, a), 0);
  Census all;
  for (int k = 0; k < 80; ++k) all.set(k);
  EXPECT_EQ(all.rank(), 80);
  EXPECT_EQ(sgm::hammingDistance(all, Census{}), 80);
  EXPECT_EQ(sgm::hammingDistance(all, a), 76);
}

TEST(CensusTransform, ConstantImageHasNoBits) {
  // Equal neighbours give 0 (strict I(q) < I(p)).
  cv::Mat img(10, 12, CV_8UC1, cv::Scalar(100));
  const auto cs = censusTransform(img);
  ASSERT_EQ(cs.size(), size_t(120));
  for (const Census& c : cs) {
    EXPECT_EQ(c.lo, 0u);
    EXPECT_EQ(c.hi, 0u);
  }
}

TEST(CensusTransform, BrightPixelInteriorAndCorner) {
  // 10x10 constant 100; (5,5) = 200 and (0,0) = 200.
  cv::Mat img(10, 10, CV_8UC1, cv::Scalar(100));
  img.at<uint8_t>(5, 5) = 200;
  img.at<uint8_t>(0, 0) = 200;
  const auto cs = censusTransform(img);
  // (5,5): the whole window is inside the image, every neighbour is darker.
  EXPECT_EQ(at(cs, img, 5, 5).rank(), 80);
  // (0,0): only offsets dx, dy in 0..4 are inside; window pixels outside give 0.
  // k = 9(dy+4) + (dx+4) - 1 after the centre.
  std::vector<int> expected = {40, 41, 42, 43};                  // dy = 0, dx = 1..4
  for (int base : {48, 57, 66, 75})                               // dy = 1..4, dx = 0..4
    for (int dx = 0; dx <= 4; ++dx) expected.push_back(base + dx);
  EXPECT_EQ(setBits(at(cs, img, 0, 0)), expected);
  EXPECT_EQ(at(cs, img, 0, 0).rank(), 24);
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
  EXPECT_EQ(setBits(at(cs, img, 5, 5)), V{11});  // offset (-2,-3): 9*1 + 2
  EXPECT_EQ(setBits(at(cs, img, 0, 0)), V{60});  // offset (3,2): 9*6 + 7 - 1
  EXPECT_EQ(setBits(at(cs, img, 7, 6)), V{0});   // offset (-4,-4)
  EXPECT_EQ(setBits(at(cs, img, 3, 6)), V{4});   // offset (0,-4)
  EXPECT_EQ(setBits(at(cs, img, 2, 2)), V{40});  // offset (1,0)
  EXPECT_EQ(setBits(at(cs, img, 4, 2)), V{39});  // offset (-1,0)
  EXPECT_EQ(setBits(at(cs, img, 8, 2)), V{});    // offset (-5,0): outside the window
  EXPECT_EQ(setBits(at(cs, img, 3, 7)), V{});    // offset (0,-5)
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
      for (int dy = -4; dy <= 4; ++dy)
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
    }
}

}  // namespace
