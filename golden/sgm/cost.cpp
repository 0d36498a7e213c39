// SPDX-License-Identifier: Apache-2.0
#include "sgm/cost.hpp"

#include "sgm/parallel.hpp"

#include <algorithm>
#include <cstdlib>

namespace sgm {

namespace {

template <CostMode kMode>
inline int censusCostOf(const Census& left, const Census& right) {
  if constexpr (kMode == CostMode::kRt) return std::abs(left.rank() - right.rank());
  if constexpr (kMode == CostMode::kRsad) return hammingDistance(left, right);
  if constexpr (kMode == CostMode::kUnified) return std::abs(left.rank() - right.rank()) + hammingDistance(left, right);
}

}  // namespace

int censusCost(CostMode mode, const Census& left, const Census& right) {
  switch (mode) {
    case CostMode::kRt: return censusCostOf<CostMode::kRt>(left, right);
    case CostMode::kRsad: return censusCostOf<CostMode::kRsad>(left, right);
    case CostMode::kUnified: return censusCostOf<CostMode::kUnified>(left, right);
    default: throw Error(std::string("cost mode ") + costModeName(mode) + " is not a census mode");
  }
}

namespace {

// One row of C for a mode; cost(x, d) gives the in-image cost (d <= x).
template <typename CostOf>
void fillCostRow(uint8_t* row, int x0, int x1, int nd, int cmax, CostOf cost) {
  for (int x = x0; x < x1; ++x) {
    uint8_t* c = row + size_t(x) * nd;
    const int inside = std::min(nd, x + 1);  // d <= x: the match is in the right image
    for (int d = 0; d < inside; ++d) c[d] = uint8_t(cost(x, d));
    for (int d = inside; d < nd; ++d) c[d] = uint8_t(cmax);
  }
}

}  // namespace

namespace {

// The hardware-mode cost of pixels x0 .. x1-1 of one row: the same arithmetic
// as censusCostOf, arranged for the compiler's vectoriser. The right row comes
// reversed (index W-1-x) so that the D candidates of one left pixel are
// contiguous.
inline __attribute__((always_inline)) void censusCostKernel(CostMode mode, int cmax, const Census* left,
                                                            const uint64_t* rightBits, const uint64_t* rightHigh,
                                                            const uint8_t* rightRank, int width, int x0, int x1, int nd,
                                                            uint8_t* row) {
  const bool wide = rightHigh != nullptr;  // 9x9: bits 64..79 in a second word
  for (int x = x0; x < x1; ++x) {
    uint8_t* c = row + size_t(x) * nd;
    const int inside = std::min(nd, x + 1), k0 = width - 1 - x;  // d <= x: the match is in the image
    const uint64_t bits = left[x].bits, high = left[x].high;
    const int rank = left[x].rank();
    const uint64_t* rBits = rightBits + k0;
    const uint64_t* rHigh = wide ? rightHigh + k0 : nullptr;
    const uint8_t* rRank = rightRank + k0;
    if (mode == CostMode::kRt)
      for (int d = 0; d < inside; ++d) c[d] = uint8_t(std::abs(rank - rRank[d]));
    else if (!wide && mode == CostMode::kRsad)
      for (int d = 0; d < inside; ++d) c[d] = uint8_t(__builtin_popcountll(bits ^ rBits[d]));
    else if (!wide)
      for (int d = 0; d < inside; ++d)
        c[d] = uint8_t(std::abs(rank - rRank[d]) + __builtin_popcountll(bits ^ rBits[d]));
    else if (mode == CostMode::kRsad)
      for (int d = 0; d < inside; ++d)
        c[d] = uint8_t(__builtin_popcountll(bits ^ rBits[d]) + __builtin_popcountll(high ^ rHigh[d]));
    else
      for (int d = 0; d < inside; ++d)
        c[d] = uint8_t(std::abs(rank - rRank[d]) + __builtin_popcountll(bits ^ rBits[d]) +
                       __builtin_popcountll(high ^ rHigh[d]));
    for (int d = inside; d < nd; ++d) c[d] = uint8_t(cmax);
  }
}

// The same kernel built for x86-64 CPUs with a vector popcount, chosen at run
// time; every other target (and x86-64 without it) runs the portable build.
using CostKernel = void (*)(CostMode, int, const Census*, const uint64_t*, const uint64_t*, const uint8_t*, int, int,
                            int, int, uint8_t*);
void censusCostKernelPortable(CostMode mode, int cmax, const Census* left, const uint64_t* bits, const uint64_t* high,
                              const uint8_t* rank, int width, int x0, int x1, int nd, uint8_t* row) {
  censusCostKernel(mode, cmax, left, bits, high, rank, width, x0, x1, nd, row);
}
#if defined(__x86_64__)
__attribute__((target("avx512f,avx512vl,avx512bw,avx512vpopcntdq"))) void censusCostKernelVectorPopcount(
    CostMode mode, int cmax, const Census* left, const uint64_t* bits, const uint64_t* high, const uint8_t* rank,
    int width, int x0, int x1, int nd, uint8_t* row) {
  censusCostKernel(mode, cmax, left, bits, high, rank, width, x0, x1, nd, row);
}
const CostKernel kCostKernel = __builtin_cpu_supports("avx512vpopcntdq") ? censusCostKernelVectorPopcount
                                                                         : censusCostKernelPortable;
#else
const CostKernel kCostKernel = censusCostKernelPortable;
#endif

// sad+rt: eq. (2) with alpha = 0.2, the SAD mean rescaled to the rank range.
void sadRtVolume(const std::vector<Census>& cl, const std::vector<Census>& cr, const std::vector<cv::Mat>& sadMean,
                 CensusWindow census, CostVolume& vol) {
  const int bits = censusShape(census).bits;
  parallelFor(vol.height, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const Census* l = cl.data() + size_t(y) * vol.width;
      const Census* r = cr.data() + size_t(y) * vol.width;
      fillCostRow(vol.at(0, y), 0, vol.width, vol.depth, maxCost(CostMode::kSadRt, census), [&](int x, int d) {
        const int rt = censusCostOf<CostMode::kRt>(l[x], r[x - d]);
        const int sadOnRankScale = (sadMean[d].at<uint8_t>(y, x) * bits + 127) / 255;
        return (2 * sadOnRankScale + 8 * rt + 5) / 10;
      });
    }
  });
}

