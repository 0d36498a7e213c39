// SPDX-License-Identifier: Apache-2.0
// The whole core (sgm_top) against the golden model: every output pixel of
// every frame, frames back to back, random stalls on both streams, several
// parameter sets, every kind of malformed frame, reset in the middle of a
// frame, real scenes in the D = 64 build. The stream checker of the harness
// watches every output cycle; its own test is here too. The census window is the
// build's (CENSUS_H, read from the model): a 9x5 build runs our defaults, a 9x9
// build the paper preset (sgm::buildDefaults); both switch the run-time P2 form and path weights.
// The run-time levers are the build's (UNIQUENESS, AD_TERM, read from the model):
// in a lean build (top-d16-lean: both 0) the bit-exact tests run with the lever it
// lacks off, and LeversTheBuildLacksAreDroppedThenGoodFrame expects the frames that
// ask for it dropped. A build with the fifth path (RIGHT_BLOCK = B) and both levers runs
// our defaults in blocks of B, a build without any of them the four-path preset.
// A build with the depth output (DEPTH = 1) runs DepthOutputIsExact: depth frames with
// several f and B between disparity frames, every word against sgm::outputWords. A build
// with the rectification (RECTIFY = 1) runs RawPairsThroughTheirMeshesAreExact: raw pairs
// through random calibrations loaded between frames, against sgm::runRectifiedPipeline.
#include "Vsgm_top.h"
#include "Vsgm_top_sgm_top.h"
#include "core_harness.hpp"
#include "malformed_frames.hpp"
#include "rectify_meshes.hpp"
#include "regress_cases.hpp"

#include "eval_lib.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>

#ifndef SGM_D
#define SGM_D 16
#endif

namespace {

using Harness = sgm::tb::CoreHarness<Vsgm_top>;
using sgm::tb::FrameInput;
using sgm::tb::Malformation;
using sgm::tb::MalformedFrames;

constexpr int kD = SGM_D;
constexpr int kMaxWidth = Vsgm_top_sgm_top::MAX_WIDTH;                // of this build
constexpr int kCensusH = Vsgm_top_sgm_top::CENSUS_H;                  // 5 or 9
constexpr bool kUniqueness = Vsgm_top_sgm_top::UNIQUENESS != 0;       // the build has the uniqueness ratio
constexpr bool kAdTerm = Vsgm_top_sgm_top::AD_TERM != 0;              // the build has the AD term
constexpr int kRightBlock = Vsgm_top_sgm_top::RIGHT_BLOCK;            // the fifth path's block (0: not built)
constexpr bool kEdgeReset = Vsgm_top_sgm_top::EDGE_RESET != 0;        // the build has the path restart
constexpr bool kDepth = Vsgm_top_sgm_top::DEPTH != 0;                 // the build has the depth output
constexpr bool kMinDisparity = Vsgm_top_sgm_top::MIN_DISPARITY != 0;  // the build has the minimum disparity
constexpr bool kRectify = Vsgm_top_sgm_top::RECTIFY != 0;             // the build has the rectification
constexpr int kRectifyRows = Vsgm_top_sgm_top::RECTIFY_ROWS;
constexpr int kRectifyGridLog2 = Vsgm_top_sgm_top::RECTIFY_GRID_LOG2;
constexpr bool kConfidence = Vsgm_top_sgm_top::CONFIDENCE != 0;  // the build has the confidence
constexpr bool kLean = !kUniqueness || !kAdTerm;

// The settings with every lever the build lacks off (bit-exact tests run what the build
// has); the fifth path in the build's blocks.
sgm::Params withBuildLevers(sgm::Params p) {
  if (!kUniqueness) p.uniqueness = 0;
  if (!kAdTerm) p.adWeight = 0;
  if (!kRightBlock) p.rightPathWeight = 0;
  p.rightPathBlock = p.rightPathWeight ? kRightBlock : 0;
  if (!kEdgeReset) p.edgeReset.threshold = 0;
  if (!kDepth) p.output = sgm::OutputMode::kDisparity;
  if (!kMinDisparity) p.minDisparity = 0;
  if (!kRectify) p.rectify = false, p.rectifyLag = 0;
  return p;
}

// Whether the core drops a frame of these settings for a lever its build lacks.
bool asksMissingLever(const sgm::Params& p) {
  return (p.uniqueness && !kUniqueness) || (p.adWeight && !kAdTerm) || (p.rightPathWeight && !kRightBlock) ||
         (p.edgeReset.threshold && !kEdgeReset) || (p.output == sgm::OutputMode::kDepth && !kDepth) ||
         (p.minDisparity && !kMinDisparity) || ((p.rectify || p.rectifyLag) && !kRectify) ||
         (p.outputConfidence && !kConfidence);
}

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

// The build's defaults (sgm::buildDefaults): ours in a build with every lever they use
// (the fifth path in the build's blocks), the four-path preset in one without, the paper
// preset in a 9x9 build.
sgm::Params hardwareDefaults() {
  sgm::BuildLevers build;
  build.rightBlock = kRightBlock, build.uniqueness = kUniqueness, build.adTerm = kAdTerm, build.edgeReset = kEdgeReset;
  build.census9x9 = kCensusH == 9;
  return sgm::buildDefaults(build, kD);
}

// Every frame but those in `cut` (reset in their middle) equals the golden model.
void expectBitExact(Harness& core, const std::vector<FrameInput>& frames, const std::string& what,
                    const std::vector<size_t>& cut = {}) {
  const std::vector<sgm::tb::FrameOutput> outputs = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    EXPECT_EQ(outputs[k].aborted, std::count(cut.begin(), cut.end(), k) == 1) << what << ", frame " << k;
    if (outputs[k].aborted) continue;
    const sgm::DisparityMap golden = sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareOutput(golden, frames[k].params, outputs[k], "sgm_top output"), "")
        << what << ", frame " << k << " (" << frames[k].left.cols << "x" << frames[k].left.rows << ")";
    EXPECT_EQ(outputs[k].errors, 0u) << what << ", frame " << k;
  }
}

