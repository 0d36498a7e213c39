// SPDX-License-Identifier: Apache-2.0
// The paper's configuration beside ours (docs/algorithm.md sections 2, 4, 5, 11):
// the 9x9 census window (bits, order, borders, Cmax), both P2 forms, both path
// weightings, the presets and their command-line options.
#include "sgm/aggregate.hpp"
#include "sgm/census.hpp"
#include "sgm/cli_args.hpp"
#include "sgm/cost.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <random>
#include <set>
#include <vector>

namespace {

using sgm::Census;
using sgm::CensusWindow;
using sgm::CostMode;
using sgm::P2Mode;
using sgm::Params;
using sgm::PathWeighting;

constexpr CensusWindow k9x9 = CensusWindow::k9x9;

std::vector<int> setBits(const Census& c) {
  std::vector<int> bits;
  for (int k = 0; k < sgm::kMaxCensusBits; ++k)
    if (c.bit(k)) bits.push_back(k);
  return bits;
}

// ------------------------------------------------------------------ 9x9 census

TEST(Census9x9, ShapeAndMaxCost) {
  const sgm::CensusShape s = sgm::censusShape(k9x9);
  EXPECT_EQ(s.width, 9);
  EXPECT_EQ(s.height, 9);
  EXPECT_EQ(s.bits, 80);
  EXPECT_EQ(sgm::censusShape(CensusWindow::k9x5).bits, 44);
  EXPECT_EQ(sgm::maxCost(CostMode::kRt, k9x9), 80);
  EXPECT_EQ(sgm::maxCost(CostMode::kRsad, k9x9), 80);
  EXPECT_EQ(sgm::maxCost(CostMode::kUnified, k9x9), 160);
  EXPECT_EQ(sgm::maxCost(CostMode::kSadRt, k9x9), 80);
  EXPECT_EQ(sgm::maxCost(CostMode::kSad, k9x9), 255);
}

TEST(Census9x9, BitIndexRowMajorBijection) {
  EXPECT_EQ(sgm::censusBitIndex(-4, -4, k9x9), 0);
  EXPECT_EQ(sgm::censusBitIndex(-1, 0, k9x9), 39);  // 9 * 4 + 3
  EXPECT_EQ(sgm::censusBitIndex(1, 0, k9x9), 40);   // 9 * 4 + 5 - 1
  EXPECT_EQ(sgm::censusBitIndex(4, 4, k9x9), 79);
  EXPECT_EQ(sgm::censusBitIndex(0, 0, k9x9), -1);
  std::set<int> seen;
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx)
      if (dx || dy) seen.insert(sgm::censusBitIndex(dx, dy, k9x9));
  EXPECT_EQ(seen.size(), 80u);
  EXPECT_EQ(*seen.begin(), 0);
  EXPECT_EQ(*seen.rbegin(), 79);
}

TEST(Census9x9, HighBitsSetRankAndHamming) {
  Census a, b;
  for (int k : {0, 63, 64, 79}) a.set(k);
  for (int k : {63, 70}) b.set(k);
  EXPECT_TRUE(a.bit(64));
  EXPECT_TRUE(a.bit(79));
  EXPECT_FALSE(a.bit(70));
  EXPECT_EQ(a.rank(), 4);
  EXPECT_EQ(sgm::hammingDistance(a, b), 4);  // {0, 64, 70, 79}
}

TEST(Census9x9, BrightPixelInteriorAndCornerBorders) {
  cv::Mat img(12, 12, CV_8UC1, cv::Scalar(100));
  img.at<uint8_t>(5, 5) = 200;
  img.at<uint8_t>(0, 0) = 200;
  const auto cs = sgm::censusTransform(img, k9x9);
  EXPECT_EQ(cs[5 * 12 + 5].rank(), 80);  // the whole window inside, all darker
  // (0,0): offsets dx 0..4, dy 0..4 inside (25 - 1 = 24 bits), bits from 40 on.
  std::vector<int> expected;
  for (int dy = 0; dy <= 4; ++dy)
    for (int dx = 0; dx <= 4; ++dx)
      if (dx || dy) expected.push_back(9 * (dy + 4) + dx + 4 - 1);
  EXPECT_EQ(setBits(cs[0]), expected);
  EXPECT_EQ(cs[0].rank(), 24);
}

TEST(Census9x9, DarkPixelFourRowsAway) {
  // A dark pixel 4 rows below p is in the 9x9 window (bit of offset (0, 4)) and not in 9x5.
  cv::Mat img(12, 12, CV_8UC1, cv::Scalar(100));
  img.at<uint8_t>(8, 6) = 50;
  const auto nine = sgm::censusTransform(img, k9x9);
  const auto five = sgm::censusTransform(img, CensusWindow::k9x5);
  EXPECT_EQ(setBits(nine[4 * 12 + 6]), std::vector<int>{9 * 8 + 4 - 1});  // 75
  EXPECT_EQ(setBits(five[4 * 12 + 6]), std::vector<int>{});
  EXPECT_EQ(setBits(nine[11 * 12 + 6]), std::vector<int>{9 * 1 + 4});  // (0, -3): 13
}