// Mean absolute difference (census window, 9x5 or 9x9) per disparity over the window pixels whose
// left and right positions are both inside the image (rounded half up).
std::vector<cv::Mat> sadMeans(const cv::Mat& gl, const cv::Mat& gr, int disparities, CensusWindow census) {
  const int w = gl.cols, h = gl.rows;
  const CensusShape shape = censusShape(census);
  std::vector<cv::Mat> means(disparities);
  parallelFor(disparities, [&](int d0, int d1) {
    cv::Mat integral(h + 1, w + 1, CV_32S);
    for (int d = d0; d < d1; ++d) {
      integral.setTo(0);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int ad = x - d >= 0 ? std::abs(int(gl.at<uint8_t>(y, x)) - int(gr.at<uint8_t>(y, x - d))) : 0;
          integral.at<int>(y + 1, x + 1) = ad + integral.at<int>(y, x + 1) + integral.at<int>(y + 1, x) -
                                           integral.at<int>(y, x);
        }
      cv::Mat mean(h, w, CV_8UC1, cv::Scalar(255));
      for (int y = 0; y < h; ++y)
        for (int x = d; x < w; ++x) {
          const int y0 = std::max(0, y - shape.radiusY), y1 = std::min(h - 1, y + shape.radiusY);
          const int x0 = std::max(d, x - shape.radiusX), x1 = std::min(w - 1, x + shape.radiusX);
          const int sum = integral.at<int>(y1 + 1, x1 + 1) - integral.at<int>(y0, x1 + 1) -
                          integral.at<int>(y1 + 1, x0) + integral.at<int>(y0, x0);
          const int n = (y1 - y0 + 1) * (x1 - x0 + 1);
          mean.at<uint8_t>(y, x) = uint8_t((2 * sum + n) / (2 * n));
        }
      means[d] = mean;
    }
  });
  return means;
}

