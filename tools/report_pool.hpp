// SPDX-License-Identifier: Apache-2.0
// `sgm-eval pool`: the golden model (and OpenCV StereoSGBM) on every scene of a
// directory in the pool layout (../shared/data/pool/README.md), each scene at its
// own D (meta.txt `ndisp:`), scored by its set's measure, with per-set and
// per-group means; rendered as markdown and JSON (the chart is report_chart).
#pragma once

#include "eval_lib.hpp"

#include "sgm/params.hpp"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sgm::eval {

// KITTI sets (`set:` starting with "kitti") are scored with D1 over the pixels
// with ground truth; every other scene with bad-delta over the non-occluded
// pixels, invalid output counted as an error.
bool isKittiSet(const std::string& set);
// The summary group of a set: "kitti" or "middlebury" (every non-KITTI set).
std::string setGroup(const std::string& set);
// The scene's figure under its set's measure: d1All (KITTI) or errNonocc; the
// same over the valid pixels only: d1Valid or errNonoccValid.
double strictFigure(const std::string& set, const ErrorFigures& f);
double validFigure(const std::string& set, const ErrorFigures& f);

// The fixed cross-validation split: within each set, the scenes sorted by name
// alternate A, B, A, B, ... ('A' for the first). Returns one half per scene, in
// the order of `names`; sets[i] is the set of names[i].
std::vector<char> crossValidationHalves(const std::vector<std::string>& names, const std::vector<std::string>& sets);

struct PoolRow {
  std::string scene, set;
  char half = 'A';
  int disparities = 0;
  ErrorFigures ours;
  std::optional<ErrorFigures>
      today;  // the four-path preset (the defaults before issue 15) at the same D, when ours are not it
  std::optional<ErrorFigures> opencv;  // StereoSGBM MODE_SGBM at D rounded up to 16
};

// Mean of the strict figure over a group of rows (a set, a group, a half).
struct PoolMean {
  std::string name;
  int scenes = 0;
  double ours = 0;
  std::optional<double> today, opencvStrict, opencvValid, opencvDensity;
};

struct PoolOptions {
  Params params;                 // D is replaced by each scene's ndisp
  int fallbackDisparities = 64;  // D of a scene whose meta.txt has no ndisp
  double delta = 1.0;
  bool opencv = true;
  // Cross-validation half of each scene by name, computed over the whole pool
  // (poolHalves); a scene missing here gets its half from the scenes given.
  std::map<std::string, char> halves;
};

// The halves of every scene directory under root (names and `set:` of each meta.txt).
std::map<std::string, char> poolHalves(const std::string& root);

struct PoolReport {
  PoolOptions options;
  bool comparesToday = false;    // params are not the four-path preset: `today` is filled
  std::vector<PoolRow> rows;     // sorted by set, then scene
  std::vector<PoolMean> sets;    // one per set, sorted
  std::vector<PoolMean> groups;  // "middlebury", "kitti" (those present)
  std::vector<PoolMean> halves;  // "middlebury A", "middlebury B", "kitti A", ...
  // Largest (ours - today) of the strict figure over the scenes, when comparing.
  std::optional<double> worstRegression;
  std::string worstScene;
};

// Means of the rows: per set, per group, per group and half; the worst regression.
void summarize(PoolReport& report);

using PoolHook = std::function<void(const PoolRow&, const Scene&, const cv::Mat& disparity)>;

// Runs the golden model (and OpenCV, and the four-path preset, "today", when params differ
// from them) on every scene, evaluates each and summarizes.
PoolReport computePool(const std::vector<Scene>& scenes, const PoolOptions& options, const PoolHook& hook = {});

// pool.md: per-scene table, per-set and per-group means, halves, parameters.
std::string poolMarkdown(const PoolReport& report);
// The means (groups, halves, worst regression) in a few lines, for stdout.
std::string poolSummary(const PoolReport& report);
// pool.json:
//   {"delta": 1, "params": {...golden parameters, "fallback_disparities"},
//    "compares_today": bool,
//    "scenes": [{"scene", "set", "group", "half", "measure": "d1" | "bad_nonocc", "disparities",
//                "ours": {"strict", "valid", "err_nonocc", "err_all", "err_nonocc_valid",
//                         "density", "d1_all", "d1_valid"},
//                "today": {...} | null, "opencv": {...} | null}],
//    "sets": [{"name", "scenes", "ours", "today", "opencv_strict", "opencv_valid", "opencv_density"}],
//    "groups": [...same...], "halves": [...same...],
//    "worst_regression": {"scene", "points"} | null}
// Percentages with 3 decimals.
std::string poolJson(const PoolReport& report);

}  // namespace sgm::eval
