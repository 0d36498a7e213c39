// SPDX-License-Identifier: Apache-2.0
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
  // CV_8UC1, the confidence of docs/algorithm.md section 7b (0 where the selection made the pixel
  // invalid), which the later stages carry unchanged; empty unless the pipeline was asked for it.
  cv::Mat confidence = cv::Mat();
};

// Input images (docs/algorithm.md, section 1, "Input files"): a regular file
// of at most kMaxImageFileBytes, an image of at most kMaxImageSide pixels a side
// and kMaxImagePixels pixels (checked from the header before decoding where the
// format allows it), 8-bit samples, 1 or 3 channels; JPEG data the decoder
// reports as truncated or corrupt is rejected. Every violation is an sgm::Error
// with a one-line message naming the file and the problem.
constexpr int kMaxImageSide = 16384;
constexpr long kMaxImagePixels = 1L << 24;
constexpr long kMaxImageFileBytes = 4 * kMaxImagePixels + (1L << 20);

// Colour (BGR, as OpenCV decodes) or gray 8-bit image -> 8-bit gray with the
// documented integer formula Y = (77 R + 150 G + 29 B + 128) >> 8.
cv::Mat toGray(const cv::Mat& image);

// Reads an input image as decoded: 8-bit gray (CV_8UC1) or colour (CV_8UC3, BGR).
cv::Mat readImage(const std::string& path);
// readImage converted to gray (toGray).
cv::Mat readGray(const std::string& path);

// Reads an 8-bit (or 16-bit) single-channel ground-truth / mask image as-is
// (same file checks as readImage).
cv::Mat readSingleChannel(const std::string& path);

// One output file: its path and its bytes.
struct OutputFile {
  std::string path;
  std::string bytes;
};
// PNG bytes of an image; throws Error naming path when OpenCV cannot encode it.
std::string encodePng(const cv::Mat& image, const std::string& path);
// Writes the files as one (temporary files + rename): either all of them
// appear or none does. Throws Error naming the file that failed.
void writeFiles(const std::vector<OutputFile>& files);
// Writes a PNG atomically: no partial file is left behind on failure.
void writePng(const std::string& path, const cv::Mat& image);
// Writes several PNGs as one: either all of them appear or none does.
void writePngs(const std::vector<std::pair<std::string, cv::Mat>>& files);
// Throws Error unless dir is a writable directory or could be created (its
// nearest existing ancestor is a writable directory). Creates nothing: tools
// call it before their long computations, and create the directory at the end.
void checkOutputDirectory(const std::string& dir);

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