// Symmetric Birchfield-Tomasi dissimilarity on one pixel, computed in half
// steps (values doubled) and rounded half up at the end.
void birchfieldTomasi(const cv::Mat& gl, const cv::Mat& gr, CostVolume& vol) {
  const int w = gl.cols, h = gl.rows, nd = vol.depth;
  auto range = [w](const uint8_t* row, int x, int& lo, int& hi) {
    const int c = 2 * row[x];
    const int left = row[std::max(x - 1, 0)] + row[x], right = row[std::min(x + 1, w - 1)] + row[x];
    lo = std::min({c, left, right});
    hi = std::max({c, left, right});
  };
  parallelFor(h, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const uint8_t* l = gl.ptr<uint8_t>(y);
      const uint8_t* r = gr.ptr<uint8_t>(y);
      for (int x = 0; x < w; ++x) {
        uint8_t* c = vol.at(x, y);
        int lLo, lHi;
        range(l, x, lLo, lHi);
        for (int d = 0; d < nd; ++d) {
          if (x - d < 0) {
            c[d] = 255;
            continue;
          }
          int rLo, rHi;
          range(r, x - d, rLo, rHi);
          const int il = 2 * l[x], ir = 2 * r[x - d];
          const int dlr = std::max({0, ir - lHi, lLo - ir});
          const int drl = std::max({0, il - rHi, rLo - il});
          c[d] = uint8_t((std::min(dlr, drl) + 1) >> 1);
        }
      }
    }
  });
}

}  // namespace

void censusCostRow(CostMode mode, CensusWindow census, const Census* left, const Census* right, int width, int x0,
                   int x1, int nd, uint8_t* row) {
  if (!isHardwareMode(mode)) throw Error(std::string("cost mode ") + costModeName(mode) + " is not a census mode");
  // The right pixels x0-D+1 .. x1-1, reversed.
  const bool wide = censusShape(census).bits > 64;
  thread_local std::vector<uint64_t> bits, high;
  thread_local std::vector<uint8_t> rank;
  bits.resize(width), high.resize(width), rank.resize(width);
  for (int x = std::max(0, x0 - nd + 1); x < x1; ++x) {
    bits[width - 1 - x] = right[x].bits;
    high[width - 1 - x] = right[x].high;
    rank[width - 1 - x] = uint8_t(right[x].rank());
  }
  kCostKernel(mode, maxCost(mode, census), left, bits.data(), wide ? high.data() : nullptr, rank.data(), width, x0, x1,
              nd, row);
}

void addAdTerm(const cv::Mat& gl, const cv::Mat& gr, int y, int x0, int x1, int nd, int weight, int cap, uint8_t* row) {
  const uint8_t* left = gl.ptr<uint8_t>(y);
  const uint8_t* right = gr.ptr<uint8_t>(y);
  const int largest = (weight * cap) >> kAdShift;
  for (int x = x0; x < x1; ++x) {
    uint8_t* c = row + size_t(x) * nd;
    for (int d = 0; d < nd; ++d) {
      const int term = x - d < 0 ? largest
                                 : (weight * std::min(std::abs(int(left[x]) - int(right[x - d])), cap)) >> kAdShift;
      c[d] = uint8_t(c[d] + term);  // <= costLimit(census) <= 255 (Params::validate)
    }
  }
}

CostVolume computeCost(const cv::Mat& gl, const cv::Mat& gr, CostMode mode, int disparities, CensusWindow census) {
  CostVolume vol(gl.cols, gl.rows, disparities);
  if (mode == CostMode::kBt) {
    birchfieldTomasi(gl, gr, vol);
    return vol;
  }
  if (mode == CostMode::kSad) {
    const std::vector<cv::Mat> means = sadMeans(gl, gr, disparities, census);
    for (int y = 0; y < gl.rows; ++y)
      for (int x = 0; x < gl.cols; ++x)
        for (int d = 0; d < disparities; ++d) vol.at(x, y)[d] = means[d].at<uint8_t>(y, x);
    return vol;
  }
  const std::vector<Census> cl = censusTransform(gl, census), cr = censusTransform(gr, census);
  if (mode == CostMode::kSadRt) {
    sadRtVolume(cl, cr, sadMeans(gl, gr, disparities, census), census, vol);
    return vol;
  }
  parallelFor(gl.rows, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const size_t first = size_t(y) * gl.cols;
      censusCostRow(mode, census, cl.data() + first, cr.data() + first, gl.cols, 0, gl.cols, disparities, vol.at(0, y));
    }
  });
  return vol;
}

}  // namespace sgm
