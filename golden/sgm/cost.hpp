// SPDX-License-Identifier: Apache-2.0
// Matching cost C(p, d) for every pixel and disparity (docs/algorithm.md,
// section "Matching cost").
#pragma once

#include "sgm/census.hpp"
#include "sgm/params.hpp"
#include "sgm/volume.hpp"

#include <opencv2/core.hpp>

namespace sgm {

// Cost of one hardware mode (rt, rsad, unified) from the left census at p and
// the right census at p - d. Throws Error for software-only modes.
int censusCost(CostMode mode, const Census& left, const Census& right);

// Pixels x0 .. x1-1 of one row of C for a hardware mode: row[x * D + d] from
// the census rows of the left and right images.
void censusCostRow(CostMode mode, CensusWindow census, const Census* left, const Census* right, int width, int x0,
                   int x1, int disparities, uint8_t* row);

// The AD term (Params::adWeight, section 3): adds
// weight * min(|IL(x, y) - IR(x - d, y)|, cap) >> kAdShift to pixels x0 .. x1-1 of row y
// of C; a match outside the right image (x - d < 0) gets the largest term. The sum
// stays within costLimit (Params::validate).
void addAdTerm(const cv::Mat& grayLeft, const cv::Mat& grayRight, int y, int x0, int x1, int disparities, int weight,
               int cap, uint8_t* row);

// Full cost volume C(x, y, d), d = 0 .. D-1; disparities with x - d < 0 cost
// maxCost(mode, census). The census window also sets the sad window.
CostVolume computeCost(const cv::Mat& grayLeft, const cv::Mat& grayRight, CostMode mode, int disparities,
                       CensusWindow census = CensusWindow::k9x5);

}  // namespace sgm
