// sgm-sim: runs the core on a stereo pair and writes disparity PNGs, a
// side-by-side picture and report.json. Until the RTL core lands (issue 3)
// the engine is the golden model only, and the report says so.
#include "eval_lib.hpp"
#include "report_json.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

using namespace sgm;

namespace {

const char* kUsage =
    "usage: sgm-sim [--left L --right R [--gt G] [--gt-scale S]] [--out DIR] [pipeline options]\n"
    "Without --left/--right runs the default scene: the Middlebury Aloe pair shipped by\n"
    "opencv-doc, scaled by 1/4 so its disparities fit D = 64.\n";

const char* kAloeDir = "/usr/share/doc/opencv-doc/examples/data";

}  // namespace

int main(int argc, char** argv) {
  try {
    auto options = CliArgs::pipelineOptions();
    options.insert({"left", "right", "gt", "gt-scale", "out"});
    const CliArgs args(argc, argv, options, {"help"});
    if (args.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (!args.positional().empty()) throw Error("unexpected argument '" + args.positional()[0] + "' (see --help)");
    if (args.has("left") != args.has("right")) throw Error("give both --left and --right, or neither");
    const Params params = args.pipelineParams();
    const std::string out = args.text("out", "build/sim");

    eval::Scene scene;
    if (args.has("left")) {
      scene = eval::loadSceneFiles(args.text("left", ""), args.text("right", ""), args.text("gt", ""),
                                   args.real("gt-scale", 0, 0, 1e6));
    } else {
      const std::string dir = kAloeDir;
      if (!std::filesystem::exists(dir + "/aloeL.jpg"))
        throw Error("default scene not found in " + dir + " (run 'make deps' to install opencv-doc)");
      scene = eval::loadSceneFiles(dir + "/aloeL.jpg", dir + "/aloeR.jpg", dir + "/aloeGT.png", 1.0, 4);
      scene.name = "aloe";
    }
    checkInput(scene.left, scene.right, params);

    const auto start = std::chrono::steady_clock::now();
    const DisparityMap golden = runPipeline(scene.left, scene.right, params);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    std::filesystem::create_directories(out);
    const float maxD = float(params.disparities - 1);
    std::vector<std::pair<std::string, cv::Mat>> pictures = {
        {out + "/disparity16.png", encodeDisparity16(golden)},
        {out + "/disparity_color.png", encodeDisparityColor(golden, params.disparities)}};
    if (scene.hasGroundTruth())
      pictures.push_back({out + "/sidebyside.png", eval::sideBySide(scene, eval::toFloat(golden), maxD)});
    writePngs(pictures);

    eval::JsonWriter json;
    json.beginObject();
    json.key("engine").string("golden");
    json.key("rtl").boolean(false);
    json.key("scene").string(scene.name);
    json.key("width").integer(scene.left.cols);
    json.key("height").integer(scene.left.rows);
    json.key("disparities").integer(params.disparities);
    json.key("mode").string(costModeName(params.mode));
    json.key("frames").integer(1);
    json.key("pixels").integer(long(scene.left.total()));
    json.key("golden_ms").real(ms);
    if (scene.hasGroundTruth()) {
      const eval::ErrorFigures f = eval::evaluate(eval::toFloat(golden), scene);
      json.key("err_nonocc").real(f.errNonocc);
      json.key("err_all").real(f.errAll);
      json.key("density").real(f.density);
      json.key("err_nonocc_valid").real(f.errNonoccValid);
      std::printf("sgm-sim: %s %dx%d D=%d: bad-1.0 nonocc %.2f%%, all %.2f%%, density %.2f%%\n", scene.name.c_str(),
                  scene.left.cols, scene.left.rows, params.disparities, f.errNonocc, f.errAll, f.density);
    }
    json.endObject();
    eval::writeTextFile(out + "/report.json", json.str());
    std::printf("sgm-sim: RTL core not built yet (issue 3): golden model only, %.1f ms; outputs in %s/\n", ms,
                out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sgm-sim: error: %s\n", e.what());
    return 2;
  }
}
