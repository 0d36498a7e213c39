// SPDX-License-Identifier: Apache-2.0
#include "report_confidence.hpp"

#include "report_chart.hpp"
#include "report_json.hpp"
#include "report_pool.hpp"
#include "report_table.hpp"
#include "report_util.hpp"

#include "sgm/pipeline.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace sgm::eval {

double errorOfMostConfident(const std::vector<uint8_t>& confidence, const std::vector<uint8_t>& errors,
                            double fraction) {
  if (confidence.size() != errors.size()) throw Error("confidence and error lists differ in length");
  if (confidence.empty()) return 0;
  std::array<long, 256> count{}, bad{};
  for (size_t i = 0; i < confidence.size(); ++i) ++count[confidence[i]], bad[confidence[i]] += errors[i] != 0;
  const double kept = fraction * double(confidence.size());
  double taken = 0, wrong = 0;
  for (int c = 255; c >= 0 && taken < kept; --c) {
    if (!count[size_t(c)]) continue;
    const double take = std::min(double(count[size_t(c)]), kept - taken);
    wrong += take * double(bad[size_t(c)]) / double(count[size_t(c)]);
    taken += take;
  }
  return taken > 0 ? 100.0 * wrong / taken : 0;
}

ConfidenceReport computeConfidence(const std::vector<Scene>& scenes, const Params& params, int fallbackDisparities,
                                   double delta) {
  ConfidenceReport report;
  for (int p = 10; p <= 100; p += 10) report.percents.push_back(p);
  report.delta = delta;
  report.params = params;
  std::vector<std::pair<std::string, std::vector<const ConfidenceRow*>>> groups;
  for (const Scene& scene : scenes) {
    if (!scene.hasGroundTruth()) continue;
    Params p = params;
    p.disparities = scene.ndisp > 0 ? scene.ndisp : fallbackDisparities;
    p.validate();
    cv::Mat confidence;
    const cv::Mat disparity = toFloat(runPipeline(scene.left, scene.right, p, &confidence));
    const bool kitti = isKittiSet(scene.set);
    std::vector<uint8_t> conf, errors;
    for (int y = 0; y < disparity.rows; ++y)
      for (int x = 0; x < disparity.cols; ++x) {
        const float g = scene.gt.at<float>(y, x), d = disparity.at<float>(y, x);
        if (g <= 0 || !(kitti ? scene.all : scene.nonocc).at<uint8_t>(y, x)) continue;
        conf.push_back(confidence.at<uint8_t>(y, x));
        errors.push_back(d < 0 || (kitti ? isD1Error(d, g) : std::fabs(d - g) > delta));
      }
    ConfidenceRow row{scene.name, scene.set, p.disparities, long(conf.size()), {}};
    for (int percent : report.percents) row.errorKept.push_back(errorOfMostConfident(conf, errors, percent / 100.0));
    report.rows.push_back(row);
  }
  for (const char* group : {"middlebury", "kitti"}) {
    std::vector<double> mean(report.percents.size(), 0);
    int n = 0;
    for (const ConfidenceRow& row : report.rows) {
      if (setGroup(row.set) != group) continue;
      for (size_t i = 0; i < mean.size(); ++i) mean[i] += row.errorKept[i];
      ++n;
    }
    if (!n) continue;
    for (double& m : mean) m /= n;
    report.means.emplace_back(group, mean);
  }
  return report;
}

std::string confidenceMarkdown(const ConfidenceReport& report) {
  std::ostringstream md;
  md << "# Confidence: the error of the most confident pixels\n\n"
     << "The golden model's confidence (docs/algorithm.md, section 7b) ranks the evaluated pixels; each column is the "
        "error of the most confident P % of them (Middlebury: bad-"
     << fixed(report.delta, 1)
     << " over the nonocc mask; KITTI: D1 over every pixel with ground truth; invalid output counts as an error). "
        "100 % is every pixel, the figure of `sgm-eval pool`.\n\n"
     << "Settings: " << goldenParamsText(report.params) << ".\n\n| scene | set | D | pixels |";
  for (int p : report.percents) md << " " << p << " % |";
  md << "\n|---|---|---:|---:|";
  for (size_t i = 0; i < report.percents.size(); ++i) md << "---:|";
  md << "\n";
  for (const ConfidenceRow& row : report.rows) {
    md << "| " << row.scene << " | " << row.set << " | " << row.disparities << " | " << row.pixels << " |";
    for (double e : row.errorKept) md << " " << fixed(e, 2) << " |";
    md << "\n";
  }
  for (const auto& [group, mean] : report.means) {
    md << "| **mean " << group << "** | | | |";
    for (double e : mean) md << " **" << fixed(e, 2) << "** |";
    md << "\n";
  }
  return md.str();
}

