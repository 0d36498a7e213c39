// SPDX-License-Identifier: Apache-2.0
// A stereo calibration as OpenCV's stereo_calib sample writes it (intrinsics.yml: M1, D1,
// M2, D2; extrinsics.yml: R, T, R1, R2, P1, P2, Q), the exact rectification map of
// cv::initUndistortRectifyMap, the mesh sampled from it (sgm/rectify.hpp) with its error
// against the exact map, and the synthetic raw pairs the tests make from rectified scenes.
#pragma once

#include "sgm/rectify.hpp"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace sgm::eval {

// One camera: its matrix M, its distortion D (k1, k2, p1, p2[, k3[, k4, k5, k6]]: 0, 4, 5
// or 8 terms), its rectifying rotation R and the projection P of the rectified frame.
struct Camera {
  cv::Matx33d M, R;
  std::vector<double> D;
  cv::Matx34d P;
};

struct StereoCalibration {
  Camera left, right;
  cv::Matx33d R;  // right camera from left: X2 = R X1 + T
  cv::Vec3d T;
  cv::Matx44d Q;
};

// Reads DIR/intrinsics.yml and DIR/extrinsics.yml; a missing file, key or a matrix of the
// wrong size throws Error naming the file and the key.
StereoCalibration readCalibration(const std::string& dir);
// Writes both files (OpenCV FileStorage YAML) into DIR (which must exist).
void writeCalibration(const std::string& dir, const StereoCalibration& calibration);

// The source position of rectified pixel (x, y): cv::initUndistortRectifyMap's formula,
// in double, at any (x, y) (the mesh's last nodes lie beyond the frame).
cv::Point2d sourcePosition(const Camera& camera, double x, double y);

// The mesh of one camera: each node the source position rounded to 1/32 px.
Mesh meshFromCamera(const Camera& camera, int width, int height, int gridLog2);

// The largest distance, over the frame, between the mesh's position and the exact map of
// cv::initUndistortRectifyMap (CV_32FC1), in px, and where it is.
struct MeshError {
  double maxPx = 0;
  int x = 0, y = 0;
};
MeshError meshError(const Camera& camera, const Mesh& mesh);

// The depth parameters of the rectified frame: f = P1(0,0) px, B = -P2(0,3) / P2(0,0) in
// calibration units, and cx1 - cx2 (the disparity of points at infinity).
struct DepthGeometry {
  double focalPx = 0, baselineUnits = 0, disparityOffsetPx = 0;
};
DepthGeometry depthGeometry(const StereoCalibration& calibration);

// The pair's meshes at step 2^gridLog2 with f and B (B in mm per calibration unit unitMm);
// throws Error (naming dir) when f or B is out of the mesh file's range. depth (when given)
// receives the geometry.
StereoMesh stereoMesh(const StereoCalibration& calibration, cv::Size size, int gridLog2, double unitMm,
                      const std::string& dir, DepthGeometry* depth = nullptr);

// A plausible calibration of a camera pair whose rectified frame is a width x height scene
// as given (both cameras with radial and tangential distortion, slightly different, a
// small rotation between them; P1, P2 keep the scene's frame: f = width, principal point
// at the centre, baseline `baseline` units).
StereoCalibration syntheticCalibration(int width, int height, double baseline);

// The raw view of a rectified image: each raw pixel takes the rectified image at the
// position the camera's rectification maps it to (cv::undistortPoints, Lanczos-4,
// the border replicated).
cv::Mat rawFromRectified(const cv::Mat& rectified, const Camera& camera);

}  // namespace sgm::eval
