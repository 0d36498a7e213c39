// The one image I/O layer of the project: the golden CLI, the evaluator and the
// Verilator harness all read and write images through these functions.
#pragma once

#include <opencv2/core.hpp>

#include <string>
#include <utility>
#include <vector>

namespace sgm {

// Disparity map as the pipeline produces it: disparity in 1/16 px (CV_16UC1)
// and a validity flag per pixel (CV_8UC1, 0 or 1), distinct from d = 0.
struct DisparityMap {
  cv::Mat disp;   // CV_16UC1, value = d * 16 (+ sub-pixel fraction)
  cv::Mat valid;  // CV_8UC1, 1 = valid
};

// Colour (BGR, as OpenCV decodes) or gray 8-bit image -> 8-bit gray with the
// documented integer formula Y = (77 R + 150 G + 29 B + 128) >> 8.
cv::Mat toGray(const cv::Mat& image);

// Reads an 8-bit gray or colour image and converts it to gray. Throws Error
// with a one-line message for missing, unreadable, empty or unsupported files.
cv::Mat readGray(const std::string& path);

// Reads an 8-bit (or 16-bit) single-channel ground-truth / mask image as-is.
cv::Mat readSingleChannel(const std::string& path);

// Writes a PNG atomically (temporary file + rename): no partial file is left
// behind on failure. Throws Error on failure.
void writePng(const std::string& path, const cv::Mat& image);
// Writes several PNGs as one: either all of them appear or none does.
void writePngs(const std::vector<std::pair<std::string, cv::Mat>>& files);

// Output encodings of a disparity map.
// 16-bit: disparity * 256, 0 = invalid; a valid d = 0 is written as 1 so 0 stays unambiguous.
cv::Mat encodeDisparity16(const DisparityMap& map);
// The paper's 8-bit rendering: [0, D-1] scaled to [0, 255], invalid = 0.
cv::Mat encodeDisparity8(const DisparityMap& map, int disparities);
// Colour map for people (JET over [0, D-1]), invalid = black.
cv::Mat encodeDisparityColor(const DisparityMap& map, int disparities);
// Same colour map for a float disparity image (ground truth; <= 0 = unknown).
cv::Mat colorizeDisparity(const cv::Mat& dispFloat, float maxDisparity);

}  // namespace sgm
