// SPDX-License-Identifier: Apache-2.0
// sgm-eval: accuracy of the golden model (and OpenCV StereoSGBM) on the
// Middlebury scenes: the paper's eq. (5) error ratio, Table I, timing.
#include "calibration.hpp"
#include "datasheet.hpp"
#include "report_confidence.hpp"
#include "eval_lib.hpp"
#include "report_bench.hpp"
#include "report_chart.hpp"
#include "report_json.hpp"
#include "report_pool.hpp"
#include "report_table.hpp"
#include "report_util.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/pipeline.hpp"
#include "sgm/rectify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <tuple>
#include <utility>

using namespace sgm;
using eval::Scene;

namespace {

const char* kUsage =
    "usage: sgm-eval run   --data DIR [pipeline options]   golden pipeline on every scene (a scene with a\n"
    "                                                      mesh.bin: a raw pair, rectified as the core does)\n"
    "       sgm-eval table --data DIR [--out DIR] [--d 64] Table I + full pipeline + OpenCV\n"
    "                                                      -> report.md, report.json, table1.png\n"
    "       sgm-eval bench --data DIR [--out DIR] [--scene cones] [--repeats 5]\n"
    "                                                      golden vs OpenCV SGBM time -> bench.json\n"
    "       sgm-eval pool  --pool DIR [--out DIR] [--half A|B] [--opencv on|off] [pipeline options]\n"
    "                                                      every scene at its meta.txt ndisp (--d for scenes\n"
    "                                                      without one): Middlebury bad-1 nonocc, KITTI D1,\n"
    "                                                      per-set means, OpenCV strict and valid-only, \"today\"\n"
    "                                                      (the four-path preset) beside -> pool.md, pool.json, pool.png\n"
    "       sgm-eval confidence --pool DIR [--out DIR] [--scenes a,b] [pipeline options]\n"
    "                                                      the error of the most confident 10 .. 100 % of the pixels\n"
    "                                                      per scene (sparsification) -> confidence.md, .json, .png\n"
    "       sgm-eval datasheet [--build DIR] [--out FILE]  the datasheet from the measured JSON reports under\n"
    "                                                      DIR (default build) -> FILE (default docs/datasheet.md)\n"
    "                  [--readme FILE]                     and the generated summary section of FILE (README.md)\n"
    "       sgm-eval calib-mesh --calib DIR --size WxH|--size-of IMAGE [--grid 16] [--unit-mm 1] [--rows R]\n"
    "                  [--out DIR]\n"
    "                                                      OpenCV's intrinsics.yml + extrinsics.yml in DIR -> the\n"
    "                                                      rectification meshes (step --grid px) -> mesh.bin, mesh.json:\n"
    "                                                      error against cv::initUndistortRectifyMap, line-buffer\n"
    "                                                      rows and the pair's lag (refused when the pair needs more\n"
    "                                                      than the build's line buffer of R rows, --rows R), f and B\n"
    "                                                      (--unit-mm: mm per calibration unit)\n"
    "       sgm-eval rectify --mesh FILE --left L --right R [--out DIR]\n"
    "                                                      the golden rectification -> left.png, right.png\n"
    "       sgm-eval raw-scene --left L --right R [--baseline-mm 160] [--out DIR]\n"
    "                                                      a raw camera pair made from a rectified one with a\n"
    "                                                      known calibration -> left.png, right.png (gray),\n"
    "                                                      intrinsics.yml, extrinsics.yml\n"
    "pipeline options: --d D --p1 N --p2 N --mode M --subpixel on|off --lr TOL|off --fill on|off\n"
    "                  --snap on|off --median on|off --census 9x5|9x9 --p2-mode knee|paper\n"
    "                  --weights 3232|equal --uniqueness U (%, 0 off) --ad-weight W (0 off .. 15)\n"
    "                  --ad-cap T (C += W min(AD, T) / 8) --preset default|four-path|paper (later options override it)\n"
    "                  --right-path W (fifth path from the right, weight 0..8) --right-block B (that path per\n"
    "                  block of B px, one block of look-ahead; 0: the whole row, golden-only)\n"
    "                  --edge-reset T --edge-reset-len R --edge-reset-paths A,B,C,D,E (a path starts again within\n"
    "                  R steps of a gray step of at least T; the paths marked 1: 0, 45, 90, 135 deg, fifth;\n"
    "                  default 40, 6, 1,1,0,1,1; 0 off)\n"
    "golden-only experiments, NOT in the RTL (off by default): --subpixel-fit parabola|linear (linear: the\n"
    "                  equiangular fit) --mgm on|off (raster MGM) --median-gate T (median over pixels within\n"
    "                  T gray levels of the centre) --p1-paths A,B,C,D,E (P1 per path in %: 0, 45, 90, 135 deg, fifth)\n"
    "                  --snap-edge T (edge snapping only onto an intensity step of at least T, with --snap on)\n"
    "                  --lr-store-bits N (the 45/90/135-degree paths read the row above's Lr saturated to N bits)\n"
    "--delta X sets the error threshold (default 1); --out defaults to build/eval;\n"
    "--scenes a,b (run, table, pool) keeps only those scenes; --half A|B (pool) keeps one half of the\n"
    "cross-validation split (per set, scenes sorted by name alternate A, B).\n";

const char* kDefaultOut = "build/eval";

// --data (or --pool): required, an existing directory.
std::string dataDir(const CliArgs& args, const std::string& option = "data") {
  if (!args.has(option)) throw Error("missing --" + option + " DIR (the scenes directory)");
  const std::string root = args.text(option, "");
  if (root.empty()) throw Error("empty --" + option + " directory name");
  std::error_code ec;
  if (!std::filesystem::exists(root, ec)) throw Error(option + " directory '" + root + "' does not exist");
  if (!std::filesystem::is_directory(root, ec)) throw Error(option + " directory '" + root + "' is not a directory");
  return root;
}

// --out: checked before the work, created (when missing) only to write the results.
std::string outDir(const CliArgs& args) {
  const std::string out = args.text("out", kDefaultOut);
  checkOutputDirectory(out);
  return out;
}

// Writes the results all together (none of them on failure), creating the directory.
void writeResults(const std::string& out, const std::vector<OutputFile>& files) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec || !std::filesystem::is_directory(out)) throw Error("cannot create output directory '" + out + "'");
  writeFiles(files);
}

