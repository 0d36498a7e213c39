// SPDX-License-Identifier: Apache-2.0
#include "report_pool.hpp"
#include "report_util.hpp"

#include "report_json.hpp"
#include "report_table.hpp"

#include "sgm/pipeline.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>

namespace sgm::eval {

bool isKittiSet(const std::string& set) { return set.rfind("kitti", 0) == 0; }

std::string setGroup(const std::string& set) { return isKittiSet(set) ? "kitti" : "middlebury"; }

double strictFigure(const std::string& set, const ErrorFigures& f) { return isKittiSet(set) ? f.d1All : f.errNonocc; }

double validFigure(const std::string& set, const ErrorFigures& f) {
  return isKittiSet(set) ? f.d1Valid : f.errNonoccValid;
}

std::vector<char> crossValidationHalves(const std::vector<std::string>& names, const std::vector<std::string>& sets) {
  std::vector<size_t> order(names.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return std::tie(sets[a], names[a]) < std::tie(sets[b], names[b]); });
  std::vector<char> halves(names.size(), 'A');
  std::map<std::string, int> seen;  // scenes of each set so far
  for (const size_t i : order) halves[i] = seen[sets[i]]++ % 2 ? 'B' : 'A';
  return halves;
}

std::map<std::string, char> poolHalves(const std::string& root) {
  std::vector<std::string> names, sets;
  for (const std::string& dir : listScenes(root)) {
    names.push_back(std::filesystem::path(dir).filename().string());
    sets.push_back(readSceneMeta(dir).set);
  }
  const std::vector<char> halves = crossValidationHalves(names, sets);
  std::map<std::string, char> out;
  for (size_t i = 0; i < names.size(); ++i) out[names[i]] = halves[i];
  return out;
}

namespace {

std::string cell(const std::optional<double>& v) { return v ? fixed(*v, 2) : "-"; }

const char* measureName(const std::string& set) { return isKittiSet(set) ? "d1" : "bad_nonocc"; }

// Mean of the rows that `keep` selects, under the name.
template <typename Keep>
std::optional<PoolMean> meanOf(const std::string& name, const std::vector<PoolRow>& rows, Keep keep) {
  PoolMean m;
  m.name = name;
  double today = 0, strict = 0, valid = 0, density = 0;
  int todays = 0, opencvs = 0;
  for (const PoolRow& r : rows) {
    if (!keep(r)) continue;
    ++m.scenes;
    m.ours += strictFigure(r.set, r.ours);
    if (r.today) today += strictFigure(r.set, *r.today), ++todays;
    if (r.opencv)
      strict += strictFigure(r.set, *r.opencv), valid += validFigure(r.set, *r.opencv), density += r.opencv->density,
          ++opencvs;
  }
  if (m.scenes == 0) return std::nullopt;
  m.ours /= m.scenes;
  if (todays == m.scenes) m.today = today / todays;
  if (opencvs == m.scenes)
    m.opencvStrict = strict / opencvs, m.opencvValid = valid / opencvs, m.opencvDensity = density / opencvs;
  return m;
}

void addMean(std::vector<PoolMean>& out, std::optional<PoolMean> m) {
  if (m) out.push_back(*m);
}

}  // namespace

void summarize(PoolReport& r) {
  r.sets.clear(), r.groups.clear(), r.halves.clear();
  r.worstRegression.reset();
  std::vector<std::string> sets;
  for (const PoolRow& row : r.rows)
    if (std::find(sets.begin(), sets.end(), row.set) == sets.end()) sets.push_back(row.set);
  std::sort(sets.begin(), sets.end());
  for (const std::string& set : sets)
    addMean(r.sets, meanOf(set, r.rows, [&](const PoolRow& x) { return x.set == set; }));
  for (const std::string group : {"middlebury", "kitti"}) {
    addMean(r.groups, meanOf(group, r.rows, [&](const PoolRow& x) { return setGroup(x.set) == group; }));
    for (const char half : {'A', 'B'})
      addMean(r.halves, meanOf(group + " " + half, r.rows,
                               [&](const PoolRow& x) { return setGroup(x.set) == group && x.half == half; }));
  }
  for (const PoolRow& row : r.rows) {
    if (!row.today) continue;
    const double change = strictFigure(row.set, row.ours) - strictFigure(row.set, *row.today);
    if (!r.worstRegression || change > *r.worstRegression) r.worstRegression = change, r.worstScene = row.scene;
  }
}