// The first frames after reset from registers and memories that start all zeros
// (an FPGA after configuration) or all ones instead of random: nothing the reset
// leaves alone may reach a pixel.
TEST(SgmTop, FirstFramesFromZeroOrOnesPowerUpState) {
  for (const int state : {0, 1}) {
    Harness core("sgm_top_power_up_" + std::to_string(state), 15, {0.1, 0.1}, state);
    std::mt19937 rng(15);
    sgm::Params unique = hardwareDefaults();
    unique.uniqueness = 20;
    const std::vector<FrameInput> frames = {
        syntheticPair(Vsgm_top_sgm_top::MIN_FRAME_WIDTH + 9, 12, rng, hardwareDefaults()),
        syntheticPair(Vsgm_top_sgm_top::MIN_FRAME_WIDTH, 9, rng, withBuildLevers(unique))};
    expectBitExact(core, frames, "power-up state " + std::to_string(state));
  }
}

TEST(SgmTop, SyntheticFramesBackToBackWithStalls) {
  for (const double stall : {0.0, 0.3}) {
    Harness core("sgm_top_synthetic", 11, {stall, stall});
    std::mt19937 rng(3);
    std::vector<FrameInput> frames;
    const int narrowest = Vsgm_top_sgm_top::MIN_FRAME_WIDTH;  // the core's minimum width
    const int widest = Vsgm_top_sgm_top::MAX_WIDTH;
    for (const auto [w, h] : {std::pair{narrowest, 9},
                              {std::min(widest, narrowest + 37), 17},
                              {std::min(widest, narrowest + 84), 12},
                              {narrowest + 1, 10}})
      frames.push_back(syntheticPair(w, h, rng, hardwareDefaults()));
    expectBitExact(core, frames, "stall " + std::to_string(stall));
  }
}

constexpr int kMinWidth = Vsgm_top_sgm_top::MIN_FRAME_WIDTH;  // MIN_WIDTH, else max(D, 16), more with many lanes
constexpr int kMaxHeight = Vsgm_top_sgm_top::MAX_HEIGHT;      // of this build

// Frames at the build's limits: MAX_WIDTH wide, MAX_HEIGHT tall, and both at
// once where the build is small enough (the Makefile gives the small whole-core
// builds a small MAX_HEIGHT), then a small frame (the core recovers its state).
TEST(SgmTop, FullWidthAndFullHeightFrames) {
  Harness core("sgm_top_full_size", 12, {0.1, 0.1});
  std::mt19937 rng(12);
  sgm::Params unified = hardwareDefaults();
  unified.mode = sgm::CostMode::kUnified, unified.lrTolerance = 3, unified.p1 = 41, unified.p2 = 201;
  std::vector<FrameInput> frames = {syntheticPair(kMaxWidth, 9, rng, hardwareDefaults()),
                                    syntheticPair(kMinWidth, kMaxHeight, rng, unified),
                                    syntheticPair(kMaxWidth, 10, rng, unified)};
  if (long(kMaxWidth) * kMaxHeight <= 200000)
    frames.push_back(syntheticPair(kMaxWidth, kMaxHeight, rng, hardwareDefaults()));
  frames.push_back(syntheticPair(kMinWidth + 3, 9, rng, hardwareDefaults()));
  expectBitExact(core, frames, "full-size frames");
}

