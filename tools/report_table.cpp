// SPDX-License-Identifier: Apache-2.0
#include "report_table.hpp"
#include "report_util.hpp"

#include "report_json.hpp"

#include "sgm/pipeline.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sgm::eval {

namespace {

struct PaperRow {
  CostMode mode;
  const char* label;
  double figures[4];  // cones, teddy, sawtooth, venus (%)
};

// Yao & Cheng, Table I: error matching ratios with different matching costs.
const PaperRow kPaperTable1[] = {
    {CostMode::kSad, "SAD", {9.1, 13.7, 4.8, 3.3}},           {CostMode::kBt, "BT", {7.7, 10.4, 4.0, 3.1}},
    {CostMode::kRt, "Rank filter/AD", {7.5, 11.7, 3.1, 5.0}}, {CostMode::kRsad, "Rank SAD", {6.2, 9.9, 2.8, 2.5}},
    {CostMode::kSadRt, "SAD+RT", {8.0, 12.6, 3.9, 3.4}},      {CostMode::kUnified, "RSAD+RT", {6.6, 11.1, 3.2, 3.8}},
};

// Penalties of the Table I rows on the paper's window (9x9, P2' / dI, equal
// weights, Table I configuration), swept like the defaults: P1 {8, 20, 50, 100} x
// P2' {80, 160, 255} (+ 500 for the software modes), lowest mean nonocc over the
// four scenes (docs/algorithm.md section 11).
struct PaperWindowPenalties {
  CostMode mode;
  int p1, p2;
};
const PaperWindowPenalties kPaperWindowPenalties[] = {
    // Measured 2026-11-24 (sgm-eval run --preset paper --mode M --p1 N --p2 N --lr off --fill off
    // --snap off); mean nonocc of the four scenes. The hardware modes' optimum is at the RTL's
    // P2' limit (255), sad+rt's and bt's at the grid's 500.
    {CostMode::kSad, 8, 255},       // 7.40
    {CostMode::kBt, 20, 500},       // 7.80
    {CostMode::kRt, 50, 255},       // 4.87
    {CostMode::kRsad, 20, 255},     // 3.92
    {CostMode::kSadRt, 20, 500},    // 4.79
    {CostMode::kUnified, 50, 255},  // 4.20
};

const char* costLabel(CostMode mode) {
  for (const PaperRow& row : kPaperTable1)
    if (row.mode == mode) return row.label;
  return costModeName(mode);
}

std::map<std::string, double> paperFigures(const PaperRow& row) {
  std::map<std::string, double> out;
  for (size_t i = 0; i < paperScenes().size(); ++i) out[paperScenes()[i]] = row.figures[i];
  return out;
}

Method goldenMethod(std::string key, std::string label, MethodKind kind, const Params& params) {
  Method m;
  m.key = std::move(key);
  m.label = std::move(label);
  m.kind = kind;
  m.params = params;
  return m;
}

Method opencvMethod(std::string key, std::string label, int mode, int disparities) {
  Method m;
  m.key = std::move(key);
  m.label = std::move(label);
  m.kind = MethodKind::kOpenCv;
  m.opencvMode = mode;
  m.params.disparities = opencvDisparities(disparities);
  return m;
}

const char* opencvModeName(int mode) { return mode == cv::StereoSGBM::MODE_HH ? "MODE_HH" : "MODE_SGBM"; }

std::vector<std::string> columnOrder(const std::vector<Scene>& scenes) {
  std::vector<std::string> columns = paperScenes();
  std::vector<std::string> extra;
  for (const Scene& s : scenes)
    if (std::find(columns.begin(), columns.end(), s.name) == columns.end()) extra.push_back(s.name);
  std::sort(extra.begin(), extra.end());
  columns.insert(columns.end(), extra.begin(), extra.end());
  return columns;
}

// ------------------------------------------------------------------ markdown

std::string optFixed(const std::optional<double>& v) { return v ? fixed(*v, 2) : "-"; }

std::string titleCase(std::string name) {
  if (!name.empty()) name[0] = char(std::toupper((unsigned char)name[0]));
  return name;
}

std::string displayLabel(const TableReport& r, const Method& m) {
  return m.key == r.hardwareDefault ? m.label + " **(hardware default)**" : m.label;
}

// Mean over the scenes of a getter, when every scene has a value.
template <typename Get>
std::optional<double> meanOver(const std::vector<std::string>& scenes, Get get) {
  double sum = 0;
  for (const std::string& s : scenes) {
    const std::optional<double> v = get(s);
    if (!v) return std::nullopt;
    sum += *v;
  }
  return scenes.empty() ? std::nullopt : std::optional<double>(sum / double(scenes.size()));
}

std::optional<double> ours(const TableReport& r, const Method& m, const std::string& scene) {
  const ErrorFigures* f = r.find(m.key, scene);
  return f ? std::optional<double>(f->errNonocc) : std::nullopt;
}

std::optional<double> paperFigure(const Method& m, const std::string& scene) {
  auto it = m.paper.find(scene);
  return it == m.paper.end() ? std::nullopt : std::optional<double>(it->second);
}

std::string comparisonCell(const std::optional<double>& our, const std::optional<double>& paper) {
  std::string cell = our ? fixed(*our, 2) : "-";
  if (paper) cell += " (" + fixed(*paper, 1) + ")";
  return cell;
}

std::string table1Row(const TableReport& r, const Method& m) {
  std::string row = "| " + displayLabel(r, m) + " | `" + m.key + "` |";
  for (const std::string& s : r.scenes) row += " " + comparisonCell(ours(r, m, s), paperFigure(m, s)) + " |";
  const auto& paper = paperScenes();
  const auto ourMean = meanOver(paper, [&](const std::string& s) { return ours(r, m, s); });
  const auto paperMean = meanOver(paper, [&](const std::string& s) { return paperFigure(m, s); });
  return row + " " + comparisonCell(ourMean, paperMean) + " |\n";
}

std::string figuresRow(const std::string& scene, const Method& m, const ErrorFigures* f) {
  std::string row = "| " + scene + " | `" + m.key + "` | ";
  if (!f) return row + "- | - | - | - | - |\n";
  return row + fixed(f->errNonocc, 2) + " | " + fixed(f->errAll, 2) + " | " + optFixed(f->errDisc) + " | " +
         fixed(f->density, 2) + " | " + fixed(f->errNonoccValid, 2) + " |\n";
}

std::string perSceneMarkdown(const TableReport& r) {
  std::string md =
      "## Figures per scene and method\n\n"
      "err_* = % of the pixels of the mask that are invalid or off by more than delta; density = % of "
      "`all` pixels with a valid disparity; err_nonocc_valid = % of the valid nonocc pixels that are off.\n\n"
      "| Scene | Method | err_nonocc | err_all | err_disc | density | err_nonocc_valid |\n"
      "|---|---|---:|---:|---:|---:|---:|\n";
  for (const std::string& s : r.scenes)
    for (const Method& m : r.methods) md += figuresRow(s, m, r.find(m.key, s));
  return md + "\n";
}

std::string onOff(bool on) { return on ? "on" : "off"; }

std::string paramsRow(const TableReport& r, const Method& m) {
  std::string row = "| `" + m.key + "` | " + methodKindName(m.kind) + " | ";
  if (m.kind == MethodKind::kOpenCv) {
    const int cn = r.opencvChannels;
    return row + "StereoSGBM " + opencvModeName(m.opencvMode) + ", D=" + std::to_string(m.params.disparities) +
           ", blockSize 3, P1=" + std::to_string(8 * cn * 9) + ", P2=" + std::to_string(32 * cn * 9) +
           ", uniqueness 10, speckle 100/32, disp12MaxDiff 1, " + std::to_string(cn) + "-channel input |\n";
  }
  return row + "D=" + std::to_string(m.params.disparities) + ", " + goldenParamsText(m.params) + " |\n";
}

std::string notesMarkdown(const TableReport& r) {
  std::string md =
      "- **Table I on the paper's window** (rows `paper-*`): the paper's 9x9 census, `P2r = max(P1, P2' / dI)` and "
      "the plain sum of the four paths (equal weights), in the Table I configuration below, with P1 / P2' swept per "
      "cost on that window. These are the rows to compare with the paper's figures.\n"
      "- **Table I configuration, our window** (rows `sad` .. `unified`): the golden model with `defaultParams(mode)`, "
      "for `rsad` the `four-path` preset (9x5 census, P2 knee, weights 3,2,3,2, four paths: the cost is what differs) but "
      "the left-right check, hole filling and edge snapping off (`lrTolerance = -1`, `fill = false`, `snap = false`); sub-pixel refinement and "
      "the 5x5 median stay as in `defaultParams` (on). The paper's figure is in parentheses.\n"
      "- **Full pipeline** (rows `full-*`): `defaultParams(mode)` as is (LR check, hole filling, sub-pixel, median; "
      "for `rsad` the defaults: the fifth path, the AD term, uniqueness 15, the path restart, no snapping; the other modes with edge "
      "snapping, four paths) for each cost mode the hardware implements; `" +
      r.hardwareDefault +
      "` is the hardware default (`Params{}.mode`); `full-four-path` is the `four-path` preset (the defaults before "
      "issue 15); `full-paper` is the `paper` preset (9x9, `unified`, P2' / dI, "
      "equal weights, LR check, sub-pixel, median, no filling, no snapping).\n"
      "- **OpenCV** rows: `cv::StereoSGBM` (settings of OpenCV's stereo_match sample) on the colour images, "
      "same process, " +
      std::to_string(opencvDisparities(r.disparities)) +
      " disparities.\n"
      "- Error = % of non-occluded pixels (`nonocc` mask, known ground truth) whose disparity is invalid or "
      "differs from the ground truth by more than delta = " +
      fixed(r.delta, 1) +
      " px (the paper's eq. (5)). "
      "Mean = mean over the paper's four scenes.\n";
  for (const std::string& s : r.derivedNonocc)
    md += "- " + titleCase(s) +
          ": no nonocc.png; the non-occluded mask was derived from the ground truth "
          "(`deriveNonOccluded`), so its figures are not exactly the Middlebury protocol.\n";
  for (const std::string& s : r.scenes)
    if (!r.present.count(s)) md += "- " + titleCase(s) + ": scene not found under the data directory (\"-\").\n";
  return md;
}

// ------------------------------------------------------------------ JSON

void writeParams(JsonWriter& j, const TableReport& r, const Method& m) {
  j.beginObject();
  j.key("disparities").integer(m.params.disparities);
  if (m.kind == MethodKind::kOpenCv) {
    const int cn = r.opencvChannels;
    j.key("mode").string(opencvModeName(m.opencvMode));
    j.key("block_size").integer(3);
    j.key("p1").integer(8 * cn * 9);
    j.key("p2").integer(32 * cn * 9);
    j.key("uniqueness_ratio").integer(10);
    j.key("speckle_window_size").integer(100);
    j.key("speckle_range").integer(32);
    j.key("disp12_max_diff").integer(1);
    j.key("input_channels").integer(cn);
  } else {
    writeGoldenParamFields(j, m.params);
  }
  j.endObject();
}

void writeFigures(JsonWriter& j, const ErrorFigures* f) {
  if (!f) {
    j.null();
    return;
  }
  j.beginObject();
  j.key("err_nonocc").real(f->errNonocc);
  j.key("err_all").real(f->errAll);
  j.key("err_disc").real(f->errDisc);
  j.key("density").real(f->density);
  j.key("err_nonocc_valid").real(f->errNonoccValid);
  j.endObject();
}

void writeMethod(JsonWriter& j, const TableReport& r, const Method& m) {
  j.beginObject();
  j.key("key").string(m.key);
  j.key("label").string(m.label);
  j.key("kind").string(methodKindName(m.kind));
  j.key("params");
  writeParams(j, r, m);
  j.key("paper");
  if (m.paper.empty()) {
    j.null();
  } else {
    j.beginObject();
    for (const std::string& s : paperScenes()) j.key(s).real(paperFigure(m, s));
    j.endObject();
  }
  j.key("results").beginObject();
  for (const std::string& s : r.scenes) {
    j.key(s);
    writeFigures(j, r.find(m.key, s));
  }
  j.endObject();
  j.endObject();
}

}  // namespace

