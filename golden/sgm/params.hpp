// SPDX-License-Identifier: Apache-2.0
// Parameters of the SGM pipeline and the fixed-point constants of the contract.
// docs/algorithm.md is the prose version of everything in this header.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace sgm {

// Every user-facing failure is an sgm::Error with a one-line message.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The census window (section 2): 9 wide, 5 high (ours, the default) or 9 high (the paper's).
enum class CensusWindow { k9x5, k9x9 };
struct CensusShape {
  int radiusX, radiusY;  // dx = -radiusX .. radiusX, dy = -radiusY .. radiusY
  int width, height;     // 2 radius + 1
  int bits;              // width * height - 1: 44 or 80
};
constexpr CensusShape censusShape(CensusWindow window) {
  return window == CensusWindow::k9x9 ? CensusShape{4, 4, 9, 9, 80} : CensusShape{4, 2, 9, 5, 44};
}
constexpr int kMaxCensusBits = 80;                        // the 9x9 window
const char* censusWindowName(CensusWindow window);        // "9x5", "9x9"
CensusWindow parseCensusWindow(const std::string& name);  // throws Error on unknown names

// P2 adaptation (section 4): the knee max(P1, 4 P2' / (dI + 4)) (ours) or the paper's
// max(P1, P2' / dI) with P2' at dI = 0.
enum class P2Mode { kKnee, kPaper };
const char* p2ModeName(P2Mode mode);  // "knee", "paper"
P2Mode parseP2Mode(const std::string& name);

// Path weights of S (section 5): 3,2,3,2 (ours) or equal (the paper's plain sum).
enum class PathWeighting { k3232, kEqual };
const char* pathWeightingName(PathWeighting weighting);     // "3232", "equal"
PathWeighting parsePathWeighting(const std::string& name);  // "3232", "3,2,3,2" or "equal"

// The core's output word (docs/algorithm.md sections 10 and 10b; register OUTPUT.MODE): the
// disparity {valid, zeros, disparity x 16}, or the depth in mm (a core built with sgm_top
// DEPTH = 1), 0 = invalid.
enum class OutputMode { kDisparity = 0, kDepth = 1 };
const char* outputModeName(OutputMode mode);          // "disparity", "depth"
OutputMode parseOutputMode(const std::string& name);  // throws Error on unknown names
constexpr int kDepthParamBits = 24;                   // Params::focalQ8 and baselineUm (registers DEPTH_*)
constexpr int kMaxRectifyLag = 254;                   // Params::rectifyLag (register RECTIFY.LAG)

// Matching-cost modes. The first three exist in the RTL; the others are
// software-only, kept to reproduce the paper's Table I.
enum class CostMode { kRt, kRsad, kUnified, kSad, kBt, kSadRt };

bool isHardwareMode(CostMode mode);
const char* costModeName(CostMode mode);          // "rt", "rsad", "unified", "sad", "bt", "sad+rt"
CostMode parseCostMode(const std::string& name);  // throws Error on unknown names
std::vector<CostMode> allCostModes();

// Largest matching cost a mode can produce (also the cost of a disparity whose
// match falls outside the right image).
int maxCost(CostMode mode, CensusWindow census);
// Largest cost the hardware's cost word holds: 2^b - 1 with b the bits of unified's
// Cmax = 2 x census bits (127 for the 9x5 census, 255 for the 9x9): Cmax of the mode
// plus the largest AD term must stay within it (Params::validate).
int costLimit(CensusWindow census);
// The largest AD cap T in 0 .. kMaxAdCap whose largest term (weight T) >> kAdShift added to
// maxCost(mode, census) stays within costLimit(census) (Params::validate's rule); kMaxAdCap
// for weight 0 (the term is off); -1 when not even T = 0 fits (a software-only mode's Cmax
// is beyond the cost word).
int largestAdCap(CostMode mode, CensusWindow census, int weight);

constexpr int kMinFrameSide = 9;                  // smallest width and height (9x9 frame)
constexpr int kSubpixelBits = 4;                  // disparities carry 1/16 px
constexpr int kSubpixelOne = 1 << kSubpixelBits;  // 16
constexpr int kMedianRadius = 2;                  // 5x5 median
constexpr int kP2Knee = 4;                        // P2r = max(P1, kP2Knee P2' / (|dI| + kP2Knee))
constexpr int kFillAgree = kSubpixelOne;          // fill keeps an own disparity within 1 px of a neighbour
constexpr int kSnapReach = 3;                     // edge snap moves a disparity edge by up to 3 px
constexpr int kSnapStep = 2 * kSubpixelOne;       // edge snap acts on drops of more than 2 px
constexpr int kPathCount = 4;                     // 0, 45, 90, 135 degrees
// S = sum of w[r] Lr. 3,2,3,2: the horizontal and vertical paths count 3, the diagonals 2.
constexpr int kPathWeights[kPathCount] = {3, 2, 3, 2};  // 0, 45, 90, 135 degrees
constexpr int kPathWeightsEqual[kPathCount] = {1, 1, 1, 1};
constexpr int kPathWeightSum = 10;  // the larger sum of the two weightings
inline const int* pathWeights(PathWeighting weighting) {
  return weighting == PathWeighting::kEqual ? kPathWeightsEqual : kPathWeights;
}
constexpr int kMaxPenalty = 6000;
constexpr int kMaxRightPathWeight =
    8;  // fifth path's weight (Params::rightPathWeight; the core's 4-bit field, 9 .. 15 out of range)
