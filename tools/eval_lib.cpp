// SPDX-License-Identifier: Apache-2.0
#include "eval_lib.hpp"
#include "report_chart.hpp"

#include "sgm/params.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace sgm::eval {

namespace {

std::string trimmed(const std::string& text) {
  const size_t a = text.find_first_not_of(" \t\r"), b = text.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : text.substr(a, b - a + 1);
}

cv::Mat readMaskIfPresent(const std::string& path, cv::Size size) {
  if (!fs::exists(path)) return {};
  cv::Mat m = readSingleChannel(path);
  if (m.size() != size || m.depth() != CV_8U) throw Error("mask '" + path + "' does not match the image");
  return m;
}

}  // namespace

SceneMeta readSceneMeta(const std::string& dir) {
  const std::string path = dir + "/meta.txt";
  SceneMeta meta;
  std::ifstream in(path);
  if (!in) return meta;
  std::set<std::string> seen;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = trimmed(line.substr(0, colon));
    std::string value = trimmed(line.substr(colon + 1));
    if (const size_t comment = value.find(" ("); comment != std::string::npos && value.back() == ')')
      value = trimmed(value.substr(0, comment));  // "4 (disparity_px = gt_value / 4)"
    if (key != "gt_scale" && key != "ndisp" && key != "set") continue;
    const std::string where = path + ":" + std::to_string(number);
    if (!seen.insert(key).second) throw Error(where + ": " + key + " given twice");
    char* end = nullptr;
    if (key == "gt_scale") {
      meta.gtScale = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !(meta.gtScale > 0) || !std::isfinite(meta.gtScale))
        throw Error(where + ": bad gt_scale '" + value + "' (expected a positive number)");
    } else if (key == "ndisp") {
      const long n = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || n < kMinDisparities || n > kMaxDisparities)
        throw Error(where + ": bad ndisp '" + value + "' (expected an integer " + std::to_string(kMinDisparities) +
                    ".." + std::to_string(kMaxDisparities) + ")");
      meta.ndisp = int(n);
    } else {
      if (value.empty() || value.find_first_of(" \t") != std::string::npos)
        throw Error(where + ": bad set '" + value + "' (expected one word)");
      meta.set = value;
    }
  }
  return meta;
}

const char* const kAloeDir = "/usr/share/doc/opencv-doc/examples/data";

bool aloeAvailable() { return std::filesystem::exists(std::string(kAloeDir) + "/aloeL.jpg"); }

Scene loadAloe() {
  const std::string dir = kAloeDir;
  if (!aloeAvailable()) throw Error("default scene not found in " + dir + " (run 'make deps' to install opencv-doc)");
  Scene scene = loadSceneFiles(dir + "/aloeL.jpg", dir + "/aloeR.jpg", dir + "/aloeGT.png", 1.0, 4);
  scene.name = "aloe";
  return scene;
}

cv::Mat deriveNonOccluded(const cv::Mat& gtRaw, double scale) {
  cv::Mat mask(gtRaw.size(), CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < gtRaw.rows; ++y) {
    // Match positions in gt units (x * scale - g), exact integers.
    long long leftmostToTheRight = LLONG_MAX;
    for (int x = gtRaw.cols - 1; x >= 0; --x) {
      const int g = gtRaw.depth() == CV_8U ? gtRaw.at<uint8_t>(y, x) : gtRaw.at<uint16_t>(y, x);
      if (g == 0) continue;
      const long long match = (long long)std::llround(x * scale) - g;
      const bool inside = match >= 0;
      const bool hidden = leftmostToTheRight <= match;
      if (inside && !hidden) mask.at<uint8_t>(y, x) = 255;
      leftmostToTheRight = std::min(leftmostToTheRight, match);
    }
  }
  return mask;
}

namespace {

// Middlebury masks (all, nonocc, disc) from dir replace the derived ones where present.
void useMasksIn(const std::string& dir, Scene& s) {
  if (cv::Mat all = readMaskIfPresent(dir + "/all.png", s.left.size()); !all.empty()) s.all = all;
  if (cv::Mat nonocc = readMaskIfPresent(dir + "/nonocc.png", s.left.size()); !nonocc.empty()) {
    s.nonocc = nonocc;
    s.nonoccDerived = false;
  }
  s.disc = readMaskIfPresent(dir + "/disc.png", s.left.size());
}

}  // namespace