std::string goldenParamsText(const Params& p) {
  std::string text = std::string("mode ") + costModeName(p.mode) + ", census " + censusWindowName(p.census) + ", P2 " +
                     p2ModeName(p.p2Mode) + ", weights " + pathWeightingName(p.weights) +
                     ", P1=" + std::to_string(p.p1) + ", P2'=" + std::to_string(p.p2) + ", sub-pixel " +
                     onOff(p.subpixel) + ", LR check " +
                     (p.lrTolerance < 0 ? std::string("off") : "tol " + std::to_string(p.lrTolerance)) + ", fill " +
                     onOff(p.fill) + ", snap " + onOff(p.snap) + ", median " + onOff(p.median) +
                     (p.uniqueness ? ", uniqueness " + std::to_string(p.uniqueness) : std::string()) +
                     (p.adWeight ? ", AD weight " + std::to_string(p.adWeight) + " cap " + std::to_string(p.adCap)
                                 : std::string()) +
                     (p.rightPathWeight && p.rightPathBlock ? ", fifth path " + std::to_string(p.rightPathWeight) +
                                                                  " in blocks of " + std::to_string(p.rightPathBlock)
                                                            : std::string()) +
                     (p.edgeReset.threshold
                          ? ", path restart T " + std::to_string(p.edgeReset.threshold) + " R " +
                                std::to_string(p.edgeReset.length) + " paths " + std::to_string(p.edgeReset.paths[0]) +
                                std::to_string(p.edgeReset.paths[1]) + std::to_string(p.edgeReset.paths[2]) +
                                std::to_string(p.edgeReset.paths[3]) + std::to_string(p.edgeReset.paths[4])
                          : std::string());
  if (p.experimental())
    text += "; golden-only experiments (not in the RTL): right path " + std::to_string(p.rightPathWeight) +
            (p.rightPathBlock ? " block " + std::to_string(p.rightPathBlock) : std::string()) + ", sub-pixel fit " +
            (p.linearSubpixel ? "linear" : "parabola") + ", MGM " + onOff(p.mgm) + ", median gate " +
            std::to_string(p.medianGate) + ", P1 per path " + std::to_string(p.p1PathPercent[0]) + "," +
            std::to_string(p.p1PathPercent[1]) + "," + std::to_string(p.p1PathPercent[2]) + "," +
            std::to_string(p.p1PathPercent[3]) + "," + std::to_string(p.p1PathPercent[4]) + " %, snap edge " +
            std::to_string(p.snapEdge) + ", stored Lr bits " + std::to_string(p.lrStoreBits);
  return text;
}

