// SPDX-License-Identifier: Apache-2.0
// `sgm-eval bench`: wall-clock time of the golden model against OpenCV
// StereoSGBM on one frame, in the same process, interleaved. Measures and
// reports only; nothing here judges the numbers.
#pragma once

#include "eval_lib.hpp"

#include <string>
#include <vector>

namespace sgm::eval {

struct BenchResult {
  std::string scene;
  int width = 0, height = 0;
  int disparities = 64;
  int repeats = 0;
  int goldenThreads = 1, opencvThreads = 1;
  double goldenMs = 0;       // median: toGray on the colour pair + runPipeline(Params{})
  double opencvColorMs = 0;  // median: MODE_SGBM, blockSize 3, on the colour pair
  double opencvGrayMs = 0;   // median: same on the gray pair (already converted)

  double opencvMs() const;          // the faster OpenCV variant (the harder comparison)
  std::string opencvInput() const;  // "gray" or "color": which variant that is
  double ratio() const;             // goldenMs / opencvMs()
};

// The median of the values (0 when there are none).
double median(std::vector<double> values);

// One warm-up of each, then `repeats` rounds of golden, OpenCV colour, OpenCV
// gray, one after the other; median time of each.
BenchResult runBench(const Scene& scene, int repeats);

std::string benchJson(const BenchResult& result);
std::string benchText(const BenchResult& result);  // several lines, ends with the ratio line

}  // namespace sgm::eval
