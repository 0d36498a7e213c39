// Disparity selection and refinement: winner-take-all, sub-pixel, left-right
// validation and the 5x5 median (docs/algorithm.md, sections 6 to 9).
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

// Right-image disparity from the same S: argmin over d of S(xr + d, d) for
// d = 0 .. min(D-1, W-1-xr), ties to the smallest d.
int rightDisparity(const PathVolume& s, int xr, int y);

// WTA (+ sub-pixel when enabled) and the left-right check when tolerance >= 0,
// one row at a time from row y of S (W x D, pixel-major).
class RowSelector {
 public:
  RowSelector(int width, int disparities, const Params& params);
  void select(const uint16_t* sumRow, uint16_t* dispRow, uint8_t* validRow);

 private:
  const int width_, disparities_;
  const Params params_;
  std::vector<uint32_t> rightKey_;  // min (S, d) key per right pixel, indexed W-1-xr
};

// The same over a whole volume.
DisparityMap selectDisparity(const PathVolume& s, const Params& params);

// Hole filling along each row: an invalid pixel takes the smaller (background)
// of the nearest valid disparities to its left and right in the same row, or
// the one that exists; a row with no valid pixel stays invalid.
DisparityMap fillHoles(const DisparityMap& in);

// 5x5 median over the valid pixels of the window (window clipped to the image);
// an invalid centre stays invalid. Lower median of an even count.
DisparityMap median5x5(const DisparityMap& in);

}  // namespace sgm
