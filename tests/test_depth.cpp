// SPDX-License-Identifier: Apache-2.0
// Depth from disparity (docs/algorithm.md, section 10b): the rounded quotient in integers,
// saturation, invalid pixels, parameter ranges.
#include "sgm/depth.hpp"

#include "expect_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

TEST(Depth, HandValues) {
  // f = 700 px, B = 120 mm, d = 42 px: 2000 mm exactly.
  EXPECT_EQ(sgm::depthMm(700 * 256, 120000, 42 * 16), 2000);
  // d = 42.0625 px (673/16): 700 * 120 / 42.0625 = 1997.03 -> 1997.
  EXPECT_EQ(sgm::depthMm(700 * 256, 120000, 673), 1997);
  // A half rounds up: f 1 px, B 3 mm, d 2 px = 1.5 mm -> 2.
  EXPECT_EQ(sgm::depthMm(256, 3000, 32), 2);
}

TEST(Depth, SaturatesAndNeverGivesZeroForAValidPixel) {
  EXPECT_EQ(sgm::depthMm(700 * 256, 120000, 0), sgm::kDepthMax);  // infinity
  EXPECT_EQ(sgm::depthMm(700 * 256, 120000, 1), sgm::kDepthMax);  // 1/16 px: 1,344,000 mm
  EXPECT_EQ(sgm::depthMm(256, 100, 4095), 1);                     // 0.0004 mm -> 1, not 0
  EXPECT_EQ(sgm::depthMm(0, 120000, 100), 1);                     // f = 0: 0 mm -> 1
  EXPECT_EQ(sgm::depthMm((1u << 24) - 1, (1u << 24) - 1, 65535), sgm::kDepthMax);
}

TEST(Depth, IsTheRoundedQuotient) {
  std::mt19937 rng(3);
  for (int i = 0; i < 20000; ++i) {
    const uint32_t f = rng() % (1u << 24), b = rng() % (1u << 24), d = 1 + rng() % 4095;
    const long double exact = (long double)f / 256 * b / 1000 / ((long double)d / 16);
    const uint16_t z = sgm::depthMm(f, b, d);
    if (exact >= sgm::kDepthMax) {
      EXPECT_EQ(z, sgm::kDepthMax);
    } else {
      EXPECT_LE(std::fabs((long double)z - exact), 0.5L + (exact < 0.5L ? 1 : 0)) << f << " " << b << " " << d;
    }
  }
}

TEST(Depth, MapKeepsInvalidAtZero) {
  sgm::DisparityMap map{cv::Mat(1, 3, CV_16UC1), cv::Mat(1, 3, CV_8UC1)};
  map.disp.at<uint16_t>(0, 0) = 42 * 16, map.valid.at<uint8_t>(0, 0) = 1;
  map.disp.at<uint16_t>(0, 1) = 42 * 16, map.valid.at<uint8_t>(0, 1) = 0;
  map.disp.at<uint16_t>(0, 2) = 0, map.valid.at<uint8_t>(0, 2) = 1;
  const cv::Mat z = sgm::depthMap(map, 700 * 256, 120000);
  EXPECT_EQ(z.at<uint16_t>(0, 0), 2000);
  EXPECT_EQ(z.at<uint16_t>(0, 1), 0);
  EXPECT_EQ(z.at<uint16_t>(0, 2), sgm::kDepthMax);
  expectError([] { sgm::depthMm(1u << 24, 1, 1); }, {"depth parameters out of range"});
}

// The core's output words (OUTPUT.MODE): the disparity word {valid, zeros, disparity x 16},
// or the depth map; the output selection is no part of a preset.
TEST(Depth, OutputWordsFollowTheMode) {
  sgm::DisparityMap map{cv::Mat(1, 3, CV_16UC1), cv::Mat(1, 3, CV_8UC1)};
  map.disp.at<uint16_t>(0, 0) = 42 * 16 + 3, map.valid.at<uint8_t>(0, 0) = 1;
  map.disp.at<uint16_t>(0, 1) = 17, map.valid.at<uint8_t>(0, 1) = 0;
  map.disp.at<uint16_t>(0, 2) = 0, map.valid.at<uint8_t>(0, 2) = 1;
  sgm::Params p;
  cv::Mat words = sgm::outputWords(map, p);
  EXPECT_EQ(words.at<uint16_t>(0, 0), 0x8000 | (42 * 16 + 3));
  EXPECT_EQ(words.at<uint16_t>(0, 1), 17);
  EXPECT_EQ(words.at<uint16_t>(0, 2), 0x8000);
  p.output = sgm::OutputMode::kDepth, p.focalQ8 = 700 * 256, p.baselineUm = 120000;
  words = sgm::outputWords(map, p);
  EXPECT_EQ(cv::countNonZero(words != sgm::depthMap(map, 700 * 256, 120000)), 0);
  EXPECT_EQ(sgm::presetName(p), "default");
  EXPECT_EQ(sgm::parseOutputMode("depth"), sgm::OutputMode::kDepth);
  EXPECT_EQ(std::string(sgm::outputModeName(sgm::OutputMode::kDisparity)), "disparity");
  expectError([] { sgm::parseOutputMode("confidence"); }, {"unknown output 'confidence'"});
  p.focalQ8 = 1 << sgm::kDepthParamBits;
  expectError([&] { p.validate(); }, {"depth parameters out of range"});
}
