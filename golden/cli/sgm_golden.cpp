// SPDX-License-Identifier: Apache-2.0
// sgm-golden: runs the golden model on a stereo pair and writes the disparity
// map as 16-bit PNG (disparity x 256), the paper's 8-bit rendering and a
// colour-mapped PNG.
#include "sgm/cli_args.hpp"
#include "sgm/depth.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"
#include "sgm/rectify.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

const char* kUsage =
    "usage: sgm-golden LEFT RIGHT [--out PREFIX] [--d D] [--p1 N] [--p2 N]\n"
    "                  [--mode rt|rsad|unified|sad|bt|sad+rt] [--subpixel on|off]\n"
    "                  [--lr TOL|off] [--fill on|off] [--snap on|off] [--median on|off]\n"
    "                  [--census 9x5|9x9] [--p2-mode knee|paper] [--weights 3232|equal]\n"
    "                  [--preset default|four-path|paper]  (options after a preset override it)\n"
    "                  [--dmin N] the search covers N .. N + D - 1 (0 .. 255; default 0); the output is the\n"
    "                             true disparity\n"
    "                  [--right-path W] fifth path from the right, weight W (0..8; default 4)\n"
    "                  [--right-block B] that path per block of B px with one block of look-ahead\n"
    "                                    (default 64, the core's RIGHT_BLOCK; 0: the whole row, golden-only)\n"
    "                  [--uniqueness U] uniqueness ratio U % (0..99; default 15, 0 off)\n"
    "                  [--ad-weight W] [--ad-cap T] C += W * min(|IL - IR|, T) / 8 (default 3, 20; W 0 off)\n"
    "                  [--edge-reset T] [--edge-reset-len R] [--edge-reset-paths A,B,C,D,E] a path starts\n"
    "                                    again (Lr = C) within R steps of a gray step >= T, for the paths\n"
    "                                    marked 1 (0, 45, 90, 135 degrees, the fifth; default 40, 6, 1,1,0,1,1; T 0 off)\n"
    "golden-only experiments, NOT in the RTL (off by default; docs/algorithm.md section 12):\n"
    "                  [--subpixel-fit parabola|linear] linear: the equiangular (V) fit\n"
    "                  [--mgm on|off] raster-order MGM: each path averages two causal neighbours\n"
    "                  [--median-gate T] the median takes only pixels within T gray levels of the centre\n"
    "                  [--p1-paths A,B,C,D,E] P1 per path in % (0, 45, 90, 135 degrees, the fifth path)\n"
    "                  [--snap-edge T] edge snapping only onto an intensity step of at least T (with --snap on)\n"
    "                  [--lr-store-bits N] the 45/90/135-degree paths read the row above's Lr saturated to N bits\n"
    "                  [--confidence on|off] also PREFIX_confidence.png (docs/algorithm.md section 7b)\n"
    "                  [--mesh FILE] LEFT and RIGHT are a raw camera pair: rectified first through the meshes\n"
    "                                of FILE (sgm-eval calib-mesh; section 13), a pixel whose left source lies\n"
    "                                outside the image invalid; also PREFIX_rectified_{left,right}.png and\n"
    "                                PREFIX_depth16.png (mm from the file's f and B, 0 = invalid; section 10b)\n"
    "                  [--output disparity|depth] [--focal F] [--baseline B] the core's output word\n"
    "                                (register OUTPUT.MODE); depth also writes PREFIX_depth16.png from f = F/256 px\n"
    "                                and B um (default 0, or the --mesh file's)\n"
    "                  [--output-confidence on|off] the core's word carries the confidence (register\n"
    "                                OUTPUT.CONFIDENCE); --confidence on writes the map\n"
    "Writes PREFIX_disp16.png (disparity x 256, 0 = invalid), PREFIX_disp8.png\n"
    "(the paper's [0, 255] scaling) and PREFIX_color.png. PREFIX defaults to 'disparity'.\n";

}  // namespace

int main(int argc, char** argv) {
  try {
    auto options = sgm::CliArgs::pipelineOptions();
    options.insert({"out", "confidence", "mesh"});
    const sgm::CliArgs args(argc, argv, options, {"help"});
    if (args.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (args.positional().size() != 2) throw sgm::Error("expected two images, LEFT and RIGHT (see --help)");
    sgm::Params params = args.pipelineParams();
    const std::string prefix = args.text("out", "disparity");
    if (prefix.empty()) throw sgm::Error("empty --out prefix");
    // Checked before the work: sgm-golden creates no directories.
    const std::filesystem::path outDir = std::filesystem::path(prefix).parent_path();
    if (!outDir.empty() && !std::filesystem::is_directory(outDir))
      throw sgm::Error("cannot write '" + prefix + "_disp16.png': directory '" + outDir.string() + "' does not exist");
    const bool withConfidence = args.onOff("confidence", false);
    const std::string meshPath = args.text("mesh", "");
    if (args.has("mesh") && meshPath.empty()) throw sgm::Error("empty --mesh file name");
    cv::Mat left = sgm::readGray(args.positional()[0]);
    cv::Mat right = sgm::readGray(args.positional()[1]);
    std::vector<std::pair<std::string, cv::Mat>> outputs;
    const auto start = std::chrono::steady_clock::now();
    cv::Mat confidence;
    sgm::DisparityMap map;
    if (!meshPath.empty()) {  // section 13: rectified first; no disparity where the left source is outside
      const sgm::StereoMesh mesh = sgm::readMeshFile(meshPath);
      if (!args.has("focal")) params.focalQ8 = int(mesh.focalQ8);
      if (!args.has("baseline")) params.baselineUm = int(mesh.baselineUm);
      params.validate();
      sgm::RectifiedPair rectified;
      map = sgm::runRectifiedPipeline(left, right, mesh, params, &rectified, &confidence);
      left = rectified.left.gray;
      outputs.push_back({prefix + "_rectified_left.png", rectified.left.gray});
      outputs.push_back({prefix + "_rectified_right.png", rectified.right.gray});
    } else {
      map = sgm::runPipeline(left, right, params, &confidence);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    outputs.push_back({prefix + "_disp16.png", sgm::encodeDisparity16(map)});
    const int range = params.minDisparity + params.disparities;  // the largest disparity + 1
    outputs.push_back({prefix + "_disp8.png", sgm::encodeDisparity8(map, range)});
    outputs.push_back({prefix + "_color.png", sgm::encodeDisparityColor(map, range)});
    if (withConfidence) outputs.push_back({prefix + "_confidence.png", confidence});
    const bool withDepth = !meshPath.empty() || params.output == sgm::OutputMode::kDepth;
    if (withDepth)
      outputs.push_back(
          {prefix + "_depth16.png", sgm::depthMap(map, uint32_t(params.focalQ8), uint32_t(params.baselineUm))});
    sgm::writePngs(outputs);
    const double density = cv::countNonZero(map.valid) * 100.0 / double(map.valid.total());
    std::printf(
        "sgm-golden: %dx%d D=%d mode=%s census=%s preset=%s: %.1f ms, density %.2f%%, wrote %s_{disp16,disp8,color%s}.png\n",
        left.cols, left.rows, params.disparities, sgm::costModeName(params.mode), sgm::censusWindowName(params.census),
        sgm::presetName(params).c_str(), ms, density, prefix.c_str(),
        (std::string(withConfidence ? ",confidence" : "") +
         (meshPath.empty() ? "" : ",rectified_left,rectified_right") + (withDepth ? ",depth16" : ""))
            .c_str());
    return 0;
  } catch (const std::exception& e) {
    return sgm::reportError("sgm-golden", e);
  }
}
