// SPDX-License-Identifier: Apache-2.0
// The synthetic scene generator: determinism, disparity range, and the ground
// truth and occlusion mask against the rendered views.
#include "synthetic_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace sgm::synth;

bool sameImage(const cv::Mat& a, const cv::Mat& b) { return a.size() == b.size() && cv::countNonZero(a != b) == 0; }

// Every visible left pixel with an integer disparity reappears unchanged in the
// right view (noise off); returns how many pixels were checked.
long expectConsistent(const SyntheticScene& s, const std::string& what) {
  long checked = 0;
  for (int y = 0; y < s.left.rows; ++y)
    for (int x = 0; x < s.left.cols; ++x) {
      const float d = s.gt.at<float>(y, x);
      if (!s.nonocc.at<uint8_t>(y, x) || d != std::floor(d)) continue;
      ++checked;
      EXPECT_EQ(int(s.right.at<uint8_t>(y, x - int(d))), int(s.left.at<uint8_t>(y, x)))
          << what << " at (" << x << ", " << y << "), d " << d;
      if (::testing::Test::HasFailure()) return checked;
    }
  return checked;
}

TEST(SyntheticScene, SameSeedSameSceneOtherSeedOtherScene) {
  const SyntheticScene a = makeSyntheticScene(60, 20, 16, 7), b = makeSyntheticScene(60, 20, 16, 7);
  const SyntheticScene c = makeSyntheticScene(60, 20, 16, 8);
  EXPECT_TRUE(sameImage(a.left, b.left) && sameImage(a.right, b.right) && sameImage(a.gt, b.gt));
  EXPECT_FALSE(sameImage(a.left, c.left) && sameImage(a.gt, c.gt));
}

TEST(SyntheticScene, DisparitiesStayInRange) {
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    const SyntheticScene s = makeSyntheticScene(50 + int(seed), 9 + int(seed % 13), 16, seed);
    double lo = 0, hi = 0;
    cv::minMaxLoc(s.gt, &lo, &hi);
    EXPECT_GE(lo, 0.0) << "seed " << seed;
    EXPECT_LE(hi, 15.0) << "seed " << seed;
  }
}

// A rectangle at d = 12 in front of a background at d = 5: the background
// pixels 7 px left of the rectangle and the first 5 columns are occluded,
// nothing else.
TEST(SyntheticScene, OcclusionsOfAFrontoParallelRectangle) {
  SceneSpec spec;
  spec.width = 64, spec.height = 16;
  Layer background;
  background.d0 = 5, background.textureSeed = 1, background.contrast = 100;
  Layer box = background;
  box.shape = Shape::kRectangle, box.centreX = 40, box.centreY = 8, box.halfWidth = 6, box.halfHeight = 4;
  box.d0 = 12, box.textureSeed = 2;
  spec.layers = {background, box};
  const SyntheticScene s = renderScene(spec);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool inBox = box.contains(x, y);
      EXPECT_EQ(s.gt.at<float>(y, x), inBox ? 12.f : 5.f) << x << "," << y;
      const bool shadow = !inBox && std::abs(y - 8) <= 4 && x >= 34 - 7 && x < 34;
      const bool occluded = x < (inBox ? 12 : 5) || shadow;
      EXPECT_EQ(s.nonocc.at<uint8_t>(y, x), occluded ? 0 : 255) << x << "," << y;
    }
  EXPECT_GT(expectConsistent(s, "rectangle"), 0);
}

TEST(SyntheticScene, RandomScenesWithoutNoiseMatchAcrossViews) {
  long checked = 0;
  for (uint32_t seed = 1; seed <= 30; ++seed) {
    SceneSpec spec = randomSceneSpec(70, 15, 16, seed);
    spec.noiseSigma = 0;
    checked += expectConsistent(renderScene(spec), "seed " + std::to_string(seed));
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