// Each kind of out-of-range configuration (width, height, penalties, mode)
// between good frames, in one stream: the core drops the frame whole (no output
// beat), flags error_o[3], and the next frame is bit-exact with error_o clear.
// The limits themselves (MIN_WIDTH, 9 rows, P2' = P1) are accepted.
TEST(SgmTop, OutOfRangeConfigurationIsDroppedThenGoodFrame) {
  std::mt19937 rng(13);
  sgm::Params inverted = hardwareDefaults();
  inverted.p1 = 21, inverted.p2 = 20;
  sgm::Params equal = hardwareDefaults();
  equal.p1 = 33, equal.p2 = 33, equal.mode = sgm::CostMode::kRsad;
  sgm::Params unified = hardwareDefaults();
  unified.mode = sgm::CostMode::kUnified, unified.median = false;
  const std::vector<std::pair<std::string, FrameInput>> bad = {
      {"width below MIN_FRAME_WIDTH", syntheticPair(kMinWidth - 1, 9, rng, hardwareDefaults())},
      {"width above MAX_WIDTH", syntheticPair(kMaxWidth + 1, 9, rng, hardwareDefaults())},
      {"height 8", syntheticPair(kMinWidth + 5, 8, rng, hardwareDefaults())},
      {"height above MAX_HEIGHT", syntheticPair(kMinWidth, kMaxHeight + 1, rng, hardwareDefaults())},
      {"P2' below P1", syntheticPair(kMinWidth + 2, 10, rng, inverted)},
      {"cost mode 3", syntheticPair(kMinWidth + 4, 9, rng, hardwareDefaults())},
      {"uniqueness 100", syntheticPair(kMinWidth + 3, 9, rng, hardwareDefaults())},
      {"uniqueness 127", syntheticPair(kMinWidth + 1, 10, rng, hardwareDefaults())},
      {"AD term beyond the cost word", syntheticPair(kMinWidth + 2, 9, rng, hardwareDefaults())},
      {"fifth-path weight 9", syntheticPair(kMinWidth + 1, 9, rng, hardwareDefaults())},
      {"path restart length 0", syntheticPair(kMinWidth + 2, 10, rng, hardwareDefaults())},
      {"output mode 2", syntheticPair(kMinWidth + 1, 9, rng, hardwareDefaults())},
      {"output mode 3", syntheticPair(kMinWidth + 3, 10, rng, hardwareDefaults())}};
  std::vector<FrameInput> frames = {syntheticPair(kMinWidth, 9, rng, equal)};
  for (size_t i = 0; i < bad.size(); ++i) {
    frames.push_back(bad[i].second);
    frames.back().dropped = true;
    std::map<std::string, uint32_t>& codes = frames.back().fieldCodes;
    if (bad[i].first == "cost mode 3") codes["CONFIG_MODE"] = 3;
    if (bad[i].first == "uniqueness 100") codes["CONFIG_UNIQUENESS"] = 100;
    if (bad[i].first == "uniqueness 127") codes["CONFIG_UNIQUENESS"] = 127;
    if (bad[i].first == "fifth-path weight 9") codes["PENALTY_RIGHT_WEIGHT"] = 9;
    if (bad[i].first == "output mode 2") codes["OUTPUT_MODE"] = 2;  // dropped in every build
    if (bad[i].first == "output mode 3") codes["OUTPUT_MODE"] = 3;
    if (bad[i].first == "path restart length 0") {  // T 30 with R 0 (dropped in every build)
      frames.back().params.edgeReset.threshold = 30;
      codes["EDGE_RESET_LEN"] = 0;
    }
    if (bad[i].first == "AD term beyond the cost word") {  // rsad 44 + (15 x 45) >> 3 = 128 > 127 (9x5; 9x9: 80 + 84)
      frames.back().params.adCap = Vsgm_top_sgm_top::CENSUS_H == 9 ? 255 : 45;
      codes["PENALTY_AD_WEIGHT"] = 15;
    }
    sgm::Params good = i % 2 ? unified : hardwareDefaults();
    good.uniqueness = i == 6 ? 99 : 0;  // the largest ratio in range, after the first out of range
    if (i == 9) good.rightPathWeight = sgm::kMaxRightPathWeight;            // the largest weight, after one above it
    if (i == 10) good.edgeReset = sgm::EdgeReset{255, 1, {1, 1, 1, 1, 1}};  // the largest T, the shortest R
    if (i == 11) good.output = sgm::OutputMode::kDepth, good.focalQ8 = 400 * 256, good.baselineUm = 50000;
    if (i == 8) {  // weight 15 with the largest cap the build's cost word leaves this mode
      good.adWeight = 15, good.adCap = sgm::largestAdCap(good.mode, good.census, 15);
    }
    frames.push_back(syntheticPair(kMinWidth + 9 - int(i % 10), 9 + int(i % 3), rng, withBuildLevers(good)));
  }
  Harness core("sgm_top_bad_config", 13, {0.2, 0.2});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const std::string what = k % 2 ? bad[k / 2].first : "good frame " + std::to_string(k);
    if (k % 2) {
      EXPECT_EQ(out[k].errors, 8u) << what << ": error_o";
      continue;
    }
    EXPECT_EQ(sgm::tb::compareOutput(sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params),
                                     frames[k].params, out[k], "sgm_top output"),
              "")
        << what << " (after " << (k ? bad[k / 2 - 1].first : "reset") << ")";
    EXPECT_EQ(out[k].errors, 0u) << what;
  }
}

// Settings beyond the defaults at every D: odd penalties, P1 = P2', the
// extremes 0 and 255, every LR tolerance 0 .. 7, each mode with and without
// sub-pixel, each post-processing switch alone.
TEST(SgmTop, SettingsSweep) {
  Harness core("sgm_top_settings", 14, {0.1, 0.1});
  std::mt19937 rng(14);
  const sgm::CostMode modes[] = {sgm::CostMode::kRt, sgm::CostMode::kRsad, sgm::CostMode::kUnified};
  std::vector<FrameInput> frames;
  for (int tol = 0; tol <= 7; ++tol) {
    sgm::Params p = hardwareDefaults();
    p.mode = modes[tol % 3];
    p.lrTolerance = tol;
    p.p1 = 2 * tol + 3 + 10 * (tol % 3);    // odd: 3, 15, 27, 9, 21, 33, 15, 27
    p.p2 = p.p1 + 2 * (tol * 17 % 23) + 1;  // odd difference to P1
    p.subpixel = tol % 2 == 0;
    p.fill = tol % 4 != 1, p.snap = tol % 4 != 2, p.median = tol % 4 != 3;
    p.uniqueness = tol * 13 % 40;           // 0, 13, 26, 39, 12, 25, 38, 11
    p.rightPathWeight = (tol * 5 + 1) % 9;  // 1, 6, 2, 7, 3, 8, 4, 0 (with the fifth path built)
    frames.push_back(syntheticPair(kMinWidth + 5 * tol + 1, 9 + tol % 3, rng, withBuildLevers(p)));
  }
  for (const auto [p1, p2] : {std::pair{255, 255}, {1, 1}, {0, 255}, {127, 129}}) {
    sgm::Params p = hardwareDefaults();
    p.p1 = p1, p.p2 = p2, p.lrTolerance = 7;
    frames.push_back(syntheticPair(kMinWidth + 11, 10, rng, p));
  }
  expectBitExact(core, frames, "settings sweep");
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
  // The run-time P2 form and path weights, both ways from the build's preset.
  sgm::Params paperP2 = hardwareDefaults();
  paperP2.p2Mode = sgm::P2Mode::kPaper, paperP2.weights = sgm::PathWeighting::k3232, paperP2.p1 = 10;
  sgm::Params kneeEqual = hardwareDefaults();
  kneeEqual.p2Mode = sgm::P2Mode::kKnee, kneeEqual.weights = sgm::PathWeighting::kEqual, kneeEqual.p2 = 255;
  sgm::Params unique = hardwareDefaults();  // uniqueness with the LR check off and on
  unique.uniqueness = 15, unique.lrTolerance = -1;
  sgm::Params uniqueLr = hardwareDefaults();
  uniqueLr.uniqueness = 30, uniqueLr.fill = false;
  sgm::Params ad = hardwareDefaults();  // the AD term (candidate C's weight and cap)
  ad.adWeight = 3, ad.adCap = 20, ad.uniqueness = 15, ad.snap = false;
  sgm::Params adRt = hardwareDefaults();
  adRt.mode = sgm::CostMode::kRt, adRt.adWeight = 8, adRt.adCap = 60;
  sgm::Params candidate = hardwareDefaults();  // issue 15's candidate C (with the fifth path built)
  candidate.rightPathWeight = 4, candidate.p1 = 24, candidate.p2 = 200, candidate.adWeight = 3;
  candidate.uniqueness = 15, candidate.snap = false;
  sgm::Params rightEqual = hardwareDefaults();  // the fifth path beside equal weights, the paper's P2
  rightEqual.rightPathWeight = 1, rightEqual.weights = sgm::PathWeighting::kEqual,
  rightEqual.p2Mode = sgm::P2Mode::kPaper;
  sgm::Params restart = candidate;  // the path restart at strong edges (issue 15's candidate)
  restart.edgeReset = sgm::EdgeReset{40, 6, {1, 1, 0, 1, 1}};
  sgm::Params restartAll = hardwareDefaults();  // every path, a low threshold, the longest R
  restartAll.edgeReset = sgm::EdgeReset{8, 15, {1, 1, 1, 1, 1}};
  sgm::Params restartFifth = hardwareDefaults();  // the fifth path alone
  restartFifth.edgeReset = sgm::EdgeReset{20, 3, {0, 0, 0, 0, 1}};
  for (const sgm::Params& p : {unified, rt, paperP2, unique, ad, strict, kneeEqual, restart, uniqueLr, adRt, raw,
                               candidate, restartAll, rightEqual, restartFifth, hardwareDefaults()})
    frames.push_back(syntheticPair(std::max(kMinWidth, kD + 20), 20, rng, withBuildLevers(p)));
  expectBitExact(core, frames, "parameter sets");
}

