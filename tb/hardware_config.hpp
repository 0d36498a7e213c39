// SPDX-License-Identifier: Apache-2.0
// The core's run-time configuration inputs (sgm_top cfg_*_i) for a golden
// model parameter set and a frame size: one mapping for every testbench (the
// verilated harness, the Icarus files, the AXI4-Lite register tests).
#pragma once

#include "sgm/params.hpp"

#include <algorithm>
#include <string>

namespace sgm::tb {

// Hardware encoding of the cost modes (cfg_mode_i).
inline int hardwareModeCode(CostMode mode) {
  switch (mode) {
    case CostMode::kRt: return 0;
    case CostMode::kRsad: return 1;
    case CostMode::kUnified: return 2;
    default: throw Error(std::string("cost mode ") + costModeName(mode) + " is not in the hardware");
  }
}

// The values of sgm_top's cfg_*_i inputs.
struct HardwareConfig {
  int width = 0, height = 0, p1 = 0, p2 = 0, mode = 0;
  bool subpixel = false, lrEnable = false;
  int lrTolerance = 0;
  bool fill = false, snap = false, median = false;
  bool p2Paper = false;         // cfg_p2_mode_i: 0 knee, 1 paper (P2'/dI)
  bool weightsEqual = false;    // cfg_weights_i: 0 = 3,2,3,2, 1 = equal
  int uniqueness = 0;           // cfg_unique_i: ratio in %, 0 = off
  int adWeight = 0, adCap = 0;  // cfg_ad_weight_i, cfg_ad_cap_i: the AD term
  int rightWeight = 0;          // cfg_right_weight_i: the fifth path's W5 (its block is the build's RIGHT_BLOCK)
  // cfg_reset_t_i, cfg_reset_len_i, cfg_reset_paths_i: the path restart at strong edges
  // (T 0 = off; bit k of the flags: path k, 0, 45, 90, 135 degrees, the fifth).
  int resetThreshold = 0, resetLength = 0, resetPaths = 0;
};

inline HardwareConfig hardwareConfig(const Params& p, int width, int height) {
  HardwareConfig c;
  c.width = width, c.height = height, c.p1 = p.p1, c.p2 = p.p2, c.mode = hardwareModeCode(p.mode);
  c.subpixel = p.subpixel, c.lrEnable = p.lrTolerance >= 0, c.lrTolerance = std::max(p.lrTolerance, 0);
  c.fill = p.fill, c.snap = p.snap, c.median = p.median;
  c.p2Paper = p.p2Mode == P2Mode::kPaper, c.weightsEqual = p.weights == PathWeighting::kEqual;
  c.uniqueness = p.uniqueness;
  c.adWeight = p.adWeight, c.adCap = p.adCap;
  c.rightWeight = p.rightPathWeight;
  c.resetThreshold = p.edgeReset.threshold, c.resetLength = p.edgeReset.length;
  for (size_t k = 0; k < p.edgeReset.paths.size(); ++k) c.resetPaths |= (p.edgeReset.paths[k] != 0) << k;
  return c;
}

}  // namespace sgm::tb
