// SPDX-License-Identifier: Apache-2.0
// Bit-exact comparison of the golden pipeline with a deliberately naive,
// independent implementation of docs/algorithm.md (sections 2 to 9, 8b), on small
// random images, for every cost mode and several parameter sets. Catches
// divergence between the optimised / streaming code paths and the contract
// (runPipeline streams rows, runPipelineStages builds full volumes).
#include "sgm/disparity.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <random>
#include <sstream>

namespace {

using sgm::CostMode;

// ------------------------------------------------------------------ naive model

struct Img {
  int w, h;
  std::vector<int> v;
  int at(int x, int y) const { return v[size_t(y) * w + x]; }
};

Img fromMat(const cv::Mat& m) {
  Img i{m.cols, m.rows, {}};
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) i.v.push_back(m.at<uint8_t>(y, x));
  return i;
}

// Census as a list of 44 bools (9x5 window), bit order of section 2.
std::vector<bool> census(const Img& im, int x, int y) {
  std::vector<bool> bits;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -4; dx <= 4; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const int qx = x + dx, qy = y + dy;
      const bool inside = qx >= 0 && qy >= 0 && qx < im.w && qy < im.h;
      bits.push_back(inside && im.at(qx, qy) < im.at(x, y));
    }
  return bits;
}

int popcount(const std::vector<bool>& b) { return int(std::count(b.begin(), b.end(), true)); }

int hamming(const std::vector<bool>& a, const std::vector<bool>& b) {
  int n = 0;
  for (size_t k = 0; k < a.size(); ++k) n += a[k] != b[k];
  return n;
}

int sadMean(const Img& l, const Img& r, int x, int y, int d) {
  int sum = 0, n = 0;
  for (int qy = y - 2; qy <= y + 2; ++qy)
    for (int qx = x - 4; qx <= x + 4; ++qx) {
      if (qy < 0 || qy >= l.h || qx < 0 || qx >= l.w || qx - d < 0) continue;
      sum += std::abs(l.at(qx, qy) - r.at(qx - d, qy));
      ++n;
    }
  return (2 * sum + n) / (2 * n);  // round half up
}

int birchfieldTomasi(const Img& l, const Img& r, int x, int y, int d) {
  // Doubled values: the half-sample interval around pixel x of row `im`.
  auto interval = [](const Img& im, int px, int py, int& lo, int& hi) {
    const int c = 2 * im.at(px, py);
    const int left = im.at(std::max(px - 1, 0), py) + im.at(px, py);
    const int right = im.at(std::min(px + 1, im.w - 1), py) + im.at(px, py);
    lo = std::min({c, left, right});
    hi = std::max({c, left, right});
  };
  int lLo, lHi, rLo, rHi;
  interval(l, x, y, lLo, lHi);
  interval(r, x - d, y, rLo, rHi);
  const int il = 2 * l.at(x, y), ir = 2 * r.at(x - d, y);
  const int dLeft = std::max({0, il - rHi, rLo - il});   // left pixel vs right interval
  const int dRight = std::max({0, ir - lHi, lLo - ir});  // right pixel vs left interval
  return (std::min(dLeft, dRight) + 1) / 2;
}

struct Reference {
  int w, h, nd;
  std::vector<int> cost, sum;  // [y][x][d]
  std::vector<int> selDisp, selValid, fillDisp, fillValid, snapDisp, outDisp, outValid;
  int& C(int x, int y, int d) { return cost[(size_t(y) * w + x) * nd + d]; }
  int& S(int x, int y, int d) { return sum[(size_t(y) * w + x) * nd + d]; }
};

