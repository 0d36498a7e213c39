// SPDX-License-Identifier: Apache-2.0
// Hardware encodings of golden model settings that are no plain number: the cost mode's code
// (CONFIG.MODE) and a flag per path (EDGE_RESET.PATHS). The golden values of the frame
// configuration word's fields (regmap/sgm_regmap.def, CFG_FIELD; tb/sgm_cfg_fields.hpp) use them.
#pragma once

#include "sgm/params.hpp"

#include <cstdint>
#include <string>

namespace sgm::tb {

// Hardware encoding of the cost modes (CONFIG.MODE; sgm_regs.h SGM_CONFIG_MODE_*).
inline int hardwareModeCode(CostMode mode) {
  switch (mode) {
    case CostMode::kRt: return 0;
    case CostMode::kRsad: return 1;
    case CostMode::kUnified: return 2;
    default: throw Error(std::string("cost mode ") + costModeName(mode) + " is not in the hardware");
  }
}

// Bit k set when flags[k] is not 0 (the path flags of the path restart).
template <class Flags>
uint32_t flagBits(const Flags& flags) {
  uint32_t bits = 0;
  for (size_t k = 0; k < flags.size(); ++k) bits |= uint32_t(flags[k] != 0) << k;
  return bits;
}

}  // namespace sgm::tb
