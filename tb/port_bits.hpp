// SPDX-License-Identifier: Apache-2.0
// Bit-field access to verilated ports of any width: CData/SData/IData (<= 32
// bits), QData (<= 64 bits) and VlWide<N> (wider), so that a flattened array
// port (element i of width W at bits [i*W +: W]) reads and writes the same way.
#pragma once

#include <verilated.h>

#include <cstdint>
#include <vector>

namespace sgm::tb {

template <typename Port>
inline uint32_t wordOf(const Port& port, int index) {
  if constexpr (sizeof(Port) <= 8)
    return uint32_t(uint64_t(port) >> (32 * index));
  else
    return port[index];
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

// values[0 .. count) into port, element i at bits [i*width +: width] (width <= 32,
// each value masked to width bits): a flattened array port such as s_i.
template <typename Port, typename T>
inline void packFields(Port& port, const T* values, int count, int width) {
  const uint64_t mask = width == 32 ? 0xffffffffull : ((uint64_t(1) << width) - 1);
  uint64_t acc = 0;
  int bits = 0, word = 0;
  for (int i = 0; i < count; ++i) {
    acc |= (uint64_t(values[i]) & mask) << bits;
    for (bits += width; bits >= 32; bits -= 32, acc >>= 32) setWord(port, word++, uint32_t(acc));
  }
  if (bits > 0) setWord(port, word, uint32_t(acc));
}

// Every 32-bit word of the given ports, in order: a snapshot of a set of
// (output) ports of any widths, to compare before and after a cycle.
template <typename... Ports>
inline std::vector<uint32_t> portWords(const Ports&... ports) {
  std::vector<uint32_t> words;
  auto append = [&](const auto& port) {
    for (int i = 0; i < int(sizeof(port) + 3) / 4; ++i) words.push_back(wordOf(port, i));
  };
  (append(ports), ...);
  return words;
}

}  // namespace sgm::tb
