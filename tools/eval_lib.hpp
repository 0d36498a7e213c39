// SPDX-License-Identifier: Apache-2.0
// Accuracy evaluation against Middlebury ground truth (the paper's eq. (5)),
// scene loading and the OpenCV StereoSGBM reference, shared by sgm-eval, the
// tests and the simulator.
#pragma once

#include "sgm/image_io.hpp"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sgm::eval {

struct Scene {
  std::string name;
  cv::Mat leftColor, rightColor;  // as decoded (BGR or gray)
  cv::Mat left, right;            // 8-bit gray (sgm::toGray)
  cv::Mat gt;                     // CV_32F disparity in px, 0 = unknown
  double gtScale = 1;
  cv::Mat nonocc, all, disc;   // CV_8U masks (255 / 128 / 0); disc may be empty
  bool nonoccDerived = false;  // true when nonocc was derived from gt
  int ndisp = 0;               // meta.txt `ndisp:` (the D to run it with), 0 = not given
  std::string set;             // meta.txt `set:` (e.g. middlebury2006, kitti2015), "" = not given
  std::string meshPath;        // the scene's mesh.bin, "" = none: with one, left and right are a raw
                               // pair and the ground truth is in the meshes' rectified frame
  bool hasGroundTruth() const { return !gt.empty(); }
};

// The keys of a scene's meta.txt that the evaluation uses (see the pool's README).
struct SceneMeta {
  double gtScale = 0;  // `gt_scale:` (disparity px = value / scale), 0 = not given
  int ndisp = 0;       // `ndisp:`, kMinDisparities .. kMaxDisparities, 0 = not given
  std::string set;     // `set:`, one word, "" = not given
};

// Reads DIR/meta.txt (a missing file reads as all keys absent); a value may be
// followed by a comment in parentheses ("gt_scale: 4 (px = value / 4)"). A key that is
// present but malformed (gt_scale not a positive number, ndisp not an integer in
// range, set not one word, a key given twice) throws Error naming the file and line.
SceneMeta readSceneMeta(const std::string& dir);

// Reads DIR/{left,right,gt}.png (gt 8- or 16-bit), the masks when present and
// gt_scale, ndisp and set from meta.txt (scaleOverride > 0 replaces gt_scale).
// Throws Error with a one-line message.
Scene loadScene(const std::string& dir, double scaleOverride = 0);

// A scene from images in memory: colour or gray left/right, the raw ground
// truth (CV_8U or CV_16U, 0 = unknown; may be empty: no figures then) and its
// scale. Masks are derived from the ground truth (all = known gt, nonocc as
// deriveNonOccluded, no disc).
Scene makeScene(const std::string& name, const cv::Mat& leftColor, const cv::Mat& rightColor, const cv::Mat& gtRaw,
                double gtScale);

// Reads a scene from explicit files; gtPath may be empty. A missing
// gtScale (<= 0) is read from meta.txt beside the ground truth, else 1.
// Middlebury masks (all.png, nonocc.png, disc.png) beside the ground truth are
// used when present (and the scene is not downscaled).
// downscale > 1 shrinks images (INTER_AREA) and ground truth (nearest) by that
// factor and divides the disparities accordingly.
Scene loadSceneFiles(const std::string& leftPath, const std::string& rightPath, const std::string& gtPath,
                     double gtScale, int downscale = 1);

// The Middlebury Aloe pair with ground truth shipped by opencv-doc
// (kAloeDir/aloe{L,R}.jpg, aloeGT.png), scaled by 1/4 so its disparities fit
// D = 64, named "aloe". aloeAvailable() says whether the files are there;
// loadAloe() throws Error (pointing at `make deps`) when they are not.
extern const char* const kAloeDir;
bool aloeAvailable();
Scene loadAloe();
// Non-occluded mask from the left ground truth: a pixel is occluded when its
// match x - d falls outside the right image or a pixel to its right lands on
// or left of that match. Unknown gt (0) is excluded.
cv::Mat deriveNonOccluded(const cv::Mat& gtRaw, double scale);

// Lists the scene directories under root that hold left/right/gt.png, sorted.
std::vector<std::string> listScenes(const std::string& root);

struct ErrorFigures {
  double errNonocc = 0;           // % of nonocc pixels with |d - gt| > delta or invalid
  double errAll = 0;              // same over `all`
  std::optional<double> errDisc;  // same over disc == 255, when the scene has a disc mask
  double density = 0;             // % of `all` pixels that are valid
  double errNonoccValid = 0;      // % of valid nonocc pixels with |d - gt| > delta
  // The KITTI D1 measure over `all` (every pixel with known gt): an error when
  // |d - gt| > kD1Pixels and > kD1Fraction * gt. d1All counts invalid output as an
  // error; d1Valid is over the valid pixels only.
  double d1All = 0;
  double d1Valid = 0;
};

constexpr double kD1Pixels = 3.0, kD1Fraction = 0.05;
// One pixel of the KITTI D1 measure: |d - gt| > 3 px and > 5 % of gt.
inline bool isD1Error(float d, float gt) {
  const double e = d > gt ? double(d) - gt : double(gt) - d;
  return e > kD1Pixels && e > kD1Fraction * gt;
}

// disparity: CV_32F px with < 0 meaning invalid.
ErrorFigures evaluate(const cv::Mat& disparity, const Scene& scene, double delta = 1.0);

// DisparityMap (1/16 px + valid) -> CV_32F px with -1 for invalid.
cv::Mat toFloat(const DisparityMap& map);

// OpenCV StereoSGBM with the settings of OpenCV's stereo_match sample
// (blockSize 3, P1 = 8*cn*9, P2 = 32*cn*9, uniqueness 10, speckle 100/32,
// disp12MaxDiff 1) on the given images; returns CV_32F px, -1 invalid.
// mode: cv::StereoSGBM::MODE_SGBM, MODE_HH, MODE_SGBM_3WAY.
cv::Mat runOpenCvSgbm(const cv::Mat& left, const cv::Mat& right, int disparities, int mode);

// Error map for people: green = correct, red = wrong, blue = invalid, black = not evaluated.
cv::Mat errorMap(const cv::Mat& disparity, const Scene& scene, double delta = 1.0);

// left | ground truth | result | error map, side by side, with panel titles, a
// disparity colour bar (px) under the two disparity panels and the error map's legend.
cv::Mat sideBySide(const Scene& scene, const cv::Mat& disparity, float maxDisparity, double delta = 1.0);

// A depth map for people (CV_16UC1 in mm, 0 = invalid, as the core's depth words):
// near red to far blue over the 2nd .. 98th percentile of the valid depths below the
// saturation (65535, drawn blue), invalid black,
// with the title above and a colour bar in mm below.
cv::Mat depthPicture(const cv::Mat& depthMm, const std::string& title);
// The confidence map (CV_8UC1, docs/algorithm.md section 7b) in colours (0 .. 255 from blue to
// red) under a title, with a colour bar: confidence.png of make sim (a CONFIDENCE build).
cv::Mat confidencePicture(const cv::Mat& confidence, const std::string& title);

}  // namespace sgm::eval