// Every scene under --data, or only those --scenes names (a comma-separated list).
std::vector<Scene> loadAll(const CliArgs& args, const std::string& option = "data") {
  const std::string root = dataDir(args, option);
  const auto dirs = eval::listScenes(root);
  if (dirs.empty()) throw Error("no scenes (left.png, right.png, gt.png) under '" + root + "'");
  std::vector<Scene> scenes;
  if (!args.has("scenes")) {
    for (const auto& d : dirs) scenes.push_back(eval::loadScene(d));
    return scenes;
  }
  std::stringstream names(args.text("scenes", ""));
  for (std::string name; std::getline(names, name, ',');) {
    const auto it = std::find_if(dirs.begin(), dirs.end(),
                                 [&](const std::string& d) { return std::filesystem::path(d).filename() == name; });
    if (it == dirs.end())
      throw Error("--scenes: scene '" + name + "' (left.png, right.png, gt.png) not found under '" + root + "'");
    scenes.push_back(eval::loadScene(*it));
  }
  if (scenes.empty()) throw Error("--scenes: empty list");
  return scenes;
}

Scene loadNamed(const std::string& root, const std::string& name) {
  for (const auto& d : eval::listScenes(root))
    if (std::filesystem::path(d).filename() == name) return eval::loadScene(d);
  throw Error("scene '" + name + "' (left.png, right.png, gt.png) not found under '" + root + "'");
}

double deltaOption(const CliArgs& args) { return args.real("delta", 1.0, 0.0, 1000.0); }