// The run-time levers against the build (UNIQUENESS, AD_TERM): a frame that asks for a
// lever the build lacks (a uniqueness ratio, an AD weight) is dropped whole with
// error_o[3], and the next frame is bit-exact; in a build that has the lever the same
// frame is bit-exact. An AD cap with weight 0 asks for nothing. Every build runs it: the
// lean top-d16-lean drops, the others stream.
TEST(SgmTop, LeversTheBuildLacksAreDroppedThenGoodFrame) {
  std::mt19937 rng(17);
  sgm::Params unique = hardwareDefaults(), unique1 = hardwareDefaults();
  unique.uniqueness = 25, unique1.uniqueness = 1;  // 1: the smallest ratio that asks for the lever
  sgm::Params ad = hardwareDefaults(), ad1 = hardwareDefaults();
  ad.adWeight = 4, ad.adCap = 30;
  ad1.adWeight = 1, ad1.adCap = 0;  // the smallest weight, with a term of 0 everywhere
  sgm::Params both = hardwareDefaults();
  both.uniqueness = 10, both.adWeight = 2, both.adCap = 12;
  sgm::Params capOnly = hardwareDefaults();
  capOnly.adWeight = 0, capOnly.adCap = 255;  // weight 0: the term is off
  sgm::Params right = hardwareDefaults();     // the fifth path, in the build's blocks when it has them
  right.rightPathWeight = 4, right.rightPathBlock = kRightBlock ? kRightBlock : 16;
  sgm::Params restart = hardwareDefaults(), restartOff = hardwareDefaults();
  restart.edgeReset = sgm::EdgeReset{1, 4, {1, 0, 1, 0, 0}};      // T 1: the smallest that asks for it
  restartOff.edgeReset = sgm::EdgeReset{0, 15, {1, 1, 1, 1, 1}};  // T 0: off, whatever R and the flags
  sgm::Params depth = hardwareDefaults(), depthOff = hardwareDefaults();
  depth.output = sgm::OutputMode::kDepth, depth.focalQ8 = 1 << 17, depth.baselineUm = 120000;
  depthOff.focalQ8 = (1 << 24) - 1, depthOff.baselineUm = 7;  // disparity words: f and B unused
  sgm::Params dmin1 = hardwareDefaults();
  dmin1.minDisparity = 1;  // the smallest that asks for the lever
  sgm::Params confidence = hardwareDefaults();
  confidence.outputConfidence = true;
  const std::vector<std::pair<std::string, sgm::Params>> asks = {{"uniqueness 25", unique},
                                                                 {"uniqueness 1", unique1},
                                                                 {"AD weight 4 cap 30", ad},
                                                                 {"AD weight 1 cap 0", ad1},
                                                                 {"uniqueness 10, AD weight 2", both},
                                                                 {"AD cap 255 weight 0", capOnly},
                                                                 {"fifth path weight 4", right},
                                                                 {"path restart T 1", restart},
                                                                 {"path restart T 0, R 15, every flag", restartOff},
                                                                 {"depth output", depth},
                                                                 {"disparity output with f and B", depthOff},
                                                                 {"minimum disparity 1", dmin1},
                                                                 {"confidence in the word", confidence}};
  std::vector<FrameInput> frames = {syntheticPair(kMinWidth + 2, 9, rng, hardwareDefaults())};
  std::vector<std::string> what = {"first good frame"};
  for (const auto& [name, p] : asks) {
    frames.push_back(syntheticPair(kMinWidth + 6, 10, rng, p));
    frames.back().dropped = asksMissingLever(p);
    what.push_back(name);
    frames.push_back(syntheticPair(kMinWidth + 1, 9, rng, hardwareDefaults()));
    what.push_back("good frame after " + name);
  }
  if (kLean) EXPECT_TRUE(std::any_of(frames.begin(), frames.end(), [](const FrameInput& f) { return f.dropped; }));
  Harness core("sgm_top_levers", 17, {0.2, 0.2});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const std::string build = std::string(" (UNIQUENESS=") + (kUniqueness ? "1" : "0") +
                              ", AD_TERM=" + (kAdTerm ? "1" : "0") + ", RIGHT_BLOCK=" + std::to_string(kRightBlock) +
                              ", EDGE_RESET=" + (kEdgeReset ? "1" : "0") + ", DEPTH=" + (kDepth ? "1" : "0") +
                              ", MIN_DISPARITY=" + (kMinDisparity ? "1" : "0") +
                              ", CONFIDENCE=" + (kConfidence ? "1" : "0") + ")";
    if (frames[k].dropped) {
      EXPECT_EQ(out[k].errors, 8u) << what[k] << build << ": error_o of a frame asking for a lever the build lacks";
      continue;
    }
    EXPECT_EQ(sgm::tb::compareOutput(sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params),
                                     frames[k].params, out[k], "sgm_top output"),
              "")
        << what[k] << build;
    EXPECT_EQ(out[k].errors, 0u) << what[k] << build;
  }
}

