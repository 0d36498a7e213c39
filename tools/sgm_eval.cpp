// SPDX-License-Identifier: Apache-2.0
// sgm-eval: accuracy of the golden model (and OpenCV StereoSGBM) on the
// Middlebury scenes: the paper's eq. (5) error ratio, Table I, timing.
#include "datasheet.hpp"
#include "eval_lib.hpp"
#include "report_bench.hpp"
#include "report_chart.hpp"
#include "report_json.hpp"
#include "report_pool.hpp"
#include "report_table.hpp"
#include "report_util.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/pipeline.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <utility>

using namespace sgm;
using eval::Scene;

namespace {

const char* kUsage =
    "usage: sgm-eval run   --data DIR [pipeline options]   golden pipeline on every scene\n"
    "       sgm-eval table --data DIR [--out DIR] [--d 64] Table I + full pipeline + OpenCV\n"
    "                                                      -> report.md, report.json, table1.png\n"
    "       sgm-eval bench --data DIR [--out DIR] [--scene cones] [--repeats 5]\n"
    "                                                      golden vs OpenCV SGBM time -> bench.json\n"
    "       sgm-eval pool  --pool DIR [--out DIR] [--half A|B] [--opencv on|off] [pipeline options]\n"
    "                                                      every scene at its meta.txt ndisp (--d for scenes\n"
    "                                                      without one): Middlebury bad-1 nonocc, KITTI D1,\n"
    "                                                      per-set means, OpenCV strict and valid-only, \"today\"\n"
    "                                                      (the four-path preset) beside -> pool.md, pool.json, pool.png\n"
    "       sgm-eval datasheet [--build DIR] [--out FILE]  the datasheet from the measured JSON reports under\n"
    "                                                      DIR (default build) -> FILE (default docs/datasheet.md)\n"
    "                  [--readme FILE]                     and the generated summary section of FILE (README.md)\n"
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
    const DisparityMap map = runPipeline(s.left, s.right, params);
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
  return {
      {"run", commandRun, runOptions},
      {"table", commandTable, {"data", "out", "d", "delta", "scenes"}},
      {"bench", commandBench, {"data", "out", "scene", "repeats"}},
      {"pool", commandPool, poolOptions},
      {"datasheet", commandDatasheet, {"build", "out", "readme"}},
  };
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw Error("missing command: run, table, bench, pool or datasheet (see --help)");
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