Scene makeScene(const std::string& name, const cv::Mat& leftColor, const cv::Mat& rightColor, const cv::Mat& gtRaw,
                double gtScale) {
  Scene s;
  s.name = name;
  s.leftColor = leftColor;
  s.rightColor = rightColor;
  s.left = toGray(leftColor);
  s.right = toGray(rightColor);
  if (s.left.size() != s.right.size())
    throw Error("left/right size mismatch: " + std::to_string(s.left.cols) + "x" + std::to_string(s.left.rows) +
                " vs " + std::to_string(s.right.cols) + "x" + std::to_string(s.right.rows));
  if (gtRaw.empty()) return s;
  if (gtRaw.size() != s.left.size()) throw Error("ground truth size does not match the images");
  if (gtScale <= 0) throw Error("ground truth scale must be positive");
  s.gtScale = gtScale;
  gtRaw.convertTo(s.gt, CV_32F, 1.0 / gtScale);
  s.all = gtRaw > 0;
  s.nonocc = deriveNonOccluded(gtRaw, gtScale);
  s.nonoccDerived = true;
  return s;
}

Scene loadScene(const std::string& dir, double scaleOverride) {
  std::string name = fs::path(dir).filename().string();
  if (name.empty()) name = fs::path(dir).parent_path().filename().string();
  const std::string leftPath = dir + "/left.png", rightPath = dir + "/right.png", gtPath = dir + "/gt.png";
  const cv::Mat left = readImage(leftPath), right = readImage(rightPath);  // one-line errors for bad files
  const cv::Mat gtRaw = readSingleChannel(gtPath);
  const SceneMeta meta = readSceneMeta(dir);
  if (scaleOverride <= 0 && meta.gtScale <= 0)
    throw Error("no gt_scale in " + dir + "/meta.txt (pass the scale explicitly)");
  Scene s = makeScene(name, left, right, gtRaw, scaleOverride > 0 ? scaleOverride : meta.gtScale);
  s.ndisp = meta.ndisp;
  s.set = meta.set;
  if (fs::exists(dir + "/mesh.bin")) s.meshPath = dir + "/mesh.bin";
  useMasksIn(dir, s);
  return s;
}

Scene loadSceneFiles(const std::string& leftPath, const std::string& rightPath, const std::string& gtPath,
                     double gtScale, int downscale) {
  cv::Mat left = readImage(leftPath), right = readImage(rightPath);  // one-line errors for bad files
  cv::Mat gtRaw;
  if (!gtPath.empty()) {
    gtRaw = readSingleChannel(gtPath);
    if (gtScale <= 0) {
      std::string dir = fs::path(gtPath).parent_path().string();
      if (dir.empty()) dir = ".";
      const SceneMeta meta = readSceneMeta(dir);
      if (meta.gtScale <= 0 && fs::exists(dir + "/meta.txt"))
        throw Error("no gt_scale in " + dir + "/meta.txt (pass the scale explicitly)");
      gtScale = meta.gtScale > 0 ? meta.gtScale : 1.0;
    }
  }
  if (downscale > 1) {
    const cv::Size size(left.cols / downscale, left.rows / downscale);
    cv::resize(left, left, size, 0, 0, cv::INTER_AREA);
    cv::resize(right, right, size, 0, 0, cv::INTER_AREA);
    if (!gtRaw.empty()) {
      cv::resize(gtRaw, gtRaw, size, 0, 0, cv::INTER_NEAREST);  // values kept, disparities shrink:
      gtScale *= downscale;                                     // the scale grows instead
    }
  }
  Scene scene = makeScene(fs::path(leftPath).stem().string(), left, right, gtRaw, gtScale);
  if (!gtPath.empty() && downscale <= 1) useMasksIn(fs::path(gtPath).parent_path().string(), scene);
  return scene;
}