// The minimum disparity (MIN_DISPARITY = 1): pairs whose right image is shifted by dmin
// more, searched from dmin (every dmin whose lag takes another path in the cost volume's
// shift: 1 and 2 from registers, 3 the shortest through its memory, then larger ones up to
// 255, beyond the frame), between frames at dmin 0, back to back with stalls: bit-exact,
// and the shifted pair finds the original pair's disparities.
TEST(SgmTop, MinDisparityIsExact) {
  if (!kMinDisparity) GTEST_SKIP() << "this build has no minimum disparity (sgm_top MIN_DISPARITY = 0)";
  std::mt19937 rng(48);
  std::vector<FrameInput> frames;
  for (const int dmin : {0, 1, 2, 3, 7, 0, 29, 255, 0}) {
    sgm::Params p = withBuildLevers(hardwareDefaults());
    p.minDisparity = dmin;
    const int w = std::max(kMinWidth, std::min(kMaxWidth, dmin + kD + 24));
    FrameInput f = syntheticPair(w, 9 + dmin % 4, rng, p);
    // The right image moved left by dmin: every disparity dmin larger.
    cv::Mat shifted(f.right.size(), CV_8UC1);
    for (int y = 0; y < shifted.rows; ++y)
      for (int x = 0; x < shifted.cols; ++x)
        shifted.at<uint8_t>(y, x) = x + dmin < w ? f.right.at<uint8_t>(y, x + dmin) : uint8_t(rng());
    f.right = shifted;
    frames.push_back(f);
  }
  Harness core("sgm_top_dmin", 48, {0.2, 0.2});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const sgm::DisparityMap golden = sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareOutput(golden, frames[k].params, out[k], "sgm_top output"), "")
        << "frame " << k << ", dmin " << frames[k].params.minDisparity;
    EXPECT_EQ(out[k].errors, 0u) << "frame " << k;
  }
  // dmin 29 on a 29-pixel shift: disparities of at least 29 px where valid.
  const sgm::DisparityMap& m = out[6].map;
  int below = 0, valid = 0;
  for (int y = 0; y < m.disp.rows; ++y)
    for (int x = 0; x < m.disp.cols; ++x)
      if (m.valid.at<uint8_t>(y, x)) ++valid, below += m.disp.at<uint16_t>(y, x) < 29 * 16;
  EXPECT_GT(valid, 0);
  EXPECT_EQ(below, 0);
}

// The rectification (RECTIFY = 1): raw pairs of several sizes back to back with stalls, each
// through a calibration loaded before it (or the one before it kept), a pair that passes
// through unrectified between them, one whose left image is shifted so that a band of its
// pixels has its source outside (output word 0), and a lag above R - 2 (dropped): every
// word equals sgm::runRectifiedPipeline's.
TEST(SgmTop, RawPairsThroughTheirMeshesAreExact) {
  if (!kRectify) GTEST_SKIP() << "this build has no rectification (sgm_top RECTIFY = 0)";
  std::mt19937 rng(49);
  std::vector<FrameInput> frames;
  std::vector<std::shared_ptr<const sgm::StereoMesh>> calibration;  // per frame, the meshes in use
  std::shared_ptr<const sgm::StereoMesh> current;
  const sgm::Params base = withBuildLevers(hardwareDefaults());
  const int sizes[][2] = {{kMaxWidth, 20}, {kMaxWidth - 13, 17}, {kMinWidth + 9, 12}, {kMaxWidth, 20}};
  for (int k = 0; k < 9; ++k) {
    const int w = sizes[k % 4][0], h = sizes[k % 4][1];
    FrameInput f = syntheticPair(w, h, rng, base);
    f.params.rectify = k != 4;
    if (k == 4) {
      calibration.push_back(nullptr);  // passes through
    } else if (k == 3 && current && current->left.width == w && current->left.height == h) {
      f.params.rectifyLag = frames.back().params.rectifyLag;  // keeps the calibration before it
    } else {
      int lag = 0;
      auto mesh = sgm::tb::fittingCalibration(w, h, kRectifyGridLog2, kRectifyRows, 1.0 + 0.5 * (k % 3),
                                              k == 7 ? 1.0 : 0.95, rng, &lag);
      if (k == 7)  // the left image's sources 5.5 px to the right: its last columns outside
        for (int32_t& u : mesh->left.u) u += 5 * 32 + 16;
      f.params.rectifyLag = std::max(lag, sgm::meshRowSpan(mesh->left).lag);
      f.mesh = current = mesh;
    }
    if (k != 4) calibration.push_back(current);
    frames.push_back(f);
  }
  // A lag above R - 2: dropped with the configuration error, then the frames go on.
  FrameInput tooFar = frames.back();
  tooFar.params.rectifyLag = kRectifyRows - 1, tooFar.mesh = nullptr, tooFar.dropped = true;
  frames.insert(frames.begin() + 6, tooFar);
  calibration.insert(calibration.begin() + 6, nullptr);
  Harness core("sgm_top_rectify", 49, {0.2, 0.2});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  int outside = 0;
  for (size_t k = 0; k < frames.size(); ++k) {
    if (frames[k].dropped) {
      EXPECT_EQ(out[k].errors, 8u) << "frame " << k << ": a lag of R - 1 is out of range";
      continue;
    }
    const sgm::DisparityMap golden = calibration[k]
                                         ? sgm::runRectifiedPipeline(frames[k].left, frames[k].right, *calibration[k],
                                                                     frames[k].params)
                                         : sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareOutput(golden, frames[k].params, out[k], "sgm_top output (rectified)"), "")
        << "frame " << k << ", lag " << frames[k].params.rectifyLag << (calibration[k] ? "" : ", passing through");
    EXPECT_EQ(out[k].errors, 0u) << "frame " << k;
    if (k == 8)
      for (int y = 0; y < golden.disp.rows; ++y) outside += out[k].words.at<uint16_t>(y, golden.disp.cols - 1) == 0;
  }
  EXPECT_EQ(outside, frames[8].left.rows) << "the shifted calibration's last column: word 0 (source outside)";
  EXPECT_FALSE(core.top()->rect_row_miss_o);
}

