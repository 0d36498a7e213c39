// SPDX-License-Identifier: Apache-2.0
// Adaptive P2 table and the four causal path costs of eq. (1)
// (docs/algorithm.md, sections "P2 table" and "Path costs").
#pragma once

#include "sgm/params.hpp"
#include "sgm/volume.hpp"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>
#include <functional>

namespace sgm {

// P2r indexed by k = |I(p) - I(p - r)|: knee max(P1, floor(4 P2' / (k + 4))) (kP2Knee = 4),
// paper max(P1, floor(P2' / k)) with P2' at k = 0.
using P2Table = std::array<uint16_t, 256>;
P2Table makeP2Table(int p1, int p2, P2Mode mode = P2Mode::kKnee);

// A path direction r: p - r = (x + dx, y + dy).
struct PathDirection {
  int dx, dy, degrees;
};
constexpr PathDirection kPathDirections[kPathCount] = {{-1, 0, 0}, {-1, -1, 45}, {0, -1, 90}, {1, -1, 135}};
// Golden-only MGM (Params::mgm): the second, perpendicular causal neighbour of each
// path (p + (dx, dy)): above for 0 degrees, above-right for 45, left for 90, above-left for 135.
constexpr PathDirection kMgmPerpendicular[kPathCount] = {{0, -1, 90}, {1, -1, 135}, {-1, 0, 0}, {-1, -1, 45}};

// Sentinel for the missing neighbours Lr(p-r, -1) and Lr(p-r, D); larger than
// any path cost, small enough that sentinel + P1 still fits in 16 bits.
constexpr uint16_t kPathSentinel = 0x7fff;

// One step of eq. (1) at one pixel, for all D disparities:
//   out[d] = C(p,d) + min(prev[d], prev[d-1] + P1, prev[d+1] + P1, minPrev + P2r) - minPrev
// prev points at Lr(p-r, 0); prev[-1] and prev[D] must hold kPathSentinel.
// Returns min_d out[d].
uint16_t pathStep(const uint8_t* cost, const uint16_t* prev, uint16_t minPrev, int disparities, int p1, int p2r,
                  uint16_t* out);

// At a path start (p - r outside the image) Lr(p, d) = C(p, d).
uint16_t pathStart(const uint8_t* cost, int disparities, uint16_t* out);

// Lr of one path (index into kPathDirections) for the whole image.
PathVolume pathCost(const CostVolume& cost, const cv::Mat& grayLeft, int pathIndex, int p1, int p2,
                    P2Mode p2Mode = P2Mode::kKnee);

// S(p, d) = sum over the four paths of w[r] Lr(p, d) (3, 2, 3, 2 or equal), for the whole volume.
// rightPathWeight > 0 adds a fifth path, 0 degrees from the right (p - r = (x + 1, y)),
// computed over each completed row of C, weighted by rightPathWeight; rightPathBlock > 0
// computes it per block of that many pixels (addRightPath; the core's form, sgm_top
// RIGHT_BLOCK), 0 over the whole row (golden-only). mgm (golden-only) replaces each
// path's recursion by the raster-order MGM one (kMgmPerpendicular). p1PathPercent
// (golden-only; nullptr = 100 each): P1 of each path (0, 45, 90, 135 degrees, the fifth)
// in percent of p1, each path's P2r from its own P1. edgeReset (the path restart; threshold 0 =
// off): the paths it marks start again (Lr = C) within `length` steps of a strong edge.
// lrStoreBits = N (golden-only, 0 = off): the 45, 90 and 135 degree paths read the row
// above's Lr as a path memory of N bits relative to the pixel's minimum would hold it,
// min Lr + min(Lr - min Lr, 2^N - 1); S takes every Lr whole. Exact for 2^N - 1 >= P2'
// (eq. (1) never takes a value beyond min Lr + P2r), so N = 8 is exact for every P2' <= 255.
PathVolume aggregateCost(const CostVolume& cost, const cv::Mat& grayLeft, int p1, int p2, P2Mode p2Mode = P2Mode::kKnee,
                         PathWeighting weights = PathWeighting::k3232, int rightPathWeight = 0, bool mgm = false,
                         int rightPathBlock = 0, const int* p1PathPercent = nullptr,
                         const EdgeReset& edgeReset = EdgeReset{}, int lrStoreBits = 0);

// The streaming form used by the pipeline: rows in order, never more than a
// few rows of C and S in memory, the work of each row split over two workers.
// costRow(y, x0, x1, row) fills pixels x0 .. x1-1 of row y of C (W x D,
// pixel-major; row points at pixel 0). sink(worker, y, row) receives row y of S
// (W x D); it is called once per row, from either worker (0 or 1), rows of
// different workers possibly at the same time.
using CostRowFn = std::function<void(int y, int x0, int x1, uint8_t* row)>;
using SumRowFn = std::function<void(int worker, int y, const uint16_t* row)>;
void aggregateRows(int width, int height, int disparities, const cv::Mat& grayLeft, int p1, int p2, P2Mode p2Mode,
                   PathWeighting weights, const CostRowFn& costRow, const SumRowFn& sink, int rightPathWeight = 0,
                   bool mgm = false, int rightPathBlock = 0, const int* p1PathPercent = nullptr,
                   const EdgeReset& edgeReset = EdgeReset{}, int lrStoreBits = 0);

// The fifth path over one row: Lr for r = (1, 0), from x = W-1 down to 0,
// added to sum (W x D) with the given weight. cost is the row of C, grayRow the row of
// the left image. block = B > 0: the row in blocks [jB, (j+1)B), the last block taking
// the remainder ([(m-1)B, W), m = max(1, W / B)); each block's path is started (Lr = C)
// one block to its right (at x0 + 2B - 1; the last block's at W - 1), the next block
// being its warm-up: a bounded look-ahead instead of the whole row (in hardware a few
// blocks of C per row lane instead of the row, sgm_right_path). block = 0: the whole row.
// edgeReset.on(kPathCount): each pass starts again within edgeReset.length steps of a strong edge.
void addRightPath(const uint8_t* cost, const uint8_t* grayRow, int width, int disparities, int p1,
                  const P2Table& p2Table, int weight, uint16_t* sum, int block = 0,
                  const EdgeReset& edgeReset = EdgeReset{});

}  // namespace sgm
