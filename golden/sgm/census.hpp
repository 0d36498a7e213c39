// SPDX-License-Identifier: Apache-2.0
// 9x5 / 9x9 census transform and rank (docs/algorithm.md, section "Census and rank").
#pragma once

#include "sgm/params.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace sgm {

// Census signature, 44 bits (9x5) or 80 bits (9x9). Bit k belongs to window
// offset (dx, dy) in row-major order over dy = -R..R, dx = -4..4 with the
// centre skipped: bit k = T[I(q) < I(p)]; window pixels outside the image give 0.
struct Census {
  uint64_t bits = 0;  // bits 0..63 (all of a 9x5 signature)
  uint64_t high = 0;  // bits 64..79 (9x9 only), the rest 0

  bool bit(int k) const { return k < 64 ? (bits >> k) & 1 : (high >> (k - 64)) & 1; }
  void set(int k) {
    if (k < 64)
      bits |= uint64_t(1) << k;
    else
      high |= uint64_t(1) << (k - 64);
  }
  int rank() const { return __builtin_popcountll(bits) + __builtin_popcountll(high); }
  bool operator==(const Census& o) const { return bits == o.bits && high == o.high; }
};
static_assert(kMaxCensusBits <= 128, "two 64-bit words hold the census");

inline int hammingDistance(const Census& a, const Census& b) {
  return __builtin_popcountll(a.bits ^ b.bits) + __builtin_popcountll(a.high ^ b.high);
}

// Bit index of window offset (dx, dy), or -1 for the centre.
int censusBitIndex(int dx, int dy, CensusWindow window = CensusWindow::k9x5);

// Census of every pixel of an 8-bit gray image, row-major (index y * W + x).
std::vector<Census> censusTransform(const cv::Mat& gray, CensusWindow window = CensusWindow::k9x5);

}  // namespace sgm