// The depth output (DEPTH = 1): frames in depth mode with f and B that give every kind of
// word (saturated at 65535 near d = 0 or for every pixel, 1 for every pixel, the range in
// between) between disparity frames, back to back with stalls: every word equals
// sgm::outputWords of the golden map, and the disparity frames stay bit-exact.
TEST(SgmTop, DepthOutputIsExact) {
  if (!kDepth) GTEST_SKIP() << "this build has no depth output (sgm_top DEPTH = 0)";
  std::mt19937 rng(47);
  const sgm::Params base = hardwareDefaults();
  auto depthParams = [&](int focalQ8, int baselineUm) {
    sgm::Params p = base;
    p.output = sgm::OutputMode::kDepth, p.focalQ8 = focalQ8, p.baselineUm = baselineUm;
    return p;
  };
  const std::vector<sgm::Params> params = {base,
                                           depthParams(700 * 256, 60000),  // 700 px, 60 mm: 65535 below 0.64 px
                                           depthParams((1 << 24) - 1, (1 << 24) - 1),  // K near 2^48: 65535 everywhere
                                           depthParams(1, 1),                          // 1 mm everywhere
                                           depthParams(1000 * 256 + 17, 1003),         // about 1000 / d mm
                                           depthParams(3 * 256, 2000000),              // 3 px, 2 m
                                           base};
  std::vector<FrameInput> frames;
  for (size_t k = 0; k < params.size(); ++k)
    frames.push_back(syntheticPair(kMinWidth + int(k % 3), 9 + int(k % 4), rng, params[k]));
  Harness core("sgm_top_depth", 47, {0.2, 0.3});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const sgm::DisparityMap golden = sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareOutput(golden, frames[k].params, out[k], "sgm_top output"), "") << "frame " << k;
    EXPECT_EQ(out[k].errors, 0u) << "frame " << k;
  }
  // The words are depth words: the saturating frame is 65535 wherever the golden map is valid.
  const cv::Mat saturated = sgm::outputWords(sgm::runPipeline(frames[2].left, frames[2].right, frames[2].params),
                                             frames[2].params);
  EXPECT_GT(cv::countNonZero(saturated == 65535), 0);
}

// The confidence (CONFIDENCE = 1): frames with OUTPUT.CONFIDENCE on and off back to back with
// stalls, with the LR check on and off, the uniqueness ratio, sub-pixel, the depth output (a
// DEPTH build: the confidence waits for sgm_depth) and a raw pair through its calibration (a
// RECTIFY build: word 0 where the source is outside): bits 23:16 equal the golden model's
// confidence (docs/algorithm.md section 7b) with it on and are 0 with it off, and bits 15:0
// stay exact.
TEST(SgmTop, ConfidenceInTheOutputWordIsExact) {
  if (!kConfidence) GTEST_SKIP() << "this build has no confidence (sgm_top CONFIDENCE = 0)";
  std::mt19937 rng(53);
  const sgm::Params base = withBuildLevers(hardwareDefaults());
  std::vector<FrameInput> frames;
  std::vector<std::shared_ptr<const sgm::StereoMesh>> calibration;
  for (int k = 0; k < 8; ++k) {
    sgm::Params p = base;
    p.outputConfidence = k != 2 && k != 5;
    p.lrTolerance = k == 3 ? -1 : k == 4 ? 0 : 1;
    p.uniqueness = kUniqueness ? (k == 1 ? 0 : k == 6 ? 40 : 15) : 0;
    p.subpixel = k % 2 == 0;
    if (kDepth && k == 6) p.output = sgm::OutputMode::kDepth, p.focalQ8 = 700 * 256, p.baselineUm = 60000;
    const int w = k % 3 == 0 ? kMaxWidth : kMinWidth + 5 * k, h = 9 + 3 * (k % 4);
    FrameInput f = syntheticPair(w, h, rng, p);
    std::shared_ptr<const sgm::StereoMesh> mesh;
    if (kRectify && k == 7) {
      int lag = 0;
      auto m = sgm::tb::fittingCalibration(w, h, kRectifyGridLog2, kRectifyRows, 1.0, 1.0, rng, &lag);
      for (int32_t& u : m->left.u) u += 3 * 32;  // the last columns' sources outside: word 0
      f.params.rectify = true, f.params.rectifyLag = std::max(lag, sgm::meshRowSpan(m->left).lag);
      f.mesh = mesh = m;
    }
    calibration.push_back(mesh);
    frames.push_back(f);
  }
  Harness core("sgm_top_confidence", 53, {0.2, 0.3});
  const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
  long confident = 0, zero = 0;
  for (size_t k = 0; k < frames.size(); ++k) {
    const sgm::DisparityMap golden = calibration[k]
                                         ? sgm::runRectifiedPipeline(frames[k].left, frames[k].right, *calibration[k],
                                                                     frames[k].params)
                                         : sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params);
    EXPECT_EQ(sgm::tb::compareOutput(golden, frames[k].params, out[k], "sgm_top output"), "")
        << "frame " << k << (frames[k].params.outputConfidence ? ", confidence on" : ", confidence off");
    EXPECT_EQ(out[k].errors, 0u) << "frame " << k;
    if (frames[k].params.outputConfidence)
      confident += cv::countNonZero(out[k].confidence),
          zero += long(out[k].confidence.total()) - cv::countNonZero(out[k].confidence);
  }
  // Both kinds of pixel occur: the comparison is not of constants.
  EXPECT_GT(confident, 0);
  EXPECT_GT(zero, 0);
}