std::vector<std::string> listScenes(const std::string& root) {
  std::vector<std::string> dirs;
  if (!fs::is_directory(root)) return dirs;
  for (const auto& entry : fs::directory_iterator(root)) {
    const fs::path p = entry.path();
    if (fs::exists(p / "left.png") && fs::exists(p / "right.png") && fs::exists(p / "gt.png"))
      dirs.push_back(p.string());
  }
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

ErrorFigures evaluate(const cv::Mat& disp, const Scene& scene, double delta) {
  if (disp.size() != scene.gt.size() || disp.type() != CV_32FC1)
    throw Error("disparity map does not match the scene '" + scene.name + "'");
  long nonocc = 0, nonoccBad = 0, all = 0, allBad = 0, disc = 0, discBad = 0, allValid = 0;
  long nonoccValid = 0, nonoccValidBad = 0, d1Bad = 0, d1ValidBad = 0;
  for (int y = 0; y < disp.rows; ++y)
    for (int x = 0; x < disp.cols; ++x) {
      const float d = disp.at<float>(y, x), g = scene.gt.at<float>(y, x);
      const bool valid = d >= 0;
      const bool bad = !valid || std::fabs(d - g) > delta;
      if (scene.all.at<uint8_t>(y, x) && g > 0) {
        ++all, allBad += bad, allValid += valid;
        const bool d1 = valid && isD1Error(d, g);
        d1Bad += !valid || d1, d1ValidBad += d1;
      }
      if (scene.nonocc.at<uint8_t>(y, x) && g > 0) {
        ++nonocc, nonoccBad += bad;
        if (valid) ++nonoccValid, nonoccValidBad += bad;
      }
      if (!scene.disc.empty() && scene.disc.at<uint8_t>(y, x) == 255 && g > 0) ++disc, discBad += bad;
    }
  auto pct = [](long a, long b) { return b ? 100.0 * double(a) / double(b) : 0.0; };
  ErrorFigures f;
  f.errNonocc = pct(nonoccBad, nonocc);
  f.errAll = pct(allBad, all);
  if (!scene.disc.empty()) f.errDisc = pct(discBad, disc);
  f.density = pct(allValid, all);
  f.errNonoccValid = pct(nonoccValidBad, nonoccValid);
  f.d1All = pct(d1Bad, all);
  f.d1Valid = pct(d1ValidBad, allValid);
  return f;
}

cv::Mat toFloat(const DisparityMap& map) {
  cv::Mat f(map.disp.size(), CV_32FC1);
  for (int y = 0; y < f.rows; ++y)
    for (int x = 0; x < f.cols; ++x)
      f.at<float>(y, x) = map.valid.at<uint8_t>(y, x) ? map.disp.at<uint16_t>(y, x) / float(kSubpixelOne) : -1.f;
  return f;
}

cv::Mat runOpenCvSgbm(const cv::Mat& left, const cv::Mat& right, int disparities, int mode) {
  const int block = 3, cn = left.channels();
  auto sgbm = cv::StereoSGBM::create(0, disparities, block, 8 * cn * block * block, 32 * cn * block * block, 1, 0, 10,
                                     100, 32, mode);
  cv::Mat raw;
  sgbm->compute(left, right, raw);
  cv::Mat out(raw.size(), CV_32FC1);
  for (int y = 0; y < raw.rows; ++y)
    for (int x = 0; x < raw.cols; ++x) {
      const short v = raw.at<short>(y, x);
      out.at<float>(y, x) = v < 0 ? -1.f : v / 16.f;
    }
  return out;
}

cv::Mat errorMap(const cv::Mat& disp, const Scene& scene, double delta) {
  cv::Mat out(disp.size(), CV_8UC3, cv::Scalar::all(0));
  for (int y = 0; y < disp.rows; ++y)
    for (int x = 0; x < disp.cols; ++x) {
      const float g = scene.gt.at<float>(y, x), d = disp.at<float>(y, x);
      if (!scene.all.at<uint8_t>(y, x) || g <= 0) continue;
      const bool occluded = !scene.nonocc.at<uint8_t>(y, x);
      cv::Vec3b c = d < 0                      ? cv::Vec3b(255, 64, 0)
                    : std::fabs(d - g) > delta ? cv::Vec3b(0, 0, 255)
                                               : cv::Vec3b(0, 160, 0);
      if (occluded) c = c / 2;  // occluded pixels dimmed
      out.at<cv::Vec3b>(y, x) = c;
    }
  return out;
}

namespace {

// Tick spacing (px) giving at most about 8 ticks over [0, maxDisparity].
float tickStep(float maxDisparity) {
  for (const float step : {1.f, 2.f, 4.f, 5.f, 8.f, 10.f, 16.f, 20.f, 32.f, 50.f, 64.f, 100.f})
    if (maxDisparity / step <= 8.f) return step;
  return 128.f;
}

std::string pixels(float v) {
  char text[16];
  std::snprintf(text, sizeof text, "%g", double(v));
  return text;
}

}  // namespace

cv::Mat sideBySide(const Scene& scene, const cv::Mat& disp, float maxDisparity, double delta) {
  cv::Mat left;
  if (scene.leftColor.channels() == 3)
    left = scene.leftColor.clone();
  else
    cv::cvtColor(scene.left, left, cv::COLOR_GRAY2BGR);
  const std::vector<cv::Mat> parts = {left, colorizeDisparity(scene.gt, maxDisparity),
                                      colorizeDisparity(disp, maxDisparity), errorMap(disp, scene, delta)};
  const int w = left.cols, h = left.rows;
  // Text and bar sizes follow the panel width (Middlebury: about 450 px).
  const double font = std::clamp(w / 750.0, 0.35, 0.8);
  const int line = int(std::lround(30 * font / 0.6)), pad = line / 3;
  const int titleH = line + pad, barH = std::max(8, line / 2), legendH = barH + 2 * line + pad;
  const cv::Scalar ink(30, 30, 30), muted(90, 90, 90);
  cv::Mat out(titleH + h + legendH, 4 * w, CV_8UC3, cv::Scalar::all(255));
  char deltaText[48];
  std::snprintf(deltaText, sizeof deltaText, "error (|d - gt| > %g px)", delta);
  const std::string titles[] = {"left image", "ground truth (px)", "result (px)", deltaText};
  for (int k = 0; k < 4; ++k) {
    parts[size_t(k)].copyTo(out(cv::Rect(k * w, titleH, w, h)));
    drawCentredText(out, titles[k], k * w + w / 2, titleH - pad, font, ink);
  }
  // Disparity colour bar under the ground truth and the result (their common scale).
  const cv::Rect bar(w + w / 8, titleH + h + pad, 2 * w - w / 4, barH);
  cv::Mat ramp(1, bar.width, CV_8UC1);
  for (int x = 0; x < bar.width; ++x)
    ramp.at<uint8_t>(0, x) = uint8_t(std::lround(255.0 * x / std::max(1, bar.width - 1)));
  cv::Mat rampColor;
  cv::applyColorMap(ramp, rampColor, cv::COLORMAP_JET);
  cv::resize(rampColor, out(bar), bar.size(), 0, 0, cv::INTER_NEAREST);
  cv::rectangle(out, bar, ink, 1);
  const float step = tickStep(maxDisparity);
  for (float v = 0; v <= maxDisparity + 1e-3f; v += step) {
    const int x = bar.x + int(std::lround(v / maxDisparity * (bar.width - 1)));
    cv::line(out, {x, bar.y + bar.height}, {x, bar.y + bar.height + pad}, ink, 1);
    drawCentredText(out, pixels(v), x, bar.y + bar.height + pad + line * 2 / 3, font * 0.8, ink);
  }
  drawCentredText(out, "disparity (px); black: none", bar.x + bar.width / 2, bar.y + bar.height + pad + line * 3 / 2,
                  font * 0.8, muted);
  // Error map legend (errorMap's colours; occluded pixels are drawn at half brightness).
  const std::pair<cv::Scalar, std::string> keys[] = {
      {cv::Scalar(0, 160, 0), "within"}, {cv::Scalar(0, 0, 255), "beyond"}, {cv::Scalar(255, 64, 0), "invalid"}};
  int x = 3 * w + pad;
  const int y = titleH + h + pad;
  for (const auto& [color, label] : keys) {
    cv::rectangle(out, cv::Rect(x, y, barH, barH), color, cv::FILLED);
    drawText(out, label, {x + barH + pad / 2, y + barH}, font * 0.8, ink);
    int base = 0;
    x += barH + pad + cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, font * 0.8, 1, &base).width + pad;
  }
  drawText(out, "dimmed: occluded", {3 * w + pad, y + barH + pad + line * 2 / 3}, font * 0.8, muted);
  return out;
}

