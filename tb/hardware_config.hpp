// SPDX-License-Identifier: Apache-2.0
// The frame configuration of a golden model parameter set and a frame size in the
// hardware's terms: the value of each field of the frame configuration word (sgm_top
// cfg_i), the word itself and the registers of sgm_axi that hold it. One mapping for every
// testbench (the verilated harness, the Icarus files, the AXI4-Lite register tests), made
// by the generated table tb/sgm_cfg_fields.hpp (regmap/sgm_regmap.def, CFG_FIELD): no field
// is named here.
#pragma once

#include "hardware_codes.hpp"
#include "sgm_cfg_fields.hpp"

#include "sgm/params.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sgm::tb {

// The index of the field REGISTER_FIELD (e.g. "CONFIG_MODE") in kCfgFields; throws for
// a name that is no field of the word.
inline size_t cfgFieldIndex(const std::string& name) {
  for (size_t i = 0; i < kCfgFields.size(); ++i)
    if (name == kCfgFields[i].name) return i;
  throw Error("'" + name + "' is no field of the frame configuration word (regmap/sgm_regmap.def, CFG_FIELD)");
}

// The fields' values, in the order of kCfgFields (each within its width).
struct HardwareConfig {
  std::array<uint32_t, kCfgFields.size()> values{};

  uint32_t get(const std::string& name) const { return values[cfgFieldIndex(name)]; }
  // Sets a field (masked to its width): an out-of-range value on purpose, say.
  void set(const std::string& name, uint32_t value) {
    const size_t i = cfgFieldIndex(name);
    values[i] = value & mask(kCfgFields[i].width);
  }

  // The word, 32 bits per element, bit 0 first.
  std::vector<uint32_t> word() const {
    std::vector<uint32_t> w((kCfgWidth + 31) / 32, 0);
    for (size_t i = 0; i < kCfgFields.size(); ++i)
      for (int b = 0; b < kCfgFields[i].width; ++b)
        if (values[i] >> b & 1u) w[size_t(kCfgFields[i].lsb + b) / 32] |= 1u << ((kCfgFields[i].lsb + b) % 32);
    return w;
  }
  // The word in hexadecimal, most significant digit first, ceil(CFG_W / 4) digits.
  std::string hex() const {
    const std::vector<uint32_t> w = word();
    std::string s;
    for (int d = (kCfgWidth + 3) / 4 - 1; d >= 0; --d) s += "0123456789abcdef"[w[size_t(d) / 8] >> (4 * (d % 8)) & 15u];
    return s;
  }
  // The value of sgm_axi's register at this byte offset: the fields of the word it holds
  // (0 for a register that holds none).
  uint32_t reg(uint32_t offset) const {
    uint32_t v = 0;
    for (size_t i = 0; i < kCfgFields.size(); ++i)
      if (kCfgFields[i].reg == offset) v |= values[i] << kCfgFields[i].shift;
    return v;
  }

  static uint32_t mask(int width) { return width >= 32 ? 0xffffffffu : (1u << width) - 1; }
};

inline HardwareConfig hardwareConfig(const Params& p, int width, int height) {
  HardwareConfig c;
  for (size_t i = 0; i < kCfgFields.size(); ++i)
    c.values[i] = kCfgFields[i].golden(p, width, height) & HardwareConfig::mask(kCfgFields[i].width);
  return c;
}

}  // namespace sgm::tb