// Every malformed kind, in two places each, between good frames: the core
// flags it in error_o, emits W x H beats for every frame it started (checked by
// the harness's stream checker), and the next good frame is bit-exact.
TEST(SgmTop, EveryMalformedFrameKindIsFlaggedAndRecovered) {
  std::mt19937 rng(6);
  const int w = kMinWidth + 8, h = 12;
  for (const Malformation kind : sgm::tb::kAllMalformations)
    for (const unsigned at : {0u, unsigned(rng())}) {
      Harness core("sgm_top_malformed", 9 + at, {0.2, 0.2});
      const FrameInput first = syntheticPair(w + 3, 10, rng, hardwareDefaults());
      const MalformedFrames bad = malform(syntheticPair(w, h, rng, hardwareDefaults()), kind, kMaxWidth, at, rng());
      const FrameInput after = syntheticPair(w + 5, 11, rng, hardwareDefaults());
      std::vector<FrameInput> frames = {first};
      frames.insert(frames.end(), bad.frames.begin(), bad.frames.end());
      frames.push_back(after);
      std::vector<sgm::tb::FrameOutput> out;
      try {
        out = core.run(frames);
      } catch (const sgm::Error& e) {
        ADD_FAILURE() << bad.description << ": " << e.what();
        continue;
      }
      for (size_t k = 0; k < bad.frames.size(); ++k)
        EXPECT_EQ(out[1 + k].errors, bad.errors[k]) << bad.description << ": error_o of frame " << 1 + k;
      if (kRectify) {  // the raw framing errors: one error_event_o pulse per frame that has them
        long framesWithErrors = 0, pulses = 0;
        for (const sgm::tb::FrameOutput& o : out) framesWithErrors += (o.errors & 7u) != 0;
        for (const unsigned e : core.errorEvents()) pulses += (e & 7u) != 0;
        EXPECT_EQ(pulses, framesWithErrors) << bad.description << ": error_event_o pulses of the raw framing";
        EXPECT_GT(framesWithErrors, 0) << bad.description;
      }
      for (const size_t k : {size_t(0), frames.size() - 1}) {
        EXPECT_EQ(sgm::tb::compareMaps(sgm::runPipeline(frames[k].left, frames[k].right, frames[k].params), out[k].map,
                                       "sgm_top output"),
                  "")
            << bad.description << ", frame " << k;
        EXPECT_EQ(out[k].errors, 0u) << bad.description << ", frame " << k;
      }
    }
}

// Reset in the middle of a frame (before its first beat, after one beat, in
// the middle, after its last beat): the next frame is bit-exact.
TEST(SgmTop, ResetInTheMiddleOfAFrameThenCleanFrame) {
  std::mt19937 rng(8);
  const int w = kMinWidth + 11, h = 14;
  for (const long resetAfter : {0L, 1L, long(w) * 7 + 3, long(w) * h}) {
    Harness core("sgm_top_reset", 3, {0.15, 0.15});
    FrameInput cut = syntheticPair(w, h, rng, hardwareDefaults());
    cut.resetAfterBeats = resetAfter;
    sgm::Params other = hardwareDefaults();
    other.mode = sgm::CostMode::kUnified, other.median = false;
    expectBitExact(core, {syntheticPair(w - 4, 10, rng, hardwareDefaults()), cut, syntheticPair(w + 6, 9, rng, other)},
                   "reset after " + std::to_string(resetAfter) + " beats", {1});
  }
}

// The stream checker on hand-made beat sequences: quiet on a good frame, and
// naming the cycle and the rule for each kind of violation.
TEST(AxisChecker, NamesTheCycleAndTheRuleOfEachViolation) {
  using sgm::tb::AxisChecker;
  using sgm::tb::Beat;
  const int w = 3, h = 2;
  std::vector<Beat> frame;
  for (int i = 0; i < w * h; ++i) frame.push_back(Beat{uint16_t(i), i == 0, i % w == w - 1});
  // Feeds the beats one per cycle (valid and ready high) after `prefix` cycles of other bus states.
  const auto check = [&](const std::vector<Beat>& beats, int frames) {
    AxisChecker c;
    for (int f = 0; f < frames; ++f) c.expectFrame(w, h);
    for (size_t i = 0; i < beats.size(); ++i) c.observe(10 + i, true, true, beats[i]);
    return c.finish();
  };
  EXPECT_EQ(check(frame, 1), "");
  std::vector<Beat> b = frame;
  b[0].user = false;
  EXPECT_EQ(check(b, 1), "cycle 10, output beat 0 (frame 0, x=0, y=0): tuser missing on the first beat of a frame");
  b = frame, b[4].user = true;
  EXPECT_EQ(check(b, 1), "cycle 14, output beat 4 (frame 0, x=1, y=1): tuser on a beat inside a frame");
  b = frame, b[2].last = false;
  EXPECT_EQ(check(b, 1), "cycle 12, output beat 2 (frame 0, x=2, y=0): tlast missing on the last beat of a line");
  b = frame, b[1].last = true;
  EXPECT_EQ(check(b, 1), "cycle 11, output beat 1 (frame 0, x=1, y=0): tlast before the last beat of a line");
  b = frame, b.pop_back();
  EXPECT_EQ(check(b, 1), "frame 0 ended after 5 of 3 x 2 output beats");
  b = frame, b.push_back(frame[0]);
  EXPECT_EQ(check(b, 1), "cycle 16, output beat 6: beat after the last announced frame (more than W x H beats)");
  // A frame one beat short shows up as a missing tlast or tuser of the next one.
  b = frame, b.erase(b.begin() + 5), b.insert(b.end(), frame.begin(), frame.end());
  EXPECT_EQ(check(b, 2), "cycle 15, output beat 5 (frame 0, x=2, y=1): tuser on a beat inside a frame");
  // Handshake: valid drops, or data changes, while ready is low.
  AxisChecker drop;
  drop.observe(0, true, false, frame[0]);
  drop.observe(1, false, true, frame[0]);
  EXPECT_EQ(drop.violation(), "cycle 1, output beat 0: tvalid dropped before its handshake");
  AxisChecker change;
  change.observe(0, true, false, frame[0]);
  change.observe(1, true, false, frame[0]);
  change.observe(2, true, true, frame[1]);
  EXPECT_EQ(change.violation(),
            "cycle 2, output beat 0: tdata/tuser/tlast changed while tvalid was high and tready low");
  // Legal: valid low without a pending beat, data changing while valid is low, a reset dropping a held beat.
  AxisChecker legal;
  legal.observe(0, false, false, frame[3]);
  legal.observe(1, true, false, frame[0]);
  legal.reset();
  legal.observe(2, false, true, frame[1]);
  EXPECT_EQ(legal.finish(), "");
}

