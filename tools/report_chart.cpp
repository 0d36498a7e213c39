// SPDX-License-Identifier: Apache-2.0
#include "report_chart.hpp"
#include "report_util.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

namespace sgm::eval {

void drawText(cv::Mat& img, const std::string& s, cv::Point org, double scale, const cv::Scalar& color, int thickness) {
  cv::putText(img, s, org, cv::FONT_HERSHEY_SIMPLEX, scale, color, thickness, cv::LINE_AA);
}

void drawCentredText(cv::Mat& img, const std::string& s, int x, int y, double scale, const cv::Scalar& color,
                     int thickness) {
  int base = 0;
  const cv::Size size = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &base);
  drawText(img, s, {x - size.width / 2, y}, scale, color, thickness);
}

namespace {

const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kAxis(60, 60, 60), kGrid(225, 225, 225), kMuted(110, 110, 110);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// Bar colours (BGR): Table I rows, full pipeline rows, OpenCV rows.
const cv::Scalar kPalette[] = {
    {180, 119, 31},  {14, 127, 255}, {44, 160, 44},  {40, 39, 214},   {189, 103, 148}, {75, 86, 140},
    {194, 119, 227}, {34, 189, 188}, {207, 190, 23}, {150, 150, 150}, {70, 70, 70},
};

cv::Scalar methodColor(size_t index) { return kPalette[index % (sizeof kPalette / sizeof kPalette[0])]; }

struct Layout {
  cv::Rect plot;     // axes area
  double yMax = 10;  // top of the y axis (%)
  double yStep = 1;  // grid spacing (%)
  int legendX = 0;
};

// Text rotated 90 degrees counter-clockwise, reading bottom to top, centred on x,
// its lower end at bottomY. Drawn darkest-wins so it sits on a light background.
void verticalText(cv::Mat& img, const std::string& s, int x, int bottomY, double scale, const cv::Scalar& color) {
  int base = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, 1, &base);
  cv::Mat strip(size.height + base + 2, size.width + 2, CV_8UC3, kWhite);
  drawText(strip, s, {1, size.height + 1}, scale, color);
  cv::rotate(strip, strip, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect where(x - strip.cols / 2, bottomY - strip.rows, strip.cols, strip.rows);
  where &= cv::Rect(0, 0, img.cols, img.rows);
  if (where.empty()) return;
  cv::Mat dst = img(where);
  cv::min(dst,
          strip(cv::Rect(where.x - (x - strip.cols / 2), where.y - (bottomY - strip.rows), where.width, where.height)),
          dst);
}

void hatchedBar(cv::Mat& img, const cv::Rect& bar, const cv::Scalar& color) {
  if (bar.height <= 0) return;
  cv::Mat roi = img(bar);
  roi.setTo(kWhite);
  for (int k = -bar.height; k < bar.width; k += 5)
    cv::line(roi, {k, bar.height}, {k + bar.height, 0}, color, 1, cv::LINE_AA);
  cv::rectangle(img, bar, color, 2);
}

double niceStep(double yMax) { return yMax <= 10 ? 1 : yMax <= 20 ? 2 : yMax <= 50 ? 5 : 10; }

double largestValue(const TableReport& r) {
  double v = 0;
  for (const Method& m : r.methods)
    for (const std::string& scene : r.scenes) {
      if (const ErrorFigures* f = r.find(m.key, scene)) v = std::max(v, f->errNonocc);
      if (m.paper.count(scene)) v = std::max(v, m.paper.at(scene));
    }
  return v;
}

Layout makeLayout(const TableReport& r, cv::Size canvas) {
  Layout l;
  const int legendWidth = 330;
  l.plot = cv::Rect(90, 110, canvas.width - 90 - legendWidth - 30, canvas.height - 110 - 90);
  l.legendX = l.plot.br().x + 40;
  const double top = largestValue(r) * 1.12 + 0.5;  // room for the value labels
  l.yStep = niceStep(top);
  l.yMax = std::max(l.yStep, std::ceil(top / l.yStep) * l.yStep);
  return l;
}

int yPixel(const Layout& l, double value) { return l.plot.br().y - int(std::lround(value / l.yMax * l.plot.height)); }

void drawAxes(cv::Mat& img, const Layout& l, const std::string& label = "error in non-occluded regions (%)") {
  for (double v = 0; v <= l.yMax + 1e-9; v += l.yStep) {
    const int y = yPixel(l, v);
    cv::line(img, {l.plot.x, y}, {l.plot.br().x, y}, v == 0 ? kAxis : kGrid, 1);
    const std::string label = fixed(v, 0);
    int base = 0;
    const cv::Size size = cv::getTextSize(label, kFont, 0.5, 1, &base);
    drawText(img, label, {l.plot.x - 10 - size.width, y + size.height / 2}, 0.5, kAxis);
  }
  cv::line(img, l.plot.tl(), {l.plot.x, l.plot.br().y}, kAxis, 2);
  cv::line(img, {l.plot.x, l.plot.br().y}, l.plot.br(), kAxis, 2);
  int base = 0;
  const int half = cv::getTextSize(label, kFont, 0.6, 1, &base).width / 2;
  verticalText(img, label, 28, l.plot.y + l.plot.height / 2 + half, 0.6, kAxis);
}

// Horizontal positions of the bars of one group, in units of a bar width:
// ours and the paper's touch; a small gap between methods, a wider one between kinds.
struct Slot {
  size_t method;
  bool paper;
  double x;
};

std::vector<Slot> groupSlots(const std::vector<Method>& methods, double& width) {
  std::vector<Slot> slots;
  double x = 0;
  for (size_t i = 0; i < methods.size(); ++i) {
    if (i > 0) x += methods[i].kind != methods[i - 1].kind ? 1.2 : 0.35;
    slots.push_back({i, false, x}), x += 1;
    if (!methods[i].paper.empty()) slots.push_back({i, true, x}), x += 1;
  }
  width = x;
  return slots;
}

// Short name of each kind of method under its bars.
void drawClusterLabels(cv::Mat& img, const Layout& l, const std::vector<Method>& methods,
                       const std::vector<Slot>& slots, double x0, double barWidth) {
  const char* names[] = {"Table I config.", "full", "OpenCV"};
  for (int kind = 0; kind < 3; ++kind) {
    double first = -1, last = -1;
    for (const Slot& s : slots)
      if (int(methods[s.method].kind) == kind) {
        if (first < 0) first = s.x;
        last = s.x + 1;
      }
    if (first < 0) continue;
    const int a = int(x0 + first * barWidth), b = int(x0 + last * barWidth);
    cv::line(img, {a + 1, l.plot.br().y + 6}, {b - 1, l.plot.br().y + 6}, kGrid, 2);
    drawCentredText(img, names[kind], (a + b) / 2, l.plot.br().y + 20, 0.38, kMuted);
  }
}

void drawGroup(cv::Mat& img, const Layout& l, const TableReport& r, const std::string& scene, cv::Range span) {
  double units = 0;
  const std::vector<Slot> slots = groupSlots(r.methods, units);
  const double barWidth = 0.9 * span.size() / units;
  const double x0 = span.start + 0.05 * span.size();
  for (const Slot& s : slots) {
    const Method& m = r.methods[s.method];
    const ErrorFigures* f = r.find(m.key, scene);
    const auto paper = m.paper.find(scene);
    if (s.paper ? paper == m.paper.end() : !f) continue;
    const double value = s.paper ? paper->second : f->errNonocc;
    const int left = int(std::lround(x0 + s.x * barWidth)), right = int(std::lround(x0 + (s.x + 1) * barWidth));
    const cv::Rect bar(left, yPixel(l, value), std::max(1, right - left - (s.paper ? 1 : 0)),
                       yPixel(l, 0) - yPixel(l, value));
    if (s.paper)
      hatchedBar(img, bar, methodColor(s.method));
    else
      cv::rectangle(img, bar, methodColor(s.method), cv::FILLED);
    verticalText(img, fixed(value, 1), (left + right) / 2, bar.y - 4, 0.4, s.paper ? kMuted : kBlack);
  }
  drawClusterLabels(img, l, r.methods, slots, x0, barWidth);
}

std::string groupTitle(const TableReport& r, const std::string& scene) {
  std::string title = scene;
  title[0] = char(std::toupper((unsigned char)title[0]));
  if (!r.present.count(scene)) return title + " (missing)";
  if (r.derivedNonocc.count(scene)) return title + " *";
  return title;
}

void drawGroups(cv::Mat& img, const Layout& l, const TableReport& r) {
  const int n = int(r.scenes.size());
  for (int i = 0; i < n; ++i) {
    const cv::Range span(l.plot.x + l.plot.width * i / n, l.plot.x + l.plot.width * (i + 1) / n);
    if (i > 0) cv::line(img, {span.start, l.plot.y}, {span.start, l.plot.br().y + 8}, kGrid, 1);
    drawGroup(img, l, r, r.scenes[i], span);
    drawCentredText(img, groupTitle(r, r.scenes[i]), (span.start + span.end) / 2, l.plot.br().y + 50, 0.75, kBlack, 2);
  }
}

void drawLegend(cv::Mat& img, const Layout& l, const TableReport& r) {
  int y = l.plot.y + 10;
  const int x = l.legendX;
  MethodKind kind = r.methods.empty() ? MethodKind::kTable1 : r.methods.front().kind;
  const char* kindTitle[] = {"Table I configuration", "Full pipeline", "OpenCV StereoSGBM"};
  drawText(img, kindTitle[int(kind)], {x, y}, 0.5, kMuted, 1);
  y += 12;
  for (size_t i = 0; i < r.methods.size(); ++i) {
    const Method& m = r.methods[i];
    if (m.kind != kind) {
      kind = m.kind;
      y += 16;
      drawText(img, kindTitle[int(kind)], {x, y}, 0.5, kMuted, 1);
      y += 12;
    }
    cv::rectangle(img, cv::Rect(x, y, 22, 16), methodColor(i), cv::FILLED);
    std::string label = m.kind == MethodKind::kFull ? m.label.substr(m.label.find(", ") + 2) : m.label;
    if (m.hardwareDefault) label += " (hw default)";
    drawText(img, label, {x + 32, y + 13}, 0.5, kBlack);
    y += 26;
  }
  y += 14;
  hatchedBar(img, cv::Rect(x, y, 22, 16), kAxis);
  drawText(img, "paper, Table I", {x + 32, y + 13}, 0.5, kBlack);
  if (!r.derivedNonocc.empty()) drawText(img, "* nonocc mask derived from GT", {x, y + 46}, 0.45, kMuted);
}

void drawTitle(cv::Mat& img, const TableReport& r, const std::string& title) {
  drawText(img, title, {90, 42}, 0.95, kBlack, 2);
  drawText(img,
           "error in non-occluded regions (%, delta = " + fixed(r.delta, 0) + " px, invalid = error), D = " +
               std::to_string(r.disparities) + ".  Solid: ours.  Hatched: the paper's figure.",
           {90, 76}, 0.55, kMuted);
}

// ------------------------------------------------------------------ pool chart

struct PoolBar {
  std::string label;
  cv::Scalar color;
  bool hatched;
  std::optional<double> (*value)(const PoolRow&);
};

std::optional<double> poolOurs(const PoolRow& r) { return strictFigure(r.set, r.ours); }
std::optional<double> poolToday(const PoolRow& r) {
  return r.today ? std::optional<double>(strictFigure(r.set, *r.today)) : std::nullopt;
}
std::optional<double> poolOpenCvStrict(const PoolRow& r) {
  return r.opencv ? std::optional<double>(strictFigure(r.set, *r.opencv)) : std::nullopt;
}
std::optional<double> poolOpenCvValid(const PoolRow& r) {
  return r.opencv ? std::optional<double>(validFigure(r.set, *r.opencv)) : std::nullopt;
}

std::vector<PoolBar> poolBars(const PoolReport& r) {
  std::vector<PoolBar> bars = {{"ours", kPalette[0], false, poolOurs}};
  if (r.comparesToday) bars.push_back({"today's defaults", kPalette[9], false, poolToday});
  if (r.options.opencv) {
    bars.push_back({"OpenCV SGBM, invalid = error", kPalette[1], false, poolOpenCvStrict});
    bars.push_back({"OpenCV SGBM, valid pixels only", kPalette[1], true, poolOpenCvValid});
  }
  return bars;
}

}  // namespace