namespace {

// level (CV_8UC1) in the JET colours, black where none (CV_8UC1, may be empty), under a
// title, above a colour bar whose left end is level leftLevel and right end 255 - leftLevel,
// with five ticks from leftValue to rightValue and a legend.
cv::Mat colourBarPicture(const cv::Mat& level, const cv::Mat& none, const std::string& title, int leftLevel,
                         double leftValue, double rightValue, const std::string& legend) {
  cv::Mat color;
  cv::applyColorMap(level, color, cv::COLORMAP_JET);
  if (!none.empty()) color.setTo(cv::Scalar::all(0), none);
  const int w = level.cols, h = level.rows;
  const double font = std::clamp(w / 750.0, 0.35, 0.8);
  const int line = int(std::lround(30 * font / 0.6)), pad = line / 3;
  const int titleH = line + pad, barH = std::max(8, line / 2), legendH = barH + 2 * line + pad;
  const cv::Scalar ink(30, 30, 30), muted(90, 90, 90);
  cv::Mat out(titleH + h + legendH, w, CV_8UC3, cv::Scalar::all(255));
  color.copyTo(out(cv::Rect(0, titleH, w, h)));
  int base = 0;  // the title fits the picture's width
  const double titleWidth = cv::getTextSize(title, cv::FONT_HERSHEY_SIMPLEX, font, 1, &base).width;
  drawCentredText(out, title, w / 2, titleH - pad, font * std::min(1.0, 0.95 * w / titleWidth), ink);
  const cv::Rect bar(w / 8, titleH + h + pad, w - w / 4, barH);
  cv::Mat ramp(1, bar.width, CV_8UC1);
  for (int x = 0; x < bar.width; ++x) {
    const double t = double(x) / std::max(1, bar.width - 1);  // 0 at the left end
    ramp.at<uint8_t>(0, x) = uint8_t(std::lround(leftLevel + (255 - 2 * leftLevel) * t));
  }
  cv::Mat rampColor;
  cv::applyColorMap(ramp, rampColor, cv::COLORMAP_JET);
  cv::resize(rampColor, out(bar), bar.size(), 0, 0, cv::INTER_NEAREST);
  cv::rectangle(out, bar, ink, 1);
  for (int k = 0; k <= 4; ++k) {
    const int x = bar.x + (bar.width - 1) * k / 4;
    cv::line(out, {x, bar.y + bar.height}, {x, bar.y + bar.height + pad}, ink, 1);
    drawCentredText(out, pixels(float(std::lround(leftValue + (rightValue - leftValue) * k / 4))), x,
                    bar.y + bar.height + pad + line * 2 / 3, font * 0.8, ink);
  }
  drawCentredText(out, legend, bar.x + bar.width / 2, bar.y + bar.height + pad + line * 3 / 2, font * 0.8, muted);
  return out;
}

}  // namespace