PoolReport computePool(const std::vector<Scene>& scenes, const PoolOptions& options, const PoolHook& hook) {
  PoolReport r;
  r.options = options;
  // "today": the defaults when the pool issue was filed (issue 15), the four-path preset.
  r.comparesToday = presetName(options.params) != "four-path";
  std::vector<std::string> names, sets;
  for (const Scene& s : scenes) names.push_back(s.name), sets.push_back(s.set);
  const std::vector<char> halves = crossValidationHalves(names, sets);
  for (size_t i = 0; i < scenes.size(); ++i) {
    const Scene& s = scenes[i];
    PoolRow row;
    row.scene = s.name;
    row.set = s.set;
    const auto given = options.halves.find(s.name);
    row.half = given != options.halves.end() ? given->second : halves[i];
    row.disparities = s.ndisp > 0 ? s.ndisp : options.fallbackDisparities;
    Params p = options.params;
    p.disparities = row.disparities;
    const cv::Mat ours = toFloat(runPipeline(s.left, s.right, p));
    row.ours = evaluate(ours, s, options.delta);
    if (r.comparesToday) {
      Params today = presetParams("four-path");
      today.disparities = row.disparities;
      row.today = evaluate(toFloat(runPipeline(s.left, s.right, today)), s, options.delta);
    }
    if (options.opencv)
      row.opencv = evaluate(
          runOpenCvSgbm(s.leftColor, s.rightColor, opencvDisparities(row.disparities), cv::StereoSGBM::MODE_SGBM), s,
          options.delta);
    if (hook) hook(row, s, ours);
    r.rows.push_back(row);
  }
  std::stable_sort(r.rows.begin(), r.rows.end(), [](const PoolRow& a, const PoolRow& b) {
    return std::tie(a.set, a.scene) < std::tie(b.set, b.scene);
  });
  summarize(r);
  return r;
}

namespace {

std::string meanRow(const PoolMean& m) {
  return "| " + m.name + " | " + std::to_string(m.scenes) + " | " + fixed(m.ours, 2) + " | " + cell(m.today) + " | " +
         cell(m.opencvStrict) + " | " + cell(m.opencvValid) + " | " + cell(m.opencvDensity) + " |\n";
}

std::string meansTable(const std::string& title, const std::vector<PoolMean>& means) {
  std::string md = "## " + title +
                   "\n\n| | scenes | ours | today | OpenCV strict | OpenCV valid only | OpenCV density |\n"
                   "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const PoolMean& m : means) md += meanRow(m);
  return md + "\n";
}

void writeFigures(JsonWriter& j, const std::string& set, const std::optional<ErrorFigures>& f) {
  if (!f) {
    j.null();
    return;
  }
  j.beginObject();
  j.key("strict").real(strictFigure(set, *f));
  j.key("valid").real(validFigure(set, *f));
  j.key("err_nonocc").real(f->errNonocc);
  j.key("err_all").real(f->errAll);
  j.key("err_nonocc_valid").real(f->errNonoccValid);
  j.key("density").real(f->density);
  j.key("d1_all").real(f->d1All);
  j.key("d1_valid").real(f->d1Valid);
  j.endObject();
}

void writeMeans(JsonWriter& j, const std::vector<PoolMean>& means) {
  j.beginArray();
  for (const PoolMean& m : means) {
    j.beginObject();
    j.key("name").string(m.name);
    j.key("scenes").integer(m.scenes);
    j.key("ours").real(m.ours);
    j.key("today").real(m.today);
    j.key("opencv_strict").real(m.opencvStrict);
    j.key("opencv_valid").real(m.opencvValid);
    j.key("opencv_density").real(m.opencvDensity);
    j.endObject();
  }
  j.endArray();
}

}  // namespace