cv::Mat poolChart(const PoolReport& r, const std::string& title) {
  const std::vector<PoolBar> bars = poolBars(r);
  const int n = std::max<int>(1, int(r.rows.size()));
  const int width = std::max(1400, 200 + n * (20 * int(bars.size()) + 24) + 330);
  cv::Mat img(820, width, CV_8UC3, kWhite);
  double top = 0;
  for (const PoolRow& row : r.rows)
    for (const PoolBar& b : bars)
      if (const auto v = b.value(row)) top = std::max(top, *v);
  Layout l;
  l.plot = cv::Rect(90, 125, width - 90 - 330 - 30, 820 - 125 - 190);
  l.legendX = l.plot.br().x + 40;
  top = top * 1.15 + 0.5;
  l.yStep = niceStep(top);
  l.yMax = std::max(l.yStep, std::ceil(top / l.yStep) * l.yStep);
  drawAxes(img, l, "error (%): bad-" + fixed(r.options.delta, 1) + " nonocc / KITTI D1");
  std::string previousSet = "\x01";
  for (int i = 0; i < int(r.rows.size()); ++i) {
    const PoolRow& row = r.rows[size_t(i)];
    const cv::Range span(l.plot.x + l.plot.width * i / n, l.plot.x + l.plot.width * (i + 1) / n);
    if (row.set != previousSet) {
      cv::line(img, {span.start, l.plot.y}, {span.start, l.plot.br().y + 150}, kGrid, 1);
      drawText(img, row.set.empty() ? "(no set)" : row.set, {span.start + 4, l.plot.br().y + 175}, 0.45, kMuted);
      previousSet = row.set;
    }
    const double barWidth = 0.8 * span.size() / double(bars.size());
    for (size_t k = 0; k < bars.size(); ++k) {
      const auto v = bars[k].value(row);
      if (!v) continue;
      const int left = int(std::lround(span.start + 0.1 * span.size() + k * barWidth));
      const int right = int(std::lround(span.start + 0.1 * span.size() + (k + 1) * barWidth));
      const cv::Rect bar(left, yPixel(l, *v), std::max(1, right - left), yPixel(l, 0) - yPixel(l, *v));
      if (bars[k].hatched)
        hatchedBar(img, bar, bars[k].color);
      else
        cv::rectangle(img, bar, bars[k].color, cv::FILLED);
      verticalText(img, fixed(*v, 1), (left + right) / 2, bar.y - 3, 0.35, kBlack);
    }
    int base = 0;
    const int textWidth = cv::getTextSize(row.scene, kFont, 0.45, 1, &base).width;
    verticalText(img, row.scene, (span.start + span.end) / 2, l.plot.br().y + 10 + textWidth, 0.45, kBlack);
  }
  int y = l.plot.y + 10;
  for (const PoolBar& b : bars) {
    const cv::Rect key(l.legendX, y, 22, 16);
    if (b.hatched)
      hatchedBar(img, key, b.color);
    else
      cv::rectangle(img, key, b.color, cv::FILLED);
    drawText(img, b.label, {l.legendX + 32, y + 13}, 0.5, kBlack);
    y += 26;
  }
  drawText(img, title, {90, 42}, 0.95, kBlack, 2);
  drawText(img,
           "error (%): Middlebury bad-" + fixed(r.options.delta, 1) +
               " non-occluded, KITTI D1 (> 3 px and > 5 %), over pixels with ground truth; D = ndisp per scene",
           {90, 72}, 0.55, kMuted);
  drawText(img, "ours: " + goldenParamsText(r.options.params), {90, 96}, 0.42, kMuted);
  return img;
}

cv::Mat table1Chart(const TableReport& r, const std::string& title) {
  const int width = std::max(1500, 420 + 380 * int(r.scenes.size()));
  cv::Mat img(900, width, CV_8UC3, kWhite);
  const Layout l = makeLayout(r, img.size());
  drawAxes(img, l);
  drawGroups(img, l, r);
  drawLegend(img, l, r);
  drawTitle(img, r, title);
  return img;
}

}  // namespace sgm::eval