void writeGoldenParamFields(JsonWriter& j, const Params& p) {
  j.key("mode").string(costModeName(p.mode));
  j.key("census").string(censusWindowName(p.census));
  j.key("p2_mode").string(p2ModeName(p.p2Mode));
  j.key("weights").string(pathWeightingName(p.weights));
  j.key("p1").integer(p.p1);
  j.key("p2").integer(p.p2);
  j.key("subpixel").boolean(p.subpixel);
  j.key("lr_tolerance").integer(p.lrTolerance);  // < 0: LR check off
  j.key("fill").boolean(p.fill);
  j.key("snap").boolean(p.snap);
  j.key("median").boolean(p.median);
  j.key("uniqueness").integer(p.uniqueness);  // 0: off
  j.key("ad_weight").integer(p.adWeight);     // 0: off
  j.key("ad_cap").integer(p.adCap);
  j.key("right_path_weight").integer(p.rightPathWeight);  // 0: off
  j.key("right_path_block").integer(p.rightPathBlock);    // 0: the whole row (golden-only)
  // Golden-only experiments (docs/algorithm.md section 12), off unless set.
  j.key("subpixel_fit").string(p.linearSubpixel ? "linear" : "parabola");
  j.key("mgm").boolean(p.mgm);
  j.key("median_gate").integer(p.medianGate);  // 0: off
  j.key("p1_path_percent").beginArray();
  for (const int percent : p.p1PathPercent) j.integer(percent);
  j.endArray();
  j.key("snap_edge").integer(p.snapEdge);              // 0: off (every drop snaps)
  j.key("lr_store_bits").integer(p.lrStoreBits);       // 0: off (the whole Lr)
  j.key("edge_reset").integer(p.edgeReset.threshold);  // 0: off
  j.key("edge_reset_length").integer(p.edgeReset.length);
  j.key("edge_reset_paths").beginArray();
  for (const int on : p.edgeReset.paths) j.integer(on);
  j.endArray();
}

