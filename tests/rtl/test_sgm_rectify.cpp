// SPDX-License-Identifier: Apache-2.0
// sgm_rectify against the golden sgm::rectify (docs/algorithm.md section 13): random smooth
// meshes (an affine map, a radial term, a row tilt) loaded through the mesh port into the
// copy not in use and swapped in at a start of frame, source frames streamed with random
// gaps and the output taken with random back-pressure, frames of several sizes back to
// back; every output pixel's gray and outside flag against the golden model, tuser and
// tlast, row_miss_o quiet while the calibration fits the build's ROWS and raised when it
// does not. The build's parameters come from the model.
#include "Vsgm_rectify.h"
#include "Vsgm_rectify_sgm_rectify.h"
#include "verilated_top.hpp"

#include "sgm/rectify.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <cmath>
#include <random>
#include <string>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_rectify>;
using Rtl = Vsgm_rectify_sgm_rectify;

constexpr int kRows = int(Rtl::ROWS);
constexpr int kGridLog2 = int(Rtl::GRID_LOG2);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kMaxHeight = int(Rtl::MAX_HEIGHT);

// A smooth mesh: source = A (x, y) + a radial term + a tilt of the rows, in 1/32 px.
sgm::Mesh randomMesh(int w, int h, double strength, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double scale = 1 + 0.03 * strength * unit(rng), shear = 0.02 * strength * unit(rng);
  const double dx = 2 * strength * unit(rng), dy = 2 * strength * unit(rng), k1 = 0.08 * strength * unit(rng);
  const double tilt = 0.03 * strength * unit(rng);
  sgm::Mesh m;
  m.width = w, m.height = h, m.gridLog2 = kGridLog2;
  m.nodesX = sgm::meshNodes(w, kGridLog2), m.nodesY = sgm::meshNodes(h, kGridLog2);
  const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0, r0 = std::max(w, h) / 2.0;
  for (int i = 0; i < m.nodesY; ++i)
    for (int j = 0; j < m.nodesX; ++j) {
      const double x = j << kGridLog2, y = i << kGridLog2;
      const double nx = (x - cx) / r0, ny = (y - cy) / r0, radial = 1 + k1 * (nx * nx + ny * ny);
      const double u = cx + (x - cx) * scale * radial + shear * (y - cy) + dx;
      const double v = cy + (y - cy) * scale * radial + tilt * (x - cx) + dy;
      m.u.push_back(int32_t(std::lround(u * 32)));
      m.v.push_back(int32_t(std::lround(v * 32)));
    }
  return m;
}

cv::Mat texture(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng());
  return img;
}

void loadMesh(Top& top, const sgm::Mesh& m) {
  for (int i = 0; i < m.nodesY; ++i)
    for (int j = 0; j < m.nodesX; ++j) {
      top->mesh_we_i = 1;
      top->mesh_row_i = uint32_t(i);
      top->mesh_col_i = uint32_t(j);
      top->mesh_u_i = uint32_t(m.u[size_t(i) * m.nodesX + j]) & 0x3ffffu;
      top->mesh_v_i = uint32_t(m.v[size_t(i) * m.nodesX + j]) & 0x3ffffu;
      top.tick();
    }
  top->mesh_we_i = 0;
  top->mesh_swap_i = 1;
  top.tick();
  top->mesh_swap_i = 0;
}

struct Frame {
  cv::Mat source;
  sgm::Mesh mesh;
  int lag;
  std::string name;
};

struct Result {
  std::string mismatch;  // "" when every pixel matched
  long cycles = 0;
  bool rowMiss = false;
};

