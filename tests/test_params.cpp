// SPDX-License-Identifier: Apache-2.0
// Parameter validation, cost-mode names and the pipeline's input checks.
#include "sgm/params.hpp"
#include "sgm/pipeline.hpp"

#include "expect_error.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace {

using sgm::CostMode;
using sgm::Params;

Params withD(int d) {
  Params p;
  p.disparities = d;
  return p;
}

TEST(ParamsValidate, DefaultsAreValid) {
  EXPECT_NO_THROW(Params{}.validate());
  for (CostMode m : sgm::allCostModes()) EXPECT_NO_THROW(sgm::defaultParams(m).validate()) << sgm::costModeName(m);
}

TEST(ParamsValidate, DisparityRange) {
  EXPECT_NO_THROW(withD(2).validate());
  EXPECT_NO_THROW(withD(256).validate());
  expectError([] { withD(1).validate(); }, {"D=1", "2..256"});
  expectError([] { withD(0).validate(); }, {"D=0"});
  expectError([] { withD(257).validate(); }, {"D=257"});
  expectError([] { withD(999).validate(); }, {"D=999"});
}

TEST(ParamsValidate, Penalties) {
  Params p = sgm::presetParams("four-path");  // the whole P2' range (no fifth path in S)
  p.p1 = 10;
  p.p2 = 10;
  EXPECT_NO_THROW(p.validate());  // P2' = P1 is allowed
  p.p2 = 9;
  expectError([&] { p.validate(); }, {"P2'=9", "P1=10"});
  p.p1 = -1;
  p.p2 = 100;
  expectError([&] { p.validate(); }, {"P1=-1"});
  p.p1 = 0;
  p.p2 = 6000;
  EXPECT_NO_THROW(p.validate());
  p.p2 = 6001;
  expectError([&] { p.validate(); }, {"P2'=6001"});
  p.p1 = 6001;
  expectError([&] { p.validate(); }, {"P1=6001"});
}

TEST(ParamsValidate, LrTolerance) {
  Params p = withD(16);
  p.lrTolerance = -1;  // off
  EXPECT_NO_THROW(p.validate());
  p.lrTolerance = 16;
  EXPECT_NO_THROW(p.validate());
  p.lrTolerance = 17;
  expectError([&] { p.validate(); }, {"17"});
}

TEST(ParamsTest, RawSgmTurnsEveryPostStageOff) {
  Params p = sgm::defaultParams(CostMode::kRt);
  p.disparities = 32;
  p.uniqueness = 15;
  const Params raw = p.rawSgm();
  EXPECT_FALSE(raw.subpixel);
  EXPECT_EQ(raw.uniqueness, 0);
  EXPECT_LT(raw.lrTolerance, 0);
  EXPECT_FALSE(raw.fill);
  EXPECT_FALSE(raw.snap);
  EXPECT_FALSE(raw.median);
  EXPECT_EQ(raw.disparities, 32);
  EXPECT_EQ(raw.mode, CostMode::kRt);
  EXPECT_EQ(raw.p1, p.p1);
  EXPECT_EQ(raw.p2, p.p2);
}

TEST(ParamsTest, DefaultParamsKeepsTheModeAndPostProcessing) {
  const Params base;
  for (CostMode m : sgm::allCostModes()) {
    const Params p = sgm::defaultParams(m);
    EXPECT_EQ(p.mode, m);
    EXPECT_EQ(p.disparities, base.disparities);
    EXPECT_EQ(p.subpixel, base.subpixel);
    EXPECT_EQ(p.lrTolerance, base.lrTolerance);
    EXPECT_EQ(p.fill, base.fill);
    EXPECT_EQ(p.median, base.median);
    if (m == base.mode) {
      EXPECT_EQ(p, base);
    } else {  // the other modes' penalties were measured without the pool's levers (issue 15)
      EXPECT_TRUE(p.snap);
      EXPECT_EQ(p.uniqueness, 0);
      EXPECT_EQ(p.adWeight, 0);
      EXPECT_EQ(p.rightPathWeight, 0);
    }
  }
  // The documented post-processing defaults (docs/algorithm.md section 11).
  EXPECT_EQ(base.disparities, 64);
  EXPECT_TRUE(base.subpixel);
  EXPECT_EQ(base.lrTolerance, 1);
  EXPECT_TRUE(base.fill);
  EXPECT_FALSE(base.snap);  // issue 15: off in the pool's pick (docs/notes/accuracy-pool.md)
  EXPECT_TRUE(base.median);
  EXPECT_TRUE(sgm::isHardwareMode(base.mode)) << "Params{} is the hardware default";
  // ... with the measured penalties of its own mode.
  EXPECT_EQ(base.p1, sgm::defaultParams(base.mode).p1);
  EXPECT_EQ(base.p2, sgm::defaultParams(base.mode).p2);
}

