// SPDX-License-Identifier: Apache-2.0
// Synthetic stereo scenes with exact ground truth, all from a seed: a layered
// scene model (a background plane, fronto-parallel or slanted, and occluding
// rectangles and discs in front of it) with textures attached to the surfaces
// (random dots, smooth gradients, flat and saturated areas), rendered into the
// left and the right view with occlusions resolved by depth, plus additive noise.
// Used by the constrained-random regression (tests/rtl/regress_main.cpp).
#pragma once

#include "eval_lib.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sgm::synth {

// Small seeded generator with the same sequence on every platform (splitmix64),
// so that a seed names the same scene and the same regression case everywhere.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next();
  int uniform(int lo, int hi);                // lo .. hi inclusive
  double real(double lo = 0, double hi = 1);  // [lo, hi)
  bool chance(double p) { return real() < p; }
  double gaussian();  // N(0, 1), Box-Muller
 private:
  uint64_t state_;
};

// One well-mixed 64-bit value of a seed and two indices (case seeds, texture cells).
uint64_t mixSeed(uint64_t seed, uint64_t a, uint64_t b = 0);

enum class Texture { kRandomDot, kGradient, kFlat, kSaturated };
enum class Shape { kPlane, kRectangle, kDisc };

const char* textureName(Texture texture);
const char* shapeName(Shape shape);

// One surface. Coordinates are those of the left view; a surface point (x, y)
// appears in the right view at x - disparity(x, y).
struct Layer {
  Shape shape = Shape::kPlane;
  double centreX = 0, centreY = 0;       // rectangle and disc
  double halfWidth = 0, halfHeight = 0;  // rectangle half sizes; a disc's radius is halfWidth
  double d0 = 0, dx = 0, dy = 0;         // disparity(x, y) = d0 + dx x + dy y (px), |dx| < 1
  Texture texture = Texture::kRandomDot;
  uint32_t textureSeed = 0;
  int dotSize = 1;                      // random-dot and saturated cell size (px)
  int level = 128, contrast = 127;      // flat level; dot / gradient range around it
  double gradientX = 0, gradientY = 0;  // gradient slope (grey levels per px)

  bool contains(double x, double y) const;
  double disparity(double x, double y) const { return d0 + dx * x + dy * y; }
  uint8_t shade(double x, double y) const;  // texture value at surface point (x, y)
};

struct SceneSpec {
  int width = 0, height = 0;
  std::vector<Layer> layers;  // layers[0] is the background plane
  double noiseSigma = 0;      // additive Gaussian noise, independent per view
  uint32_t noiseSeed = 0;
};

struct SyntheticScene {
  cv::Mat left, right;  // CV_8UC1
  cv::Mat gt;           // CV_32F: exact disparity of every left pixel (px)
  cv::Mat nonocc;       // CV_8U: 255 where the left pixel is visible in the right view, else 0
  std::string summary;  // one line: layers, textures, slant, noise
};

// A random layered scene whose disparities lie in [0, maxDisparity - 1].
SceneSpec randomSceneSpec(int width, int height, int maxDisparity, uint32_t seed);
SyntheticScene renderScene(const SceneSpec& spec);
// renderScene(randomSceneSpec(...)).
SyntheticScene makeSyntheticScene(int width, int height, int maxDisparity, uint32_t seed);

// The scene in the evaluator's form (gt in px, nonocc as rendered, all = every pixel).
eval::Scene toEvalScene(const SyntheticScene& scene, const std::string& name);

}  // namespace sgm::synth
