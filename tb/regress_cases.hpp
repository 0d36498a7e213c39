// SPDX-License-Identifier: Apache-2.0
// The cases of the constrained-random regression of sgm_top (sgm-regress,
// tests/rtl/regress_main.cpp), shared with the whole-core GoogleTest of the
// D = 64 build (tests/rtl/test_sgm_top.cpp runs a short seeded slice of them):
// case K of a master seed draws a few frames streamed back to back through a
// freshly reset core (synthetic scenes at random sizes up to MAX_WIDTH, random
// parameters, stall profiles, a reset in the middle of a frame or a malformed
// frame followed by a clean one) and checks every good frame against the
// golden model, every malformed frame's error_o and every output cycle.
// Include it in one translation unit per binary (a verilated sgm_top).
#pragma once

#include "Vsgm_top.h"
#include "Vsgm_top_sgm_top.h"
#include "core_harness.hpp"
#include "malformed_frames.hpp"
#include "rectify_meshes.hpp"

#include "eval_lib.hpp"
#include "synthetic_scene.hpp"

#include "sgm/pipeline.hpp"

#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::regress {

using synth::Rng;

constexpr int kD = Vsgm_top_sgm_top::D;
constexpr int kMaxWidth = Vsgm_top_sgm_top::MAX_WIDTH;
constexpr int kMinWidth = Vsgm_top_sgm_top::MIN_FRAME_WIDTH;  // max(D, 16), more with many lanes
constexpr int kMinHeight = 9;

struct Frame {
  tb::FrameInput input;
  unsigned expectedErrors = 0;
  bool good = true;             // compared with the golden model
  std::string text;             // one-line description
  synth::SyntheticScene scene;  // ground truth of a good frame
};

struct Case {
  uint64_t seed = 0;
  std::string kind;
  tb::Stalls stalls;
  std::string sourceStalls, sinkStalls;  // profile names
  std::string stallText;
  std::vector<Frame> frames;
};

// Stall profiles of one side, by name (the summary counts the names seen).
const char* const kStallNames[] = {"none", "light", "heavy", "bursts", "toggle"};

tb::StallProfile drawStalls(Rng& rng, std::string& name) {
  name = kStallNames[rng.uniform(0, 4)];
  if (name == "light") return rng.real(0.02, 0.15);
  if (name == "heavy") return rng.real(0.5, 0.85);
  if (name == "bursts") return tb::StallProfile::bursts(rng.real(0.001, 0.01), 50, rng.uniform(100, 600));
  if (name == "toggle") return tb::StallProfile::toggle();
  return 0.0;
}

