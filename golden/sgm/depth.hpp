// SPDX-License-Identifier: Apache-2.0
// Depth from disparity (docs/algorithm.md, section 10b): Z = f B / d in millimetres, 16 bits,
// 0 = invalid, saturating, in integers (the exactly rounded quotient).
#pragma once

#include "sgm/image_io.hpp"
#include "sgm/params.hpp"

#include <opencv2/core.hpp>

#include <cstdint>

namespace sgm {

// The depth parameters as the registers hold them.
constexpr int kFocalBits = kDepthParamBits;     // f in 1/256 px: up to 65535.996 px
constexpr int kBaselineBits = kDepthParamBits;  // B in micrometres: up to 16.78 m
constexpr uint16_t kDepthMax = 0xffff;

// Z in mm for a disparity of dispQ4 / 16 px: round(f B / d) with f = focalQ8 / 256 px and
// B = baselineUm / 1000 mm, that is floor((K + 8000 dq) / (16000 dq)) with K = focalQ8 x
// baselineUm and dq = dispQ4; at least 1 (0 means invalid), at most kDepthMax (also for
// dq = 0, a point at infinity).
uint16_t depthMm(uint32_t focalQ8, uint32_t baselineUm, uint32_t dispQ4);

// The depth map (CV_16UC1): depthMm of every valid pixel, 0 where the map is invalid.
cv::Mat depthMap(const DisparityMap& map, uint32_t focalQ8, uint32_t baselineUm);

// The core's output words (CV_16UC1) for a map and the parameters' output mode: with
// OutputMode::kDisparity {valid, zeros, disparity x 16} (section 10), with kDepth
// depthMap(map, focalQ8, baselineUm).
cv::Mat outputWords(const DisparityMap& map, const Params& params);

}  // namespace sgm