int commandRun(const CliArgs& args) {
  const Params params = args.pipelineParams();
  const double delta = deltaOption(args);
  double sum = 0;
  const std::vector<Scene> scenes = loadAll(args);
  for (const auto& s : scenes) {
    // A raw pair with its meshes (mesh.bin in the scene) is rectified as the core does it: the
    // pixels whose left source lies outside the raw image are invalid.
    const DisparityMap map = s.meshPath.empty()
                                 ? runPipeline(s.left, s.right, params)
                                 : runRectifiedPipeline(s.left, s.right, readMeshFile(s.meshPath), params);
    const eval::ErrorFigures f = eval::evaluate(eval::toFloat(map), s, delta);
    std::printf("%-10s nonocc %6.2f%%  all %6.2f%%  disc %6.2f%%  density %6.2f%%  valid-nonocc %6.2f%%\n",
                s.name.c_str(), f.errNonocc, f.errAll, f.errDisc.value_or(-1), f.density, f.errNonoccValid);
    sum += f.errNonocc;
  }
  std::printf("mean nonocc %.3f%%\n", sum / scenes.size());
  return 0;
}

int commandTable(const CliArgs& args) {
  const int d = int(args.integer("d", 64, kMinDisparities, kMaxDisparities));
  const double delta = deltaOption(args);
  const std::string out = outDir(args);
  const std::vector<Scene> scenes = loadAll(args);

  std::vector<OutputFile> files;  // written together at the end
  const auto keepSideBySide = [&](const eval::Method& m, const Scene& s, const cv::Mat& disparity) {
    if (!m.hardwareDefault) return;
    const std::string path = out + "/" + s.name + "_sidebyside.png";
    files.push_back({path, encodePng(eval::sideBySide(s, disparity, float(d), delta), path)});
  };
  const eval::TableReport report = eval::computeTable(scenes, d, delta, keepSideBySide);
  const size_t sideBySides = files.size();
  files.push_back({out + "/table1.png", encodePng(eval::table1Chart(report), out + "/table1.png")});
  files.push_back({out + "/report.md", eval::reportMarkdown(report)});
  files.push_back({out + "/report.json", eval::reportJson(report)});
  writeResults(out, files);

  std::cout << eval::table1Markdown(report);
  std::cout << "wrote " << out << "/report.md, report.json, table1.png and " << sideBySides << " side-by-side images ("
            << report.hardwareDefault << ")\n";
  return 0;
}

int commandBench(const CliArgs& args) {
  const std::string root = dataDir(args);
  const int repeats = int(args.integer("repeats", 5, 1, 1000));
  const std::string out = outDir(args);
  const Scene scene = loadNamed(root, args.text("scene", "cones"));
  const eval::BenchResult result = eval::runBench(scene, repeats);
  writeResults(out, {{out + "/bench.json", eval::benchJson(result)}});
  std::cout << eval::benchText(result) << "wrote " << out << "/bench.json\n";
  return 0;
}

int commandPool(const CliArgs& args) {
  eval::PoolOptions options;
  options.params = args.pipelineParams();
  options.fallbackDisparities = options.params.disparities;
  options.delta = deltaOption(args);
  options.opencv = args.onOff("opencv", true);
  const std::string half = args.text("half", "");
  if (!half.empty() && half != "A" && half != "B") throw Error("option --half expects A or B, got '" + half + "'");
  const std::string out = outDir(args);
  std::vector<Scene> scenes = loadAll(args, "pool");
  options.halves = eval::poolHalves(args.text("pool", ""));  // the split of the whole pool, whatever --scenes keeps
  if (!half.empty()) {
    scenes.erase(
        std::remove_if(scenes.begin(), scenes.end(), [&](const Scene& s) { return options.halves[s.name] != half[0]; }),
        scenes.end());
    if (scenes.empty()) throw Error("--half " + half + ": no scene of the selection is in that half");
  }
  const eval::PoolReport report = eval::computePool(scenes, options);
  writeResults(out, {{out + "/pool.md", eval::poolMarkdown(report)},
                     {out + "/pool.json", eval::poolJson(report)},
                     {out + "/pool.png", encodePng(eval::poolChart(report), out + "/pool.png")}});
  std::cout << eval::poolSummary(report) << "wrote " << out << "/pool.md, pool.json, pool.png\n";
  return 0;
}