constexpr int kMaxRightPathBlock = 4096;  // fifth path's block (Params::rightPathBlock; the core: sgm_top RIGHT_BLOCK)
constexpr int kMaxAdWeight = 15;          // AD term weight (Params::adWeight, 4 bits in the RTL)
constexpr int kMinP1PathPercent = 25, kMaxP1PathPercent = 400;  // golden-only per-path P1 (Params::p1PathPercent)
constexpr int kMaxEdgeResetLength = 15;                         // the path restart (Params::edgeReset.length)
constexpr int kMinLrStoreBits = 4, kMaxLrStoreBits = 12;
constexpr int kMaxMinDisparity =
    255;  // Params::minDisparity (dmin), 0 .. 255        // golden-only Params::lrStoreBits (0 = off)
constexpr int kMaxAdCap = 255;  // AD term truncation (Params::adCap, 8 bits)
constexpr int kAdShift =
    3;  // AD term = adWeight * min(AD, adCap) >> kAdShift                 // keeps kPathWeightSum * (Cmax + P2') < 2^16

// The path restart at strong edges (issue 15, docs/algorithm.md section 12; in the core
// with sgm_top EDGE_RESET = 1, run-time T, R and flags): a path
// starts again (Lr = C) at every pixel whose last `length` steps along the path, the step
// into it included, cross a gray step |I(q) - I(q - r)| >= threshold, for the paths marked
// in `paths` (0, 45, 90, 135 degrees, the fifth path). Within a census window of an edge the
// costs favour the side with the stronger texture (the foreground fattens); restarting the
// paths there keeps them from carrying that disparity on into the untextured region beyond.
struct EdgeReset {
  int threshold = 0;  // gray step of a strong edge; 0 = off
  int length = 5;     // steps restarted from the edge on, 1 .. kMaxEdgeResetLength
  std::array<int, kPathCount + 1> paths = {1, 1, 1, 1, 1};  // 1 = that path restarts, 0 = it does not
  bool on(int path) const { return threshold > 0 && paths[size_t(path)] != 0; }
  bool operator==(const EdgeReset& o) const {
    return threshold == o.threshold && length == o.length && paths == o.paths;
  }
  bool operator!=(const EdgeReset& o) const { return !(*this == o); }
};

// The defaults (issue 15, docs/notes/accuracy-pool.md: chosen on half A of the scene pool,
// reported on half B): the four paths with a fifth from the right in blocks of 64,
// the AD term, the uniqueness ratio, the path restart at strong edges, no edge snapping. The preset "four-path" is the
// former defaults, for builds without these levers (sgm_top RIGHT_BLOCK = 0, ...).
struct Params {
  int disparities = 64;                          // D: candidates 0 .. D-1
  int p1 = 24;                                   // small-change penalty
  int p2 = 200;                                  // P2' of the adaptive P2r = max(P1, 4 P2' / (|dI| + 4))
  CostMode mode = CostMode::kRsad;               // the hardware default (measured best)
  bool subpixel = true;                          // quadratic refinement to 1/16 px
  int lrTolerance = 1;                           // left-right check tolerance in px; < 0 disables it
  bool fill = true;                              // fill invalid pixels along the row from the background side
  bool snap = false;                             // move disparity drops onto the nearby intensity edge
  bool median = true;                            // 5x5 median over valid pixels
  CensusWindow census = CensusWindow::k9x5;      // census window (section 2)
  P2Mode p2Mode = P2Mode::kKnee;                 // P2 adaptation (section 4)
  PathWeighting weights = PathWeighting::k3232;  // path weights of S (section 5)
  int uniqueness = 15;  // uniqueness ratio U (%, section 7): invalid when some S(k), |k - d*| > 1,
                        // has S(k) (100 - U) < 100 S(d*); 0 = off
  int adWeight = 3;     // AD term added to C (section 3): adWeight * min(|IL(x) - IR(x-d)|, adCap) >> 3; 0 = off
  int adCap = 20;       // the AD term's truncation (gray levels)

