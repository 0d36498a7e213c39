// SPDX-License-Identifier: Apache-2.0
#include "report_bench.hpp"

#include "report_json.hpp"

#include "sgm/parallel.hpp"
#include "sgm/pipeline.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

namespace sgm::eval {

namespace {

double timeMs(const std::function<void()>& job) {
  const auto start = std::chrono::steady_clock::now();
  job();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string line(const char* format, double a, double b = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b);
  return std::string(buf) + "\n";
}

}  // namespace

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double BenchResult::opencvMs() const { return std::min(opencvColorMs, opencvGrayMs); }
std::string BenchResult::opencvInput() const { return opencvGrayMs <= opencvColorMs ? "gray" : "color"; }
double BenchResult::ratio() const { return opencvMs() > 0 ? goldenMs / opencvMs() : 0; }

BenchResult runBench(const Scene& scene, int repeats) {
  const Params params;  // the hardware configuration
  const int opencvD = params.disparities;
  const std::vector<std::function<void()>> jobs = {
      [&] { runPipeline(toGray(scene.leftColor), toGray(scene.rightColor), params); },
      [&] { runOpenCvSgbm(scene.leftColor, scene.rightColor, opencvD, cv::StereoSGBM::MODE_SGBM); },
      [&] { runOpenCvSgbm(scene.left, scene.right, opencvD, cv::StereoSGBM::MODE_SGBM); },
  };
  for (const auto& job : jobs) job();  // warm-up
  std::vector<std::vector<double>> times(jobs.size());
  for (int r = 0; r < repeats; ++r)
    for (size_t j = 0; j < jobs.size(); ++j) times[j].push_back(timeMs(jobs[j]));

  BenchResult b;
  b.scene = scene.name;
  b.width = scene.left.cols, b.height = scene.left.rows;
  b.disparities = params.disparities;
  b.repeats = repeats;
  b.goldenThreads = workerCount();
  b.opencvThreads = cv::getNumThreads();
  b.goldenMs = median(times[0]);
  b.opencvColorMs = median(times[1]);
  b.opencvGrayMs = median(times[2]);
  return b;
}

std::string benchJson(const BenchResult& b) {
  JsonWriter j;
  j.beginObject();
  j.key("scene").string(b.scene);
  j.key("width").integer(b.width);
  j.key("height").integer(b.height);
  j.key("disparities").integer(b.disparities);
  j.key("golden_ms").real(b.goldenMs);
  j.key("opencv_sgbm_ms").real(b.opencvMs());
  j.key("opencv_sgbm_gray_ms").real(b.opencvGrayMs);
  j.key("opencv_sgbm_color_ms").real(b.opencvColorMs);
  j.key("opencv_sgbm_input").string(b.opencvInput());
  j.key("ratio").real(b.ratio());
  j.key("threads").integer(b.goldenThreads);
  j.key("opencv_threads").integer(b.opencvThreads);
  j.key("repeats").integer(b.repeats);
  j.endObject();
  return j.str();
}

std::string benchText(const BenchResult& b) {
  std::string out = "scene " + b.scene + " " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                    ", D=" + std::to_string(b.disparities) + ", median of " + std::to_string(b.repeats) +
                    " interleaved runs after one warm-up; golden threads " + std::to_string(b.goldenThreads) +
                    ", OpenCV threads " + std::to_string(b.opencvThreads) + "\n";
  out += line("golden model (toGray + runPipeline, Params{}): %9.2f ms", b.goldenMs);
  out += line("OpenCV StereoSGBM MODE_SGBM, colour input:     %9.2f ms", b.opencvColorMs);
  out += line("OpenCV StereoSGBM MODE_SGBM, gray input:       %9.2f ms", b.opencvGrayMs);
  out += "ratio against the faster OpenCV variant (" + b.opencvInput() + line(" input, %.2f ms):", b.opencvMs());
  out += line("golden/OpenCV time ratio: %.2f", b.ratio());
  return out;
}

}  // namespace sgm::eval