int commandConfidence(const CliArgs& args) {
  std::vector<Scene> scenes = loadAll(args, "pool");
  const std::string out = outDir(args);
  const double delta = args.real("delta", 1.0, 0.0, 1000.0);
  const int fallback = int(args.integer("d", Params{}.disparities, kMinDisparities, kMaxDisparities));
  const eval::ConfidenceReport report = eval::computeConfidence(scenes, args.pipelineParams(), fallback, delta);
  if (report.rows.empty()) throw Error("no scene with ground truth");
  writeResults(out, {{out + "/confidence.md", eval::confidenceMarkdown(report)},
                     {out + "/confidence.json", eval::confidenceJson(report)},
                     {out + "/confidence.png", encodePng(eval::confidenceChart(report), out + "/confidence.png")}});
  for (const auto& [group, mean] : report.means)
    std::printf("%-11s error of the most confident 50 %%: %.2f %%, 90 %%: %.2f %%, all: %.2f %%\n", group.c_str(),
                mean[4], mean[8], mean.back());
  std::printf("wrote %s/confidence.md, confidence.json, confidence.png\n", out.c_str());
  return 0;
}

int commandDatasheet(const CliArgs& args) {
  const std::string build = args.text("build", "build");
  const std::string out = args.text("out", "docs/datasheet.md");
  if (build.empty() || out.empty()) throw Error("empty --build or --out");
  const std::string md = eval::datasheetMarkdown(build);
  const std::filesystem::path parent = std::filesystem::path(out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  eval::writeTextFile(out, md);
  std::cout << "sgm-eval datasheet: wrote " << out << " from the reports under " << build << "/\n";
  if (const std::string readme = args.text("readme", ""); !readme.empty()) {
    const std::string page = eval::readTextFile(readme);
    eval::writeTextFile(
        readme, eval::replaceGeneratedSection(page, "datasheet: summary", eval::summaryMarkdown(build), readme));
    std::cout << "sgm-eval datasheet: wrote the summary section of " << readme << "\n";
  }
  return 0;
}

std::string requiredText(const CliArgs& args, const std::string& name, const std::string& what) {
  const std::string value = args.text(name, "");
  if (value.empty()) throw Error("missing --" + name + " " + what);
  return value;
}

// --size WxH, or --size-of IMAGE (that image's size).
cv::Size frameSize(const CliArgs& args) {
  if (args.has("size-of")) {
    if (args.has("size")) throw Error("--size and --size-of: give one");
    return readImage(requiredText(args, "size-of", "IMAGE")).size();
  }
  if (!args.has("size")) throw Error("missing --size WxH or --size-of IMAGE (the frame of the calibrated cameras)");
  const std::string text = args.text("size", "");
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 2 || h < 2 ||
      w > kMaxImageSide || h > kMaxImageSide)
    throw Error("--size '" + text + "': expected WxH, 2 .. " + std::to_string(kMaxImageSide) + " a side");
  return {w, h};
}