Reference referencePipeline(const cv::Mat& lm, const cv::Mat& rm, const sgm::Params& p) {
  const Img l = fromMat(lm), r = fromMat(rm);
  const int w = l.w, h = l.h, nd = p.disparities;
  Reference ref{
      w,  h,  nd, std::vector<int>(size_t(w) * h * nd), std::vector<int>(size_t(w) * h * nd, 0), {}, {}, {}, {},
      {}, {}, {}};
  const int cmax = p.mode == CostMode::kUnified ? 88 : p.mode == CostMode::kSad || p.mode == CostMode::kBt ? 255 : 44;
  // Section 3: C(p, d).
  std::vector<std::vector<bool>> cl, cr;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) cl.push_back(census(l, x, y)), cr.push_back(census(r, x, y));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = 0; d < nd; ++d) {
        if (x - d < 0) {
          ref.C(x, y, d) = cmax;
          continue;
        }
        const auto& a = cl[size_t(y) * w + x];
        const auto& b = cr[size_t(y) * w + x - d];
        const int rt = std::abs(popcount(a) - popcount(b)), rsad = hamming(a, b);
        int c = 0;
        switch (p.mode) {
          case CostMode::kRt: c = rt; break;
          case CostMode::kRsad: c = rsad; break;
          case CostMode::kUnified: c = rt + rsad; break;
          case CostMode::kSad: c = sadMean(l, r, x, y, d); break;
          case CostMode::kBt: c = birchfieldTomasi(l, r, x, y, d); break;
          case CostMode::kSadRt: c = (2 * ((sadMean(l, r, x, y, d) * 44 + 127) / 255) + 8 * rt + 5) / 10; break;
        }
        ref.C(x, y, d) = c;
      }
  // Sections 4 and 5: four paths, summed with weights 3, 2, 3, 2.
  const int dirs[4][3] = {{-1, 0, 3}, {-1, -1, 2}, {0, -1, 3}, {1, -1, 2}};  // dx, dy, weight
  for (const auto& dir : dirs) {
    std::vector<int> lr(size_t(w) * h * nd);
    auto L = [&](int x, int y, int d) -> int& { return lr[(size_t(y) * w + x) * nd + d]; };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int px = x + dir[0], py = y + dir[1];
        if (px < 0 || px >= w || py < 0) {
          for (int d = 0; d < nd; ++d) L(x, y, d) = ref.C(x, y, d);
        } else {
          int m = 1 << 30;
          for (int d = 0; d < nd; ++d) m = std::min(m, L(px, py, d));
          const int di = std::abs(l.at(x, y) - l.at(px, py));
          const int p2r = std::max(p.p1, 4 * p.p2 / (di + 4));
          for (int d = 0; d < nd; ++d) {
            int best = std::min(L(px, py, d), m + p2r);
            if (d > 0) best = std::min(best, L(px, py, d - 1) + p.p1);
            if (d < nd - 1) best = std::min(best, L(px, py, d + 1) + p.p1);
            L(x, y, d) = ref.C(x, y, d) + best - m;
          }
        }
        for (int d = 0; d < nd; ++d) ref.S(x, y, d) += dir[2] * L(x, y, d);
      }
  }
  // Sections 6 and 7.
  auto argminS = [&](int x, int y) {
    int best = 0;
    for (int d = 1; d < nd; ++d)
      if (ref.S(x, y, d) < ref.S(x, y, best)) best = d;
    return best;
  };
  auto rightD = [&](int xr, int y) {
    int best = 0;
    for (int d = 1; d <= std::min(nd - 1, w - 1 - xr); ++d)
      if (ref.S(xr + d, y, d) < ref.S(xr + best, y, best)) best = d;
    return best;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int d = argminS(x, y);
      int disp = 16 * d;
      if (p.subpixel && d > 0 && d < nd - 1) {
        const int a = ref.S(x, y, d - 1), m = ref.S(x, y, d), b = ref.S(x, y, d + 1);
        const int den = a + b - 2 * m, num = a - b;
        if (den > 0) {
          const int q = (std::abs(num) * 16 + den) / (2 * den);
          disp += num < 0 ? -q : q;
        }
      }
      bool valid = true;
      if (p.lrTolerance >= 0) valid = x - d >= 0 && std::abs(rightD(x - d, y) - d) <= p.lrTolerance;
      ref.selDisp.push_back(disp);
      ref.selValid.push_back(valid);
    }
  // Section 8.
  ref.fillDisp = ref.selDisp;
  ref.fillValid = ref.selValid;
  if (p.fill)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        if (ref.selValid[i]) continue;
        int left = -1, right = -1;
        for (int q = x - 1; q >= 0 && left < 0; --q)
          if (ref.selValid[size_t(y) * w + q]) left = ref.selDisp[size_t(y) * w + q];
        for (int q = x + 1; q < w && right < 0; ++q)
          if (ref.selValid[size_t(y) * w + q]) right = ref.selDisp[size_t(y) * w + q];
        if (left < 0 && right < 0) continue;
        const int own = ref.selDisp[i];
        if ((left >= 0 && std::abs(own - left) <= 16) || (right >= 0 && std::abs(own - right) <= 16))
          ref.fillDisp[i] = own;
        else
          ref.fillDisp[i] = left < 0 ? right : right < 0 ? left : std::min(left, right);
        ref.fillValid[i] = 1;
      }
  // Section 8b: pixel x takes d(e+1) of the nearest drop e >= x whose edge k(e) <= x.
  ref.snapDisp = ref.fillDisp;
  if (p.snap)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        auto d = [&](int q) { return ref.fillDisp[size_t(y) * w + q]; };
        auto v = [&](int q) { return ref.fillValid[size_t(y) * w + q] != 0; };
        auto step = [&](int k) { return std::abs(l.at(k, y) - l.at(k - 1, y)); };
        if (!v(x)) continue;
        for (int e = x; e <= std::min(x + 2, w - 2); ++e) {
          if (!v(e) || !v(e + 1) || d(e) - d(e + 1) <= 32) continue;
          int edge = e + 1;
          for (int k = e + 1; k >= std::max(1, e - 2); --k)
            if (step(k) > step(edge)) edge = k;
          if (edge <= x) {
            ref.snapDisp[size_t(y) * w + x] = d(e + 1);
            break;
          }
        }
      }
  // Section 9.
  ref.outDisp = ref.snapDisp;
  ref.outValid = ref.fillValid;
  if (p.median)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!ref.fillValid[size_t(y) * w + x] || y >= h - 2) continue;  // the last two rows pass through
        std::vector<int> win;
        for (int qy = std::max(0, y - 2); qy <= std::min(h - 1, y + 2); ++qy)
          for (int qx = std::max(0, x - 2); qx <= std::min(w - 1, x + 2); ++qx)
            if (ref.fillValid[size_t(qy) * w + qx]) win.push_back(ref.snapDisp[size_t(qy) * w + qx]);
        std::sort(win.begin(), win.end());
        ref.outDisp[size_t(y) * w + x] = win[(win.size() - 1) / 2];
      }
  return ref;
}

