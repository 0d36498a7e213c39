// SPDX-License-Identifier: Apache-2.0
#include "calibration.hpp"

#include "sgm/params.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>

namespace sgm::eval {

namespace {

cv::Mat readMatrix(const cv::FileStorage& fs, const std::string& path, const char* key, int rows, int cols) {
  cv::Mat m;
  const cv::FileNode node = fs[key];
  if (node.empty()) throw Error(path + ": no " + key);
  try {
    node >> m;
  } catch (const cv::Exception&) {
    throw Error(path + ": " + key + " is not a matrix");
  }
  if (m.empty()) throw Error(path + ": " + key + " is not a matrix");
  m.convertTo(m, CV_64F);
  if (m.rows != rows || m.cols != cols)
    throw Error(path + ": " + key + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ", expected " +
                std::to_string(rows) + "x" + std::to_string(cols));
  return m;
}

std::vector<double> readDistortion(const cv::FileStorage& fs, const std::string& path, const char* key) {
  cv::Mat m;
  const cv::FileNode node = fs[key];
  if (node.empty()) throw Error(path + ": no " + key);
  try {
    node >> m;
  } catch (const cv::Exception&) {
    throw Error(path + ": " + key + " is not a matrix");
  }
  m.convertTo(m, CV_64F);
  const int n = int(m.total());
  if ((m.rows != 1 && m.cols != 1 && n != 0) || (n != 0 && n != 4 && n != 5 && n != 8))
    throw Error(path + ": " + key + " has " + std::to_string(n) +
                " terms; the mesh tool takes 0, 4, 5 or 8 (k1 k2 p1 p2 [k3 [k4 k5 k6]])");
  return std::vector<double>(m.begin<double>(), m.end<double>());
}

cv::FileStorage openYaml(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error("cannot read '" + path + "'");
  try {
    cv::FileStorage fs(path, cv::FileStorage::READ);
    if (!fs.isOpened()) throw Error(path + ": not an OpenCV YAML/XML file");
    return fs;
  } catch (const cv::Exception&) {
    throw Error(path + ": not an OpenCV YAML/XML file");
  }
}

template <int R, int C>
cv::Matx<double, R, C> toMatx(const cv::Mat& m) {
  cv::Matx<double, R, C> out;
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) out(r, c) = m.at<double>(r, c);
  return out;
}

cv::Mat distortionMat(const std::vector<double>& d) { return cv::Mat(d, true).reshape(1, 1); }

int32_t toMeshCoordinate(double px, const char* axis, int x, int y) {
  const double scaled = std::floor(px * (1 << kMeshFracBits) + 0.5);
  if (!(scaled >= kMeshCoordMin && scaled <= kMeshCoordMax))
    throw Error(std::string("the calibration maps mesh node (") + std::to_string(x) + ", " + std::to_string(y) +
                ") to " + axis + " = " + std::to_string(px) + " px, outside the mesh's 18-bit range");
  return int32_t(scaled);
}

}  // namespace

StereoCalibration readCalibration(const std::string& dir) {
  const std::string intrinsics = dir + "/intrinsics.yml", extrinsics = dir + "/extrinsics.yml";
  StereoCalibration c;
  {
    cv::FileStorage fs = openYaml(intrinsics);
    c.left.M = toMatx<3, 3>(readMatrix(fs, intrinsics, "M1", 3, 3));
    c.right.M = toMatx<3, 3>(readMatrix(fs, intrinsics, "M2", 3, 3));
    c.left.D = readDistortion(fs, intrinsics, "D1");
    c.right.D = readDistortion(fs, intrinsics, "D2");
  }
  cv::FileStorage fs = openYaml(extrinsics);
  c.R = toMatx<3, 3>(readMatrix(fs, extrinsics, "R", 3, 3));
  cv::Mat t = readMatrix(fs, extrinsics, "T", 3, 1);
  c.T = cv::Vec3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
  c.left.R = toMatx<3, 3>(readMatrix(fs, extrinsics, "R1", 3, 3));
  c.right.R = toMatx<3, 3>(readMatrix(fs, extrinsics, "R2", 3, 3));
  c.left.P = toMatx<3, 4>(readMatrix(fs, extrinsics, "P1", 3, 4));
  c.right.P = toMatx<3, 4>(readMatrix(fs, extrinsics, "P2", 3, 4));
  c.Q = toMatx<4, 4>(readMatrix(fs, extrinsics, "Q", 4, 4));
  for (const Camera* cam : {&c.left, &c.right})
    if (!(cam->M(0, 0) > 0 && cam->M(1, 1) > 0 && cam->P(0, 0) > 0 && cam->P(1, 1) > 0))
      throw Error(dir + ": a camera matrix or projection without a positive focal length");
  return c;
}