TEST(Census9x9, MatchesNaiveDefinitionOnRandomImage) {
  std::mt19937 rng(99);
  cv::Mat img(13, 15, CV_8UC1);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 8 * 32);
  const auto cs = sgm::censusTransform(img, k9x9);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const Census& c = cs[size_t(y) * img.cols + x];
      int k = 0, rank = 0;
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
          if (!dx && !dy) continue;
          const int qx = x + dx, qy = y + dy;
          const bool inside = qx >= 0 && qy >= 0 && qx < img.cols && qy < img.rows;
          const bool want = inside && img.at<uint8_t>(qy, qx) < img.at<uint8_t>(y, x);
          ASSERT_EQ(c.bit(k), want) << "x=" << x << " y=" << y << " dx=" << dx << " dy=" << dy;
          rank += want;
          ++k;
        }
      EXPECT_EQ(c.rank(), rank);
      EXPECT_EQ(c.high >> 16, 0u);
    }
}

TEST(Census9x9, CostVolumeUsesTheWideSignature) {
  // A difference only in the bottom rows (bits >= 64) must show in rsad and unified,
  // and x - d < 0 costs the 9x9 Cmax.
  std::mt19937 rng(5);
  cv::Mat l(14, 16, CV_8UC1), r;
  for (int y = 0; y < l.rows; ++y)
    for (int x = 0; x < l.cols; ++x) l.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  r = l.clone();
  const auto cl = sgm::censusTransform(l, k9x9), cr = sgm::censusTransform(r, k9x9);
  for (CostMode m : {CostMode::kRt, CostMode::kRsad, CostMode::kUnified}) {
    const sgm::CostVolume v = sgm::computeCost(l, r, m, 5, k9x9);
    for (int y = 0; y < l.rows; ++y)
      for (int x = 0; x < l.cols; ++x)
        for (int d = 0; d < 5; ++d) {
          const int want = x - d < 0 ? sgm::maxCost(m, k9x9)
                                     : sgm::censusCost(m, cl[size_t(y) * 16 + x], cr[size_t(y) * 16 + x - d]);
          ASSERT_EQ(v.at(x, y)[d], want) << sgm::costModeName(m) << " x=" << x << " y=" << y << " d=" << d;
        }
  }
  Census a, b;
  b.set(75);
  EXPECT_EQ(sgm::censusCost(CostMode::kRsad, a, b), 1);
  EXPECT_EQ(sgm::censusCost(CostMode::kUnified, a, b), 2);
}

// ------------------------------------------------------------------ P2 forms

TEST(P2Forms, PaperIsP2OverDeltaClampedAtP1) {
  const sgm::P2Table t = sgm::makeP2Table(7, 100, P2Mode::kPaper);
  EXPECT_EQ(t[0], 100);  // P2' at dI = 0
  EXPECT_EQ(t[1], 100);
  EXPECT_EQ(t[2], 50);
  EXPECT_EQ(t[3], 33);
  EXPECT_EQ(t[14], 7);  // floor(100 / 14) = 7
  EXPECT_EQ(t[15], 7);  // max(P1, 6)
  EXPECT_EQ(t[255], 7);
  for (int k = 1; k < 256; ++k) EXPECT_LE(t[k], t[k - 1]);
}

TEST(P2Forms, KneeIsTheDefaultAndDiffers) {
  const sgm::P2Table knee = sgm::makeP2Table(7, 100, P2Mode::kKnee);
  EXPECT_EQ(knee, sgm::makeP2Table(7, 100));
  EXPECT_EQ(knee[4], 50);  // 400 / 8
  EXPECT_EQ(sgm::makeP2Table(7, 100, P2Mode::kPaper)[4], 25);
}

// ------------------------------------------------------------------ weightings

TEST(PathWeightings, EqualIsThePlainSum) {
  std::mt19937 rng(17);
  const int w = 20, h = 14, nd = 8;
  cv::Mat gray(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) gray.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  sgm::CostVolume c(w, h, nd);
  for (auto& v : c.data) v = uint8_t(rng() % 161);
  for (PathWeighting weighting : {PathWeighting::kEqual, PathWeighting::k3232})
    for (P2Mode p2Mode : {P2Mode::kPaper, P2Mode::kKnee}) {
      const sgm::PathVolume s = sgm::aggregateCost(c, gray, 9, 120, p2Mode, weighting);
      const int* weights = sgm::pathWeights(weighting);
      std::vector<int> sum(s.data.size(), 0);
      for (int path = 0; path < 4; ++path) {
        const sgm::PathVolume lr = sgm::pathCost(c, gray, path, 9, 120, p2Mode);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += weights[path] * lr.data[i];
      }
      for (size_t i = 0; i < sum.size(); ++i) ASSERT_EQ(int(s.data[i]), sum[i]) << i;
    }
  EXPECT_EQ(sgm::pathWeights(PathWeighting::kEqual)[0], 1);
  EXPECT_EQ(sgm::pathWeights(PathWeighting::kEqual)[3], 1);
  EXPECT_EQ(sgm::pathWeights(PathWeighting::k3232)[0], 3);
  EXPECT_EQ(sgm::pathWeights(PathWeighting::k3232)[1], 2);
}

