// SPDX-License-Identifier: Apache-2.0
// How well the confidence map ranks the errors (docs/algorithm.md section 7b), sparsification
// style: per scene, the error of the most confident P % of the evaluated pixels for P = 10 ..
// 100 (Middlebury: bad-delta over the nonocc mask; KITTI: D1 over every pixel with ground
// truth; invalid output counts as an error) -> confidence.md, confidence.json, confidence.png.
#pragma once

#include "eval_lib.hpp"

#include "sgm/params.hpp"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace sgm::eval {

// The error of the most confident fraction of the pixels, pixels in descending order of
// confidence; a run of equal confidences that the fraction cuts counts with its own error
// rate (no order within it). errors[i] is 1 for an error; both vectors have the same size.
double errorOfMostConfident(const std::vector<uint8_t>& confidence, const std::vector<uint8_t>& errors,
                            double fraction);

struct ConfidenceRow {
  std::string scene, set;
  int disparities = 0;
  long pixels = 0;                // evaluated pixels
  std::vector<double> errorKept;  // % at each of ConfidenceReport::percents
};

struct ConfidenceReport {
  std::vector<int> percents;  // 10, 20, .. 100
  double delta = 1;
  Params params;
  std::vector<ConfidenceRow> rows;
  // Per group (middlebury, kitti): the mean over its scenes at each percent.
  std::vector<std::pair<std::string, std::vector<double>>> means;
};

// fallbackDisparities: D for a scene without ndisp.
ConfidenceReport computeConfidence(const std::vector<Scene>& scenes, const Params& params, int fallbackDisparities,
                                   double delta);
std::string confidenceMarkdown(const ConfidenceReport& report);
std::string confidenceJson(const ConfidenceReport& report);
// Error (%) against the fraction kept (%), one line per group mean, thin lines per scene.
cv::Mat confidenceChart(const ConfidenceReport& report);

}  // namespace sgm::eval