Params drawParams(Rng& rng) {
  const CostMode modes[] = {CostMode::kRt, CostMode::kRsad, CostMode::kUnified};
  Params p = defaultParams(modes[rng.uniform(0, 2)]);
  p.disparities = kD;
  if (!rng.chance(0.3)) p.p1 = rng.chance(0.1) ? (rng.chance(0.5) ? 0 : 255) : rng.uniform(0, 255);
  // The golden model takes P2' >= P1 (docs/algorithm.md).
  if (!rng.chance(0.3) || p.p2 < p.p1) p.p2 = rng.chance(0.1) ? (rng.chance(0.5) ? p.p1 : 255) : rng.uniform(p.p1, 255);
  p.subpixel = rng.chance(0.5);
  p.lrTolerance = rng.chance(0.3) ? -1 : rng.chance(0.7) ? rng.uniform(0, 2) : rng.uniform(0, 7);
  p.fill = rng.chance(0.5);
  p.snap = rng.chance(0.5);
  p.median = rng.chance(0.5);
  // The run-time P2 form and path weights; the census window is the build's.
  p.p2Mode = rng.chance(0.5) ? P2Mode::kPaper : P2Mode::kKnee;
  p.weights = rng.chance(0.5) ? PathWeighting::kEqual : PathWeighting::k3232;
  p.uniqueness = rng.chance(0.5) ? 0 : rng.chance(0.1) ? 99 : rng.uniform(1, 40);
  // The AD term: half the frames, up to the largest term the mode's cost word leaves.
  p.census = Vsgm_top_sgm_top::CENSUS_H == 9 ? CensusWindow::k9x9 : CensusWindow::k9x5;
  p.adWeight = rng.chance(0.5) ? 0 : rng.uniform(1, kMaxAdWeight);
  p.adCap = p.adWeight ? rng.uniform(0, largestAdCap(p.mode, p.census, p.adWeight)) : 20;
  // The fifth path: half the frames, any weight, in the build's blocks.
  p.rightPathWeight = rng.chance(0.5) ? 0 : rng.uniform(1, kMaxRightPathWeight);
  p.rightPathBlock = Vsgm_top_sgm_top::RIGHT_BLOCK;
  // The path restart at strong edges: half the frames, any threshold, length and paths.
  p.edgeReset.threshold = rng.chance(0.5) ? 0 : rng.uniform(1, 160);
  p.edgeReset.length = rng.uniform(1, kMaxEdgeResetLength);
  for (int& on : p.edgeReset.paths) on = rng.chance(0.7);
  // The depth output: a quarter of the frames, any f and B (the extremes now and then).
  p.output = rng.chance(0.25) ? OutputMode::kDepth : OutputMode::kDisparity;
  constexpr int kDepthParamMax = (1 << kDepthParamBits) - 1;
  p.focalQ8 = rng.chance(0.1) ? (rng.chance(0.5) ? 1 : kDepthParamMax) : rng.uniform(1, kDepthParamMax);
  p.baselineUm = rng.chance(0.1) ? (rng.chance(0.5) ? 0 : kDepthParamMax) : rng.uniform(1, kDepthParamMax);
  // The minimum disparity: a third of the frames, 1 .. 3 (the cost volume's register paths
  // and its shortest memory lag) or any up to 255.
  p.minDisparity = rng.chance(0.67) ? 0 : rng.chance(0.5) ? rng.uniform(1, 3) : rng.uniform(4, kMaxMinDisparity);
  // The confidence in the output word (with either output): half the frames.
  p.outputConfidence = rng.chance(0.5);
  // A lever the build lacks (sgm_top UNIQUENESS / AD_TERM / EDGE_RESET = 0, RIGHT_BLOCK = 0)
  // stays off: drawn all the same, so that a case is the same in every build but for it.
  if (!Vsgm_top_sgm_top::UNIQUENESS) p.uniqueness = 0;
  if (!Vsgm_top_sgm_top::AD_TERM) p.adWeight = 0;
  if (!Vsgm_top_sgm_top::RIGHT_BLOCK) p.rightPathWeight = 0;
  if (!Vsgm_top_sgm_top::EDGE_RESET) p.edgeReset.threshold = 0;
  if (!Vsgm_top_sgm_top::DEPTH) p.output = OutputMode::kDisparity;
  if (!Vsgm_top_sgm_top::MIN_DISPARITY) p.minDisparity = 0;
  if (!Vsgm_top_sgm_top::CONFIDENCE) p.outputConfidence = false;
  return p;
}

// Rectification in the stream (a build with RECTIFY = 1): a third of the frames are raw pairs
// through a calibration of their own, random smooth meshes that fit the build's line buffer,
// pulled inside the source or not (pixels whose source is outside: word 0).
// Drawn in every build (a case is the same in every build but for it).
void drawRectification(Rng& rng, tb::FrameInput& in) {
  const bool rectify = rng.chance(1.0 / 3);
  std::mt19937 meshRng(uint32_t(rng.next()));
  const double strength = rng.real() * 2.0, inside = rng.chance(0.5) ? 1.0 : 0.9;
  if (!Vsgm_top_sgm_top::RECTIFY || !rectify) return;
  int lag = 0;
  in.mesh = tb::fittingCalibration(in.left.cols, in.left.rows, Vsgm_top_sgm_top::RECTIFY_GRID_LOG2,
                                   Vsgm_top_sgm_top::RECTIFY_ROWS, strength, inside, meshRng, &lag);
  in.params.rectify = true, in.params.rectifyLag = lag;
}

std::string paramText(const Params& p) {
  std::ostringstream t;
  t << costModeName(p.mode) << " P1=" << p.p1 << " P2'=" << p.p2 << " sub=" << p.subpixel << " lr=" << p.lrTolerance
    << " fill=" << p.fill << " snap=" << p.snap << " median=" << p.median << " census=" << censusWindowName(p.census)
    << " p2-mode=" << p2ModeName(p.p2Mode) << " weights=" << pathWeightingName(p.weights)
    << " uniqueness=" << p.uniqueness << " ad=" << p.adWeight << "/" << p.adCap << " right=" << p.rightPathWeight << "/"
    << p.rightPathBlock << " restart=" << p.edgeReset.threshold << "/" << p.edgeReset.length << "/";
  for (int on : p.edgeReset.paths) t << on;
  t << " dmin=" << p.minDisparity << " output=" << outputModeName(p.output);
  if (p.outputConfidence) t << "+confidence";
  if (p.rectify) t << " rectified lag " << p.rectifyLag;
  if (p.output == OutputMode::kDepth) t << "/" << p.focalQ8 << "/" << p.baselineUm;
  return t.str();
}

