// SPDX-License-Identifier: Apache-2.0
// Disparity selection and refinement: winner-take-all, sub-pixel, left-right
// validation, hole filling, edge snapping and the 5x5 median
// (docs/algorithm.md, sections 6 to 9).
#pragma once

#include "sgm/image_io.hpp"
#include "sgm/params.hpp"
#include "sgm/volume.hpp"

#include <cstdint>
#include <vector>

namespace sgm {

// argmin_d s[d], ties to the smallest d.
int winnerTakeAll(const uint16_t* s, int disparities);

// Quadratic sub-pixel offset in 1/16 px (-8 .. 8) from the costs at d-1, d, d+1:
//   round((a - b) / (2 (a + b - 2m)) * 16), half away from zero; 0 when a + b - 2m = 0.
int subpixelOffset(int a, int m, int b);

// Golden-only experiment (Params::linearSubpixel, not in the RTL): the equiangular
// (V) fit, round((a - b) / (2 (max(a, b) - m)) * 16), half away from zero; 0 when
// max(a, b) = m.
int subpixelOffsetLinear(int a, int m, int b);

// Right-image disparity from the same S: argmin over d of S(xr + d, d) for
// d = 0 .. min(D-1, W-1-xr), ties to the smallest d.
int rightDisparity(const PathVolume& s, int xr, int y);

// Uniqueness (Params::uniqueness, section 7): the winner d of s is unique when no
// S(k) with |k - d| > 1 has S(k) (100 - ratio) < 100 S(d); always at ratio 0.
bool isUnique(const uint16_t* s, int disparities, int d, int ratio);

// Confidence of the winner d of s (docs/algorithm.md section 7b): with S1 = S(d) and S2 the
// smallest S(k) with |k - d| > 1 (S1 when there is none), floor(256 (S2 - S1) / (S2 + 1)),
// 0 .. 255.
int confidence(const uint16_t* s, int disparities, int d);

// WTA (+ sub-pixel when enabled) and the left-right check when tolerance >= 0,
// one row at a time from row y of S (W x D, pixel-major); confidenceRow (when given)
// receives each pixel's confidence, 0 where the pixel is invalid.
class RowSelector {
 public:
  RowSelector(int width, int disparities, const Params& params);
  void select(const uint16_t* sumRow, uint16_t* dispRow, uint8_t* validRow, uint8_t* confidenceRow = nullptr);

 private:
  const int width_, disparities_;
  const Params params_;
  std::vector<uint32_t> rightKey_;  // min (S, d) key per right pixel, indexed W-1-xr
};

// The same over a whole volume (and the confidence map, CV_8UC1, when asked for).
DisparityMap selectDisparity(const PathVolume& s, const Params& params, cv::Mat* confidence = nullptr);

// Hole filling along each row: an invalid pixel keeps its own disparity when it
// is within kFillAgree (1 px) of the nearest valid disparity to its left or to
// its right in the same row, else it takes the smaller (background) of the two,
// or the one that exists; a row with no valid pixel stays invalid.
DisparityMap fillHoles(const DisparityMap& in);

// Edge snapping along each row (docs/algorithm.md section 8b): a drop of more
// than kSnapStep between valid neighbours e, e+1 (foreground on the left) moves
// left to the strongest step |I(k) - I(k-1)| of the left gray image among
// k = e+1-kSnapReach .. e+1 (ties to the largest k): the valid pixels k .. e
// take the disparity of e+1. A pixel under several drops takes the nearest.
// minStep > 0 (golden-only experiment, Params::snapEdge): a drop whose strongest step is
// below minStep is left alone.
DisparityMap snapEdges(const DisparityMap& in, const cv::Mat& grayLeft, int minStep = 0);

// 5x5 median over the valid pixels of the window (window clipped to the image);
// an invalid centre stays invalid. Lower median of an even count. The last
// kMedianRadius rows (window clipped by the bottom edge) pass through.
DisparityMap median5x5(const DisparityMap& in, const cv::Mat& gray = cv::Mat(), int gate = 0);

}  // namespace sgm
