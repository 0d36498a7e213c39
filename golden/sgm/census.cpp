#include "sgm/census.hpp"

#include "sgm/parallel.hpp"
#include "sgm/params.hpp"

#include <algorithm>

namespace sgm {

int censusBitIndex(int dx, int dy) {
  if (dx == 0 && dy == 0) return -1;
  const int linear = (dy + kCensusRadius) * (2 * kCensusRadius + 1) + (dx + kCensusRadius);
  const int centre = kCensusRadius * (2 * kCensusRadius + 1) + kCensusRadius;
  return linear < centre ? linear : linear - 1;
}

std::vector<Census> censusTransform(const cv::Mat& gray) {
  const int w = gray.cols, h = gray.rows;
  // Window offset of every bit, the inverse of censusBitIndex.
  int offsetX[kCensusBits], offsetY[kCensusBits];
  for (int dy = -kCensusRadius; dy <= kCensusRadius; ++dy)
    for (int dx = -kCensusRadius; dx <= kCensusRadius; ++dx)
      if (const int k = censusBitIndex(dx, dy); k >= 0) offsetX[k] = dx, offsetY[k] = dy;
  constexpr int kBytes = kCensusBits / 8;
  std::vector<Census> out(size_t(w) * h);
  parallelFor(h, [&](int y0, int y1) {
    std::vector<uint8_t> bytes(size_t(kBytes) * w);  // byte j of every pixel's signature
    for (int y = y0; y < y1; ++y) {
      std::fill(bytes.begin(), bytes.end(), 0);
      const uint8_t* centre = gray.ptr<uint8_t>(y);
      for (int k = 0; k < kCensusBits; ++k) {
        const int dx = offsetX[k], qy = y + offsetY[k];
        if (qy < 0 || qy >= h) continue;  // rows outside the image give 0 bits
        const uint8_t* row = gray.ptr<uint8_t>(qy);
        uint8_t* plane = bytes.data() + size_t(k / 8) * w;
        const int x0 = std::max(0, -dx), x1 = std::min(w, w - dx);  // columns with q inside
        const uint8_t bit = uint8_t(1u << (k % 8));
        for (int x = x0; x < x1; ++x) plane[x] |= row[x + dx] < centre[x] ? bit : uint8_t(0);
      }
      for (int x = 0; x < w; ++x) {
        Census c;
        for (int j = 0; j < 8; ++j) c.lo |= uint64_t(bytes[size_t(j) * w + x]) << (8 * j);
        c.hi = uint16_t(bytes[size_t(8) * w + x] | bytes[size_t(9) * w + x] << 8);
        out[size_t(y) * w + x] = c;
      }
    }
  });
  return out;
}

}  // namespace sgm
