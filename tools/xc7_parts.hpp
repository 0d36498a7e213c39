// SPDX-License-Identifier: Apache-2.0
// The Artix-7 and Kintex-7 devices a Yosys xc7 estimate is fitted to (synth-summary's
// smallest_part, the datasheet's reference builds): 6-input LUTs (4 per slice), flip-flops
// (8 per slice), 36 Kbit block RAMs (a RAMB36E1, or two RAMB18E1) and DSP48E1 slices, from
// Xilinx DS180 (7 Series FPGAs Data Sheet: Overview, "7 Series Families Comparison").
// Ordered by LUTs: the first that holds a design is the smallest that does.
#pragma once

namespace sgm::eval {

struct Xc7Part {
  const char* name;
  long luts, ffs, bram36, dsp;
};

inline constexpr Xc7Part kXc7Parts[] = {
    {"XC7A12T", 8000, 16000, 20, 40},        {"XC7A15T", 10400, 20800, 25, 45},
    {"XC7A25T", 14600, 29200, 45, 80},       {"XC7A35T", 20800, 41600, 50, 90},
    {"XC7A50T", 32600, 65200, 75, 120},      {"XC7K70T", 41000, 82000, 135, 240},
    {"XC7A75T", 47200, 94400, 105, 180},     {"XC7A100T", 63400, 126800, 135, 240},
    {"XC7K160T", 101400, 202800, 325, 600},  {"XC7A200T", 134600, 269200, 365, 740},
    {"XC7K325T", 203800, 407600, 445, 840},  {"XC7K355T", 222600, 445200, 715, 1440},
    {"XC7K410T", 254200, 508400, 795, 1540}, {"XC7K420T", 260600, 521200, 835, 1680},
    {"XC7K480T", 298600, 597200, 955, 1920},
};

// The smallest part holding luts, ffs, bram36 (RAMB36 + RAMB18 / 2, rounded up) and dsp;
// nullptr when none does.
inline const Xc7Part* smallestXc7Part(long luts, long ffs, long bram36, long dsp) {
  for (const Xc7Part& p : kXc7Parts)
    if (luts <= p.luts && ffs <= p.ffs && bram36 <= p.bram36 && dsp <= p.dsp) return &p;
  return nullptr;
}

}  // namespace sgm::eval
