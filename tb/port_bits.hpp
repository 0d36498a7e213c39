// Bit-field access to verilated ports of any width: CData/SData/IData (<= 32
// bits), QData (<= 64 bits) and VlWide<N> (wider), so that a flattened array
// port (element i of width W at bits [i*W +: W]) reads and writes the same way.
#pragma once

#include <verilated.h>

#include <cstdint>

namespace sgm::tb {

template <typename Port>
inline uint32_t wordOf(const Port& port, int index) {
  if constexpr (sizeof(Port) <= 8) return uint32_t(uint64_t(port) >> (32 * index));
  else return port[index];
}

template <typename Port>
inline void setWord(Port& port, int index, uint32_t value) {
  if constexpr (sizeof(Port) <= 8) {
    const uint64_t mask = uint64_t(0xffffffffu) << (32 * index);
    port = Port((uint64_t(port) & ~mask) | (uint64_t(value) << (32 * index)));
  } else {
    port[index] = value;
  }
}

// Bits [lsb +: width] of port, width <= 32.
template <typename Port>
inline uint32_t getBits(const Port& port, int lsb, int width) {
  uint64_t window = wordOf(port, lsb / 32);
  if ((lsb % 32) + width > 32) window |= uint64_t(wordOf(port, lsb / 32 + 1)) << 32;
  const uint64_t mask = width == 32 ? 0xffffffffull : ((uint64_t(1) << width) - 1);
  return uint32_t((window >> (lsb % 32)) & mask);
}

template <typename Port>
inline void setBits(Port& port, int lsb, int width, uint32_t value) {
  for (int i = 0; i < width; ++i) {
    const int bit = lsb + i, word = bit / 32;
    uint32_t w = wordOf(port, word);
    w = (w & ~(1u << (bit % 32))) | (((value >> i) & 1u) << (bit % 32));
    setWord(port, word, w);
  }
}

}  // namespace sgm::tb
