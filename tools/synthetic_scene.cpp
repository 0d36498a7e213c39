// SPDX-License-Identifier: Apache-2.0
#include "synthetic_scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sgm::synth {

namespace {

uint64_t splitmix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

uint8_t clampGray(double v) { return uint8_t(std::clamp(std::lround(v), 0L, 255L)); }

// Index of the frontmost layer (largest disparity, the later layer on a tie)
// whose surface lands on right-view position (xr, y), or -1; its disparity in *d.
int frontAtRight(const std::vector<Layer>& layers, double xr, double y, double* d) {
  int best = -1;
  for (size_t i = 0; i < layers.size(); ++i) {
    const Layer& l = layers[i];
    const double x = (xr + l.d0 + l.dy * y) / (1.0 - l.dx);  // solves x - disparity(x, y) = xr
    if (!l.contains(x, y)) continue;
    const double di = l.disparity(x, y);
    if (best < 0 || di >= *d) best = int(i), *d = di;
  }
  return best;
}

// Disparity plane with values inside [lo, hi] over the frame: random slope
// (or none), random offset.
void placePlane(Layer& l, int w, int h, double lo, double hi, bool slanted, Rng& rng) {
  l.dx = l.dy = 0;
  if (slanted) l.dx = rng.real(-0.15, 0.15), l.dy = rng.real(-0.3, 0.3);
  const double span = std::abs(l.dx) * (w - 1) + std::abs(l.dy) * (h - 1);
  if (span > hi - lo) {
    const double scale = (hi - lo) / span * rng.real(0.3, 1.0);
    l.dx *= scale, l.dy *= scale;
  }
  const double used = std::abs(l.dx) * (w - 1) + std::abs(l.dy) * (h - 1);
  const double base = rng.real(lo, std::max(lo, hi - used));
  l.d0 = base - std::min(0.0, l.dx * (w - 1)) - std::min(0.0, l.dy * (h - 1));
  if (!slanted) l.d0 = std::floor(l.d0);  // integer: right(x - d) == left(x) exactly
}

void randomTexture(Layer& l, Rng& rng) {
  const double pick = rng.real();
  l.texture = pick < 0.5    ? Texture::kRandomDot
              : pick < 0.7  ? Texture::kGradient
              : pick < 0.85 ? Texture::kFlat
                            : Texture::kSaturated;
  l.textureSeed = uint32_t(rng.next());
  l.dotSize = rng.chance(0.6) ? 1 : rng.uniform(2, 4);
  l.level = rng.chance(0.15) ? (rng.chance(0.5) ? 0 : 255) : rng.uniform(0, 255);
  l.contrast = rng.uniform(4, 127);
  l.gradientX = rng.real(-3, 3), l.gradientY = rng.real(-3, 3);
}

}  // namespace

