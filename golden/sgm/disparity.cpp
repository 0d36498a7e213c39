#include "sgm/disparity.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace sgm {

int winnerTakeAll(const uint16_t* s, int disparities) {
  int best = 0;
  for (int d = 1; d < disparities; ++d)
    if (s[d] < s[best]) best = d;
  return best;
}

int subpixelOffset(int a, int m, int b) {
  const int den = a + b - 2 * m;
  if (den <= 0) return 0;
  const int num = a - b;
  // |num| <= den, so the magnitude is at most half a pixel.
  const int magnitude = (std::abs(num) * kSubpixelOne + den) / (2 * den);
  return num < 0 ? -magnitude : magnitude;
}

int rightDisparity(const PathVolume& s, int xr, int y) {
  const int last = std::min(s.depth - 1, s.width - 1 - xr);
  int best = 0;
  uint16_t bestCost = s.at(xr, y)[0];
  for (int d = 1; d <= last; ++d) {
    const uint16_t c = s.at(xr + d, y)[d];
    if (c < bestCost) best = d, bestCost = c;
  }
  return best;
}

DisparityMap selectDisparity(const PathVolume& s, const Params& params) {
  const int w = s.width, h = s.height, nd = s.depth;
  DisparityMap out{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  parallelFor(h, [&](int y0, int y1) {
    std::vector<int> right(w);
    for (int y = y0; y < y1; ++y) {
      if (params.lrTolerance >= 0)
        for (int xr = 0; xr < w; ++xr) right[xr] = rightDisparity(s, xr, y);
      for (int x = 0; x < w; ++x) {
        const uint16_t* sp = s.at(x, y);
        const int d = winnerTakeAll(sp, nd);
        int fixed = d * kSubpixelOne;
        if (params.subpixel && d > 0 && d < nd - 1) fixed += subpixelOffset(sp[d - 1], sp[d], sp[d + 1]);
        bool valid = true;
        if (params.lrTolerance >= 0) valid = x - d >= 0 && std::abs(right[x - d] - d) <= params.lrTolerance;
        out.disp.at<uint16_t>(y, x) = uint16_t(fixed);
        out.valid.at<uint8_t>(y, x) = valid ? 1 : 0;
      }
    }
  });
  return out;
}

DisparityMap fillHoles(const DisparityMap& in) {
  const int w = in.disp.cols, h = in.disp.rows;
  DisparityMap out{in.disp.clone(), in.valid.clone()};
  constexpr int kNone = -1;
  std::vector<int> fromRight(w);
  for (int y = 0; y < h; ++y) {
    const uint16_t* d = in.disp.ptr<uint16_t>(y);
    const uint8_t* v = in.valid.ptr<uint8_t>(y);
    int last = kNone;
    for (int x = w - 1; x >= 0; --x) fromRight[x] = last = v[x] ? d[x] : last;
    last = kNone;
    for (int x = 0; x < w; ++x) {
      if (v[x]) {
        last = d[x];
        continue;
      }
      const int left = last, right = fromRight[x];
      if (left == kNone && right == kNone) continue;
      const int fill = left == kNone ? right : right == kNone ? left : std::min(left, right);
      out.disp.at<uint16_t>(y, x) = uint16_t(fill);
      out.valid.at<uint8_t>(y, x) = 1;
    }
  }
  return out;
}

DisparityMap median5x5(const DisparityMap& in) {
  const int w = in.disp.cols, h = in.disp.rows;
  DisparityMap out{in.disp.clone(), in.valid.clone()};
  parallelFor(h, [&](int y0, int y1) {
    std::vector<uint16_t> window;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < w; ++x) {
        if (!in.valid.at<uint8_t>(y, x)) continue;
        window.clear();
        for (int qy = std::max(0, y - kMedianRadius); qy <= std::min(h - 1, y + kMedianRadius); ++qy)
          for (int qx = std::max(0, x - kMedianRadius); qx <= std::min(w - 1, x + kMedianRadius); ++qx)
            if (in.valid.at<uint8_t>(qy, qx)) window.push_back(in.disp.at<uint16_t>(qy, qx));
        std::sort(window.begin(), window.end());
        out.disp.at<uint16_t>(y, x) = window[(window.size() - 1) / 2];
      }
  });
  return out;
}

}  // namespace sgm