// ------------------------------------------------------------------ comparison

// Textured test pair: blocks at two disparities plus noise, so that the LR
// check, the fill, the edge snap and the median all have work to do.
std::pair<cv::Mat, cv::Mat> testPair(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  cv::Mat wide(h, w + 16, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w + 16; ++x) wide.at<uint8_t>(y, x) = uint8_t(rng() % 4 * 60 + rng() % 8);
  cv::Mat left = wide(cv::Rect(0, 0, w, h)).clone(), right(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int shift = x > w / 2 && x < w * 3 / 4 ? 5 : 2;  // a block in front: a rise and a drop
      right.at<uint8_t>(y, x) = wide.at<uint8_t>(y, std::min(x + shift, w + 15));
    }
  // A few flat areas (many ties) and noise in the right image.
  left(cv::Rect(w / 4, h / 3, 6, 5)).setTo(100);
  for (int i = 0; i < w * h / 20; ++i) right.at<uint8_t>(int(rng() % h), int(rng() % w)) = uint8_t(rng() % 256);
  return {left, right};
}

std::vector<int> flat(const cv::Mat& m) {
  std::vector<int> v;
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) v.push_back(m.depth() == CV_16U ? m.at<uint16_t>(y, x) : m.at<uint8_t>(y, x));
  return v;
}

// Index of the first difference, for a readable failure message.
std::string firstDiff(const std::vector<int>& a, const std::vector<int>& b, int w, int depth = 1) {
  if (a.size() != b.size()) return "size " + std::to_string(a.size()) + " vs " + std::to_string(b.size());
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) {
      std::ostringstream s;
      const size_t pix = i / depth;
      s << "first difference at x=" << pix % w << " y=" << pix / w;
      if (depth > 1) s << " d=" << i % depth;
      s << ": golden " << a[i] << " vs reference " << b[i];
      return s.str();
    }
  return "equal";
}