  // The fifth path, 0 degrees from the right (docs/algorithm.md section 5): in blocks it
  // is in the core (sgm_top RIGHT_BLOCK = rightPathBlock, run-time weight), over the
  // whole row (rightPathBlock = 0) golden-only.
  int rightPathWeight = 4;  // its weight in S, 0..kMaxRightPathWeight; 0 = off
  int rightPathBlock = 64;  // per block of this many pixels with one block of look-ahead; 0 = whole row
  // The path restart at strong edges (in the core with sgm_top EDGE_RESET = 1): T 40, R 6,
  // every path but 90 degrees (docs/notes/accuracy-pool.md, "The path restart at strong edges").
  EdgeReset edgeReset{40, 6, {1, 1, 0, 1, 1}};
  // The minimum disparity dmin (docs/algorithm.md section 3): the search covers dmin .. dmin + D - 1
  // (left x against right x - dmin - d) and the output is the true disparity. In the core with
  // sgm_top MIN_DISPARITY = 1 (register MIN_DISPARITY).
  int minDisparity = 0;
  // The output word and the depth's frame constants (docs/algorithm.md section 10b): f in 1/256 px
  // and B in micrometres, each 0 .. 2^24 - 1 (sgm-eval calib-mesh gives both). They change what
  // the core sends, not the disparities: a preset is the same preset with any of them.
  OutputMode output = OutputMode::kDisparity;
  // The confidence of section 7b in the output word's bits 23:16 (register OUTPUT.CONFIDENCE; a
  // core built with sgm_top CONFIDENCE = 1, whose word is 24 bits): disparity plus confidence,
  // or depth plus confidence.
  bool outputConfidence = false;
  int focalQ8 = 0;
  int baselineUm = 0;
  // Rectification in the stream (docs/algorithm.md section 13; in the core with sgm_top RECTIFY =
  // 1, register RECTIFY): the frame's images are raw and go through the meshes of a calibration
  // (sgm::runRectifiedPipeline), whose row lag (sgm::meshRowSpan) is rectifyLag, 0 ..
  // kMaxRectifyLag. They describe the input, not the algorithm: a preset is the same preset
  // with them.
  bool rectify = false;
  int rectifyLag = 0;
  // Golden-only experiments (issue 15, docs/algorithm.md section 12): NOT in the RTL,
  // every one off by default, so Params{} and the presets stay bit-exact with the core.
  bool linearSubpixel = false;  // sub-pixel by the equiangular (V) fit instead of the parabola
  bool mgm = false;             // raster-order MGM: each path averages two causal neighbours
  int medianGate = 0;           // the median takes only window pixels within this gray distance of the centre; 0 = off
  int snapEdge = 0;             // edge snapping acts only when its strongest step |I(k) - I(k-1)| >= this; 0 = always
  int lrStoreBits =
      0;  // the 45/90/135-degree paths read the row above's Lr - min Lr saturated to this many bits; 0 = off
  // P1 per path in percent of p1 (0, 45, 90, 135 degrees, the fifth path); each path's P2r = max(its P1, ...).
  std::array<int, kPathCount + 1> p1PathPercent = {100, 100, 100, 100, 100};
  int pathP1(int path) const { return p1 * p1PathPercent[size_t(path)] / 100; }
  // Golden-only options: the fifth path over the whole row (in blocks it is in the
  // core, sgm_top RIGHT_BLOCK), the equiangular sub-pixel fit, MGM, the gated median,
  // per-path P1, the gated edge snap, the narrower stored Lr.
  bool experimental() const {
    return (rightPathWeight && !rightPathBlock) || linearSubpixel || mgm || medianGate ||
           p1PathPercent != Params{}.p1PathPercent || snapEdge || lrStoreBits;
  }

  bool operator==(const Params& o) const;
  bool operator!=(const Params& o) const { return !(*this == o); }

  // Throws Error naming the first parameter that is out of range.
  void validate() const;
  // Parameters with every post-processing stage off (raw SGM + WTA: no uniqueness ratio,
  // LR check, sub-pixel, fill, snap or median; the cost and the paths as they are).
  Params rawSgm() const;
};

// Defaults for a cost mode: the measured P1 / P2' of that mode (see
// docs/algorithm.md, "Defaults"), everything else as in Params{}.
Params defaultParams(CostMode mode);

// Named configurations, the same in every tool (--preset): "default" (Params{}),
// "four-path" (the defaults before issue 15: no fifth path, AD term or uniqueness
// ratio, P1 18, P2' 100, edge snapping; what a build without those levers runs) and
// "paper", the paper's system: 9x9 census, unified cost, P2' / dI, equal weights, LR
// check, sub-pixel, 5x5 median, no filling, no snapping (docs/algorithm.md, section 11).
Params presetParams(const std::string& name);  // throws Error on unknown names
const std::vector<std::string>& presetNames();
// The preset's name when params equal it (D aside), "custom" otherwise.
std::string presetName(const Params& params);

// What a core build has of the levers the defaults use (sgm_top RIGHT_BLOCK, UNIQUENESS,
// AD_TERM) and its census window (CENSUS_H).
struct BuildLevers {
  int rightBlock = 0;  // the fifth path's block, 0: not built
  bool uniqueness = true, adTerm = true;
  bool edgeReset = true;  // sgm_top EDGE_RESET
  bool census9x9 = false;
};
// The configuration such a build runs by default (its reset values): "default" with the
// build's block when it has all four levers, "four-path" otherwise, "paper" on the 9x9
// window; D as given.
Params buildDefaults(const BuildLevers& build, int disparities);

// The disparity counts the RTL is built and tested for; the golden model
// accepts any D in [kMinDisparities, kMaxDisparities].
constexpr int kMinDisparities = 2;
constexpr int kMaxDisparities = 256;

}  // namespace sgm
