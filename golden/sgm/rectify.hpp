// SPDX-License-Identifier: Apache-2.0
// Rectification in the stream (docs/algorithm.md, section 0): the source position of
// every output pixel is interpolated from a compact mesh of source positions, and the
// output gray is the bilinear interpolation of the four source pixels around it, all in
// integers, bit for bit what sgm_rectify computes. The mesh file format is defined here
// too (the calibration tool writes it, the driver and the harness read it).
#pragma once

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sgm {

// Source positions are in 1/32 px, signed, 18 bits (one ECP5 block RAM word each).
constexpr int kMeshFracBits = 5;
constexpr int kMeshCoordBits = 18;
constexpr int32_t kMeshCoordMax = (1 << (kMeshCoordBits - 1)) - 1;
constexpr int32_t kMeshCoordMin = -(1 << (kMeshCoordBits - 1));
// The mesh step G = 1 << gridLog2 px, 4 .. 64.
constexpr int kMeshGridLog2Min = 2;
constexpr int kMeshGridLog2Max = 6;

// Nodes along a side of `size` pixels: node j sits at pixel j * G; the last pixel
// (size - 1) lies between node (size - 1) >> gridLog2 and the one after it.
int meshNodes(int size, int gridLog2);

// One image's mesh: the source position (u, v) of output pixel (j G, i G) at u[i * nodesX + j].
struct Mesh {
  int width = 0, height = 0;  // the frame, the same in and out
  int gridLog2 = 4;
  int nodesX = 0, nodesY = 0;
  std::vector<int32_t> u, v;  // 1/32 px
};

// Throws Error (naming `what`) unless the mesh is consistent: sizes, step, node counts,
// every coordinate within kMeshCoordMin .. kMeshCoordMax.
void checkMesh(const Mesh& mesh, const std::string& what);

// The source position of output pixel (x, y), in 1/32 px: the bilinear interpolation of
// the four nodes around it, rounded half up: (sum of weight x node + G^2 / 2) >> 2 gridLog2.
struct SourcePosition {
  int32_t u, v;
};
SourcePosition meshPosition(const Mesh& mesh, int x, int y);

// The rectified image: gray (CV_8UC1) and valid (CV_8UC1, 1 = the source position lies
// within the source image, 0 = outside, gray 0).
struct RectifiedImage {
  cv::Mat gray, valid;
};
RectifiedImage rectify(const cv::Mat& source, const Mesh& mesh);

// The line buffer a mesh needs: output row y reads source rows y + back .. y + lag (over
// the valid output pixels), so a buffer of rows = lag - back + 1 source rows, written
// lag rows ahead of the output row, holds every row it reads.
struct RowSpan {
  int lag = 0, back = 0, rows = 1;
};
RowSpan meshRowSpan(const Mesh& mesh);

// A stereo pair's meshes and the depth parameters of its rectified frame.
struct StereoMesh {
  Mesh left, right;
  uint32_t focalQ8 = 0;     // focal length of the rectified frame, 1/256 px
  uint32_t baselineUm = 0;  // baseline, micrometres
};

// The line buffer of a pair in the core: one lag for both images (the larger, at least 0)
// and the rows from the smaller back, rows = lag - back + 1; the core's buffer of R rows
// also holds the row being written, so the pair needs R >= lineBufferRows = rows + 1.
RowSpan stereoRowSpan(const StereoMesh& mesh);
inline int lineBufferRows(const RowSpan& span) { return span.rows + 1; }

// The mesh file (little-endian): "SGMMESH1", then uint32 width, height, gridLog2,
// fracBits (5), nodesX, nodesY, focalQ8, baselineUm, then the left mesh's nodes and the
// right's, row by row, each node int32 u then int32 v (1/32 px).
std::string encodeMeshFile(const StereoMesh& mesh);
StereoMesh decodeMeshFile(const std::string& bytes, const std::string& path);
StereoMesh readMeshFile(const std::string& path);

}  // namespace sgm
