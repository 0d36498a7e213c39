// SPDX-License-Identifier: Apache-2.0
// A W x H x depth array stored pixel-major ([y][x][d]), the layout in which the
// pipeline streams: all disparities of one pixel are adjacent.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sgm {

template <typename T>
struct Volume {
  int width = 0, height = 0, depth = 0;
  std::vector<T> data;

  Volume() = default;
  Volume(int w, int h, int d) : width(w), height(h), depth(d), data(size_t(w) * h * d, T{}) {}
  T* at(int x, int y) { return data.data() + (size_t(y) * width + x) * depth; }
  const T* at(int x, int y) const { return data.data() + (size_t(y) * width + x) * depth; }
};

using CostVolume = Volume<uint8_t>;   // C(p, d), at most 255
using PathVolume = Volume<uint16_t>;  // Lr(p, d) or S(p, d)

}  // namespace sgm