cv::Mat depthPicture(const cv::Mat& depthMm, const std::string& title) {
  if (depthMm.type() != CV_16UC1) throw Error("depthPicture: expected a 16-bit depth map");
  std::vector<uint16_t> valid;
  for (int y = 0; y < depthMm.rows; ++y)
    for (int x = 0; x < depthMm.cols; ++x)
      if (const uint16_t z = depthMm.at<uint16_t>(y, x); z && z != 0xffff) valid.push_back(z);  // not saturated
  std::sort(valid.begin(), valid.end());
  const double lo = valid.empty() ? 0 : valid[valid.size() * 2 / 100];
  const double hi = valid.empty() ? 1 : std::max(lo + 1, double(valid[valid.size() * 98 / 100]));
  cv::Mat level(depthMm.size(), CV_8UC1);  // 255 near .. 0 far
  for (int y = 0; y < depthMm.rows; ++y)
    for (int x = 0; x < depthMm.cols; ++x)
      level.at<uint8_t>(
          y, x) = uint8_t(std::lround(255.0 * std::clamp((hi - depthMm.at<uint16_t>(y, x)) / (hi - lo), 0.0, 1.0)));
  // Near (left) to far (right).
  return colourBarPicture(level, depthMm == 0, title, 255, lo, hi, "depth (mm); black: none");
}

cv::Mat confidencePicture(const cv::Mat& confidence, const std::string& title) {
  if (confidence.type() != CV_8UC1) throw Error("confidencePicture: expected an 8-bit confidence map");
  return colourBarPicture(confidence, cv::Mat(), title, 0, 0, 255, "confidence (0: invalid or none)");
}

}  // namespace sgm::eval
