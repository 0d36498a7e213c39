// SPDX-License-Identifier: Apache-2.0
#include "sgm/params.hpp"

#include <algorithm>

namespace sgm {

namespace {
struct ModeInfo {
  CostMode mode;
  const char* name;
  int censusBitsFactor;  // Cmax = factor x census bits, or
  int fixedMaxCost;      // Cmax of the 8-bit modes
  bool hardware;
};
constexpr ModeInfo kModes[] = {
    {CostMode::kRt, "rt", 1, 0, true},           {CostMode::kRsad, "rsad", 1, 0, true},
    {CostMode::kUnified, "unified", 2, 0, true}, {CostMode::kSad, "sad", 0, 255, false},
    {CostMode::kBt, "bt", 0, 255, false},        {CostMode::kSadRt, "sad+rt", 1, 0, false},
};

const ModeInfo& info(CostMode mode) {
  for (const ModeInfo& m : kModes)
    if (m.mode == mode) return m;
  throw Error("internal: unknown cost mode");
}
}  // namespace

bool isHardwareMode(CostMode mode) { return info(mode).hardware; }
const char* costModeName(CostMode mode) { return info(mode).name; }
int maxCost(CostMode mode, CensusWindow census) {
  const ModeInfo& m = info(mode);
  return m.censusBitsFactor ? m.censusBitsFactor * censusShape(census).bits : m.fixedMaxCost;
}

int costLimit(CensusWindow census) {
  int bits = 0;
  while ((1 << bits) <= 2 * censusShape(census).bits) ++bits;
  return (1 << bits) - 1;
}

int largestAdCap(CostMode mode, CensusWindow census, int weight) {
  if (weight <= 0) return kMaxAdCap;
  const int room = costLimit(census) - maxCost(mode, census);  // (weight T) >> kAdShift <= room
  if (room < 0) return -1;
  // (w T) >> s <= room  <=>  w T < (room + 1) << s  <=>  T <= (((room + 1) << s) - 1) / w
  return std::min(kMaxAdCap, (((room + 1) << kAdShift) - 1) / weight);
}

const char* censusWindowName(CensusWindow window) { return window == CensusWindow::k9x9 ? "9x9" : "9x5"; }
CensusWindow parseCensusWindow(const std::string& name) {
  if (name == "9x5") return CensusWindow::k9x5;
  if (name == "9x9") return CensusWindow::k9x9;
  throw Error("unknown census window '" + name + "' (expected 9x5 or 9x9)");
}

const char* p2ModeName(P2Mode mode) { return mode == P2Mode::kPaper ? "paper" : "knee"; }
P2Mode parseP2Mode(const std::string& name) {
  if (name == "knee") return P2Mode::kKnee;
  if (name == "paper") return P2Mode::kPaper;
  throw Error("unknown P2 mode '" + name + "' (expected knee or paper)");
}

const char* pathWeightingName(PathWeighting weighting) { return weighting == PathWeighting::kEqual ? "equal" : "3232"; }
PathWeighting parsePathWeighting(const std::string& name) {
  if (name == "3232" || name == "3,2,3,2") return PathWeighting::k3232;
  if (name == "equal") return PathWeighting::kEqual;
  throw Error("unknown path weights '" + name + "' (expected 3232 or equal)");
}

const char* outputModeName(OutputMode mode) { return mode == OutputMode::kDepth ? "depth" : "disparity"; }

OutputMode parseOutputMode(const std::string& name) {
  if (name == "disparity") return OutputMode::kDisparity;
  if (name == "depth") return OutputMode::kDepth;
  throw Error("unknown output '" + name + "' (expected disparity or depth)");
}

bool Params::operator==(const Params& o) const {
  return disparities == o.disparities && p1 == o.p1 && p2 == o.p2 && mode == o.mode && subpixel == o.subpixel &&
         lrTolerance == o.lrTolerance && fill == o.fill && snap == o.snap && median == o.median && census == o.census &&
         p2Mode == o.p2Mode && weights == o.weights && rightPathWeight == o.rightPathWeight &&
         rightPathBlock == o.rightPathBlock && uniqueness == o.uniqueness && adWeight == o.adWeight &&
         adCap == o.adCap && linearSubpixel == o.linearSubpixel && mgm == o.mgm && medianGate == o.medianGate &&
         p1PathPercent == o.p1PathPercent && snapEdge == o.snapEdge && edgeReset == o.edgeReset &&
         lrStoreBits == o.lrStoreBits && minDisparity == o.minDisparity && output == o.output &&
         outputConfidence == o.outputConfidence && focalQ8 == o.focalQ8 && baselineUm == o.baselineUm &&
         rectify == o.rectify && rectifyLag == o.rectifyLag;
}

const std::vector<std::string>& presetNames() {
  static const std::vector<std::string> names = {"default", "four-path", "paper"};
  return names;
}

Params presetParams(const std::string& name) {
  if (name == "default") return Params{};
  if (name == "four-path") {  // the defaults before issue 15 (measured in docs/notes/accuracy-pool.md, "today")
    Params p;
    p.p1 = 18, p.p2 = 100;
    p.snap = true;
    p.uniqueness = 0;
    p.adWeight = 0;
    p.rightPathWeight = 0, p.rightPathBlock = 0;
    p.edgeReset = EdgeReset{};  // off
    return p;
  }
  if (name == "paper") {
    Params p;
    p.census = CensusWindow::k9x9;
    p.mode = CostMode::kUnified;
    p.p2Mode = P2Mode::kPaper;
    p.weights = PathWeighting::kEqual;
    // Swept like the other defaults, on the 9x9 window (docs/algorithm.md, section 11).
    p.p1 = 100, p.p2 = 255;
    p.fill = false;
    p.snap = false;
    // None of the levers the paper does not have, whatever the defaults (issue 15).
    p.uniqueness = 0;
    p.adWeight = 0;
    p.rightPathWeight = 0, p.rightPathBlock = 0;
    p.edgeReset = EdgeReset{};  // off
    return p;
  }
  throw Error("unknown preset '" + name + "' (expected default, four-path or paper)");
}

std::string presetName(const Params& params) {
  for (const std::string& name : presetNames()) {
    Params preset = presetParams(name);
    preset.disparities = params.disparities;  // a preset fixes the algorithm, not the build's D
    preset.output = params.output;            // nor the output word
    preset.outputConfidence = params.outputConfidence;
    preset.focalQ8 = params.focalQ8, preset.baselineUm = params.baselineUm;
    preset.rectify = params.rectify, preset.rectifyLag = params.rectifyLag;  // nor the input
    if (params == preset) return name;
  }
  return "custom";
}

Params buildDefaults(const BuildLevers& build, int disparities) {
  Params p = presetParams(build.census9x9                                                           ? "paper"
                          : build.rightBlock && build.uniqueness && build.adTerm && build.edgeReset ? "default"
                                                                                                    : "four-path");
  if (p.rightPathWeight) p.rightPathBlock = build.rightBlock;
  p.disparities = disparities;
  return p;
}

CostMode parseCostMode(const std::string& name) {
  for (const ModeInfo& m : kModes)
    if (name == m.name) return m.mode;
  throw Error("unknown cost mode '" + name + "' (expected rt, rsad, unified, sad, bt or sad+rt)");
}

std::vector<CostMode> allCostModes() {
  std::vector<CostMode> modes;
  for (const ModeInfo& m : kModes) modes.push_back(m.mode);
  return modes;
}

void Params::validate() const {
  if (disparities < kMinDisparities || disparities > kMaxDisparities)
    throw Error("unsupported disparity count D=" + std::to_string(disparities) + " (expected " +
                std::to_string(kMinDisparities) + ".." + std::to_string(kMaxDisparities) + ")");
  if (p1 < 0 || p1 > kMaxPenalty)
    throw Error("P1=" + std::to_string(p1) + " out of range 0.." + std::to_string(kMaxPenalty));
  if (p2 < p1 || p2 > kMaxPenalty)
    throw Error("P2'=" + std::to_string(p2) + " out of range P1.." + std::to_string(kMaxPenalty) +
                " (P1=" + std::to_string(p1) + ")");
  if (rightPathWeight < 0 || rightPathWeight > kMaxRightPathWeight)
    throw Error("right-path weight " + std::to_string(rightPathWeight) + " out of range 0.." +
                std::to_string(kMaxRightPathWeight));
  if (rightPathBlock < 0 || rightPathBlock > kMaxRightPathBlock)
    throw Error("right-path block " + std::to_string(rightPathBlock) + " out of range 0.." +
                std::to_string(kMaxRightPathBlock));
  for (int path = 0; path <= kPathCount; ++path)
    if (p1PathPercent[size_t(path)] < kMinP1PathPercent || p1PathPercent[size_t(path)] > kMaxP1PathPercent ||
        pathP1(path) > p2)
      throw Error("P1 of path " + std::to_string(path) + " (" + std::to_string(p1PathPercent[size_t(path)]) +
                  " % of P1=" + std::to_string(p1) + ") out of range " + std::to_string(kMinP1PathPercent) + ".." +
                  std::to_string(kMaxP1PathPercent) + " % and 0..P2'=" + std::to_string(p2));
  if (medianGate < 0 || medianGate > 255)
    throw Error("median gate " + std::to_string(medianGate) + " out of range 0..255");
  if (snapEdge < 0 || snapEdge > 255) throw Error("snap edge " + std::to_string(snapEdge) + " out of range 0..255");
  if (lrStoreBits != 0 && (lrStoreBits < kMinLrStoreBits || lrStoreBits > kMaxLrStoreBits))
    throw Error("stored Lr bits " + std::to_string(lrStoreBits) + " out of range " + std::to_string(kMinLrStoreBits) +
                ".." + std::to_string(kMaxLrStoreBits) + " (0 off)");
  if (lrStoreBits && mgm) throw Error("--lr-store-bits does not combine with --mgm");
  if (minDisparity < 0 || minDisparity > kMaxMinDisparity)
    throw Error("minimum disparity " + std::to_string(minDisparity) + " out of range 0.." +
                std::to_string(kMaxMinDisparity));
  if (rectifyLag < 0 || rectifyLag > kMaxRectifyLag)
    throw Error("rectification lag " + std::to_string(rectifyLag) + " out of range 0.." +
                std::to_string(kMaxRectifyLag));
  if (focalQ8 < 0 || focalQ8 >= 1 << kDepthParamBits || baselineUm < 0 || baselineUm >= 1 << kDepthParamBits)
    throw Error("depth parameters out of range: f " + std::to_string(focalQ8) + "/256 px, B " +
                std::to_string(baselineUm) + " um (0.." + std::to_string((1 << kDepthParamBits) - 1) + " each)");
  if (edgeReset.threshold < 0 || edgeReset.threshold > 255)
    throw Error("edge reset " + std::to_string(edgeReset.threshold) + " out of range 0..255");
  if (edgeReset.length < 1 || edgeReset.length > kMaxEdgeResetLength)
    throw Error("edge reset length " + std::to_string(edgeReset.length) + " out of range 1.." +
                std::to_string(kMaxEdgeResetLength));
  for (const int on : edgeReset.paths)
    if (on != 0 && on != 1) throw Error("edge reset paths expect 0 or 1 each, got " + std::to_string(on));
  if (edgeReset.threshold && mgm)
    throw Error(
        "the path restart at strong edges (--edge-reset, on by default) does not combine with --mgm: give --edge-reset 0");
  if (uniqueness < 0 || uniqueness > 99)
    throw Error("uniqueness " + std::to_string(uniqueness) + " out of range 0..99");
  if (adWeight < 0 || adWeight > kMaxAdWeight || adCap < 0 || adCap > kMaxAdCap)
    throw Error("AD term weight " + std::to_string(adWeight) + " / cap " + std::to_string(adCap) + " out of range 0.." +
                std::to_string(kMaxAdWeight) + " / 0.." + std::to_string(kMaxAdCap));
  if (adWeight && !isHardwareMode(mode)) throw Error("the AD term (--ad-weight) needs a census cost mode");
  if (adWeight && adCap > largestAdCap(mode, census, adWeight))
    throw Error("AD term weight " + std::to_string(adWeight) + " x cap " + std::to_string(adCap) + " makes " +
                costModeName(mode) + " costs exceed " + std::to_string(costLimit(census)) + " (the " +
                censusWindowName(census) + " core's cost word)");
  if ((kPathWeightSum + rightPathWeight) * (255 + p2) >= 65536)
    throw Error("right-path weight " + std::to_string(rightPathWeight) + " with P2'=" + std::to_string(p2) +
                " overflows the 16-bit S");
  if (lrTolerance > disparities)
    throw Error("LR tolerance " + std::to_string(lrTolerance) + " exceeds D=" + std::to_string(disparities));
}

Params defaultParams(CostMode mode) {
  if (mode == Params{}.mode) return Params{};
  // The other modes' penalties were measured with the four-path configuration (issue 15
  // re-tuned the pool's levers for rsad only; the AD term is for census modes).
  Params p = presetParams("four-path");
  p.mode = mode;
  switch (mode) {
    // Measured on cones, teddy, sawtooth, venus: docs/algorithm.md, section 11.
    case CostMode::kRt: p.p1 = 28, p.p2 = 130; break;
    case CostMode::kRsad: p.p1 = 18, p.p2 = 100; break;
    case CostMode::kUnified: p.p1 = 40, p.p2 = 200; break;
    case CostMode::kSad: p.p1 = 8, p.p2 = 80; break;
    case CostMode::kBt: p.p1 = 14, p.p2 = 200; break;
    case CostMode::kSadRt: p.p1 = 20, p.p2 = 100; break;
  }
  return p;
}

Params Params::rawSgm() const {
  Params raw = *this;
  raw.subpixel = false;
  raw.uniqueness = 0;
  raw.lrTolerance = -1;
  raw.fill = false;
  raw.snap = false;
  raw.median = false;
  return raw;
}

}  // namespace sgm