// Real scenes, in the D = 64 builds only: the four Middlebury scenes and Aloe in
// the 9x5 build, Aloe in the 9x9 build (its paper preset; CI time).
TEST(SgmTop, MiddleburyAndAloe) {
  if (kD != 64) GTEST_SKIP() << "real scenes run in the D = 64 build";
  const char* data = std::getenv("SGM_DATA");
  std::vector<sgm::eval::Scene> scenes;
  const std::vector<const char*> middlebury = {"cones", "teddy", "sawtooth", "venus"};
  for (const char* name : kCensusH == 9 ? std::vector<const char*>{} : middlebury) {
    const std::string dir = std::string(data ? data : "") + "/" + name;
    if (data && std::filesystem::exists(dir + "/left.png")) scenes.push_back(sgm::eval::loadScene(dir));
  }
  if (sgm::eval::aloeAvailable()) scenes.push_back(sgm::eval::loadAloe());
  if (kCensusH != 9 && scenes.size() < 5)
    std::cout << "[ note     ] Middlebury data not found at " << (data ? data : "(SGM_DATA unset)")
              << "; set DATA=...\n";
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
              << (mismatches == 0 ? "yes" : "NO") << ", " << cycles << " cycles, " << double(cycles) / double(pixels)
              << " cycles/pixel, bad-1.0 nonocc " << f.errNonocc << "%\n";
    // One pixel per clock: at most 1.05 W H + a fixed latency of a few (here 12) lines.
    EXPECT_LE(double(cycles), 1.05 * double(pixels) + 12.0 * s.left.cols) << s.name;
  }
}

TEST(SgmTop, RealSceneUnderStalls) {
  if (kD != 64 || kCensusH == 9) GTEST_SKIP() << "real scenes under stalls run in the D = 64 9x5 build";
  const char* data = std::getenv("SGM_DATA");
  const std::string dir = std::string(data ? data : "") + "/cones";
  if (!data || !std::filesystem::exists(dir + "/left.png"))
    GTEST_SKIP() << "Middlebury data not found at " << dir << "; set DATA=...";
  const sgm::eval::Scene s = sgm::eval::loadScene(dir);
  Harness core("sgm_top_cones_stalls", 2, {0.25, 0.25});
  expectBitExact(core, {FrameInput{s.left, s.right, hardwareDefaults()}}, "cones with stalls");
}

// A seeded slice of the constrained-random regression (tb/regress_cases.hpp)
// in the D = 64 build, which CI builds anyway: random widths up to its MAX_WIDTH,
// every parameter random, stalls, resets and malformed frames. `make regress
// REGRESS_D=64 REGRESS_MAX_WIDTH=512 REGRESS_SEED=64` runs the same cases at length.
TEST(SgmTop, RegressionSlice) {
  // The lean build runs it too: its random scenes and settings with the levers it lacks off
  // (tb/regress_cases.hpp drawParams); and the fifth-path builds, with random weights.
  const bool other = kLean || kRightBlock;  // a build the D = 16 regression does not cover
  if (kD != 64 && !other)
    GTEST_SKIP()
        << "the regression slice runs in the D = 64, the lean and the fifth-path builds (make regress-ci runs D = 16)";
  constexpr uint64_t kMaster = 64;
  constexpr long kGoodFrames = 12;
  sgm::regress::Totals totals;
  for (uint64_t k = 0; totals.goodFrames < kGoodFrames; ++k) {
    const sgm::regress::Case c = sgm::regress::drawCase(kMaster, k, 40);
    std::string failure;
    try {
      failure = sgm::regress::runCase(c, totals);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    EXPECT_EQ(failure, "") << "case " << k << " (" << c.kind << ", " << c.stallText << "); replay: "
                           << (other ? "case " + std::to_string(k) + " of master seed " + std::to_string(kMaster) +
                                           " in this build (sgm::regress::drawCase)"
                                     : "make regress REGRESS_D=64 REGRESS_MAX_WIDTH=512 REGRESS_SEED=" +
                                           std::to_string(kMaster) + " REGRESS_CASE=" + std::to_string(k));
    ASSERT_LT(k, 200u) << "too few good frames";
  }
  std::cout << "[ figures  ] regression slice: " << totals.goodFrames << " good frames (" << totals.pixels
            << " pixels, widths " << *totals.widths.begin() << ".." << *totals.widths.rbegin() << "), "
            << totals.malformed << " malformed, " << totals.resets << " resets, " << totals.combinations.size()
            << " switch combinations\n";
}

}  // namespace
