// SPDX-License-Identifier: Apache-2.0
#include "sgm/disparity.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace sgm {

namespace {
// (cost, d) packed so that one unsigned minimum picks the smallest cost and,
// among equal costs, the smallest d (d < 256).
inline uint32_t costKey(uint16_t cost, int d) { return uint32_t(cost) << 8 | uint32_t(d); }
}  // namespace

int winnerTakeAll(const uint16_t* s, int disparities) {
  uint32_t best = 0xffffffff;
  for (int d = 0; d < disparities; ++d) best = std::min(best, costKey(s[d], d));
  return int(best & 0xff);
}

int subpixelOffset(int a, int m, int b) {
  const int den = a + b - 2 * m;
  if (den <= 0) return 0;
  const int num = a - b;
  // |num| <= den, so the magnitude is at most half a pixel.
  const int magnitude = (std::abs(num) * kSubpixelOne + den) / (2 * den);
  return num < 0 ? -magnitude : magnitude;
}

int subpixelOffsetLinear(int a, int m, int b) {
  const int den = std::max(a, b) - m;
  if (den <= 0) return 0;
  const int num = a - b;  // |num| <= den
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

bool isUnique(const uint16_t* s, int disparities, int d, int ratio) {
  const uint32_t best = uint32_t(s[d]) * 100;
  for (int k = 0; k < disparities; ++k)
    if (std::abs(k - d) > 1 && uint32_t(s[k]) * uint32_t(100 - ratio) < best) return false;
  return true;
}

int confidence(const uint16_t* s, int disparities, int d) {
  const uint32_t best = s[d];
  uint32_t second = 0xffffffff;
  for (int k = 0; k < disparities; ++k)
    if (std::abs(k - d) > 1) second = std::min<uint32_t>(second, s[k]);
  if (second == 0xffffffff) return 0;
  return int(((second - best) << 8) / (second + 1));
}

RowSelector::RowSelector(int width, int disparities, const Params& params)
    : width_(width), disparities_(disparities), params_(params), rightKey_(width) {}

void RowSelector::select(const uint16_t* sumRow, uint16_t* dispRow, uint8_t* validRow, uint8_t* confidenceRow) {
  const int w = width_, nd = disparities_;
  const bool check = params_.lrTolerance >= 0;
  if (check) {
    // dR(xr) for every xr of the row (section 7) in one left-to-right sweep: the
    // candidate S(x, d) belongs to right pixel x - d. Keys are indexed by
    // k = W-1-xr so that the D candidates of one x are contiguous.
    std::fill(rightKey_.begin(), rightKey_.end(), 0xffffffff);
    for (int x = 0; x < w; ++x) {
      const uint16_t* sp = sumRow + size_t(x) * nd;
      uint32_t* key = rightKey_.data() + (w - 1 - x);
      const int count = std::min(nd, x + 1);
      for (int d = 0; d < count; ++d) key[d] = std::min(key[d], costKey(sp[d], d));
    }
  }
  for (int x = 0; x < w; ++x) {
    const uint16_t* sp = sumRow + size_t(x) * nd;
    const int d = winnerTakeAll(sp, nd);
    int fixed = (params_.minDisparity + d) * kSubpixelOne;  // section 3: the true disparity
    if (params_.subpixel && d > 0 && d < nd - 1)
      fixed += params_.linearSubpixel ? subpixelOffsetLinear(sp[d - 1], sp[d], sp[d + 1])
                                      : subpixelOffset(sp[d - 1], sp[d], sp[d + 1]);
    // Right pixel x - dmin - d; the keys are indexed by x - d (the search's own frame).
    const bool inside = x - d - params_.minDisparity >= 0;
    const int rightD = check && inside ? int(rightKey_[w - 1 - (x - d)] & 0xff) : 0;
    dispRow[x] = uint16_t(fixed);
    validRow[x] = (!check || (inside && std::abs(rightD - d) <= params_.lrTolerance)) &&
                  (!params_.uniqueness || isUnique(sp, nd, d, params_.uniqueness));
    if (confidenceRow) confidenceRow[x] = uint8_t(validRow[x] ? confidence(sp, nd, d) : 0);
  }
}

DisparityMap selectDisparity(const PathVolume& s, const Params& params, cv::Mat* confidence) {
  DisparityMap out{cv::Mat(s.height, s.width, CV_16UC1), cv::Mat(s.height, s.width, CV_8UC1)};
  if (confidence) confidence->create(s.height, s.width, CV_8UC1);
  parallelFor(s.height, [&](int y0, int y1) {
    RowSelector selector(s.width, s.depth, params);
    for (int y = y0; y < y1; ++y)
      selector.select(s.at(0, y), out.disp.ptr<uint16_t>(y), out.valid.ptr<uint8_t>(y),
                      confidence ? confidence->ptr<uint8_t>(y) : nullptr);
  });
  return out;
}

DisparityMap fillHoles(const DisparityMap& in) {
  const int w = in.disp.cols, h = in.disp.rows;
  DisparityMap out{in.disp.clone(), in.valid.clone(), in.confidence};
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
      const int left = last, right = fromRight[x], own = d[x];
      if (left == kNone && right == kNone) continue;
      const auto agrees = [own](int n) { return n != kNone && std::abs(own - n) <= kFillAgree; };
      const int background = left == kNone ? right : right == kNone ? left : std::min(left, right);
      const int fill = agrees(left) || agrees(right) ? own : background;
      out.disp.at<uint16_t>(y, x) = uint16_t(fill);
      out.valid.at<uint8_t>(y, x) = 1;
    }
  }
  return out;
}