uint64_t Rng::next() { return splitmix(state_++); }
int Rng::uniform(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }
double Rng::real(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
double Rng::gaussian() {
  const double u = 1.0 - real(), v = real();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
}

uint64_t mixSeed(uint64_t seed, uint64_t a, uint64_t b) { return splitmix(splitmix(splitmix(seed) ^ a) ^ b); }

const char* textureName(Texture texture) {
  switch (texture) {
    case Texture::kRandomDot: return "dots";
    case Texture::kGradient: return "gradient";
    case Texture::kFlat: return "flat";
    case Texture::kSaturated: return "saturated";
  }
  return "?";
}

const char* shapeName(Shape shape) {
  switch (shape) {
    case Shape::kPlane: return "plane";
    case Shape::kRectangle: return "rect";
    case Shape::kDisc: return "disc";
  }
  return "?";
}

bool Layer::contains(double x, double y) const {
  switch (shape) {
    case Shape::kPlane: return true;
    case Shape::kRectangle: return std::abs(x - centreX) <= halfWidth && std::abs(y - centreY) <= halfHeight;
    case Shape::kDisc: return (x - centreX) * (x - centreX) + (y - centreY) * (y - centreY) <= halfWidth * halfWidth;
  }
  return false;
}

uint8_t Layer::shade(double x, double y) const {
  const auto cell = [&] {
    return mixSeed(textureSeed, uint64_t(int64_t(std::floor(x / dotSize))), uint64_t(int64_t(std::floor(y / dotSize))));
  };
  switch (texture) {
    case Texture::kRandomDot: return clampGray(level + int(cell() % uint64_t(2 * contrast + 1)) - contrast);
    case Texture::kSaturated: return (cell() & 1) ? 255 : 0;
    case Texture::kFlat: return uint8_t(level);
    case Texture::kGradient: return clampGray(level + gradientX * x + gradientY * y);
  }
  return 0;
}

SceneSpec randomSceneSpec(int width, int height, int maxDisparity, uint32_t seed) {
  Rng rng(mixSeed(seed, 0x5ce7e));
  SceneSpec spec;
  spec.width = width, spec.height = height;
  const double top = std::max(0, maxDisparity - 1);
  Layer background;
  placePlane(background, width, height, 0, top * rng.real(0.2, 1.0), rng.chance(0.5), rng);
  randomTexture(background, rng);
  spec.layers.push_back(background);
  const int objects = rng.uniform(0, 3);
  for (int i = 0; i < objects; ++i) {
    Layer o;
    o.shape = rng.chance(0.5) ? Shape::kRectangle : Shape::kDisc;
    o.centreX = rng.real(0, width), o.centreY = rng.real(0, height);
    o.halfWidth = rng.real(2, std::max(3.0, width / 3.0));
    o.halfHeight = rng.real(2, std::max(3.0, height / 2.0));
    placePlane(o, width, height, top * rng.real(0.0, 0.7), top, rng.chance(0.2), rng);
    randomTexture(o, rng);
    spec.layers.push_back(o);
  }
  spec.noiseSigma = rng.chance(0.4) ? 0.0 : rng.real(0.5, 6.0);
  spec.noiseSeed = uint32_t(rng.next());
  return spec;
}

SyntheticScene renderScene(const SceneSpec& spec) {
  const int w = spec.width, h = spec.height;
  SyntheticScene s{cv::Mat(h, w, CV_8UC1), cv::Mat(h, w, CV_8UC1), cv::Mat(h, w, CV_32F), cv::Mat(h, w, CV_8UC1), ""};
  const std::vector<Layer>& layers = spec.layers;
  Rng noise(spec.noiseSeed);
  const auto noisy = [&](uint8_t v) {
    return spec.noiseSigma > 0 ? clampGray(v + spec.noiseSigma * noise.gaussian()) : v;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Left view: the frontmost surface at (x, y).
      int front = -1;
      double d = 0;
      for (size_t i = 0; i < layers.size(); ++i)
        if (layers[i].contains(x, y) && (front < 0 || layers[i].disparity(x, y) >= d))
          front = int(i), d = layers[i].disparity(x, y);
      s.left.at<uint8_t>(y, x) = noisy(layers[front].shade(x, y));
      s.gt.at<float>(y, x) = float(d);
      // Visible in the right view when inside it and nothing else is in front there.
      double other = 0;
      bool visible = x - d >= 0;
      for (size_t i = 0; visible && i < layers.size(); ++i) {
        if (int(i) == front) continue;
        const Layer& l = layers[i];
        const double xs = (x - d + l.d0 + l.dy * y) / (1.0 - l.dx);
        if (l.contains(xs, y) && ((other = l.disparity(xs, y)) > d || (other == d && int(i) > front))) visible = false;
      }
      s.nonocc.at<uint8_t>(y, x) = visible ? 255 : 0;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double d = 0;
      const int front = frontAtRight(layers, x, y, &d);
      s.right.at<uint8_t>(y, x) = noisy(front < 0 ? 0 : layers[front].shade(x + d, y));
    }
  std::ostringstream summary;
  for (size_t i = 0; i < layers.size(); ++i) {
    const Layer& l = layers[i];
    summary << (i ? " + " : "") << shapeName(l.shape) << "(" << textureName(l.texture) << ", d "
            << l.disparity(l.centreX, l.centreY) << (l.dx != 0 || l.dy != 0 ? " slanted" : "") << ")";
  }
  summary << ", noise " << spec.noiseSigma;
  s.summary = summary.str();
  return s;
}

SyntheticScene makeSyntheticScene(int width, int height, int maxDisparity, uint32_t seed) {
  return renderScene(randomSceneSpec(width, height, maxDisparity, seed));
}

eval::Scene toEvalScene(const SyntheticScene& scene, const std::string& name) {
  eval::Scene e;
  e.name = name;
  e.left = e.leftColor = scene.left;
  e.right = e.rightColor = scene.right;
  e.gt = scene.gt.clone();
  e.gt.setTo(1e-3f, scene.gt == 0);  // 0 means "unknown" to the evaluator; a true 0 stays known
  e.nonocc = scene.nonocc;
  e.all = cv::Mat(scene.gt.size(), CV_8UC1, cv::Scalar(255));
  return e;
}

}  // namespace sgm::synth