// Which of the 3 x 2 x 2 x 2 x 2 x 2 switch combinations a parameter set is.
int paramCombination(const Params& p) {
  return (((tb::hardwareModeCode(p.mode) * 2 + p.subpixel) * 2 + (p.lrTolerance >= 0)) * 4 + p.fill * 2 + p.median) *
             2 +
         p.snap;
}

Frame goodFrame(Rng& rng, int maxHeight) {
  const int w = rng.chance(0.2) ? kMinWidth : rng.chance(0.15) ? kMaxWidth : rng.uniform(kMinWidth, kMaxWidth);
  const int h = rng.chance(0.25) ? kMinHeight : rng.uniform(kMinHeight, maxHeight);
  const uint32_t sceneSeed = uint32_t(rng.next());
  const synth::SyntheticScene scene = synth::makeSyntheticScene(w, h, kD, sceneSeed);
  Frame f{tb::FrameInput{scene.left, scene.right, drawParams(rng)}, 0, true, "", scene};
  drawRectification(rng, f.input);
  f.text = std::to_string(w) + "x" + std::to_string(h) + " scene " + std::to_string(sceneSeed) + " " +
           paramText(f.input.params);
  return f;
}

Case drawCase(uint64_t master, uint64_t index, int maxHeight) {
  Case c;
  c.seed = synth::mixSeed(master, index);
  Rng rng(c.seed);
  c.stalls.sourceIdle = drawStalls(rng, c.sourceStalls);
  c.stalls.sinkBusy = drawStalls(rng, c.sinkStalls);
  const auto text = [](const std::string& name, const tb::StallProfile& p) {
    return name == "light" || name == "heavy" ? name + " " + p.describe() : name == "none" ? name : p.describe();
  };
  c.stallText = "stalls: source " + text(c.sourceStalls, c.stalls.sourceIdle) + ", sink " +
                text(c.sinkStalls, c.stalls.sinkBusy);
  const double pick = rng.real();
  const int before = rng.uniform(0, 2);
  for (int i = 0; i < before; ++i) c.frames.push_back(goodFrame(rng, maxHeight));
  if (pick < 0.55) {
    c.kind = "frames";
    c.frames.push_back(goodFrame(rng, maxHeight));
    if (rng.chance(0.5)) c.frames.push_back(goodFrame(rng, maxHeight));
  } else if (pick < 0.7) {
    c.kind = "reset";
    Frame cut = goodFrame(rng, maxHeight);
    const long beats = long(cut.input.left.total());
    cut.input.resetAfterBeats = rng.chance(0.1) ? 0 : rng.chance(0.1) ? beats : rng.uniform(1, int(beats) - 1);
    cut.good = false;
    cut.text = "reset after " + std::to_string(cut.input.resetAfterBeats) + " beats of " + cut.text;
    c.frames.push_back(cut);
    c.frames.push_back(goodFrame(rng, maxHeight));
  } else {
    Frame base = goodFrame(rng, maxHeight);
    auto kind = tb::kAllMalformations[rng.uniform(0, int(std::size(tb::kAllMalformations)) - 1)];
    if (kind == tb::Malformation::kLongLine && base.input.left.cols == kMaxWidth)
      kind = tb::Malformation::kBeyondMaxWidth;
    // Where it breaks (malform() reduces `at` to a line or a cut): often at the
    // edges, a one-beat frame (at 0), one beat short (W H - 2), a line boundary.
    const int w = base.input.left.cols, h = base.input.left.rows;
    const double where = rng.real();
    const unsigned at = where < 0.2    ? 0u
                        : where < 0.35 ? unsigned(w * h - 2)
                        : where < 0.5  ? unsigned(w * rng.uniform(1, h - 1) - 1)
                                       : unsigned(rng.next());
    const tb::MalformedFrames bad = tb::malform(base.input, kind, kMaxWidth, at, unsigned(rng.next()));
    c.kind = std::string("malformed ") + tb::malformationName(kind);
    for (size_t k = 0; k < bad.frames.size(); ++k)
      c.frames.push_back(Frame{
          bad.frames[k], bad.errors[k], false, (k ? "rest of the frame, " : bad.description + ", ") + base.text, {}});
    c.frames.push_back(goodFrame(rng, maxHeight));
  }
  return c;
}