std::string confidenceJson(const ConfidenceReport& report) {
  JsonWriter j;
  j.beginObject().key("delta").real(report.delta).key("percents").beginArray();
  for (int p : report.percents) j.integer(p);
  j.endArray().key("params").beginObject();
  writeGoldenParamFields(j, report.params);
  j.endObject().key("scenes").beginArray();
  for (const ConfidenceRow& row : report.rows) {
    j.beginObject()
        .key("scene")
        .string(row.scene)
        .key("set")
        .string(row.set)
        .key("disparities")
        .integer(row.disparities);
    j.key("pixels").integer(row.pixels).key("error_kept").beginArray();
    for (double e : row.errorKept) j.real(e);
    j.endArray().endObject();
  }
  j.endArray().key("means").beginArray();
  for (const auto& [group, mean] : report.means) {
    j.beginObject().key("group").string(group).key("error_kept").beginArray();
    for (double e : mean) j.real(e);
    j.endArray().endObject();
  }
  j.endArray().endObject();
  return j.str();
}

cv::Mat confidenceChart(const ConfidenceReport& report) {
  const int width = 900, height = 560, left = 80, right = 200, top = 60, bottom = 70;
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int plotW = width - left - right, plotH = height - top - bottom;
  double yMax = 1;
  for (const ConfidenceRow& row : report.rows)
    for (double e : row.errorKept) yMax = std::max(yMax, e);
  yMax = std::ceil(yMax / 5) * 5;
  const auto px = [&](double percent) { return left + int(std::lround(percent / 100.0 * plotW)); };
  const auto py = [&](double error) { return top + plotH - int(std::lround(error / yMax * plotH)); };
  drawCentredText(img, "Confidence ranks the errors: error of the most confident pixels", width / 2, 32, 0.7,
                  cv::Scalar(0, 0, 0), 2);
  for (int t = 0; t <= 5; ++t) {
    const double e = yMax * t / 5;
    cv::line(img, {left, py(e)}, {left + plotW, py(e)}, cv::Scalar(225, 225, 225), 1);
    drawText(img, fixed(e, 0), {left - 40, py(e) + 5}, 0.45, cv::Scalar(0, 0, 0));
  }
  for (int p = 0; p <= 100; p += 10) {
    cv::line(img, {px(p), top + plotH}, {px(p), top + plotH + 5}, cv::Scalar(0, 0, 0), 1);
    drawCentredText(img, std::to_string(p), px(p), top + plotH + 22, 0.45, cv::Scalar(0, 0, 0));
  }
  cv::rectangle(img, {left, top}, {left + plotW, top + plotH}, cv::Scalar(0, 0, 0), 1);
  drawCentredText(img, "most confident pixels kept (%)", left + plotW / 2, height - 18, 0.5, cv::Scalar(0, 0, 0));
  drawText(img, "error (%)", {10, top - 12}, 0.5, cv::Scalar(0, 0, 0));
  const auto polyline = [&](const std::vector<double>& errors, const cv::Scalar& colour, int thickness) {
    for (size_t i = 1; i < errors.size(); ++i)
      cv::line(img, {px(report.percents[i - 1]), py(errors[i - 1])}, {px(report.percents[i]), py(errors[i])}, colour,
               thickness, cv::LINE_AA);
  };
  const cv::Scalar middlebury(200, 120, 40), kitti(40, 120, 220);
  for (const ConfidenceRow& row : report.rows)
    polyline(row.errorKept, setGroup(row.set) == "kitti" ? cv::Scalar(190, 215, 245) : cv::Scalar(240, 215, 190), 1);
  int legendY = top + 20;
  for (const auto& [group, mean] : report.means) {
    const cv::Scalar colour = group == "kitti" ? kitti : middlebury;
    polyline(mean, colour, 3);
    cv::line(img, {left + plotW + 15, legendY - 5}, {left + plotW + 45, legendY - 5}, colour, 3);
    drawText(img, "mean " + group, {left + plotW + 52, legendY}, 0.45, cv::Scalar(0, 0, 0));
    legendY += 24;
  }
  cv::line(img, {left + plotW + 15, legendY - 5}, {left + plotW + 45, legendY - 5}, cv::Scalar(200, 200, 200), 1);
  drawText(img, "each scene", {left + plotW + 52, legendY}, 0.45, cv::Scalar(0, 0, 0));
  return img;
}

}  // namespace sgm::eval