struct Case {
  CostMode mode;
  int w, h, d, p1, p2, lr;
  bool subpixel, fill, median;
  bool snap = true;
};

std::string caseName(const Case& c) {
  std::ostringstream s;
  s << sgm::costModeName(c.mode) << "_" << c.w << "x" << c.h << "_D" << c.d << "_P" << c.p1 << "_" << c.p2 << "_lr"
    << c.lr << (c.subpixel ? "_sub" : "") << (c.fill ? "_fill" : "") << (c.snap ? "_snap" : "")
    << (c.median ? "_med" : "");
  std::string n = s.str();
  for (char& ch : n)
    if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

void PrintTo(const Case& c, std::ostream* os) { *os << caseName(c); }

class ReferenceModel : public testing::TestWithParam<Case> {};

TEST_P(ReferenceModel, GoldenMatchesTheNaiveContract) {
  const Case c = GetParam();
  sgm::Params p = sgm::presetParams("four-path");  // the naive contract: four paths, no AD term or uniqueness
  p.mode = c.mode;
  p.disparities = c.d;
  p.p1 = c.p1;
  p.p2 = c.p2;
  p.lrTolerance = c.lr;
  p.subpixel = c.subpixel;
  p.fill = c.fill;
  p.snap = c.snap;
  p.median = c.median;
  const auto [left, right] = testPair(c.w, c.h, 1000u + unsigned(c.w * 31 + c.d));
  const Reference ref = referencePipeline(left, right, p);

  const sgm::PipelineStages st = sgm::runPipelineStages(left, right, p);
  const std::vector<int> cost(st.cost.data.begin(), st.cost.data.end());
  EXPECT_TRUE(cost == ref.cost) << "cost: " << firstDiff(cost, ref.cost, c.w, c.d);
  const std::vector<int> sum(st.aggregated.data.begin(), st.aggregated.data.end());
  EXPECT_TRUE(sum == ref.sum) << "S: " << firstDiff(sum, ref.sum, c.w, c.d);
  EXPECT_TRUE(flat(st.selected.disp) == ref.selDisp)
      << "selected: " << firstDiff(flat(st.selected.disp), ref.selDisp, c.w);
  EXPECT_TRUE(flat(st.selected.valid) == ref.selValid)
      << "selected valid: " << firstDiff(flat(st.selected.valid), ref.selValid, c.w);
  EXPECT_TRUE(flat(st.filled.disp) == ref.fillDisp) << "filled: " << firstDiff(flat(st.filled.disp), ref.fillDisp, c.w);
  EXPECT_TRUE(flat(st.filled.valid) == ref.fillValid);
  EXPECT_TRUE(flat(st.snapped.disp) == ref.snapDisp)
      << "snapped: " << firstDiff(flat(st.snapped.disp), ref.snapDisp, c.w);
  EXPECT_TRUE(flat(st.result.disp) == ref.outDisp) << "result: " << firstDiff(flat(st.result.disp), ref.outDisp, c.w);
  EXPECT_TRUE(flat(st.result.valid) == ref.outValid);

  // The streaming runPipeline must produce the very same map.
  const sgm::DisparityMap direct = sgm::runPipeline(left, right, p);
  EXPECT_TRUE(flat(direct.disp) == ref.outDisp) << "runPipeline: " << firstDiff(flat(direct.disp), ref.outDisp, c.w);
  EXPECT_TRUE(flat(direct.valid) == ref.outValid)
      << "runPipeline valid: " << firstDiff(flat(direct.valid), ref.outValid, c.w);

  // Sanity: the case exercises the post-processing stages.
  if (c.lr >= 0 && c.d >= 8) {
    EXPECT_GT(std::count(ref.selValid.begin(), ref.selValid.end(), 0), 0) << "no invalid pixel in this case";
  }
  if (c.snap && c.d >= 16) {
    EXPECT_NE(ref.snapDisp, ref.fillDisp) << "no pixel snapped in this case";
  }
}

const Case kCases[] = {
    // mode               w   h   D   P1  P2     lr  sub    fill   median
    {CostMode::kUnified, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kRt, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kRsad, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kSad, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kBt, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kSadRt, 41, 23, 16, 7, 100, 1, true, true, true},
    {CostMode::kUnified, 37, 19, 8, 3, 40, 0, false, true, true},
    {CostMode::kRsad, 37, 19, 8, 0, 0, -1, true, false, false},
    {CostMode::kUnified, 12, 10, 20, 7, 100, 2, true, true, true},  // D > W
    {CostMode::kUnified, 9, 9, 2, 7, 100, 1, true, true, true},     // smallest image and D
    // Largest penalties (P1 = P2' = kMaxPenalty): S <= 10 (88 + 6000) = 60880. The map
    // comes out too smooth for a drop of more than 2 px, so snap is off here; the other
    // D >= 16 cases with snap on check that some pixel snaps.
    {CostMode::kUnified, 50, 12, 32, 6000, 6000, 1, true, true, true, false},
    {CostMode::kRt, 50, 12, 32, 1, 6000, 3, true, false, true},
    {CostMode::kRsad, 70, 14, 24, 10, 200, 1, true, true, true},           // several 16-lane median blocks
    {CostMode::kRsad, 41, 23, 16, 7, 100, 1, true, true, true, false},     // fill without snap
    {CostMode::kRsad, 41, 23, 16, 7, 100, -1, false, false, false, true},  // snap alone
};

INSTANTIATE_TEST_SUITE_P(Cases, ReferenceModel, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return caseName(info.param); });