// ------------------------------------------------------------------ presets and options

sgm::CliArgs parse(std::vector<std::string> words) {
  words.insert(words.begin(), "tool");
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  return sgm::CliArgs(int(argv.size()), argv.data(), sgm::CliArgs::pipelineOptions());
}

TEST(Presets, PaperIsThePapersSystem) {
  const Params p = sgm::presetParams("paper");
  EXPECT_EQ(p.census, k9x9);
  EXPECT_EQ(p.mode, CostMode::kUnified);
  EXPECT_EQ(p.p2Mode, P2Mode::kPaper);
  EXPECT_EQ(p.weights, PathWeighting::kEqual);
  EXPECT_EQ(p.lrTolerance, 1);
  EXPECT_TRUE(p.subpixel);
  EXPECT_TRUE(p.median);
  EXPECT_FALSE(p.fill);
  EXPECT_FALSE(p.snap);
  EXPECT_LE(p.p2, 255);  // fits the RTL's 8-bit P2'
  // None of the levers the paper lacks, whatever the defaults take.
  EXPECT_EQ(p.uniqueness, 0);
  EXPECT_EQ(p.adWeight, 0);
  EXPECT_EQ(p.rightPathWeight, 0);
  EXPECT_EQ(p.rightPathBlock, 0);
  EXPECT_FALSE(p.experimental());
  EXPECT_EQ(sgm::presetParams("default"), Params{});
  EXPECT_EQ(Params{}.census, CensusWindow::k9x5);
  EXPECT_EQ(Params{}.p2Mode, P2Mode::kKnee);
  EXPECT_EQ(Params{}.weights, PathWeighting::k3232);
  EXPECT_THROW(sgm::presetParams("nope"), sgm::Error);
}

TEST(Presets, CommandLineOptionsOverrideThePreset) {
  EXPECT_EQ(parse({"--preset", "paper"}).pipelineParams(), sgm::presetParams("paper"));
  EXPECT_EQ(sgm::presetName(parse({"--preset", "paper"}).pipelineParams()), "paper");
  EXPECT_EQ(sgm::presetName(parse({}).pipelineParams()), "default");
  const Params fill = parse({"--preset", "paper", "--fill", "on"}).pipelineParams();
  EXPECT_TRUE(fill.fill);
  EXPECT_EQ(fill.census, k9x9);
  EXPECT_EQ(sgm::presetName(fill), "custom");
  const Params c = parse({"--census", "9x9", "--p2-mode", "paper", "--weights", "equal"}).pipelineParams();
  EXPECT_EQ(c.census, k9x9);
  EXPECT_EQ(c.p2Mode, P2Mode::kPaper);
  EXPECT_EQ(c.weights, PathWeighting::kEqual);
  EXPECT_EQ(c.mode, CostMode::kRsad);
  EXPECT_EQ(parse({"--weights", "3,2,3,2"}).pipelineParams().weights, PathWeighting::k3232);
  // D comes from the base (a simulator's build), not from the preset.
  Params base;
  base.disparities = 16;
  const Params d16 = parse({"--preset", "paper"}).pipelineParams(base);
  EXPECT_EQ(d16.disparities, 16);
  EXPECT_EQ(sgm::presetName(d16), "paper");
  for (const char* bad : {"--census", "--p2-mode", "--weights", "--preset"})
    EXPECT_THROW(parse({bad, "9x7"}).pipelineParams(), sgm::Error) << bad;
}

TEST(Presets, PaperPipelineDiffersFromDefault) {
  std::mt19937 rng(3);
  cv::Mat l(20, 40, CV_8UC1), r;
  for (int y = 0; y < l.rows; ++y)
    for (int x = 0; x < l.cols; ++x) l.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  r = cv::Mat(l.size(), CV_8UC1, cv::Scalar(0));
  l(cv::Rect(3, 0, 37, 20)).copyTo(r(cv::Rect(0, 0, 37, 20)));  // disparity 3
  Params paper = sgm::presetParams("paper");
  paper.disparities = 8;
  const sgm::PipelineStages a = sgm::runPipelineStages(l, r, paper);
  const sgm::DisparityMap b = sgm::runPipeline(l, r, paper);
  EXPECT_EQ(cv::countNonZero(a.result.disp != b.disp), 0);  // streaming and staged forms agree
  EXPECT_EQ(cv::countNonZero(a.result.valid != b.valid), 0);
  EXPECT_EQ(a.cost.at(20, 10)[3], 0);
  EXPECT_EQ(a.cost.at(1, 10)[3], 160);  // x - d < 0: the 9x9 unified Cmax
}

}  // namespace