const char* methodKindName(MethodKind kind) {
  switch (kind) {
    case MethodKind::kTable1: return "table1";
    case MethodKind::kFull: return "full";
    case MethodKind::kOpenCv: return "opencv";
  }
  return "?";
}

const std::vector<std::string>& paperScenes() {
  static const std::vector<std::string> scenes = {"cones", "teddy", "sawtooth", "venus"};
  return scenes;
}

Params table1Params(CostMode mode, int disparities) {
  // The mode's four-path configuration: Table I compares the costs on four paths (rsad's
  // defaults add the fifth path, the AD term and the uniqueness ratio: its four-path preset).
  Params p = mode == Params{}.mode ? presetParams("four-path") : defaultParams(mode);
  p.disparities = disparities;
  p.lrTolerance = -1;
  p.fill = false;
  p.snap = false;
  p.validate();
  return p;
}

int opencvDisparities(int disparities) { return (disparities + 15) / 16 * 16; }

Params paperTable1Params(CostMode mode, int disparities) {
  Params p = presetParams("paper");
  p.mode = mode;
  for (const PaperWindowPenalties& row : kPaperWindowPenalties)
    if (row.mode == mode) p.p1 = row.p1, p.p2 = row.p2;
  p.disparities = disparities;
  p.lrTolerance = -1;
  p.fill = false;
  p.snap = false;
  p.validate();
  return p;
}