// ------------------------------------------------------------------ kernels on wider rows

TEST(ReferenceKernels, MedianOnWideRandomMap) {
  std::mt19937 rng(3);
  const int w = 53, h = 17;
  sgm::DisparityMap in{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      in.disp.at<uint16_t>(y, x) = uint16_t(rng() % 4089);
      in.valid.at<uint8_t>(y, x) = rng() % 3 != 0;
    }
  const sgm::DisparityMap out = sgm::median5x5(in);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!in.valid.at<uint8_t>(y, x) || y >= h - 2) {  // invalid, or one of the last two rows: passed through
        ASSERT_EQ(out.disp.at<uint16_t>(y, x), in.disp.at<uint16_t>(y, x)) << "x=" << x << " y=" << y;
        ASSERT_EQ(out.valid.at<uint8_t>(y, x), in.valid.at<uint8_t>(y, x)) << "x=" << x << " y=" << y;
        continue;
      }
      std::vector<int> win;
      for (int qy = std::max(0, y - 2); qy <= std::min(h - 1, y + 2); ++qy)
        for (int qx = std::max(0, x - 2); qx <= std::min(w - 1, x + 2); ++qx)
          if (in.valid.at<uint8_t>(qy, qx)) win.push_back(in.disp.at<uint16_t>(qy, qx));
      std::sort(win.begin(), win.end());
      ASSERT_EQ(out.disp.at<uint16_t>(y, x), win[(win.size() - 1) / 2]) << "x=" << x << " y=" << y;
      ASSERT_EQ(out.valid.at<uint8_t>(y, x), 1);
    }
}

TEST(ReferenceKernels, WinnerTakeAllAndRightDisparityOnRandomVolumes) {
  std::mt19937 rng(4);
  for (int nd : {2, 3, 17, 64, 256}) {
    const int w = 30, h = 2;
    sgm::PathVolume s(w, h, nd);
    for (auto& v : s.data) v = uint16_t(rng() % 6 == 0 ? 65535 : rng() % 40);  // many ties, large values
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint16_t* sp = s.at(x, y);
        int best = 0;
        for (int d = 1; d < nd; ++d)
          if (sp[d] < sp[best]) best = d;
        ASSERT_EQ(sgm::winnerTakeAll(sp, nd), best) << "D=" << nd;
        int rbest = 0;
        for (int d = 1; d <= std::min(nd - 1, w - 1 - x); ++d)
          if (s.at(x + d, y)[d] < s.at(x + rbest, y)[rbest]) rbest = d;
        ASSERT_EQ(sgm::rightDisparity(s, x, y), rbest) << "D=" << nd << " xr=" << x;
      }
  }
}

}  // namespace
