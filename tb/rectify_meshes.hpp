// SPDX-License-Identifier: Apache-2.0
// Meshes of rectification for the testbenches (docs/algorithm.md section 13): smooth random
// source maps (an affine map, a radial term, a row tilt) and the same map pulled towards the
// frame's centre (every position inside the source), in the golden model's fixed point.
#pragma once

#include "sgm/rectify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>

namespace sgm::tb {

// source = A (x, y) + a radial term + a tilt of the rows, in 1/32 px; strength 0 is the
// identity, 1 a few pixels of shift and a few percent of scale, shear, tilt and distortion.
inline Mesh smoothMesh(int w, int h, int gridLog2, double strength, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double scale = 1 + 0.03 * strength * unit(rng), shear = 0.02 * strength * unit(rng);
  const double dx = 2 * strength * unit(rng), dy = 2 * strength * unit(rng), k1 = 0.08 * strength * unit(rng);
  const double tilt = 0.03 * strength * unit(rng);
  Mesh m;
  m.width = w, m.height = h, m.gridLog2 = gridLog2;
  m.nodesX = meshNodes(w, gridLog2), m.nodesY = meshNodes(h, gridLog2);
  const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0, r0 = std::max(w, h) / 2.0;
  for (int i = 0; i < m.nodesY; ++i)
    for (int j = 0; j < m.nodesX; ++j) {
      const double x = j << gridLog2, y = i << gridLog2;
      const double nx = (x - cx) / r0, ny = (y - cy) / r0, radial = 1 + k1 * (nx * nx + ny * ny);
      const double u = cx + (x - cx) * scale * radial + shear * (y - cy) + dx;
      const double v = cy + (y - cy) * scale * radial + tilt * (x - cx) + dy;
      m.u.push_back(int32_t(std::lround(u * 32)));
      m.v.push_back(int32_t(std::lround(v * 32)));
    }
  return m;
}

// The mesh's positions pulled towards the frame's centre by factor (< 1: inside the source).
inline void shrinkMesh(Mesh& m, double factor) {
  const double cx = (m.width - 1) * 16.0, cy = (m.height - 1) * 16.0;  // the centre in 1/32 px
  for (int32_t& u : m.u) u = int32_t(std::lround(cx + (u - cx) * factor));
  for (int32_t& v : m.v) v = int32_t(std::lround(cy + (v - cy) * factor));
}

// A calibration of smooth random meshes (smoothMesh, the left and the right) for w x h frames
// that fits a line buffer of `rows` rows (sgm::lineBufferRows <= rows; the strongest such,
// from `strength` down), each pulled inside the source by `inside` (1: not); lag receives
// the pair's lag (RECTIFY.LAG).
inline std::shared_ptr<StereoMesh> fittingCalibration(int w, int h, int gridLog2, int rows, double strength,
                                                      double inside, std::mt19937& rng, int* lag) {
  for (;; strength *= 0.8) {
    auto mesh = std::make_shared<StereoMesh>();
    mesh->left = smoothMesh(w, h, gridLog2, strength, rng);
    mesh->right = smoothMesh(w, h, gridLog2, strength, rng);
    shrinkMesh(mesh->left, inside), shrinkMesh(mesh->right, inside);
    const RowSpan span = stereoRowSpan(*mesh);
    if (lineBufferRows(span) <= rows) {
      *lag = span.lag;
      return mesh;
    }
  }
}

}  // namespace sgm::tb