std::vector<Method> tableMethods(int disparities) {
  std::vector<Method> methods;
  // The paper's window first: 9x9 census, P2' / dI, equal path weights.
  for (const PaperRow& row : kPaperTable1) {
    Method m = goldenMethod(std::string("paper-") + costModeName(row.mode), std::string(row.label) + ", 9x9",
                            MethodKind::kTable1, paperTable1Params(row.mode, disparities));
    m.paper = paperFigures(row);
    methods.push_back(m);
  }
  for (const PaperRow& row : kPaperTable1) {
    Method m = goldenMethod(costModeName(row.mode), row.label, MethodKind::kTable1,
                            table1Params(row.mode, disparities));
    m.paper = paperFigures(row);
    methods.push_back(m);
  }
  for (CostMode mode : allCostModes()) {
    if (!isHardwareMode(mode)) continue;
    Params p = defaultParams(mode);
    p.disparities = disparities;
    p.validate();
    Method m = goldenMethod(std::string("full-") + costModeName(mode), std::string("Full pipeline, ") + costLabel(mode),
                            MethodKind::kFull, p);
    m.hardwareDefault = mode == Params{}.mode;
    methods.push_back(m);
  }
  Params four = presetParams("four-path");
  four.disparities = disparities;
  methods.push_back(goldenMethod("full-four-path", "Full pipeline, four-path preset (the defaults before issue 15)",
                                 MethodKind::kFull, four));
  Params paper = presetParams("paper");
  paper.disparities = disparities;
  methods.push_back(goldenMethod("full-paper", "Full pipeline, paper preset (9x9, RSAD+RT)", MethodKind::kFull, paper));
  methods.push_back(opencvMethod("opencv-sgbm", "OpenCV SGBM (MODE_SGBM)", cv::StereoSGBM::MODE_SGBM, disparities));
  methods.push_back(opencvMethod("opencv-hh", "OpenCV SGBM (MODE_HH)", cv::StereoSGBM::MODE_HH, disparities));
  return methods;
}