// Streams the frame (its mesh already swapped in at this start of frame) and checks the output.
Result runFrame(Top& top, const Frame& f, std::mt19937& rng, double gap, double stall, bool check = true) {
  const int w = f.source.cols, h = f.source.rows;
  const sgm::RectifiedImage want = sgm::rectify(f.source, f.mesh);
  top->width_i = uint32_t(w);
  top->height_i = uint32_t(h);
  top->lag_i = uint32_t(f.lag);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long in = 0, out = 0;
  const long pixels = long(w) * h;
  Result r;
  const long limit = pixels * 20 + 100000;
  for (long cycle = 0; out < pixels; ++cycle) {
    if (cycle > limit) {
      r.mismatch = f.name + ": stalled after " + std::to_string(out) + " of " + std::to_string(pixels) + " pixels";
      return r;
    }
    const bool offer = in < pixels && unit(rng) >= gap;
    top->s_tvalid_i = offer;
    top->s_tdata_i = offer ? f.source.at<uint8_t>(int(in / w), int(in % w)) : uint8_t(rng());
    top->s_tuser_i = offer && in == 0;
    top->s_tlast_i = offer && in % w == w - 1;
    top->m_tready_i = unit(rng) >= stall;
    top->eval();
    const bool took = offer && top->s_tready_o;
    if (top->m_tvalid_o && top->m_tready_i) {
      const int y = int(out / w), x = int(out % w);
      const int gray = want.gray.at<uint8_t>(y, x), outside = want.valid.at<uint8_t>(y, x) ? 0 : 1;
      const std::string where = f.name + " stage sgm_rectify pixel (x=" + std::to_string(x) +
                                ", y=" + std::to_string(y) + ")";
      if (check && r.mismatch.empty()) {
        if (int(top->m_tdata_o) != gray || int(top->m_outside_o) != outside)
          r.mismatch = where + ": expected gray " + std::to_string(gray) + " outside " + std::to_string(outside) +
                       ", got " + std::to_string(int(top->m_tdata_o)) + " outside " +
                       std::to_string(int(top->m_outside_o));
      }
      if (r.mismatch.empty() && (bool(top->m_tuser_o) != (out == 0) || bool(top->m_tlast_o) != (x == w - 1)))
        r.mismatch = where + ": tuser " + std::to_string(int(top->m_tuser_o)) + " tlast " +
                     std::to_string(int(top->m_tlast_o));
      ++out;
    }
    top.tick();
    if (took) ++in;
    r.rowMiss = r.rowMiss || top->row_miss_o;
    ++r.cycles;
  }
  top->s_tvalid_i = 0;
  return r;
}

// A frame whose mesh fits the build (rows + 1 <= ROWS), or the strongest that does.
Frame fittingFrame(int w, int h, double strength, std::mt19937& rng, const std::string& name) {
  for (;;) {
    Frame f{texture(w, h, rng), randomMesh(w, h, strength, rng), 0, name};
    const sgm::RowSpan span = sgm::meshRowSpan(f.mesh);
    if (span.rows + 1 <= kRows && span.lag >= 0) {
      f.lag = span.lag;
      return f;
    }
    strength *= 0.8;
  }
}

// Inputs quiet (the model's ports start random), then reset.
void start(Top& top) {
  top->s_tvalid_i = 0, top->s_tuser_i = 0, top->s_tlast_i = 0, top->m_tready_i = 1;
  top->mesh_we_i = 0, top->mesh_swap_i = 0;
  top->width_i = kMaxWidth, top->height_i = kMaxHeight, top->lag_i = 0;
  top.reset();
}

class SgmRectify : public testing::Test {};

TEST_F(SgmRectify, FramesBackToBackEveryPixelAgainstTheGoldenModel) {
  Top top("sgm_rectify_frames");
  start(top);
  std::mt19937 rng(11);
  const int sizes[][2] = {
      {kMaxWidth, kMaxHeight}, {kMaxWidth - 3, kMaxHeight / 2 + 1}, {17, 9}, {kMaxWidth / 2 + 5, 24}};
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& size : sizes) {
      const double gap = pass ? 0.3 : 0.0, stall = pass ? 0.3 : 0.0;
      const Frame f = fittingFrame(size[0], size[1], 1.0 + pass, rng,
                                   std::to_string(size[0]) + "x" + std::to_string(size[1]) + (pass ? " stalls" : ""));
      loadMesh(top, f.mesh);
      const Result r = runFrame(top, f, rng, gap, stall);
      EXPECT_EQ(r.mismatch, "");
      EXPECT_FALSE(r.rowMiss) << f.name << ": row_miss_o with a calibration that fits";
      if (!pass && size[0] == kMaxWidth)
        std::cout << "[ figures  ] " << f.name << " lag " << f.lag << ": " << double(r.cycles) / (size[0] * size[1])
                  << " cycles per pixel without stalls\n";
    }
}

