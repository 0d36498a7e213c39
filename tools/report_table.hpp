// SPDX-License-Identifier: Apache-2.0
// `sgm-eval table`: the paper's Table I (golden model with each matching cost),
// the full pipeline per hardware cost mode and OpenCV StereoSGBM, evaluated on
// the same scenes; rendered as markdown and JSON (the chart is report_chart).
#pragma once

#include "eval_lib.hpp"

#include "sgm/params.hpp"

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sgm::eval {

enum class MethodKind { kTable1, kFull, kOpenCv };
const char* methodKindName(MethodKind kind);  // "table1", "full", "opencv"

struct Method {
  std::string key;    // stable identifier: "rsad", "full-unified", "opencv-hh", ...
  std::string label;  // for people: "Rank SAD", ...
  MethodKind kind = MethodKind::kTable1;
  Params params;                        // golden methods
  int opencvMode = -1;                  // OpenCV methods: cv::StereoSGBM::MODE_SGBM or MODE_HH
  std::map<std::string, double> paper;  // scene -> the paper's Table I figure (%), Table I rows only
  bool hardwareDefault = false;         // the full pipeline with Params{}.mode
};

// The scenes of the paper's Table I, in its column order.
const std::vector<std::string>& paperScenes();

// "Table I configuration": the mode's four-path configuration (defaultParams(mode),
// for rsad the four-path preset) with the LR check, hole filling and snapping off;
// sub-pixel refinement and the median stay on.
Params table1Params(CostMode mode, int disparities);

// Table I on the paper's window: presetParams("paper") (9x9, P2' / dI, equal
// weights) with the mode, its penalties swept on that window, and the LR check,
// hole filling and edge snapping off.
Params paperTable1Params(CostMode mode, int disparities);

// OpenCV needs a multiple of 16 disparities: D rounded up.
int opencvDisparities(int disparities);

// Rows of the table in order: the six Table I costs on the paper's window
// ("paper-*"), the six on ours, the full pipeline for each hardware cost mode
// and the paper preset ("full-paper"), OpenCV MODE_SGBM and MODE_HH.
std::vector<Method> tableMethods(int disparities);

// Disparity of a method on a scene: CV_32F px, -1 = invalid. OpenCV runs on the colour pair.
cv::Mat runMethod(const Method& method, const Scene& scene);

struct TableReport {
  int disparities = 64;
  double delta = 1;
  std::vector<std::string> scenes;      // columns: paper scenes, then extra ones (sorted)
  std::set<std::string> present;        // scenes that were found and evaluated
  std::set<std::string> derivedNonocc;  // nonocc mask derived from the ground truth
  int opencvChannels = 3;               // channels of the images given to OpenCV
  std::vector<Method> methods;
  std::map<std::string, std::map<std::string, ErrorFigures>> results;  // key -> scene -> figures
  std::string hardwareDefault;                                         // key of the hardware-default full pipeline

  const ErrorFigures* find(const std::string& key, const std::string& scene) const;
};

// Called once per (method, scene) with the disparity, e.g. to keep images.
using ResultHook = std::function<void(const Method&, const Scene&, const cv::Mat& disparity)>;

// Runs every method on every scene and evaluates it (nonocc, all, disc at delta).
TableReport computeTable(const std::vector<Scene>& scenes, int disparities, double delta, const ResultHook& hook = {});

// The golden model's parameters for people, without D: "mode rsad, census 9x5, ...",
// the golden-only experiments appended when any is on.
std::string goldenParamsText(const Params& params);

class JsonWriter;
// The golden model's parameters as the fields of an open JSON object (every
// report writes them with these names): mode, census, p2_mode, weights, p1, p2,
// subpixel, lr_tolerance, fill, snap, median, and the golden-only experiments
// right_path_weight, uniqueness, ad_weight, ad_cap, subpixel_fit, mgm.
void writeGoldenParamFields(JsonWriter& j, const Params& params);

// The Table I comparison (every row, the paper's figure beside ours) in markdown.
std::string table1Markdown(const TableReport& report);
// The whole report.md: Table I comparison, notes, per-scene figures, parameters.
std::string reportMarkdown(const TableReport& report);
// report.json:
//   {"delta": 1, "disparities": 64, "scenes": [names],
//    "methods": [{"key", "label", "kind": "table1|full|opencv", "params": {...},
//                 "paper": {scene: %} | null,
//                 "results": {scene: {"err_nonocc", "err_all", "err_disc" | null,
//                                     "density", "err_nonocc_valid"} | null}}],
//    "hardware_default": "full-...", "nonocc_derived": [names]}
// Percentages with 3 decimals; a scene that was not found is null.
std::string reportJson(const TableReport& report);

}  // namespace sgm::eval
