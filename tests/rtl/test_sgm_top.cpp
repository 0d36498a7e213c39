// The whole core (sgm_top) against the golden model: every output pixel of
// every frame, frames back to back without reset, random stalls on both
// streams, several parameter sets, real scenes in the D = 64 build.
#include "Vsgm_top.h"
#include "core_harness.hpp"

#include "eval_lib.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <filesystem>
#include <random>

#ifndef SGM_D
#define SGM_D 16
#endif

namespace {

using Harness = sgm::tb::CoreHarness<Vsgm_top>;
using sgm::tb::FrameInput;

constexpr int kD = SGM_D;

// A textured left image and a right image shifted by a few pixels plus noise.
FrameInput syntheticPair(int w, int h, std::mt19937& rng, const sgm::Params& params) {
  cv::Mat left(h, w, CV_8UC1), right(h, w, CV_8UC1);
  cv::Mat noise(h, w + kD, CV_8UC1);
  for (int y = 0; y < noise.rows; ++y)
    for (int x = 0; x < noise.cols; ++x) noise.at<uint8_t>(y, x) = uint8_t(rng());
  cv::GaussianBlur(noise, noise, cv::Size(5, 5), 1.2);
  const int shift = int(rng() % std::max(1, kD / 2));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      left.at<uint8_t>(y, x) = noise.at<uint8_t>(y, x + kD / 2);
      const int v = noise.at<uint8_t>(y, x + kD / 2 + shift * (y < h / 2 ? 1 : 0)) + int(rng() % 5) - 2;
      right.at<uint8_t>(y, x) = uint8_t(std::clamp(v, 0, 255));
    }
  return FrameInput{left, right, params};
}

sgm::Params hardwareDefaults() {
  sgm::Params p;
  p.disparities = kD;
  return p;
}

void expectBitExact(Harness& core, const std::vector<FrameInput>& frames, const std::string& what) {
  const std::vector<sgm::tb::FrameOutput> outputs = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const sgm::DisparityMap golden = sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareMaps(golden, outputs[k].map, "sgm_top output"), "")
        << what << ", frame " << k << " (" << frames[k].left.cols << "x" << frames[k].left.rows << ")";
    EXPECT_EQ(outputs[k].errors, 0u) << what << ", frame " << k;
  }
}

TEST(SgmTop, SyntheticFramesBackToBackWithStalls) {
  for (const double stall : {0.0, 0.3}) {
    Harness core("sgm_top_synthetic", 11, {stall, stall});
    std::mt19937 rng(3);
    std::vector<FrameInput> frames;
    const int narrowest = std::max(kD, 16);  // the core's minimum width
    for (const auto [w, h] : {std::pair{narrowest, 9}, {narrowest + 37, 17}, {narrowest + 84, 12}, {narrowest + 1, 10}})
      frames.push_back(syntheticPair(w, h, rng, hardwareDefaults()));
    expectBitExact(core, frames, "stall " + std::to_string(stall));
  }
}

TEST(SgmTop, ParameterSetsChangeFromFrameToFrame) {
  Harness core("sgm_top_params", 5, {0.1, 0.1});
  std::mt19937 rng(4);
  std::vector<FrameInput> frames;
  sgm::Params unified = hardwareDefaults();
  unified.mode = sgm::CostMode::kUnified, unified.p1 = 40, unified.p2 = 255, unified.median = false;
  sgm::Params rt = hardwareDefaults();
  rt.mode = sgm::CostMode::kRt, rt.lrTolerance = -1, rt.fill = false, rt.subpixel = false;
  sgm::Params strict = hardwareDefaults();
  strict.lrTolerance = 0, strict.p1 = 0, strict.p2 = 0, strict.snap = false;
  sgm::Params raw = hardwareDefaults().rawSgm();
  for (const sgm::Params& p : {unified, rt, strict, raw, hardwareDefaults()}) frames.push_back(syntheticPair(kD + 20, 20, rng, p));
  expectBitExact(core, frames, "parameter sets");
}