TEST_F(SgmRectify, MeshSwapsOnlyAtTheStartOfFrame) {
  Top top("sgm_rectify_swap");
  start(top);
  std::mt19937 rng(5);
  Frame a = fittingFrame(kMaxWidth, 20, 1.0, rng, "mesh A");
  Frame b = fittingFrame(kMaxWidth, 20, 1.0, rng, "mesh B");
  b.lag = std::max(a.lag, b.lag), a.lag = b.lag;
  loadMesh(top, a.mesh);
  // Mesh B is written while frame A runs: frame A must still use A, the next frame B.
  Frame first = a;
  first.name = "frame under mesh A, B written meanwhile";
  {
    const int nodes = b.mesh.nodesX * b.mesh.nodesY;
    int written = 0;
    top->width_i = kMaxWidth, top->height_i = 20, top->lag_i = uint32_t(a.lag);
    // Interleave the writes with the frame: one node per cycle from the frame's start on.
    const sgm::RectifiedImage want = sgm::rectify(first.source, a.mesh);
    long in = 0, out = 0;
    const long pixels = long(kMaxWidth) * 20;
    while (out < pixels) {
      top->s_tvalid_i = in < pixels;
      top->s_tdata_i = in < pixels ? first.source.at<uint8_t>(int(in / kMaxWidth), int(in % kMaxWidth)) : 0;
      top->s_tuser_i = in == 0;
      top->s_tlast_i = in % kMaxWidth == kMaxWidth - 1;
      top->m_tready_i = 1;
      top->mesh_we_i = written < nodes;
      if (written < nodes) {
        top->mesh_row_i = uint32_t(written / b.mesh.nodesX), top->mesh_col_i = uint32_t(written % b.mesh.nodesX);
        top->mesh_u_i = uint32_t(b.mesh.u[size_t(written)]) & 0x3ffffu;
        top->mesh_v_i = uint32_t(b.mesh.v[size_t(written)]) & 0x3ffffu;
      }
      top->mesh_swap_i = written == nodes;
      top->eval();
      const bool took = top->s_tvalid_i && top->s_tready_o;
      if (top->m_tvalid_o) {
        const int y = int(out / kMaxWidth), x = int(out % kMaxWidth);
        ASSERT_EQ(int(top->m_tdata_o), int(want.gray.at<uint8_t>(y, x))) << "frame A at (" << x << ", " << y << ")";
        ++out;
      }
      top.tick();
      if (took) ++in;
      if (written <= nodes) ++written;
      ASSERT_EQ(bool(top->mesh_swap_pending_o), written > nodes)
          << "swap pending after the request only, written " << written << " of " << nodes << ", in " << in << ", out "
          << out;
    }
    top->mesh_we_i = 0, top->mesh_swap_i = 0, top->s_tvalid_i = 0;
  }
  b.name = "frame after the swap: mesh B";
  const Result r = runFrame(top, b, rng, 0.1, 0.1);
  EXPECT_EQ(r.mismatch, "");
  EXPECT_FALSE(top->mesh_swap_pending_o);
}

TEST_F(SgmRectify, RowMissWhenTheCalibrationNeedsMoreRows) {
  Top top("sgm_rectify_miss");
  start(top);
  std::mt19937 rng(9);
  // A vertical squeeze: the bottom rows read far behind (back much below lag + 2 - ROWS).
  Frame f{texture(kMaxWidth, kMaxHeight, rng), randomMesh(kMaxWidth, kMaxHeight, 0.0, rng), 0, "squeezed rows"};
  for (int32_t& v : f.mesh.v) v = v / 2;
  const sgm::RowSpan span = sgm::meshRowSpan(f.mesh);
  ASSERT_GT(span.rows + 1, kRows) << "the test mesh must not fit";
  f.lag = std::max(0, span.lag);
  loadMesh(top, f.mesh);
  const Result r = runFrame(top, f, rng, 0.0, 0.0, false);
  EXPECT_TRUE(r.rowMiss);
  // The next frame starts clean.
  Frame g = fittingFrame(kMaxWidth, 12, 1.0, rng, "after the miss");
  loadMesh(top, g.mesh);
  const Result after = runFrame(top, g, rng, 0.0, 0.0);
  EXPECT_EQ(after.mismatch, "");
  EXPECT_FALSE(after.rowMiss);
}

}  // namespace