struct Totals {
  long cases = 0, failed = 0, goodFrames = 0, pixels = 0, malformed = 0, resets = 0;
  long depthFrames = 0, minDisparityFrames = 0;  // good frames with the depth output, with dmin != 0
  long rectifiedFrames = 0;                      // good frames rectified in the core
  long confidenceFrames = 0;                     // good frames with the confidence in the word
  double badNonocc = 0;   // sum over the good frames not rectified of bad-1.0 (nonocc) vs the scene ground truth
  long scoredFrames = 0;  // those frames
  std::set<std::string> kinds, sourceStalls, sinkStalls;
  std::set<int> combinations, widths;
  int minHeight = 1 << 30, maxHeight = 0;
};

// Compares a good frame; "" or the first mismatch with the mismatch counts
// against the golden stages (which stage the core's output agrees with).
// result: the golden output map (what the core's words encode).
std::string checkGoodFrame(const tb::FrameInput& in, const tb::FrameOutput& out, DisparityMap& result) {
  if (in.params.rectify) {  // a raw pair through its calibration: the whole chain
    result = runRectifiedPipeline(in.left, in.right, *in.mesh, in.params);
    return tb::compareOutput(result, in.params, out, "sgm_top output (rectified)");
  }
  const PipelineStages golden = runPipelineStages(in.left, in.right, in.params);
  result = golden.result;
  long mismatches = 0;
  const std::string first = tb::compareOutput(golden.result, in.params, out, "sgm_top output", &mismatches);
  if (first.empty() || in.params.output == OutputMode::kDepth) return first;
  long afterLr = 0, afterFill = 0;
  tb::compareMaps(golden.selected, out.map, "", &afterLr);
  tb::compareMaps(golden.filled, out.map, "", &afterFill);
  std::ostringstream msg;
  msg << first << "; " << mismatches << " pixels differ from the golden output (" << afterFill
      << " from its hole-filled map, " << afterLr << " from its LR-checked map)";
  return msg.str();
}

// Runs one case; returns "" or why it failed.
std::string runCase(const Case& c, Totals& totals) {
  std::vector<tb::FrameInput> inputs;
  for (const Frame& f : c.frames) inputs.push_back(f.input);
  tb::CoreHarness<Vsgm_top> core("sgm_top", uint32_t(c.seed), c.stalls);
  std::vector<tb::FrameOutput> outputs;
  try {
    outputs = core.run(inputs);
  } catch (const Error& e) {
    return e.what();
  }
  for (size_t k = 0; k < c.frames.size(); ++k) {
    const Frame& f = c.frames[k];
    const std::string where = "frame " + std::to_string(k) + " (" + f.text + "): ";
    if (f.input.resetAfterBeats >= 0) {
      ++totals.resets;
      continue;
    }
    if (outputs[k].errors != f.expectedErrors)
      return where + "error_o " + std::to_string(outputs[k].errors) + ", expected " + std::to_string(f.expectedErrors);
    if (!f.good) {
      ++totals.malformed;
      continue;
    }
    DisparityMap map;  // the core's map: equal to the golden one, as checked
    const std::string mismatch = checkGoodFrame(f.input, outputs[k], map);
    if (!mismatch.empty()) return where + mismatch;
    if (!f.input.params.rectify) {  // the scene's ground truth is in the frame of the pair as sent
      totals.badNonocc += eval::evaluate(eval::toFloat(map), synth::toEvalScene(f.scene, "synthetic")).errNonocc;
      ++totals.scoredFrames;
    }
    ++totals.goodFrames;
    totals.pixels += long(f.input.left.total());
    totals.combinations.insert(paramCombination(f.input.params));
    totals.depthFrames += f.input.params.output == OutputMode::kDepth;
    totals.minDisparityFrames += f.input.params.minDisparity != 0;
    totals.rectifiedFrames += f.input.params.rectify;
    totals.confidenceFrames += f.input.params.outputConfidence;
    totals.widths.insert(f.input.left.cols);
    totals.minHeight = std::min(totals.minHeight, f.input.left.rows);
    totals.maxHeight = std::max(totals.maxHeight, f.input.left.rows);
  }
  return "";
}

}  // namespace sgm::regress
