// SPDX-License-Identifier: Apache-2.0
// The Middlebury cones pair under $SGM_DATA/cones for the fixtures' real-data
// cases, and the golden pipeline's stages on it (computed once per D).
#pragma once

#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

namespace sgm::tb {

inline std::string conesDir() {
  const char* root = std::getenv("SGM_DATA");
  return std::string(root ? root : "") + "/cones";
}

// Empty when left.png and right.png are there, else why not (for GTEST_SKIP).
inline std::string conesMissing() {
  const std::string dir = conesDir();
  if (std::getenv("SGM_DATA") && std::filesystem::exists(dir + "/left.png") &&
      std::filesystem::exists(dir + "/right.png"))
    return "";
  return "Middlebury cones not found at '" + dir + "' (set SGM_DATA, e.g. via make rtl-tests DATA=...)";
}

inline cv::Mat conesGray(const std::string& side) { return sgm::readGray(conesDir() + "/" + side + ".png"); }

// runPipelineStages on cones with the four-path preset and d disparities; call
// only when conesMissing() is empty.
inline const sgm::PipelineStages& conesStages(int d) {
  static std::map<int, sgm::PipelineStages> cache;
  auto it = cache.find(d);
  if (it == cache.end()) {
    // The four-path preset: the stage fixtures' widths (S of four paths) are built for it.
    sgm::Params params = sgm::presetParams("four-path");
    params.disparities = d;
    it = cache.emplace(d, sgm::runPipelineStages(conesGray("left"), conesGray("right"), params)).first;
  }
  return it->second;
}

}  // namespace sgm::tb
