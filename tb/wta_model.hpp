// SPDX-License-Identifier: Apache-2.0
// What the sgm_wta and sgm_lr_check fixtures share: the golden winner-take-all
// result of one S vector (sgm::winnerTakeAll + sgm::subpixelOffset, as sgm_wta
// delivers it), sgm_wta's latency for D, random S volumes and junk S vectors
// (packFields of port_bits.hpp puts a vector into the flattened s_i port).
#pragma once

#include "sgm/disparity.hpp"
#include "sgm/volume.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace sgm::tb {

constexpr int log2Ceil(int n) { return n <= 1 ? 0 : 1 + log2Ceil((n + 1) / 2); }

// sgm_wta's LATENCY: T0 + log2(D) - 1 tree stages (levels 1 and 2 in one) + 5 (P, Q3 .. Q0, output).
constexpr int wtaLatency(int d) { return log2Ceil(d) + 5; }

struct WtaResult {
  int d, disp;  // winner, and disparity in 1/16 px (sub-pixel refined when enabled)
  bool unique;  // sgm::isUnique at the uniqueness ratio (always true at 0)
};
inline WtaResult goldenWta(const uint16_t* s, int disparities, bool subpixel, int uniqueness = 0) {
  const int d = sgm::winnerTakeAll(s, disparities);
  int disp = d * sgm::kSubpixelOne;
  if (subpixel && d > 0 && d < disparities - 1) disp += sgm::subpixelOffset(s[d - 1], s[d], s[d + 1]);
  return {d, disp, sgm::isUnique(s, disparities, d, uniqueness)};
}

// Uniform S(p, d) in 0 .. maxValue.
inline sgm::PathVolume randomVolume(int w, int h, int disparities, int maxValue, std::mt19937& rng) {
  sgm::PathVolume v(w, h, disparities);
  std::uniform_int_distribution<int> value(0, maxValue);
  for (auto& s : v.data) s = uint16_t(value(rng));
  return v;
}

// Random junk S vector (values 0 .. maxS) in `s`, for flush slots and
// disabled cycles; returns s.data().
inline const uint16_t* junkVector(std::vector<uint16_t>& s, int maxS, std::mt19937& junk) {
  for (auto& v : s) v = uint16_t(junk() & unsigned(maxS));
  return s.data();
}

}  // namespace sgm::tb
