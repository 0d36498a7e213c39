// sgm-eval: accuracy of the golden model (and OpenCV StereoSGBM) on the
// Middlebury scenes: the paper's eq. (5) error ratio, Table I, timing.
#include "eval_lib.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/pipeline.hpp"

#include <cstdio>
#include <iostream>

using namespace sgm;
using eval::Scene;

namespace {

const char* kUsage =
    "usage: sgm-eval run   --data DIR [pipeline options]   golden pipeline on every scene\n"
    "       sgm-eval table --data DIR [--out DIR]          Table I + full pipeline + OpenCV\n"
    "       sgm-eval bench --data DIR [--out DIR]          golden vs OpenCV SGBM time\n"
    "pipeline options: --d D --p1 N --p2 N --mode M --subpixel on|off --lr TOL|off --median on|off\n"
    "--delta X sets the error threshold (default 1).\n";

std::vector<Scene> loadAll(const std::string& root) {
  const auto dirs = eval::listScenes(root);
  if (dirs.empty()) throw Error("no scenes (left.png, right.png, gt.png) under '" + root + "'");
  std::vector<Scene> scenes;
  for (const auto& d : dirs) scenes.push_back(eval::loadScene(d));
  return scenes;
}

int commandRun(const CliArgs& args) {
  const Params params = args.pipelineParams();
  const double delta = args.real("delta", 1.0, 0.0, 1000.0);
  double sum = 0;
  std::vector<eval::Scene> scenes = loadAll(args.text("data", ""));
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

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2 || std::string(argv[1]) == "--help") {
      std::cout << kUsage;
      return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    auto options = CliArgs::pipelineOptions();
    options.insert({"data", "out", "delta"});
    const CliArgs args(argc - 1, argv + 1, options, {"help"});
    if (command == "run") return commandRun(args);
    throw Error("unknown command '" + command + "' (see --help)");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sgm-eval: error: %s\n", e.what());
    return 2;
  }
}