TEST(ParamsTest, DocumentedPenaltyDefaults) {
  // docs/algorithm.md, "Defaults": rsad (the hardware default) P1 24, P2' 200 with the
  // fifth path (weight 4, blocks of 64), AD term 3 / 20, uniqueness 15; the four-path
  // preset keeps the former P1 18, P2' 100.
  EXPECT_EQ(Params{}.mode, CostMode::kRsad);
  EXPECT_EQ(Params{}.p1, 24);
  EXPECT_EQ(Params{}.p2, 200);
  EXPECT_EQ(Params{}.rightPathWeight, 4);
  EXPECT_EQ(Params{}.rightPathBlock, 64);
  EXPECT_EQ(Params{}.adWeight, 3);
  EXPECT_EQ(Params{}.adCap, 20);
  EXPECT_EQ(Params{}.uniqueness, 15);
  EXPECT_EQ(sgm::defaultParams(CostMode::kRsad), Params{});
  const Params four = sgm::presetParams("four-path");
  EXPECT_EQ(four.p1, 18);
  EXPECT_EQ(four.p2, 100);
  EXPECT_TRUE(four.snap);
  EXPECT_EQ(four.rightPathWeight + four.adWeight + four.uniqueness, 0);
  EXPECT_EQ(sgm::presetName(four), "four-path");
}

TEST(ParamsTest, PenaltyLimitKeepsTheWeightedSumInSixteenBits) {
  // S = 3 L0 + 2 L45 + 3 L90 + 2 L135 and Lr <= Cmax + P2': with the largest
  // Cmax (255, sad and bt) and P2' = kMaxPenalty, 10 (255 + 6000) = 62550 < 65536.
  EXPECT_EQ(sgm::kPathWeights[0], 3);
  EXPECT_EQ(sgm::kPathWeights[1], 2);
  EXPECT_EQ(sgm::kPathWeights[2], 3);
  EXPECT_EQ(sgm::kPathWeights[3], 2);
  EXPECT_EQ(sgm::kPathWeightSum, 10);
  EXPECT_EQ(sgm::kMaxPenalty, 6000);
  for (CostMode m : sgm::allCostModes())
    EXPECT_LT(sgm::kPathWeightSum * (sgm::maxCost(m, sgm::CensusWindow::k9x9) + sgm::kMaxPenalty), 65536)
        << sgm::costModeName(m);
}

// largestAdCap: hand-checked values, and for every hardware mode, census and weight it is
// the largest cap validate() accepts (cap + 1 is refused unless already at kMaxAdCap).
TEST(ParamsTest, LargestAdCapIsTheLargestCapValidateAccepts) {
  using sgm::CensusWindow;
  EXPECT_EQ(sgm::largestAdCap(CostMode::kRsad, CensusWindow::k9x5, 15), 44);           // 44 + 82 = 126 <= 127; 45: 128
  EXPECT_EQ(sgm::largestAdCap(CostMode::kUnified, CensusWindow::k9x5, 15), 21);        // 88 + 39 = 127; 22: 88 + 41
  EXPECT_EQ(sgm::largestAdCap(CostMode::kRt, CensusWindow::k9x5, 1), sgm::kMaxAdCap);  // 44 + 31 fits
  EXPECT_EQ(sgm::largestAdCap(CostMode::kRt, CensusWindow::k9x9, 8), 175);             // 80 + 175 = 255
  EXPECT_EQ(sgm::largestAdCap(CostMode::kRsad, CensusWindow::k9x5, 0), sgm::kMaxAdCap);  // off: any cap
  EXPECT_EQ(sgm::largestAdCap(CostMode::kSad, CensusWindow::k9x5, 8), -1);               // Cmax 255 > 127
  for (const CensusWindow census : {CensusWindow::k9x5, CensusWindow::k9x9})
    for (const CostMode m : {CostMode::kRt, CostMode::kRsad, CostMode::kUnified})
      for (int w = 1; w <= sgm::kMaxAdWeight; ++w) {
        Params p;
        p.mode = m, p.census = census, p.adWeight = w;
        p.adCap = sgm::largestAdCap(m, census, w);
        ASSERT_GE(p.adCap, 0);
        EXPECT_NO_THROW(p.validate()) << sgm::costModeName(m) << " W=" << w;
        if (p.adCap == sgm::kMaxAdCap) continue;
        ++p.adCap;
        EXPECT_THROW(p.validate(), sgm::Error) << sgm::costModeName(m) << " W=" << w << " T=" << p.adCap;
      }
}

