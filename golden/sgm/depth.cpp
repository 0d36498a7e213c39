// SPDX-License-Identifier: Apache-2.0
#include "sgm/depth.hpp"

#include "sgm/params.hpp"

#include <algorithm>
#include <string>

namespace sgm {

uint16_t depthMm(uint32_t focalQ8, uint32_t baselineUm, uint32_t dispQ4) {
  if (focalQ8 >> kFocalBits || baselineUm >> kBaselineBits)
    throw Error("depth parameters out of range: f " + std::to_string(focalQ8) + "/256 px, B " +
                std::to_string(baselineUm) + " um (" + std::to_string(kFocalBits) + " and " +
                std::to_string(kBaselineBits) + " bits)");
  if (dispQ4 == 0) return kDepthMax;
  const uint64_t k = uint64_t(focalQ8) * baselineUm;  // < 2^48
  const uint64_t divisor = uint64_t(16000) * dispQ4;
  const uint64_t z = (k + divisor / 2) / divisor;
  return uint16_t(std::clamp<uint64_t>(z, 1, kDepthMax));
}

cv::Mat depthMap(const DisparityMap& map, uint32_t focalQ8, uint32_t baselineUm) {
  cv::Mat depth = cv::Mat::zeros(map.disp.size(), CV_16UC1);
  for (int y = 0; y < depth.rows; ++y)
    for (int x = 0; x < depth.cols; ++x)
      if (map.valid.at<uint8_t>(y, x))
        depth.at<uint16_t>(y, x) = depthMm(focalQ8, baselineUm, map.disp.at<uint16_t>(y, x));
  return depth;
}

cv::Mat outputWords(const DisparityMap& map, const Params& params) {
  if (params.output == OutputMode::kDepth) return depthMap(map, uint32_t(params.focalQ8), uint32_t(params.baselineUm));
  cv::Mat words(map.disp.size(), CV_16UC1);
  for (int y = 0; y < words.rows; ++y)
    for (int x = 0; x < words.cols; ++x)
      words.at<uint16_t>(
          y, x) = uint16_t((map.valid.at<uint8_t>(y, x) ? 0x8000u : 0u) | (map.disp.at<uint16_t>(y, x) & 0x7fffu));
  return words;
}

}  // namespace sgm