int commandCalibMesh(const CliArgs& args) {
  const std::string dir = requiredText(args, "calib", "DIR (intrinsics.yml and extrinsics.yml)");
  const cv::Size size = frameSize(args);
  const long grid = args.integer("grid", 16, 1L << kMeshGridLog2Min, 1L << kMeshGridLog2Max);
  if (grid & (grid - 1)) throw Error("--grid " + std::to_string(grid) + ": not a power of two");
  const double unitMm = args.real("unit-mm", 1, 1e-6, 1e6);
  const long rowsLimit = args.integer("rows", 0, 0, 4096);
  const std::string out = args.text("out", "build/calib");
  checkOutputDirectory(out);
  const eval::StereoCalibration calibration = eval::readCalibration(dir);
  int gridLog2 = 0;
  while ((1L << gridLog2) < grid) ++gridLog2;
  eval::DepthGeometry depth;
  const StereoMesh mesh = eval::stereoMesh(calibration, size, gridLog2, unitMm, dir, &depth);
  const double baselineMm = depth.baselineUnits * unitMm;
  eval::JsonWriter json;
  json.beginObject().key("width").integer(size.width).key("height").integer(size.height);
  json.key("grid").integer(grid).key("frac_bits").integer(kMeshFracBits);
  json.key("nodes_x").integer(mesh.left.nodesX).key("nodes_y").integer(mesh.left.nodesY);
  json.key("focal_px").real(depth.focalPx, 4).key("baseline_mm").real(baselineMm, 4);
  json.key("disparity_offset_px").real(depth.disparityOffsetPx, 4);
  std::string summary;
  json.key("images").beginArray();
  for (const auto& [name, camera, m] :
       {std::tuple<const char*, const eval::Camera&, const Mesh&>{"left", calibration.left, mesh.left},
        {"right", calibration.right, mesh.right}}) {
    const eval::MeshError error = eval::meshError(camera, m);
    const RowSpan span = meshRowSpan(m);
    json.beginObject().key("image").string(name).key("mesh_error_max_px").real(error.maxPx, 4);
    json.key("mesh_error_at").beginArray().integer(error.x).integer(error.y).endArray();
    json.key("row_lag").integer(span.lag).key("row_back").integer(span.back).key("rows").integer(span.rows).endObject();
    char line[200];
    std::snprintf(line, sizeof line,
                  "  %s: mesh error at most %.4f px (at %d, %d; goal 0.0625), rows %d .. %+d: %d rows\n", name,
                  error.maxPx, error.x, error.y, span.back, span.lag, span.rows);
    summary += line;
  }
  // The pair in the core: one lag (RECTIFY.LAG) and a line buffer of R >= rows_needed rows.
  const RowSpan pair = stereoRowSpan(mesh);
  const int rowsNeeded = lineBufferRows(pair);
  json.endArray().key("lag").integer(pair.lag).key("rows_needed").integer(rowsNeeded).endObject();
  if (rowsLimit > 0 && rowsNeeded > rowsLimit)
    throw Error(dir + ": the calibration needs a line buffer of " + std::to_string(rowsNeeded) +
                " rows (RECTIFY_ROWS), the build has " + std::to_string(rowsLimit) + " (--rows)");
  char pairLine[160];
  std::snprintf(pairLine, sizeof pairLine,
                "  the pair: lag %d (RECTIFY.LAG), line buffer of at least %d rows (RECTIFY_ROWS)\n", pair.lag,
                rowsNeeded);
  summary += pairLine;
  writeResults(out, {{out + "/mesh.bin", encodeMeshFile(mesh)}, {out + "/mesh.json", json.str()}});
  std::printf(
      "sgm-eval calib-mesh: %dx%d, step %ld px, %dx%d nodes, f %.3f px, B %.3f mm, disparity offset %.3f px\n%s"
      "wrote %s/mesh.bin, mesh.json\n",
      size.width, size.height, grid, mesh.left.nodesX, mesh.left.nodesY, depth.focalPx, baselineMm,
      depth.disparityOffsetPx, summary.c_str(), out.c_str());
  return 0;
}