cv::Mat runMethod(const Method& m, const Scene& s) {
  if (m.kind == MethodKind::kOpenCv)
    return runOpenCvSgbm(s.leftColor, s.rightColor, m.params.disparities, m.opencvMode);
  return toFloat(runPipeline(s.left, s.right, m.params));
}

const ErrorFigures* TableReport::find(const std::string& key, const std::string& scene) const {
  auto method = results.find(key);
  if (method == results.end()) return nullptr;
  auto it = method->second.find(scene);
  return it == method->second.end() ? nullptr : &it->second;
}

TableReport computeTable(const std::vector<Scene>& scenes, int disparities, double delta, const ResultHook& hook) {
  TableReport r;
  r.disparities = disparities;
  r.delta = delta;
  r.scenes = columnOrder(scenes);
  r.methods = tableMethods(disparities);
  if (!scenes.empty()) r.opencvChannels = scenes.front().leftColor.channels();
  for (const Method& m : r.methods)
    if (m.hardwareDefault) r.hardwareDefault = m.key;
  for (const Scene& s : scenes) {
    r.present.insert(s.name);
    if (s.nonoccDerived) r.derivedNonocc.insert(s.name);
    for (const Method& m : r.methods) {
      const cv::Mat disparity = runMethod(m, s);
      r.results[m.key][s.name] = evaluate(disparity, s, delta);
      if (hook) hook(m, s, disparity);
    }
  }
  return r;
}

std::string table1Markdown(const TableReport& r) {
  std::string md = "## Table I: error in non-occluded regions (%, delta = " + fixed(r.delta, 1) +
                   "), ours (paper)\n\n| Method | Key |";
  std::string rule = "|---|---|";
  for (const std::string& s : r.scenes) md += " " + titleCase(s) + " |", rule += "---:|";
  md += " Mean |\n" + rule + "---:|\n";
  for (const Method& m : r.methods) md += table1Row(r, m);
  return md + "\n";
}

std::string reportMarkdown(const TableReport& r) {
  std::string md = "# SGM golden model: accuracy report (D = " + std::to_string(r.disparities) + ")\n\n" +
                   table1Markdown(r) + notesMarkdown(r) + "\n![Table I chart](table1.png)\n\n" + perSceneMarkdown(r) +
                   "## Parameters\n\n| Key | Kind | Settings |\n|---|---|---|\n";
  for (const Method& m : r.methods) md += paramsRow(r, m);
  return md;
}

std::string reportJson(const TableReport& r) {
  JsonWriter j;
  j.beginObject();
  if (r.delta == std::floor(r.delta))
    j.key("delta").integer(long(r.delta));
  else
    j.key("delta").real(r.delta);
  j.key("disparities").integer(r.disparities);
  j.key("scenes").beginArray();
  for (const std::string& s : r.scenes) j.string(s);
  j.endArray();
  j.key("nonocc_derived").beginArray();
  for (const std::string& s : r.derivedNonocc) j.string(s);
  j.endArray();
  j.key("methods").beginArray();
  for (const Method& m : r.methods) writeMethod(j, r, m);
  j.endArray();
  j.key("hardware_default").string(r.hardwareDefault);
  j.endObject();
  return j.str();
}

}  // namespace sgm::eval
