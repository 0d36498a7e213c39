// SPDX-License-Identifier: Apache-2.0
#include "sgm/rectify.hpp"

#include "sgm/image_io.hpp"
#include "sgm/params.hpp"
#include "sgm_mesh_file.hpp"

#include <algorithm>
#include <limits>

namespace sgm {

int meshNodes(int size, int gridLog2) { return ((size - 1) >> gridLog2) + 2; }

void checkMesh(const Mesh& mesh, const std::string& what) {
  if (mesh.width < 2 || mesh.height < 2 || mesh.width > kMaxImageSide || mesh.height > kMaxImageSide)
    throw Error(what + ": frame " + std::to_string(mesh.width) + "x" + std::to_string(mesh.height) + " outside 2 .. " +
                std::to_string(kMaxImageSide) + " a side");
  if (mesh.gridLog2 < kMeshGridLog2Min || mesh.gridLog2 > kMeshGridLog2Max)
    throw Error(what + ": mesh step 2^" + std::to_string(mesh.gridLog2) + " outside 2^" +
                std::to_string(kMeshGridLog2Min) + " .. 2^" + std::to_string(kMeshGridLog2Max));
  if (mesh.nodesX != meshNodes(mesh.width, mesh.gridLog2) || mesh.nodesY != meshNodes(mesh.height, mesh.gridLog2))
    throw Error(what + ": " + std::to_string(mesh.nodesX) + "x" + std::to_string(mesh.nodesY) +
                " nodes, the frame needs " + std::to_string(meshNodes(mesh.width, mesh.gridLog2)) + "x" +
                std::to_string(meshNodes(mesh.height, mesh.gridLog2)));
  const size_t nodes = size_t(mesh.nodesX) * size_t(mesh.nodesY);
  if (mesh.u.size() != nodes || mesh.v.size() != nodes) throw Error(what + ": node arrays do not match the node count");
  for (size_t i = 0; i < nodes; ++i)
    for (int32_t c : {mesh.u[i], mesh.v[i]})
      if (c < kMeshCoordMin || c > kMeshCoordMax)
        throw Error(what + ": node " + std::to_string(i % mesh.nodesX) + "," + std::to_string(i / mesh.nodesX) +
                    " position " + std::to_string(c) + "/32 px outside the 18-bit range");
}

SourcePosition meshPosition(const Mesh& mesh, int x, int y) {
  const int g = mesh.gridLog2;
  const int grid = 1 << g;
  const int j = x >> g, i = y >> g;
  const int64_t fx = x & (grid - 1), fy = y & (grid - 1);
  const size_t n00 = size_t(i) * mesh.nodesX + j, n10 = n00 + 1, n01 = n00 + mesh.nodesX, n11 = n01 + 1;
  const int64_t w00 = (grid - fx) * (grid - fy), w10 = fx * (grid - fy), w01 = (grid - fx) * fy, w11 = fx * fy;
  const int64_t half = int64_t(1) << (2 * g - 1);
  const auto blend = [&](const std::vector<int32_t>& c) {
    const int64_t sum = w00 * c[n00] + w10 * c[n10] + w01 * c[n01] + w11 * c[n11];
    return int32_t((sum + half) >> (2 * g));  // arithmetic shift: floor, so half up
  };
  return {blend(mesh.u), blend(mesh.v)};
}

RectifiedImage rectify(const cv::Mat& source, const Mesh& mesh) {
  if (source.type() != CV_8UC1) throw Error("rectify: the source image must be 8-bit gray");
  if (source.cols != mesh.width || source.rows != mesh.height)
    throw Error("rectify: image " + std::to_string(source.cols) + "x" + std::to_string(source.rows) +
                " but the mesh is for " + std::to_string(mesh.width) + "x" + std::to_string(mesh.height));
  constexpr int one = 1 << kMeshFracBits;
  const int32_t uLast = (mesh.width - 1) * one, vLast = (mesh.height - 1) * one;
  RectifiedImage out{cv::Mat::zeros(mesh.height, mesh.width, CV_8UC1),
                     cv::Mat::zeros(mesh.height, mesh.width, CV_8UC1)};
  for (int y = 0; y < mesh.height; ++y) {
    for (int x = 0; x < mesh.width; ++x) {
      const SourcePosition p = meshPosition(mesh, x, y);
      if (p.u < 0 || p.v < 0 || p.u > uLast || p.v > vLast) continue;
      const int x0 = p.u >> kMeshFracBits, y0 = p.v >> kMeshFracBits;
      const int x1 = std::min(x0 + 1, mesh.width - 1), y1 = std::min(y0 + 1, mesh.height - 1);
      const int ax = p.u & (one - 1), ay = p.v & (one - 1);
      const int sum = (one - ax) * (one - ay) * source.at<uint8_t>(y0, x0) +
                      ax * (one - ay) * source.at<uint8_t>(y0, x1) + (one - ax) * ay * source.at<uint8_t>(y1, x0) +
                      ax * ay * source.at<uint8_t>(y1, x1);
      out.gray.at<uint8_t>(y, x) = uint8_t((sum + (one * one / 2)) >> (2 * kMeshFracBits));
      out.valid.at<uint8_t>(y, x) = 1;
    }
  }
  return out;
}

RowSpan meshRowSpan(const Mesh& mesh) {
  constexpr int one = 1 << kMeshFracBits;
  const int32_t uLast = (mesh.width - 1) * one, vLast = (mesh.height - 1) * one;
  int lag = std::numeric_limits<int>::min(), back = std::numeric_limits<int>::max();
  for (int y = 0; y < mesh.height; ++y) {
    for (int x = 0; x < mesh.width; ++x) {
      const SourcePosition p = meshPosition(mesh, x, y);
      if (p.u < 0 || p.v < 0 || p.u > uLast || p.v > vLast) continue;
      const int y0 = p.v >> kMeshFracBits, y1 = std::min(y0 + 1, mesh.height - 1);
      lag = std::max(lag, y1 - y);
      back = std::min(back, y0 - y);
    }
  }
  if (back > lag) return {};  // no valid pixel
  return {lag, back, lag - back + 1};
}

RowSpan stereoRowSpan(const StereoMesh& mesh) {
  const RowSpan l = meshRowSpan(mesh.left), r = meshRowSpan(mesh.right);
  const int lag = std::max({0, l.lag, r.lag}), back = std::min({lag, l.back, r.back});
  return {lag, back, lag - back + 1};
}

// The file's format is the driver's (sw/include/sgm_mesh_file.hpp): one definition of it.
std::string encodeMeshFile(const StereoMesh& mesh) {
  checkMesh(mesh.left, "left mesh");
  checkMesh(mesh.right, "right mesh");
  const Mesh& l = mesh.left;
  const Mesh& r = mesh.right;
  if (l.width != r.width || l.height != r.height || l.gridLog2 != r.gridLog2)
    throw Error("the left and right meshes differ in frame or step");
  driver::MeshFile file;
  file.width = uint32_t(l.width), file.height = uint32_t(l.height), file.gridLog2 = uint32_t(l.gridLog2);
  file.nodesX = uint32_t(l.nodesX), file.nodesY = uint32_t(l.nodesY);
  file.focalQ8 = mesh.focalQ8, file.baselineUm = mesh.baselineUm;
  file.leftU = l.u, file.leftV = l.v, file.rightU = r.u, file.rightV = r.v;
  return driver::formatMeshFile(file);
}

namespace {

// A parsed file's meshes, checked as every mesh is (the frame, the step, the node counts, the
// coordinates).
StereoMesh meshesOf(driver::MeshFile&& file, const std::string& path) {
  static_assert(driver::kMeshFileFracBits == uint32_t(kMeshFracBits), "the file's fraction is the core's");
  for (uint32_t field : {file.width, file.height, file.gridLog2})
    if (field > uint32_t(kMaxImageSide))
      throw Error(path + ": header field " + std::to_string(field) + " out of range");
  StereoMesh mesh;
  for (Mesh* m : {&mesh.left, &mesh.right}) {
    m->width = int(file.width);
    m->height = int(file.height);
    m->gridLog2 = int(file.gridLog2);
    m->nodesX = int(file.nodesX);
    m->nodesY = int(file.nodesY);
  }
  mesh.left.u = std::move(file.leftU), mesh.left.v = std::move(file.leftV);
  mesh.right.u = std::move(file.rightU), mesh.right.v = std::move(file.rightV);
  mesh.focalQ8 = file.focalQ8;
  mesh.baselineUm = file.baselineUm;
  checkMesh(mesh.left, path + ": left mesh");
  checkMesh(mesh.right, path + ": right mesh");
  return mesh;
}

}  // namespace

StereoMesh decodeMeshFile(const std::string& bytes, const std::string& path) {
  driver::MeshFile file;
  const std::string error = driver::parseMeshFile(bytes.data(), bytes.size(), &file);
  if (!error.empty()) throw Error(path + ": " + error);
  return meshesOf(std::move(file), path);
}

StereoMesh readMeshFile(const std::string& path) {
  driver::MeshFile file;
  const std::string error = driver::readMeshFile(path, &file);
  if (!error.empty()) throw Error(error);
  return meshesOf(std::move(file), path);
}

}  // namespace sgm