int commandRectify(const CliArgs& args) {
  const StereoMesh mesh = readMeshFile(requiredText(args, "mesh", "FILE (from calib-mesh)"));
  const cv::Mat left = readGray(requiredText(args, "left", "IMAGE"));
  const cv::Mat right = readGray(requiredText(args, "right", "IMAGE"));
  const std::string out = args.text("out", "build/rectify");
  checkOutputDirectory(out);
  const RectifiedImage l = rectify(left, mesh.left), r = rectify(right, mesh.right);
  writeResults(out, {{out + "/left.png", encodePng(l.gray, out + "/left.png")},
                     {out + "/right.png", encodePng(r.gray, out + "/right.png")}});
  std::printf("sgm-eval rectify: %dx%d, valid %.2f%% (left), %.2f%% (right); wrote %s/left.png, right.png\n", left.cols,
              left.rows, 100.0 * cv::countNonZero(l.valid) / double(l.valid.total()),
              100.0 * cv::countNonZero(r.valid) / double(r.valid.total()), out.c_str());
  return 0;
}

int commandRawScene(const CliArgs& args) {
  const cv::Mat left = readGray(requiredText(args, "left", "IMAGE (rectified)"));
  const cv::Mat right = readGray(requiredText(args, "right", "IMAGE (rectified)"));
  if (left.size() != right.size()) throw Error("the left and right images differ in size");
  const double baseline = args.real("baseline-mm", 160, 1, 10000);
  const std::string out = args.text("out", "build/raw-scene");
  checkOutputDirectory(out);
  const eval::StereoCalibration calibration = eval::syntheticCalibration(left.cols, left.rows, baseline);
  const cv::Mat rawLeft = eval::rawFromRectified(left, calibration.left);
  const cv::Mat rawRight = eval::rawFromRectified(right, calibration.right);
  writeResults(out, {{out + "/left.png", encodePng(rawLeft, out + "/left.png")},
                     {out + "/right.png", encodePng(rawRight, out + "/right.png")}});
  eval::writeCalibration(out, calibration);
  std::printf(
      "sgm-eval raw-scene: %dx%d, baseline %.1f mm; wrote %s/left.png, right.png, intrinsics.yml, extrinsics.yml\n",
      left.cols, left.rows, baseline, out.c_str());
  return 0;
}

struct Command {
  const char* name;
  int (*run)(const CliArgs&);
  std::set<std::string> options;
};

std::vector<Command> commands() {
  std::set<std::string> runOptions = CliArgs::pipelineOptions();
  runOptions.insert({"data", "out", "delta", "scenes"});
  std::set<std::string> poolOptions = CliArgs::pipelineOptions();
  poolOptions.insert({"pool", "out", "delta", "scenes", "half", "opencv"});
  std::set<std::string> confidenceOptions = CliArgs::pipelineOptions();
  confidenceOptions.insert({"pool", "out", "delta", "scenes"});
  return {
      {"run", commandRun, runOptions},
      {"table", commandTable, {"data", "out", "d", "delta", "scenes"}},
      {"bench", commandBench, {"data", "out", "scene", "repeats"}},
      {"pool", commandPool, poolOptions},
      {"confidence", commandConfidence, confidenceOptions},
      {"datasheet", commandDatasheet, {"build", "out", "readme"}},
      {"calib-mesh", commandCalibMesh, {"calib", "size", "size-of", "grid", "unit-mm", "rows", "out"}},
      {"rectify", commandRectify, {"mesh", "left", "right", "out"}},
      {"raw-scene", commandRawScene, {"left", "right", "baseline-mm", "out"}},
  };
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2)
      throw Error(
          "missing command: run, table, bench, pool, confidence, datasheet, calib-mesh, rectify or raw-scene (see --help)");
    if (std::string(argv[1]) == "--help") {
      std::cout << kUsage;
      return 0;
    }
    const std::string name = argv[1];
    for (const Command& command : commands()) {
      if (name != command.name) continue;
      const CliArgs args(argc - 1, argv + 1, command.options, {"help"});
      if (args.has("help")) {
        std::cout << kUsage;
        return 0;
      }
      if (!args.positional().empty()) throw Error("unexpected argument '" + args.positional().front() + "'");
      return command.run(args);
    }
    throw Error("unknown command '" + name + "' (see --help)");
  } catch (const std::exception& e) {
    return reportError("sgm-eval", e);
  }
}