TEST(CostModes, NamesRoundTripAndUnknownThrows) {
  const std::vector<std::string> names = {"rt", "rsad", "unified", "sad", "bt", "sad+rt"};
  const auto modes = sgm::allCostModes();
  ASSERT_EQ(modes.size(), names.size());
  for (size_t i = 0; i < modes.size(); ++i) {
    EXPECT_EQ(sgm::costModeName(modes[i]), names[i]);
    EXPECT_EQ(sgm::parseCostMode(names[i]), modes[i]);
  }
  EXPECT_TRUE(sgm::isHardwareMode(CostMode::kRt));
  EXPECT_TRUE(sgm::isHardwareMode(CostMode::kRsad));
  EXPECT_TRUE(sgm::isHardwareMode(CostMode::kUnified));
  EXPECT_FALSE(sgm::isHardwareMode(CostMode::kSad));
  EXPECT_FALSE(sgm::isHardwareMode(CostMode::kBt));
  EXPECT_FALSE(sgm::isHardwareMode(CostMode::kSadRt));
  expectError([] { sgm::parseCostMode("census"); }, {"census"});
  expectError([] { sgm::parseCostMode("RT"); }, {"RT"});
  expectError([] { sgm::parseCostMode(""); }, {"unknown cost mode"});
}

// ------------------------------------------------------------------ checkInput

cv::Mat gray(int w, int h) { return cv::Mat(h, w, CV_8UC1, cv::Scalar(7)); }

TEST(CheckInput, AcceptsTheSmallestImage) { EXPECT_NO_THROW(sgm::checkInput(gray(9, 9), gray(9, 9), Params{})); }

TEST(CheckInput, SizeMismatch) {
  expectError([] { sgm::checkInput(gray(20, 16), gray(21, 16), Params{}); }, {"size mismatch", "20x16", "21x16"});
  expectError([] { sgm::checkInput(gray(20, 16), gray(20, 15), Params{}); }, {"size mismatch"});
}

TEST(CheckInput, SmallerThanTheMinimumFrame) {
  expectError([] { sgm::checkInput(gray(8, 9), gray(8, 9), Params{}); }, {"8x9", "smaller", "9x9 minimum frame"});
  // The census window is only 5 rows high, but the minimum frame stays 9x9.
  expectError([] { sgm::checkInput(gray(9, 8), gray(9, 8), Params{}); }, {"9x8", "smaller"});
  expectError([] { sgm::checkInput(gray(40, 5), gray(40, 5), Params{}); }, {"40x5", "smaller"});
  expectError([] { sgm::checkInput(gray(1, 1), gray(1, 1), Params{}); }, {"smaller"});
}

TEST(CheckInput, InvalidParameters) {
  expectError([] { sgm::checkInput(gray(20, 20), gray(20, 20), withD(1)); }, {"D=1"});
  expectError([] { sgm::checkInput(gray(20, 20), gray(20, 20), withD(257)); }, {"D=257"});
  Params p;
  p.p1 = 50;
  p.p2 = 20;
  expectError([&] { sgm::checkInput(gray(20, 20), gray(20, 20), p); }, {"P2'"});
}

TEST(CheckInput, NonGrayImages) {
  const cv::Mat colour(16, 16, CV_8UC3, cv::Scalar::all(1));
  EXPECT_THROW(sgm::checkInput(colour, colour, Params{}), sgm::Error);
  const cv::Mat deep(16, 16, CV_16UC1, cv::Scalar(1));
  EXPECT_THROW(sgm::checkInput(deep, deep, Params{}), sgm::Error);
}

TEST(CheckInput, RunPipelineChecksToo) {
  EXPECT_THROW(sgm::runPipeline(gray(20, 16), gray(21, 16), Params{}), sgm::Error);
  EXPECT_THROW(sgm::runPipeline(gray(8, 8), gray(8, 8), Params{}), sgm::Error);
  EXPECT_THROW(sgm::runPipeline(gray(20, 16), gray(20, 16), withD(1)), sgm::Error);
}

}  // namespace
