// SPDX-License-Identifier: Apache-2.0
// The whole golden pipeline: gray pair in, disparity map out.
#pragma once

#include "sgm/image_io.hpp"
#include "sgm/params.hpp"
#include "sgm/rectify.hpp"
#include "sgm/volume.hpp"

#include <opencv2/core.hpp>

namespace sgm {

// Intermediate results, for tests and for the harness's per-stage comparison.
struct PipelineStages {
  CostVolume cost;        // C(p, d)
  PathVolume aggregated;  // S(p, d)
  DisparityMap selected;  // after WTA, sub-pixel and LR check
  DisparityMap filled;    // after hole filling (== selected when filling is off)
  DisparityMap snapped;   // after edge snapping (== filled when snapping is off)
  DisparityMap result;    // after the median (== snapped when the median is off)
  cv::Mat confidence;     // CV_8UC1, section 7b: from the selection, 0 where it was invalid
};

// Throws Error for bad input: size mismatch, non-gray images, images smaller
// than the 9x9 minimum frame, invalid parameters.
void checkInput(const cv::Mat& grayLeft, const cv::Mat& grayRight, const Params& params);

PipelineStages runPipelineStages(const cv::Mat& grayLeft, const cv::Mat& grayRight, const Params& params);
// The streaming pipeline; confidence (when given) receives the confidence map (section 7b).
DisparityMap runPipeline(const cv::Mat& grayLeft, const cv::Mat& grayRight, const Params& params,
                         cv::Mat* confidence = nullptr);

// Rectification in the stream (section 13): the raw pair goes through its meshes, the pipeline
// runs on the rectified grays, and a pixel whose left source position lies outside the raw
// image gets disparity 0, invalid (output word 0 in either output mode) and confidence 0.
// rectified and confidence (when given) receive the rectified pair and the confidence map.
struct RectifiedPair {
  RectifiedImage left, right;
};
DisparityMap runRectifiedPipeline(const cv::Mat& rawLeft, const cv::Mat& rawRight, const StereoMesh& mesh,
                                  const Params& params, RectifiedPair* rectified = nullptr,
                                  cv::Mat* confidence = nullptr);

}  // namespace sgm
