// SPDX-License-Identifier: Apache-2.0
#include "sgm/census.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>

namespace sgm {

int censusBitIndex(int dx, int dy, CensusWindow window) {
  if (dx == 0 && dy == 0) return -1;
  const CensusShape s = censusShape(window);
  const int linear = (dy + s.radiusY) * s.width + (dx + s.radiusX);
  const int centre = s.radiusY * s.width + s.radiusX;
  return linear < centre ? linear : linear - 1;
}

std::vector<Census> censusTransform(const cv::Mat& gray, CensusWindow window) {
  const CensusShape shape = censusShape(window);
  const int w = gray.cols, h = gray.rows;
  std::vector<Census> out(size_t(w) * h);
  parallelFor(h, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const uint8_t* centre = gray.ptr<uint8_t>(y);
      Census* sig = out.data() + size_t(y) * w;
      for (int dy = -shape.radiusY; dy <= shape.radiusY; ++dy) {
        const int qy = y + dy;
        if (qy < 0 || qy >= h) continue;  // rows outside the image give 0 bits
        const uint8_t* row = gray.ptr<uint8_t>(qy);
        for (int dx = -shape.radiusX; dx <= shape.radiusX; ++dx) {
          const int k = censusBitIndex(dx, dy, window);
          if (k < 0) continue;
          const int x0 = std::max(0, -dx), x1 = std::min(w, w - dx);  // columns with q inside
          if (k < 64)
            for (int x = x0; x < x1; ++x) sig[x].bits |= uint64_t(row[x + dx] < centre[x]) << k;
          else
            for (int x = x0; x < x1; ++x) sig[x].high |= uint64_t(row[x + dx] < centre[x]) << (k - 64);
        }
      }
    }
  });
  return out;
}

}  // namespace sgm