void writeCalibration(const std::string& dir, const StereoCalibration& c) {
  {
    cv::FileStorage fs(dir + "/intrinsics.yml", cv::FileStorage::WRITE);
    if (!fs.isOpened()) throw Error("cannot write '" + dir + "/intrinsics.yml'");
    fs << "M1" << cv::Mat(c.left.M) << "D1" << distortionMat(c.left.D) << "M2" << cv::Mat(c.right.M) << "D2"
       << distortionMat(c.right.D);
  }
  cv::FileStorage fs(dir + "/extrinsics.yml", cv::FileStorage::WRITE);
  if (!fs.isOpened()) throw Error("cannot write '" + dir + "/extrinsics.yml'");
  fs << "R" << cv::Mat(c.R) << "T" << cv::Mat(c.T) << "R1" << cv::Mat(c.left.R) << "R2" << cv::Mat(c.right.R) << "P1"
     << cv::Mat(c.left.P) << "P2" << cv::Mat(c.right.P) << "Q" << cv::Mat(c.Q);
}

cv::Point2d sourcePosition(const Camera& camera, double x, double y) {
  const cv::Matx33d P3(camera.P(0, 0), camera.P(0, 1), camera.P(0, 2), camera.P(1, 0), camera.P(1, 1), camera.P(1, 2),
                       camera.P(2, 0), camera.P(2, 1), camera.P(2, 2));
  const cv::Matx33d inverse = (P3 * camera.R).inv(cv::DECOMP_SVD);
  const cv::Vec3d ray = inverse * cv::Vec3d(x, y, 1);
  const double w = ray[2] != 0 ? 1 / ray[2] : 1;
  const double xp = ray[0] * w, yp = ray[1] * w;
  double d[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < camera.D.size() && i < 8; ++i) d[i] = camera.D[i];
  const double r2 = xp * xp + yp * yp, r4 = r2 * r2, r6 = r4 * r2;
  const double radial = (1 + d[0] * r2 + d[1] * r4 + d[4] * r6) / (1 + d[5] * r2 + d[6] * r4 + d[7] * r6);
  const double xd = xp * radial + 2 * d[2] * xp * yp + d[3] * (r2 + 2 * xp * xp);
  const double yd = yp * radial + d[2] * (r2 + 2 * yp * yp) + 2 * d[3] * xp * yp;
  return {camera.M(0, 0) * xd + camera.M(0, 1) * yd + camera.M(0, 2), camera.M(1, 1) * yd + camera.M(1, 2)};
}

Mesh meshFromCamera(const Camera& camera, int width, int height, int gridLog2) {
  Mesh mesh;
  mesh.width = width;
  mesh.height = height;
  mesh.gridLog2 = gridLog2;
  mesh.nodesX = meshNodes(width, gridLog2);
  mesh.nodesY = meshNodes(height, gridLog2);
  for (int i = 0; i < mesh.nodesY; ++i)
    for (int j = 0; j < mesh.nodesX; ++j) {
      const cv::Point2d p = sourcePosition(camera, j << gridLog2, i << gridLog2);
      mesh.u.push_back(toMeshCoordinate(p.x, "u", j << gridLog2, i << gridLog2));
      mesh.v.push_back(toMeshCoordinate(p.y, "v", j << gridLog2, i << gridLog2));
    }
  checkMesh(mesh, "mesh");
  return mesh;
}

MeshError meshError(const Camera& camera, const Mesh& mesh) {
  cv::Mat mapX, mapY;
  cv::initUndistortRectifyMap(cv::Mat(camera.M), distortionMat(camera.D), cv::Mat(camera.R), cv::Mat(camera.P),
                              cv::Size(mesh.width, mesh.height), CV_32FC1, mapX, mapY);
  MeshError worst;
  constexpr double one = 1 << kMeshFracBits;
  for (int y = 0; y < mesh.height; ++y)
    for (int x = 0; x < mesh.width; ++x) {
      const SourcePosition p = meshPosition(mesh, x, y);
      const double e = std::hypot(p.u / one - mapX.at<float>(y, x), p.v / one - mapY.at<float>(y, x));
      if (e > worst.maxPx) worst = {e, x, y};
    }
  return worst;
}