TEST(SgmTop, MalformedFrameThenCleanFrame) {
  Harness core("sgm_top_malformed", 9, {0.1, 0.1});
  std::mt19937 rng(6);
  const int w = std::max(kD, 16) + 8, h = 16;
  const FrameInput first = syntheticPair(w, h, rng, hardwareDefaults());
  // Line 3 ends early (tlast at column 10), then the source moves on to the
  // next frame: the core flags it, still emits w x h beats, and is exact again.
  FrameInput broken = syntheticPair(w, h, rng, hardwareDefaults());
  broken.rawBeats = sgm::tb::frameBeats(broken.left.data, broken.right.data, w, h, broken.left.step, broken.right.step);
  broken.rawBeats[3 * w + 10].last = true;
  broken.rawBeats.resize(3 * w + 11);
  const FrameInput after = syntheticPair(w + 5, 12, rng, hardwareDefaults());
  const auto out = core.run({first, broken, after});
  for (int k : {0, 2}) {
    const FrameInput& f = k == 0 ? first : after;
    EXPECT_EQ(sgm::tb::compareMaps(sgm::runPipeline(f.left, f.right, f.params), out[k].map, "sgm_top output"), "")
        << "frame " << k;
    EXPECT_EQ(out[k].errors, 0u) << "frame " << k;
  }
  EXPECT_EQ(out[1].errors, 0x1u) << "early tlast flagged in error_o[0]";
}

// Real scenes, in the D = 64 build only.
TEST(SgmTop, MiddleburyAndAloe) {
  if (kD != 64) GTEST_SKIP() << "real scenes run in the D = 64 build";
  const char* data = std::getenv("SGM_DATA");
  std::vector<sgm::eval::Scene> scenes;
  for (const char* name : {"cones", "teddy", "sawtooth", "venus"}) {
    const std::string dir = std::string(data ? data : "") + "/" + name;
    if (data && std::filesystem::exists(dir + "/left.png")) scenes.push_back(sgm::eval::loadScene(dir));
  }
  const std::string aloe = "/usr/share/doc/opencv-doc/examples/data";
  if (std::filesystem::exists(aloe + "/aloeL.jpg"))
    scenes.push_back(sgm::eval::loadSceneFiles(aloe + "/aloeL.jpg", aloe + "/aloeR.jpg", aloe + "/aloeGT.png", 1, 4));
  if (scenes.size() < 5) std::cout << "[ note     ] Middlebury data not found at " << (data ? data : "(SGM_DATA unset)") << "; set DATA=...\n";
  if (scenes.empty()) GTEST_SKIP() << "no scenes";
  for (const sgm::eval::Scene& s : scenes) {
    Harness core("sgm_top_" + s.name, 1, {0.0, 0.0});
    const FrameInput in{s.left, s.right, hardwareDefaults()};
    const auto out = core.run({in});
    const sgm::DisparityMap golden = sgm::runPipeline(s.left, s.right, in.params);
    long mismatches = 0;
    EXPECT_EQ(sgm::tb::compareMaps(golden, out[0].map, "sgm_top output", &mismatches), "") << s.name;
    const long pixels = long(s.left.total());
    const uint64_t cycles = out[0].lastOutCycle - out[0].firstInCycle + 1;
    const sgm::eval::ErrorFigures f = sgm::eval::evaluate(sgm::eval::toFloat(out[0].map), s);
    std::cout << "[ figures  ] " << s.name << " " << s.left.cols << "x" << s.left.rows << ": bit-exact "
              << (mismatches == 0 ? "yes" : "NO") << ", " << cycles << " cycles, "
              << double(cycles) / double(pixels) << " cycles/pixel, bad-1.0 nonocc " << f.errNonocc << "%\n";
    // One pixel per clock: at most 1.05 W H + a fixed latency of a few (here 12) lines.
    EXPECT_LE(double(cycles), 1.05 * double(pixels) + 12.0 * s.left.cols) << s.name;
  }
}

TEST(SgmTop, RealSceneUnderStalls) {
  if (kD != 64) GTEST_SKIP() << "real scenes run in the D = 64 build";
  const char* data = std::getenv("SGM_DATA");
  const std::string dir = std::string(data ? data : "") + "/cones";
  if (!data || !std::filesystem::exists(dir + "/left.png")) GTEST_SKIP() << "Middlebury data not found at " << dir << "; set DATA=...";
  const sgm::eval::Scene s = sgm::eval::loadScene(dir);
  Harness core("sgm_top_cones_stalls", 2, {0.25, 0.25});
  expectBitExact(core, {FrameInput{s.left, s.right, hardwareDefaults()}}, "cones with stalls");
}

}  // namespace
