// 9x5 census transform and rank (docs/algorithm.md, section "Census and rank").
#pragma once

#include "sgm/params.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace sgm {

// 44-bit census signature. Bit k (k = 0..43) belongs to window offset
// (dx, dy) in row-major order over dy = -2..2, dx = -4..4 with the centre
// skipped: bit k = T[I(q) < I(p)]; window pixels outside the image give 0.
struct Census {
  uint64_t bits = 0;  // bits 0..43, the rest 0

  bool bit(int k) const { return (bits >> k) & 1; }
  void set(int k) { bits |= uint64_t(1) << k; }
  int rank() const { return __builtin_popcountll(bits); }
};
static_assert(kCensusBits <= 64, "one 64-bit word holds the census");

inline int hammingDistance(const Census& a, const Census& b) { return __builtin_popcountll(a.bits ^ b.bits); }

// Bit index of window offset (dx, dy), or -1 for the centre.
int censusBitIndex(int dx, int dy);

// Census of every pixel of an 8-bit gray image, row-major (index y * W + x).
std::vector<Census> censusTransform(const cv::Mat& gray);

}  // namespace sgm