DepthGeometry depthGeometry(const StereoCalibration& c) {
  DepthGeometry g;
  g.focalPx = c.left.P(0, 0);
  g.baselineUnits = -c.right.P(0, 3) / c.right.P(0, 0);
  g.disparityOffsetPx = c.left.P(0, 2) - c.right.P(0, 2);
  return g;
}

StereoCalibration syntheticCalibration(int width, int height, double baseline) {
  StereoCalibration c;
  const double f = width, cx = (width - 1) / 2.0, cy = (height - 1) / 2.0;
  // The rectified frame: the scene as given, the right camera `baseline` to the right.
  c.left.P = cv::Matx34d(f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0);
  c.right.P = cv::Matx34d(f, 0, cx, -f * baseline, 0, f, cy, 0, 0, 0, 1, 0);
  c.Q = cv::Matx44d(1, 0, 0, -cx, 0, 1, 0, -cy, 0, 0, 0, f, 0, 0, 1 / baseline, 0);
  // The raw cameras: each a little off the rectified one in focal length, principal point
  // and orientation, with barrel distortion and a tangential term.
  c.left.M = cv::Matx33d(0.985 * f, 0, cx + 0.006 * width, 0, 0.988 * f, cy - 0.008 * height, 0, 0, 1);
  c.right.M = cv::Matx33d(0.99 * f, 0, cx - 0.005 * width, 0, 0.987 * f, cy + 0.012 * height, 0, 0, 1);
  c.left.D = {-0.11, 0.06, 0.0012, -0.0009, -0.01};
  c.right.D = {-0.095, 0.045, -0.0008, 0.0011, -0.008};
  cv::Matx33d r1, r2;
  cv::Rodrigues(cv::Vec3d(0.004, -0.012, 0.003), r1);
  cv::Rodrigues(cv::Vec3d(-0.003, 0.009, -0.002), r2);
  c.left.R = r1;
  c.right.R = r2;
  // X_rect1 = R1 X1, X_rect2 = R2 X2 = X_rect1 - (baseline, 0, 0): X2 = R2^T R1 X1 - R2^T (baseline, 0, 0).
  c.R = r2.t() * r1;
  c.T = -(r2.t() * cv::Vec3d(baseline, 0, 0));
  return c;
}

cv::Mat rawFromRectified(const cv::Mat& rectified, const Camera& camera) {
  std::vector<cv::Point2f> raw, rect;
  raw.reserve(size_t(rectified.total()));
  for (int y = 0; y < rectified.rows; ++y)
    for (int x = 0; x < rectified.cols; ++x) raw.emplace_back(float(x), float(y));
  cv::undistortPoints(raw, rect, cv::Mat(camera.M), distortionMat(camera.D), cv::Mat(camera.R), cv::Mat(camera.P),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 40, 1e-10));
  cv::Mat mapX(rectified.size(), CV_32FC1), mapY(rectified.size(), CV_32FC1);
  for (int y = 0, i = 0; y < rectified.rows; ++y)
    for (int x = 0; x < rectified.cols; ++x, ++i) {
      mapX.at<float>(y, x) = rect[i].x;
      mapY.at<float>(y, x) = rect[i].y;
    }
  cv::Mat out;
  cv::remap(rectified, out, mapX, mapY, cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
  return out;
}

StereoMesh stereoMesh(const StereoCalibration& calibration, cv::Size size, int gridLog2, double unitMm,
                      const std::string& dir, DepthGeometry* depth) {
  StereoMesh mesh;
  mesh.left = meshFromCamera(calibration.left, size.width, size.height, gridLog2);
  mesh.right = meshFromCamera(calibration.right, size.width, size.height, gridLog2);
  const DepthGeometry geometry = depthGeometry(calibration);
  const double baselineMm = geometry.baselineUnits * unitMm;
  if (!(geometry.focalPx > 0 && geometry.focalPx * 256 < 4294967296.0))
    throw Error(dir + ": focal length " + std::to_string(geometry.focalPx) + " px out of range");
  if (!(baselineMm > 0 && baselineMm * 1000 < 4294967296.0))
    throw Error(dir + ": baseline " + std::to_string(baselineMm) + " mm out of range (P2(0,3) must be negative)");
  mesh.focalQ8 = uint32_t(std::lround(geometry.focalPx * 256));
  mesh.baselineUm = uint32_t(std::lround(baselineMm * 1000));
  if (depth) *depth = geometry;
  return mesh;
}

}  // namespace sgm::eval
