// 9x9 census transform and rank (docs/algorithm.md, section "Census and rank").
#pragma once

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace sgm {

// 80-bit census signature. Bit k (k = 0..79) belongs to window offset
// (dx, dy) in row-major order over dy = -4..4, dx = -4..4 with the centre
// skipped: bit k = T[I(q) < I(p)]; window pixels outside the image give 0.
struct Census {
  uint64_t lo = 0;  // bits 0..63
  uint16_t hi = 0;  // bits 64..79

  bool bit(int k) const { return k < 64 ? (lo >> k) & 1 : (hi >> (k - 64)) & 1; }
  void set(int k) {
    if (k < 64) lo |= uint64_t(1) << k;
    else hi = uint16_t(hi | (1u << (k - 64)));
  }
  int rank() const { return __builtin_popcountll(lo) + __builtin_popcount(hi); }
};

inline int hammingDistance(const Census& a, const Census& b) {
  return __builtin_popcountll(a.lo ^ b.lo) + __builtin_popcount(unsigned(a.hi ^ b.hi));
}

// Bit index of window offset (dx, dy), or -1 for the centre.
int censusBitIndex(int dx, int dy);

// Census of every pixel of an 8-bit gray image, row-major (index y * W + x).
std::vector<Census> censusTransform(const cv::Mat& gray);

}  // namespace sgm
