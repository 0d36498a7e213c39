#include "sgm/census.hpp"

#include "sgm/parallel.hpp"
#include "sgm/params.hpp"

namespace sgm {

int censusBitIndex(int dx, int dy) {
  if (dx == 0 && dy == 0) return -1;
  const int linear = (dy + kCensusRadius) * (2 * kCensusRadius + 1) + (dx + kCensusRadius);
  const int centre = kCensusRadius * (2 * kCensusRadius + 1) + kCensusRadius;
  return linear < centre ? linear : linear - 1;
}

std::vector<Census> censusTransform(const cv::Mat& gray) {
  const int w = gray.cols, h = gray.rows;
  std::vector<Census> out(size_t(w) * h);
  parallelFor(h, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < w; ++x) {
        const int centre = gray.at<uint8_t>(y, x);
        Census c;
        for (int dy = -kCensusRadius; dy <= kCensusRadius; ++dy) {
          const int qy = y + dy;
          if (qy < 0 || qy >= h) continue;
          const uint8_t* row = gray.ptr<uint8_t>(qy);
          for (int dx = -kCensusRadius; dx <= kCensusRadius; ++dx) {
            const int qx = x + dx;
            if ((dx == 0 && dy == 0) || qx < 0 || qx >= w) continue;
            if (row[qx] < centre) c.set(censusBitIndex(dx, dy));
          }
        }
        out[size_t(y) * w + x] = c;
      }
  });
  return out;
}

}  // namespace sgm