std::string poolMarkdown(const PoolReport& r) {
  const std::string delta = fixed(r.options.delta, 2);
  std::string md =
      "# SGM golden model on the scene pool\n\n"
      "Measure: Middlebury scenes bad-" +
      delta + " (|d - gt| > " + delta +
      " px) over the non-occluded pixels with known ground truth (the derived mask when a scene has no "
      "nonocc.png), invalid = error; KITTI scenes D1 (|d - gt| > 3 px and > 5 % of gt) over the pixels with "
      "ground truth, invalid = error. D = `ndisp` of each scene (" +
      std::to_string(r.options.fallbackDisparities) +
      " when meta.txt has none). OpenCV: StereoSGBM MODE_SGBM (the stereo_match sample's settings) on the colour "
      "pair at D rounded up to 16; strict counts its invalid pixels as errors, valid only leaves them out, density "
      "= % of the pixels with ground truth that are valid. Half: the fixed cross-validation split (per set, "
      "scenes sorted by name alternate A, B).\n\n"
      "Ours: " +
      goldenParamsText(r.options.params) + " (preset: " + presetName(r.options.params) + ").\n\n";
  md += "| scene | set | half | D | ours | today | ours bad-" + delta +
        " (all gt) | OpenCV strict | OpenCV valid only | OpenCV density |\n"
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const PoolRow& row : r.rows) {
    md += "| " + row.scene + " | " + row.set + " | " + row.half + " | " + std::to_string(row.disparities) + " | " +
          fixed(strictFigure(row.set, row.ours), 2) + " | " +
          cell(row.today ? std::optional<double>(strictFigure(row.set, *row.today)) : std::nullopt) + " | " +
          fixed(row.ours.errAll, 2) + " | " +
          cell(row.opencv ? std::optional<double>(strictFigure(row.set, *row.opencv)) : std::nullopt) + " | " +
          cell(row.opencv ? std::optional<double>(validFigure(row.set, *row.opencv)) : std::nullopt) + " | " +
          cell(row.opencv ? std::optional<double>(row.opencv->density) : std::nullopt) + " |\n";
  }
  md += "\n(today: the four-path preset, the defaults before issue 15; only when ours are not it.)\n\n";
  md += meansTable("Means per set", r.sets) +
        meansTable("Means per group (Middlebury: bad-" + delta + " nonocc; KITTI: D1)", r.groups) +
        meansTable("Means per cross-validation half", r.halves);
  if (r.worstRegression)
    md += "Worst change of a scene vs today: " + r.worstScene + " " + (*r.worstRegression >= 0 ? "+" : "") +
          fixed(*r.worstRegression, 2) + " points.\n\n";
  md += "![pool chart](pool.png)\n";
  return md;
}

std::string poolSummary(const PoolReport& r) {
  std::string text;
  for (const auto* means : {&r.groups, &r.halves})
    for (const PoolMean& m : *means) {
      char line[200];
      std::snprintf(line, sizeof line, "%-14s %2d scenes  ours %6.2f%%", m.name.c_str(), m.scenes, m.ours);
      text += line;
      if (m.today) text += "  today " + fixed(*m.today, 2) + "%";
      if (m.opencvStrict)
        text += "  opencv strict " + fixed(*m.opencvStrict, 2) + "%  valid " + fixed(*m.opencvValid, 2) +
                "% (density " + fixed(*m.opencvDensity, 2) + "%)";
      text += "\n";
    }
  if (r.worstRegression)
    text += "worst change vs today: " + r.worstScene + " " + fixed(*r.worstRegression, 2) + " points\n";
  return text;
}

std::string poolJson(const PoolReport& r) {
  JsonWriter j;
  j.beginObject();
  j.key("delta").real(r.options.delta);
  j.key("params").beginObject();
  writeGoldenParamFields(j, r.options.params);
  j.key("fallback_disparities").integer(r.options.fallbackDisparities);
  j.endObject();
  j.key("compares_today").boolean(r.comparesToday);
  j.key("scenes").beginArray();
  for (const PoolRow& row : r.rows) {
    j.beginObject();
    j.key("scene").string(row.scene);
    j.key("set").string(row.set);
    j.key("group").string(setGroup(row.set));
    j.key("half").string(std::string(1, row.half));
    j.key("measure").string(measureName(row.set));
    j.key("disparities").integer(row.disparities);
    j.key("ours");
    writeFigures(j, row.set, row.ours);
    j.key("today");
    writeFigures(j, row.set, row.today);
    j.key("opencv");
    writeFigures(j, row.set, row.opencv);
    j.endObject();
  }
  j.endArray();
  j.key("sets");
  writeMeans(j, r.sets);
  j.key("groups");
  writeMeans(j, r.groups);
  j.key("halves");
  writeMeans(j, r.halves);
  j.key("worst_regression");
  if (r.worstRegression) {
    j.beginObject();
    j.key("scene").string(r.worstScene);
    j.key("points").real(*r.worstRegression);
    j.endObject();
  } else {
    j.null();
  }
  j.endObject();
  return j.str();
}

}  // namespace sgm::eval