DisparityMap snapEdges(const DisparityMap& in, const cv::Mat& grayLeft, int minStep) {
  const int w = in.disp.cols, h = in.disp.rows, r = kSnapReach;
  DisparityMap out{in.disp.clone(), in.valid.clone(), in.confidence};
  for (int y = 0; y < h; ++y) {
    const uint16_t* d = in.disp.ptr<uint16_t>(y);
    const uint8_t* v = in.valid.ptr<uint8_t>(y);
    const uint8_t* g = grayLeft.ptr<uint8_t>(y);
    uint16_t* o = out.disp.ptr<uint16_t>(y);
    const auto step = [g](int k) { return std::abs(int(g[k]) - int(g[k - 1])); };
    // Drops from right to left, so that the nearest drop right of a pixel writes last.
    for (int e = w - 2; e >= 0; --e) {
      if (!v[e] || !v[e + 1] || d[e] <= d[e + 1] + kSnapStep) continue;
      int edge = e + 1;  // the strongest step in k = e+1-R .. e+1, ties to the largest k
      for (int k = e; k >= std::max(1, e + 1 - r); --k)
        if (step(k) > step(edge)) edge = k;
      if (step(edge) < minStep) continue;
      for (int x = edge; x <= e; ++x)
        if (v[x]) o[x] = d[e + 1];
    }
  }
  return out;
}

namespace {

constexpr int kMedianWindow = (2 * kMedianRadius + 1) * (2 * kMedianRadius + 1);  // 25

// Batcher's odd-even merge sort for 32 inputs, keeping only the comparators
// within the first 25 positions: with +inf in positions 25..31 the others
// never change anything.
std::vector<std::pair<int, int>> medianSortingNetwork() {
  std::vector<std::pair<int, int>> net;
  const int n = 32;
  for (int p = 1; p < n; p <<= 1)
    for (int k = p; k >= 1; k >>= 1)
      for (int j = k % p; j + k < n; j += 2 * k)
        for (int i = 0; i < std::min(k, n - j - k); ++i)
          if ((i + j) / (2 * p) == (i + j + k) / (2 * p) && i + j + k < kMedianWindow)
            net.emplace_back(i + j, i + j + k);
  return net;
}

}  // namespace

DisparityMap median5x5(const DisparityMap& in, const cv::Mat& gray, int gate) {
  const int w = in.disp.cols, h = in.disp.rows, r = kMedianRadius;
  // 16 pixels are sorted at once: lane l of window[k] is window entry k of pixel x0 + l.
  typedef uint16_t Lanes __attribute__((vector_size(32)));
  constexpr int kLanes = sizeof(Lanes) / sizeof(uint16_t);
  constexpr uint16_t kAbsent = 0xffff;  // invalid or outside: sorts after every disparity
  static const std::vector<std::pair<int, int>> network = medianSortingNetwork();
  // The valid disparities framed by kAbsent: r rows/columns around, plus a lane block of slack.
  const int pw = w + 2 * r + kLanes;
  std::vector<uint16_t> padded(size_t(pw) * (h + 2 * r), kAbsent);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (in.valid.at<uint8_t>(y, x)) padded[size_t(y + r) * pw + x + r] = in.disp.at<uint16_t>(y, x);
  std::vector<uint16_t> paddedGray(gate ? padded.size() : 0, 0);
  for (int y = 0; gate && y < h; ++y)
    for (int x = 0; x < w; ++x) paddedGray[size_t(y + r) * pw + x + r] = gray.at<uint8_t>(y, x);
  DisparityMap out{in.disp.clone(), in.valid.clone(), in.confidence};
  parallelFor(h, [&](int y0, int y1) {
    Lanes window[kMedianWindow];
    for (int y = y0; y < std::min(y1, h - r); ++y)  // the last r rows pass through (section 9)
      for (int x0 = 0; x0 < w; x0 += kLanes) {
        Lanes count = {}, centre;
        if (gate) std::memcpy(&centre, paddedGray.data() + size_t(y + r) * pw + x0 + r, sizeof(Lanes));
        for (int k = 0; k < kMedianWindow; ++k) {
          const int dy = k / (2 * r + 1), dx = k % (2 * r + 1);  // window offset + r
          std::memcpy(&window[k], padded.data() + size_t(y + dy) * pw + x0 + dx, sizeof(Lanes));
          if (gate) {
            Lanes g;
            std::memcpy(&g, paddedGray.data() + size_t(y + dy) * pw + x0 + dx, sizeof(Lanes));
            const Lanes diff = g > centre ? g - centre : centre - g;
            window[k] = diff > uint16_t(gate) ? kAbsent : window[k];
          }
          count -= window[k] != kAbsent;  // a true lane compares as -1
        }
        for (const auto& [i, j] : network) {
          const Lanes a = window[i], b = window[j];
          window[i] = a < b ? a : b;
          window[j] = a < b ? b : a;
        }
        for (int l = 0; l < kLanes && x0 + l < w; ++l)
          if (in.valid.at<uint8_t>(y, x0 + l)) out.disp.at<uint16_t>(y, x0 + l) = window[(count[l] - 1) / 2][l];
      }
  });
  return out;
}

}  // namespace sgm
