// SPDX-License-Identifier: Apache-2.0
// sgm_mesh_file.hpp: the rectification meshes' file, mesh.bin (written by sgm-eval calib-mesh
// from an OpenCV stereo calibration; docs/algorithm.md section 13), read into the two meshes
// Driver::loadMeshes takes, and written from them. Header only (C++17, no other dependency);
// the golden model's sgm::encodeMeshFile / decodeMeshFile use the same functions.
//
// The file, little-endian: the 8 bytes "SGMMESH1"; eight uint32: the frame width and height,
// the mesh step's log2 g (G = 2^g px), the position fraction bits (5), the nodes per row, the
// node rows, the rectified frame's focal length f in 1/256 px and the baseline B in
// micrometres; then the left mesh's nodes and the right's, row by row, each an int32 u then an
// int32 v (source position in 1/32 px).
//
//   sgm::driver::MeshFile mesh;
//   const std::string error = sgm::driver::readMeshFile("mesh.bin", &mesh);
//   if (!error.empty()) { std::fprintf(stderr, "%s\n", error.c_str()); return 1; }
//   core.loadMeshes(mesh.left(), mesh.right(), 100000);
//   frame.focalQ8 = mesh.focalQ8, frame.baselineUm = mesh.baselineUm;  // for the depth output
#pragma once

#include "sgm_driver.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace sgm::driver {

inline constexpr char kMeshFileMagic[8] = {'S', 'G', 'M', 'M', 'E', 'S', 'H', '1'};
inline constexpr size_t kMeshFileHeaderWords = 8;
inline constexpr uint32_t kMeshFileFracBits = 5;  // positions in 1/32 px
inline constexpr size_t kMeshFileHeaderBytes = sizeof kMeshFileMagic + 4 * kMeshFileHeaderWords;
inline constexpr uint32_t kMeshFileMaxNodesPerSide = 65535;  // a bound on the header's node counts
inline constexpr size_t kMeshFileMaxBytes = size_t(64) << 20;

// A calibration's two meshes as the file holds them.
struct MeshFile {
  uint32_t width = 0, height = 0, gridLog2 = 0;       // the frame, the step G = 2^gridLog2 px
  uint32_t nodesX = 0, nodesY = 0;                    // nodes per row, node rows (both meshes)
  uint32_t focalQ8 = 0;                               // f, 1/256 px (FrameConfig::focalQ8)
  uint32_t baselineUm = 0;                            // B, micrometres (FrameConfig::baselineUm)
  std::vector<int32_t> leftU, leftV, rightU, rightV;  // nodesX x nodesY each, row by row, 1/32 px

  MeshImage left() const { return MeshImage{nodesX, nodesY, leftU.data(), leftV.data()}; }
  MeshImage right() const { return MeshImage{nodesX, nodesY, rightU.data(), rightV.data()}; }
};

namespace mesh_file_detail {
inline void putWord(std::string& out, uint32_t word) {
  for (int i = 0; i < 4; ++i) out.push_back(char((word >> (8 * i)) & 0xffu));
}
inline uint32_t getWord(const unsigned char* bytes, size_t at) {
  return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
         uint32_t(bytes[at + 3]) << 24;
}
}  // namespace mesh_file_detail

// The file's bytes of `mesh` ("" when its four node arrays do not hold nodesX x nodesY each).
inline std::string formatMeshFile(const MeshFile& mesh) {
  const size_t nodes = size_t(mesh.nodesX) * mesh.nodesY;
  for (const std::vector<int32_t>* a : {&mesh.leftU, &mesh.leftV, &mesh.rightU, &mesh.rightV})
    if (a->size() != nodes) return "";
  std::string out(kMeshFileMagic, sizeof kMeshFileMagic);
  for (uint32_t word : {mesh.width, mesh.height, mesh.gridLog2, kMeshFileFracBits, mesh.nodesX, mesh.nodesY,
                        mesh.focalQ8, mesh.baselineUm})
    mesh_file_detail::putWord(out, word);
  for (const auto& [u, v] : {std::pair{&mesh.leftU, &mesh.leftV}, std::pair{&mesh.rightU, &mesh.rightV}})
    for (size_t i = 0; i < nodes; ++i) {
      mesh_file_detail::putWord(out, uint32_t((*u)[i]));
      mesh_file_detail::putWord(out, uint32_t((*v)[i]));
    }
  return out;
}

// Parses a mesh file's `size` bytes into *out. Returns "" on success, else one line saying what
// is wrong: not a mesh file (its first 8 bytes), positions in another fraction, node counts of
// 0 or beyond kMeshFileMaxNodesPerSide, or a size other than the header announces. It checks
// the format only; Driver::loadMeshes refuses a mesh larger than the core's mesh registers
// hold, and the core's build its own step and line buffer (sgm-eval calib-mesh reports both).
inline std::string parseMeshFile(const void* data, size_t size, MeshFile* out) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  if (size < kMeshFileHeaderBytes || std::memcmp(bytes, kMeshFileMagic, sizeof kMeshFileMagic) != 0)
    return "not a mesh file (no SGMMESH1 header)";
  uint32_t words[kMeshFileHeaderWords];
  for (size_t i = 0; i < kMeshFileHeaderWords; ++i)
    words[i] = mesh_file_detail::getWord(bytes, sizeof kMeshFileMagic + 4 * i);
  if (words[3] != kMeshFileFracBits)
    return "positions in 1/2^" + std::to_string(words[3]) + " px, this driver reads 1/32 px";
  for (size_t i : {4, 5})
    if (words[i] == 0 || words[i] > kMeshFileMaxNodesPerSide)
      return "node count " + std::to_string(words[i]) + " (header field " + std::to_string(i) + ") out of range 1 .. " +
             std::to_string(kMeshFileMaxNodesPerSide);
  const size_t nodes = size_t(words[4]) * words[5];
  const size_t expected = kMeshFileHeaderBytes + 2 * nodes * 8;
  if (size != expected) return std::to_string(size) + " bytes, the header announces " + std::to_string(expected);
  MeshFile mesh;
  mesh.width = words[0], mesh.height = words[1], mesh.gridLog2 = words[2];
  mesh.nodesX = words[4], mesh.nodesY = words[5], mesh.focalQ8 = words[6], mesh.baselineUm = words[7];
  size_t at = kMeshFileHeaderBytes;
  for (const auto& [u, v] : {std::pair{&mesh.leftU, &mesh.leftV}, std::pair{&mesh.rightU, &mesh.rightV}}) {
    u->resize(nodes), v->resize(nodes);
    for (size_t i = 0; i < nodes; ++i, at += 8) {
      (*u)[i] = int32_t(mesh_file_detail::getWord(bytes, at));
      (*v)[i] = int32_t(mesh_file_detail::getWord(bytes, at + 4));
    }
  }
  *out = std::move(mesh);
  return "";
}

// Reads and parses the file at `path`: "" on success, else one line naming the path.
inline std::string readMeshFile(const std::string& path, MeshFile* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot read '" + path + "'";
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0 || size_t(size) > kMeshFileMaxBytes) return path + ": not a mesh file (size)";
  in.seekg(0);
  std::string bytes(size_t(size), '\0');
  if (!in.read(bytes.data(), size)) return "cannot read '" + path + "'";
  const std::string error = parseMeshFile(bytes.data(), bytes.size(), out);
  return error.empty() ? error : path + ": " + error;
}

}  // namespace sgm::driver
