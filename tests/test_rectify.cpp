// SPDX-License-Identifier: Apache-2.0
// Rectification (docs/algorithm.md, section 13): the mesh interpolation and the bilinear
// gray in integers, the line-buffer rows, the mesh file, the calibration files and the
// mesh's error against cv::initUndistortRectifyMap, the synthetic raw pairs.
#include "calibration.hpp"
#include "eval_lib.hpp"
#include "sgm/rectify.hpp"
#include "sgm_mesh_file.hpp"

#include "expect_error.hpp"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdlib.h>
#include <unistd.h>

namespace fs = std::filesystem;
using sgm::Mesh;

namespace {

// A mesh that maps every output pixel to source (x * a + bx, y + by) (1/32 px, per node).
Mesh affineMesh(int width, int height, int gridLog2, double scaleX, double shiftX, double shiftY) {
  Mesh m;
  m.width = width;
  m.height = height;
  m.gridLog2 = gridLog2;
  m.nodesX = sgm::meshNodes(width, gridLog2);
  m.nodesY = sgm::meshNodes(height, gridLog2);
  for (int i = 0; i < m.nodesY; ++i)
    for (int j = 0; j < m.nodesX; ++j) {
      m.u.push_back(int32_t(std::lround(((j << gridLog2) * scaleX + shiftX) * 32)));
      m.v.push_back(int32_t(std::lround(((i << gridLog2) + shiftY) * 32)));
    }
  return m;
}

cv::Mat texture(int width, int height, int seed) {
  cv::Mat noise(height, width, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat smooth;
  cv::GaussianBlur(noise, smooth, cv::Size(0, 0), 1.5);
  cv::normalize(smooth, smooth, 0, 255, cv::NORM_MINMAX);
  return smooth;
}

struct TempDir {
  std::string path;
  TempDir() {
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string pattern = base + "sgm_rectify_XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// A 40x30 pair's meshes (step 8) with the depth parameters f (1/256 px) and B (um).
sgm::StereoMesh meshPair(uint32_t focalQ8, uint32_t baselineUm) {
  sgm::StereoMesh mesh;
  mesh.left = affineMesh(40, 30, 3, 1, 0.5, -1);
  mesh.right = affineMesh(40, 30, 3, 0.99, 2, 1);
  mesh.focalQ8 = focalQ8;
  mesh.baselineUm = baselineUm;
  return mesh;
}

}  // namespace

TEST(Rectify, NodeCountCoversTheLastPixel) {
  EXPECT_EQ(sgm::meshNodes(640, 4), 41);  // pixels 0 .. 639: nodes at 0 .. 640
  EXPECT_EQ(sgm::meshNodes(641, 4), 42);  // pixel 640 needs the node at 656
  EXPECT_EQ(sgm::meshNodes(450, 4), 30);
}

TEST(Rectify, IdentityMeshGivesTheSourceBack) {
  const cv::Mat source = texture(77, 41, 1);
  const Mesh mesh = affineMesh(77, 41, 3, 1, 0, 0);
  const sgm::RectifiedImage out = sgm::rectify(source, mesh);
  EXPECT_EQ(cv::countNonZero(out.gray != source), 0);
  EXPECT_EQ(cv::countNonZero(out.valid), 77 * 41);
}

TEST(Rectify, PositionIsTheRoundedBilinearBlendOfTheNodes) {
  Mesh mesh = affineMesh(20, 20, 2, 1, 0, 0);
  // Node (1, 1) at (4, 4) moves by +3/32 px in u: pixel (5, 5) gets 3 * (3 * 3) / 16 = 1.6875 -> 2.
  mesh.u[size_t(1) * mesh.nodesX + 1] += 3;
  EXPECT_EQ(sgm::meshPosition(mesh, 5, 5).u, 5 * 32 + 2);
  EXPECT_EQ(sgm::meshPosition(mesh, 4, 4).u, 4 * 32 + 3);
  EXPECT_EQ(sgm::meshPosition(mesh, 6, 6).u, 6 * 32 + 1);  // 3 * 2 * 2 / 16 = 0.75 -> 1
  EXPECT_EQ(sgm::meshPosition(mesh, 7, 7).u, 7 * 32 + 0);  // 3 * 1 * 1 / 16 = 0.1875 -> 0
  // Half up for negative blends too: -8/16 = -0.5 -> 0, -9/16 -> -1.
  mesh.u[size_t(1) * mesh.nodesX + 1] -= 3 + 2;  // -2: pixel (6, 6) gets -2 * 4 / 16 = -0.5
  EXPECT_EQ(sgm::meshPosition(mesh, 6, 6).u, 6 * 32);
  EXPECT_EQ(sgm::meshPosition(mesh, 5, 5).u, 5 * 32 - 1);  // -2 * 9 / 16 = -1.125 -> -1
}

TEST(Rectify, GrayIsTheRoundedBilinearBlendOfFourPixels) {
  cv::Mat source = cv::Mat::zeros(8, 8, CV_8UC1);
  source.at<uint8_t>(3, 3) = 10;
  source.at<uint8_t>(3, 4) = 20;
  source.at<uint8_t>(4, 3) = 30;
  source.at<uint8_t>(4, 4) = 41;
  // Every pixel shifted by (+0.25, +0.5) px: output (3, 3) reads (3.25, 3.5).
  const Mesh mesh = affineMesh(8, 8, 2, 1, 0.25, 0.5);
  const sgm::RectifiedImage out = sgm::rectify(source, mesh);
  // (24 * 16 * 10 + 8 * 16 * 20 + 24 * 16 * 30 + 8 * 16 * 41 + 512) >> 10 = 23.1 -> 23
  EXPECT_EQ(out.gray.at<uint8_t>(3, 3), (24 * 16 * 10 + 8 * 16 * 20 + 24 * 16 * 30 + 8 * 16 * 41 + 512) >> 10);
  EXPECT_EQ(out.gray.at<uint8_t>(3, 3), 23);
}

TEST(Rectify, OutsideTheSourceIsInvalidAndZero) {
  const cv::Mat source(16, 16, CV_8UC1, cv::Scalar(200));
  // Shifted right by 0.5 px: the last column reads x = 15.5, outside [0, 15].
  const sgm::RectifiedImage right = sgm::rectify(source, affineMesh(16, 16, 2, 1, 0.5, 0));
  EXPECT_EQ(right.valid.at<uint8_t>(5, 14), 1);
  EXPECT_EQ(right.valid.at<uint8_t>(5, 15), 0);
  EXPECT_EQ(right.gray.at<uint8_t>(5, 15), 0);
  EXPECT_EQ(right.gray.at<uint8_t>(5, 14), 200);
  // Shifted left by 1/32 px: the first column is outside, the last reads x = 15 - 1/32 (inside).
  const sgm::RectifiedImage left = sgm::rectify(source, affineMesh(16, 16, 2, 1, -1.0 / 32, 0));
  EXPECT_EQ(left.valid.at<uint8_t>(7, 0), 0);
  EXPECT_EQ(left.valid.at<uint8_t>(7, 15), 1);
  // Exactly on the last row and column: valid, the missing neighbour has weight 0.
  const sgm::RectifiedImage exact = sgm::rectify(source, affineMesh(16, 16, 2, 1, 0, 0));
  EXPECT_EQ(exact.valid.at<uint8_t>(15, 15), 1);
  EXPECT_EQ(exact.gray.at<uint8_t>(15, 15), 200);
}

TEST(Rectify, RowSpanFollowsTheVerticalShift) {
  const sgm::RowSpan identity = sgm::meshRowSpan(affineMesh(32, 32, 3, 1, 0, 0));
  EXPECT_EQ(identity.lag, 1);
  EXPECT_EQ(identity.back, 0);
  EXPECT_EQ(identity.rows, 2);
  const sgm::RowSpan down = sgm::meshRowSpan(affineMesh(32, 32, 3, 1, 0, 5.5));
  EXPECT_EQ(down.lag, 6);  // output row y reads source rows y + 5 and y + 6
  EXPECT_EQ(down.back, 5);
  EXPECT_EQ(down.rows, 2);
  // A mesh that squeezes the rows reads further and further behind towards the bottom.
  Mesh fan = affineMesh(32, 64, 3, 1, 0, 0);
  for (size_t i = 0; i < fan.v.size(); ++i) fan.v[i] = fan.v[i] * 5 / 8;  // v = 0.625 y: reads behind
  const sgm::RowSpan behind = sgm::meshRowSpan(fan);
  EXPECT_EQ(behind.lag, 1);
  EXPECT_EQ(behind.back, -24);  // y = 63: v = 39.375, row 39
  EXPECT_EQ(behind.rows, 26);
}

TEST(Rectify, MeshFileRoundTripsAndRejectsDamage) {
  const sgm::StereoMesh mesh = meshPair(12345, 160000);
  const std::string bytes = sgm::encodeMeshFile(mesh);
  const sgm::StereoMesh back = sgm::decodeMeshFile(bytes, "m.bin");
  EXPECT_EQ(back.left.u, mesh.left.u);
  EXPECT_EQ(back.right.v, mesh.right.v);
  EXPECT_EQ(back.focalQ8, 12345u);
  EXPECT_EQ(back.baselineUm, 160000u);
  EXPECT_EQ(back.left.nodesX, mesh.left.nodesX);
  expectError([&] { sgm::decodeMeshFile("SGMMESH2" + bytes.substr(8), "m.bin"); }, {"m.bin", "not a mesh file"});
  expectError([&] { sgm::decodeMeshFile(bytes.substr(0, bytes.size() - 4), "m.bin"); }, {"m.bin", "bytes"});
  std::string frac = bytes;
  frac[8 + 12] = 4;
  expectError([&] { sgm::decodeMeshFile(frac, "m.bin"); }, {"m.bin", "1/2^4"});
  std::string nodes = bytes;
  nodes[8 + 16] = char(nodes[8 + 16] + 1);
  expectError([&] { sgm::decodeMeshFile(nodes, "m.bin"); }, {"m.bin"});
  expectError([&] { sgm::readMeshFile("/nonexistent/m.bin"); }, {"/nonexistent/m.bin"});
  Mesh wide = mesh.left;
  wide.u[3] = sgm::kMeshCoordMax + 1;
  expectError([&] { sgm::checkMesh(wide, "left mesh"); }, {"left mesh", "18-bit"});
  expectError([&] { sgm::rectify(cv::Mat(31, 40, CV_8UC1), mesh.left); }, {"40x30"});
}

// The driver reads the file the tool writes (sw/include/sgm_mesh_file.hpp, the one parser of the
// format): the same nodes, f and B, MeshImage views of them for Driver::loadMeshes, and one line
// naming the path for a file that is not whole.
TEST(Rectify, TheDriverReadsTheMeshFile) {
  const sgm::StereoMesh mesh = meshPair(4321, 75000);
  const std::string bytes = sgm::encodeMeshFile(mesh);
  const fs::path dir = fs::temp_directory_path() / ("sgm-mesh-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "mesh.bin").string(), cut = (dir / "cut.bin").string();
  std::ofstream(path, std::ios::binary) << bytes;
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 8);
  sgm::driver::MeshFile file;
  ASSERT_EQ(sgm::driver::readMeshFile(path, &file), "");
  EXPECT_EQ(file.width, 40u);
  EXPECT_EQ(file.height, 30u);
  EXPECT_EQ(file.gridLog2, 3u);
  EXPECT_EQ(file.focalQ8, 4321u);
  EXPECT_EQ(file.baselineUm, 75000u);
  EXPECT_EQ(file.leftU, mesh.left.u);
  EXPECT_EQ(file.leftV, mesh.left.v);
  EXPECT_EQ(file.rightU, mesh.right.u);
  EXPECT_EQ(file.rightV, mesh.right.v);
  const sgm::driver::MeshImage right = file.right();
  EXPECT_EQ(right.nodesX, uint32_t(mesh.right.nodesX));
  EXPECT_EQ(right.nodesY, uint32_t(mesh.right.nodesY));
  EXPECT_EQ(right.v[right.nodesX + 1], mesh.right.v[size_t(mesh.right.nodesX) + 1]);
  EXPECT_EQ(sgm::driver::formatMeshFile(file), bytes);
  const std::string truncated = sgm::driver::readMeshFile(cut, &file);
  EXPECT_NE(truncated.find(cut + ": "), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("the header announces"), std::string::npos) << truncated;
  EXPECT_EQ(truncated.find('\n'), std::string::npos) << "one line";
  std::string zero = bytes;
  zero[8 + 20] = zero[8 + 21] = zero[8 + 22] = zero[8 + 23] = 0;  // no node rows
  EXPECT_NE(sgm::driver::parseMeshFile(zero.data(), zero.size(), &file).find("node count 0"), std::string::npos);
  EXPECT_NE(sgm::driver::readMeshFile((dir / "none.bin").string(), &file).find("cannot read"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Calibration, SourcePositionIsOpenCvsMap) {
  const sgm::eval::StereoCalibration c = sgm::eval::syntheticCalibration(320, 240, 100);
  sgm::eval::Camera rational = c.right;
  rational.D = {-0.2, 0.05, 0.001, -0.002, 0.01, 0.1, 0.02, 0.003};
  for (const sgm::eval::Camera& camera : {c.left, c.right, rational}) {
    cv::Mat mapX, mapY;
    cv::initUndistortRectifyMap(cv::Mat(camera.M), cv::Mat(camera.D), cv::Mat(camera.R), cv::Mat(camera.P),
                                cv::Size(320, 240), CV_32FC1, mapX, mapY);
    double worst = 0;
    for (int y = 0; y < 240; y += 7)
      for (int x = 0; x < 320; x += 5) {
        const cv::Point2d p = sgm::eval::sourcePosition(camera, x, y);
        worst = std::max({worst, std::abs(p.x - mapX.at<float>(y, x)), std::abs(p.y - mapY.at<float>(y, x))});
      }
    EXPECT_LT(worst, 1e-3);
  }
}

TEST(Calibration, MeshMeetsTheSixteenthAtStep16AndNotAt64) {
  const sgm::eval::StereoCalibration c = sgm::eval::syntheticCalibration(640, 480, 160);
  for (const sgm::eval::Camera& camera : {c.left, c.right}) {
    const sgm::eval::MeshError fine = sgm::eval::meshError(camera, sgm::eval::meshFromCamera(camera, 640, 480, 4));
    EXPECT_LE(fine.maxPx, 1.0 / 16);
    const sgm::eval::MeshError coarse = sgm::eval::meshError(camera, sgm::eval::meshFromCamera(camera, 640, 480, 6));
    EXPECT_GT(coarse.maxPx, 1.0 / 16);
  }
}

TEST(Calibration, FilesRoundTripAndGiveTheDepthGeometry) {
  TempDir dir;
  const sgm::eval::StereoCalibration c = sgm::eval::syntheticCalibration(320, 240, 120);
  sgm::eval::writeCalibration(dir.path, c);
  const sgm::eval::StereoCalibration back = sgm::eval::readCalibration(dir.path);
  EXPECT_NEAR(cv::norm(cv::Mat(back.left.M), cv::Mat(c.left.M)), 0, 1e-9);
  EXPECT_EQ(back.right.D, c.right.D);
  EXPECT_NEAR(cv::norm(cv::Mat(back.right.P), cv::Mat(c.right.P)), 0, 1e-9);
  const sgm::eval::DepthGeometry g = sgm::eval::depthGeometry(back);
  EXPECT_DOUBLE_EQ(g.focalPx, 320);
  EXPECT_NEAR(g.baselineUnits, 120, 1e-9);
  EXPECT_DOUBLE_EQ(g.disparityOffsetPx, 0);
  // The extrinsics agree with the rectification: R2 R = R1, and R2 T is the baseline along -x.
  EXPECT_NEAR(cv::norm(cv::Mat(c.right.R * c.R), cv::Mat(c.left.R)), 0, 1e-12);
  EXPECT_NEAR(cv::norm(cv::Mat(c.right.R * c.T), cv::Mat(cv::Vec3d(-120, 0, 0))), 0, 1e-9);
}

TEST(Calibration, BadFilesGiveOneLine) {
  TempDir dir;
  expectError([&] { sgm::eval::readCalibration(dir.path); }, {"intrinsics.yml"});
  sgm::eval::writeCalibration(dir.path, sgm::eval::syntheticCalibration(64, 48, 10));
  { std::ofstream(dir.path + "/extrinsics.yml") << "%YAML:1.0\n---\nR: 1\n"; }
  expectError([&] { sgm::eval::readCalibration(dir.path); }, {"extrinsics.yml", "R"});
  {
    cv::FileStorage fs(dir.path + "/intrinsics.yml", cv::FileStorage::WRITE);
    fs << "M1" << cv::Mat::eye(3, 3, CV_64F) << "D1" << cv::Mat::zeros(1, 12, CV_64F) << "M2"
       << cv::Mat::eye(3, 3, CV_64F) << "D2" << cv::Mat::zeros(1, 5, CV_64F);
  }
  expectError([&] { sgm::eval::readCalibration(dir.path); }, {"intrinsics.yml", "D1", "12 terms"});
  { std::ofstream(dir.path + "/intrinsics.yml") << "not yaml {{{"; }
  expectError([&] { sgm::eval::readCalibration(dir.path); }, {"intrinsics.yml"});
}

TEST(Calibration, RawPairRectifiesBackToTheScene) {
  const cv::Mat scene = texture(320, 240, 7);
  const sgm::eval::StereoCalibration c = sgm::eval::syntheticCalibration(320, 240, 160);
  for (const sgm::eval::Camera& camera : {c.left, c.right}) {
    const cv::Mat raw = sgm::eval::rawFromRectified(scene, camera);
    EXPECT_GT(cv::norm(raw, scene, cv::NORM_L1) / double(scene.total()), 4.0);  // the raw view is another view
    const sgm::RectifiedImage back = sgm::rectify(raw, sgm::eval::meshFromCamera(camera, 320, 240, 4));
    EXPECT_GT(cv::countNonZero(back.valid), int(scene.total() * 99 / 100));
    cv::Mat diff;
    cv::absdiff(back.gray, scene, diff);
    EXPECT_LT(cv::mean(diff, back.valid)[0], 4.0);  // two resamplings of a texture of 1.5 px blobs
  }
}
