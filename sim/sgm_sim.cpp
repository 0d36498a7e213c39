// SPDX-License-Identifier: Apache-2.0
// sgm-sim: streams a stereo pair through the verilated sgm_top, runs the
// golden model on the same pair in the same process, compares every output
// pixel, and writes disparity PNGs, a side-by-side picture and report.json (with
// --output depth, a build with DEPTH = 1: the depth words as depth16.png and a depth
// picture instead of the disparity pictures). With --calib DIR (a build with RECTIFY = 1) the
// pair is raw: the core rectifies it through the meshes of the calibration in DIR (OpenCV's
// intrinsics.yml and extrinsics.yml, sgm-eval calib-mesh's arithmetic), the golden model is
// sgm::runRectifiedPipeline, and the rectified pair (the golden model's) is written too; a
// build with DEPTH = 1 also runs one frame of depth from the calibration's f and B. A build with
// CONFIDENCE = 1 sends the confidence in bits 23:16 (--output-confidence, on by default there),
// checked against the golden model's and written as confidence.png and a picture.
#include "Vsgm_top.h"
#include "Vsgm_top_sgm_top.h"
#include "core_harness.hpp"

#include "calibration.hpp"
#include "eval_lib.hpp"
#include "report_json.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/depth.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <unistd.h>

#ifndef SGM_D
#define SGM_D 64
#endif
#ifndef SGM_MAX_WIDTH
#define SGM_MAX_WIDTH 1280
#endif
#ifndef SGM_MAX_HEIGHT
#define SGM_MAX_HEIGHT 1024  // sgm_top's default (make sim passes MAX_HEIGHT)
#endif

using namespace sgm;

namespace {

const char* kUsage =
    "usage: sgm-sim [--left L --right R [--gt G] [--gt-scale S] [--calib DIR [--unit-mm U]]] [--out DIR]\n"
    "               [--stall P] [--seed N] [--frames N] [--preset default|four-path|paper] [pipeline options]\n"
    "Pipeline options as sgm-golden's (--d --p1 --p2 --mode --subpixel --lr --fill --snap\n"
    "--median --census --p2-mode --weights --output --output-confidence --focal --baseline; not the golden-only\n"
    "experiments); options after\n"
    "--preset override it. The census window must be the build's (make sim CENSUS=9x9 or\n"
    "PRESET=paper builds 9x9).\n"
    "Without --left/--right runs the default scene: the Middlebury Aloe pair shipped by\n"
    "opencv-doc, scaled by 1/4 so its disparities fit D = 64. --stall P idles the input and\n"
    "stalls the output with probability P per cycle; --frames N sends the pair N times back\n"
    "to back. --calib DIR: L and R are a raw camera pair, rectified in the core (make sim RECTIFY=1) through\n"
    "the meshes of the OpenCV calibration in DIR (intrinsics.yml, extrinsics.yml; --unit-mm: mm per\n"
    "calibration unit, for the depth); the ground truth is in the rectified frame; 3 frames by default\n"
    "(report.json: frame_period_cycles_per_pixel). TRACE=1 (at build and run time) writes\n"
    "build/trace/sgm_top.fst.\n";

}  // namespace

int main(int argc, char** argv) {
  try {
    auto options = CliArgs::pipelineOptions();
    options.insert({"left", "right", "gt", "gt-scale", "out", "stall", "seed", "frames", "calib", "unit-mm"});
    const CliArgs args(argc, argv, options, {"help"});
    if (args.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (!args.positional().empty()) throw Error("unexpected argument '" + args.positional()[0] + "' (see --help)");
    if (args.has("left") != args.has("right")) throw Error("give both --left and --right, or neither");
    constexpr int kRightBlock = Vsgm_top_sgm_top::RIGHT_BLOCK;  // this build's fifth path (0: none)
    constexpr int kCensusH = Vsgm_top_sgm_top::CENSUS_H;        // this build's census window
    BuildLevers build;
    build.rightBlock = kRightBlock, build.census9x9 = kCensusH == 9;
    build.edgeReset = Vsgm_top_sgm_top::EDGE_RESET != 0;
    Params base = buildDefaults(build, SGM_D);                  // the build's defaults, then the options
    base.outputConfidence = Vsgm_top_sgm_top::CONFIDENCE != 0;  // a build with the confidence sends it
    const Params params = args.pipelineParams(base);
    if (params.disparities != SGM_D)
      throw Error("this simulator is built for D=" + std::to_string(SGM_D) +
                  " (make sim D=" + std::to_string(params.disparities) + " builds another)");
    const CensusWindow built = kCensusH == 9 ? CensusWindow::k9x9 : CensusWindow::k9x5;
    if (params.census != built)
      throw Error(std::string("this simulator is built for the ") + censusWindowName(built) + " census, not " +
                  censusWindowName(params.census) + " (make sim CENSUS=" + censusWindowName(params.census) +
                  " builds that one)");
    if (!isHardwareMode(params.mode))
      throw Error("cost mode " + std::string(costModeName(params.mode)) + " is software only");
    if (params.p2 > 255) throw Error("P2'=" + std::to_string(params.p2) + " exceeds the core's 8-bit input");
    if (params.lrTolerance > 7)
      throw Error("LR tolerance " + std::to_string(params.lrTolerance) + " exceeds the core's 3-bit input");
    if (params.experimental())
      throw Error(
          "--right-path without --right-block, --subpixel-fit linear, --mgm, --median-gate, --p1-paths, "
          "--snap-edge and --lr-store-bits are golden-only experiments, not in the core");
    if (params.minDisparity && !Vsgm_top_sgm_top::MIN_DISPARITY)
      throw Error("--dmin " + std::to_string(params.minDisparity) +
                  ": this simulator is built without the minimum disparity (make sim MIN_DISPARITY=1 builds one)");
    if (params.outputConfidence && !Vsgm_top_sgm_top::CONFIDENCE)
      throw Error(
          "--output-confidence on: this simulator is built without the confidence (make sim CONFIDENCE=1 "
          "builds one)");
    const bool depthOut = params.output == OutputMode::kDepth;
    if (depthOut && !Vsgm_top_sgm_top::DEPTH)
      throw Error("this simulator is built without the depth output (make sim DEPTH=1 builds one)");
    if (params.edgeReset.threshold && !Vsgm_top_sgm_top::EDGE_RESET)
      throw Error("this simulator is built without the path restart (sgm_top EDGE_RESET = 0): give --edge-reset 0");
    if (params.rightPathWeight && params.rightPathBlock != kRightBlock)
      throw Error(kRightBlock ? "this simulator's fifth path runs in blocks of " + std::to_string(kRightBlock) +
                                    " (--right-block " + std::to_string(kRightBlock) + ")"
                              : std::string("this simulator is built without the fifth path (make sim RIGHT_BLOCK=B "
                                            "builds one)"));
    const std::string out = args.text("out", "build/sim");
    checkOutputDirectory(out);  // before the simulation; created only to write the results
    const double stall = args.real("stall", 0.0, 0.0, 0.95);
    const uint32_t seed = uint32_t(args.integer("seed", 1, 0, 0xffffffffL));
    const bool calibrated = args.has("calib");
    const int frames = int(args.integer("frames", calibrated ? 3 : 1, 1, 100));
    if (calibrated && !args.has("left")) throw Error("--calib needs the raw pair: --left and --right");
    if (calibrated && !Vsgm_top_sgm_top::RECTIFY)
      throw Error("--calib: this simulator is built without the rectification (make sim RECTIFY=1 builds one)");

    eval::Scene scene;
    if (args.has("left")) {
      scene = eval::loadSceneFiles(args.text("left", ""), args.text("right", ""), args.text("gt", ""),
                                   args.real("gt-scale", 0, 0, 1e6));
    } else {
      scene = eval::loadAloe();
    }
    checkInput(scene.left, scene.right, params);
    const int w = scene.left.cols, h = scene.left.rows;
    if (w > SGM_MAX_WIDTH)
      throw Error("width " + std::to_string(w) + " exceeds this simulator's MAX_WIDTH=" +
                  std::to_string(SGM_MAX_WIDTH) + " (make sim MAX_WIDTH=" + std::to_string(w) + " builds another)");
    constexpr int kMinWidth = Vsgm_top_sgm_top::MIN_FRAME_WIDTH;  // max(D, 16), more with many lanes
    if (w < kMinWidth)
      throw Error("width " + std::to_string(w) + " is below the core's minimum " + std::to_string(kMinWidth));
    if (h > SGM_MAX_HEIGHT)
      throw Error("height " + std::to_string(h) + " exceeds MAX_HEIGHT=" + std::to_string(SGM_MAX_HEIGHT));

    // The calibration: the pair's meshes at the build's step, their fit in its line buffer.
    Params frameParams = params;
    std::shared_ptr<StereoMesh> mesh;
    RectifiedPair rectified;
    RowSpan pairSpan;
    eval::MeshError meshError[2];
    if (calibrated) {
      const std::string dir = args.text("calib", "");
      const eval::StereoCalibration calibration = eval::readCalibration(dir);
      mesh = std::make_shared<StereoMesh>(eval::stereoMesh(calibration, scene.left.size(),
                                                           Vsgm_top_sgm_top::RECTIFY_GRID_LOG2,
                                                           args.real("unit-mm", 1, 1e-6, 1e6), dir));
      pairSpan = stereoRowSpan(*mesh);
      if (lineBufferRows(pairSpan) > Vsgm_top_sgm_top::RECTIFY_ROWS)
        throw Error(dir + ": the calibration needs a line buffer of " + std::to_string(lineBufferRows(pairSpan)) +
                    " rows, this simulator's has " + std::to_string(Vsgm_top_sgm_top::RECTIFY_ROWS) +
                    " (make sim RECTIFY_ROWS=" + std::to_string(lineBufferRows(pairSpan)) + " or more)");
      meshError[0] = eval::meshError(calibration.left, mesh->left);
      meshError[1] = eval::meshError(calibration.right, mesh->right);
      frameParams.rectify = true, frameParams.rectifyLag = pairSpan.lag;
    }
    const DisparityMap golden = calibrated
                                    ? runRectifiedPipeline(scene.left, scene.right, *mesh, frameParams, &rectified)
                                    : runPipeline(scene.left, scene.right, frameParams);

    tb::CoreHarness<Vsgm_top> core("sgm_top", seed, tb::Stalls{stall, stall});
    std::vector<tb::FrameInput> inputs(frames, tb::FrameInput{scene.left, scene.right, frameParams});
    if (calibrated) inputs[0].mesh = mesh;
    // A calibrated pair in a build with the depth output: one more frame of depth (the
    // calibration's f and B).
    const bool depthFrame = calibrated && Vsgm_top_sgm_top::DEPTH && !depthOut;
    Params depthParams = frameParams;
    if (depthFrame) {
      depthParams.output = OutputMode::kDepth;
      depthParams.focalQ8 = int(mesh->focalQ8), depthParams.baselineUm = int(mesh->baselineUm);
      inputs.push_back(tb::FrameInput{scene.left, scene.right, depthParams});
    }
    const auto start = std::chrono::steady_clock::now();
    const bool tty = isatty(fileno(stderr));
    const std::vector<tb::FrameOutput> outputs = core.run(inputs, [&](uint64_t done, uint64_t total) {
      if (tty)
        std::fprintf(stderr, "\rsgm-sim: %3d%% of %llu output pixels", int(100 * done / total),
                     (unsigned long long)total);
    });
    if (tty) std::fprintf(stderr, "\r%60s\r", "");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    long mismatches = 0;
    std::string firstMismatch;
    for (size_t k = 0; k < inputs.size(); ++k) {
      long m = 0;
      const std::string text = tb::compareOutput(golden, inputs[k].params, outputs[k], "sgm_top output", &m);
      if (firstMismatch.empty() && !text.empty()) firstMismatch = "frame " + std::to_string(k) + ": " + text;
      mismatches += m;
    }
    const DisparityMap& rtl = outputs[0].map;
    const uint64_t cycles = outputs[0].lastOutCycle - outputs[0].firstInCycle + 1;
    const uint64_t allCycles = outputs[size_t(frames) - 1].lastOutCycle - outputs[0].firstInCycle + 1;
    // Frames back to back: the input of frame k + 1 starts a frame period after frame k's.
    const double period = frames > 1 ? double(outputs[size_t(frames) - 1].firstInCycle - outputs[0].firstInCycle) /
                                           double(frames - 1)
                                     : 0.0;
    const long pixels = long(w) * h;

    const int range = params.minDisparity + params.disparities;  // the largest disparity + 1
    const float maxD = float(range - 1);
    std::vector<std::pair<std::string, cv::Mat>> pictures;
    if (depthOut) {  // the core sent depth words: no disparity to draw or score
      char title[96];
      std::snprintf(title, sizeof title, "depth (f %.1f px, B %.1f mm)", params.focalQ8 / 256.0,
                    params.baselineUm / 1000.0);
      pictures = {{out + "/depth16.png", outputs[0].words},
                  {out + "/depth_color.png", eval::depthPicture(outputs[0].words, title)}};
    } else {
      pictures = {{out + "/disparity16.png", encodeDisparity16(rtl)},
                  {out + "/disparity8.png", encodeDisparity8(rtl, range)},
                  {out + "/disparity_color.png", encodeDisparityColor(rtl, range)}};
      if (scene.hasGroundTruth())
        pictures.push_back({out + "/sidebyside.png", eval::sideBySide(scene, eval::toFloat(rtl), maxD)});
    }
    if (params.outputConfidence) {  // the first frame's bits 23:16 (docs/algorithm.md section 7b)
      pictures.push_back({out + "/confidence.png", outputs[0].confidence});
      pictures.push_back({out + "/confidence_color.png",
                          eval::confidencePicture(outputs[0].confidence, "confidence, the output word's bits 23:16")});
    }
    if (calibrated) {
      pictures.push_back({out + "/rectified_left.png", rectified.left.gray});
      pictures.push_back({out + "/rectified_right.png", rectified.right.gray});
    }
    if (depthFrame) {
      char title[96];
      std::snprintf(title, sizeof title, "depth (f %.1f px, B %.1f mm)", depthParams.focalQ8 / 256.0,
                    depthParams.baselineUm / 1000.0);
      pictures.push_back({out + "/depth16.png", outputs.back().words});
      pictures.push_back({out + "/depth_color.png", eval::depthPicture(outputs.back().words, title)});
    }
    if (mismatches) {  // where the core differs from the golden model (the first frame): white
      const cv::Mat expected = outputWords(golden, inputs[0].params);
      cv::Mat where(h, w, CV_8UC1);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          where.at<uint8_t>(y, x) = outputs[0].words.at<uint16_t>(y, x) != expected.at<uint16_t>(y, x) ? 255 : 0;
      pictures.push_back({out + "/mismatch.png", where});
    }

    eval::JsonWriter json;
    json.beginObject();
    json.key("scene").string(scene.name);
    json.key("bit_exact").boolean(mismatches == 0);
    json.key("mismatches").integer(mismatches);
    json.key("first_mismatch").string(firstMismatch);
    json.key("pixels").integer(pixels * long(inputs.size()));
    json.key("frames").integer(long(inputs.size()));
    json.key("width").integer(w);
    json.key("height").integer(h);
    json.key("disparities").integer(params.disparities);
    json.key("lanes").integer(Vsgm_top_sgm_top::LANES);
    json.key("mode").string(costModeName(params.mode));
    json.key("census").string(censusWindowName(params.census));
    json.key("preset").string(presetName(params));
    json.key("p1").integer(params.p1);
    json.key("p2").integer(params.p2);
    json.key("p2_mode").string(p2ModeName(params.p2Mode));
    json.key("weights").string(pathWeightingName(params.weights));
    json.key("min_disparity").integer(params.minDisparity);
    json.key("output").string(outputModeName(params.output));
    json.key("output_confidence").boolean(params.outputConfidence);
    if (depthOut) {
      json.key("focal_q8").integer(params.focalQ8);
      json.key("baseline_um").integer(params.baselineUm);
    }
    json.key("stall").real(stall);
    json.key("seed").integer(seed);
    json.key("cycles").integer(long(cycles));
    json.key("cycles_per_pixel").real(double(cycles) / double(pixels));
    json.key("latency_cycles").integer(long(cycles) - pixels);
    json.key("sustained_cycles_per_pixel").real(double(allCycles) / double(pixels * frames));
    if (frames > 1) json.key("frame_period_cycles_per_pixel").real(period / double(pixels));
    json.key("rectified").boolean(calibrated);
    if (calibrated) {
      json.key("calib").string(args.text("calib", ""));
      json.key("rectify_lag").integer(pairSpan.lag);
      json.key("line_buffer_rows_needed").integer(lineBufferRows(pairSpan));
      json.key("line_buffer_rows").integer(Vsgm_top_sgm_top::RECTIFY_ROWS);
      json.key("mesh_error_max_px").beginArray().real(meshError[0].maxPx, 4).real(meshError[1].maxPx, 4).endArray();
      if (!depthOut) json.key("focal_q8").integer(mesh->focalQ8).key("baseline_um").integer(mesh->baselineUm);
      json.key("depth_frame").boolean(depthFrame);
    }
    json.key("sim_cycles_per_second").real(double(core.top().cycles()) / seconds);
    json.key("sim_seconds").real(seconds);
    json.key("frame_errors").integer(long(outputs[0].errors));
    std::optional<eval::ErrorFigures> figures;
    if (scene.hasGroundTruth() && !depthOut) {
      figures = eval::evaluate(eval::toFloat(rtl), scene);
      const eval::ErrorFigures& f = *figures;
      json.key("err_nonocc").real(f.errNonocc);
      json.key("err_all").real(f.errAll);
      json.key("err_disc").real(f.errDisc);
      json.key("density").real(f.density);
      json.key("err_nonocc_valid").real(f.errNonoccValid);
    }
    json.endObject();
    // Pictures and report together, or nothing.
    std::vector<OutputFile> files;
    for (const auto& [path, image] : pictures) files.push_back({path, encodePng(image, path)});
    files.push_back({out + "/report.json", json.str()});
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec || !std::filesystem::is_directory(out)) throw Error("cannot create output directory '" + out + "'");
    writeFiles(files);

    std::printf(
        "sgm-sim: %s %dx%d D=%d mode=%s census=%s preset=%s (P1 %d, P2' %d, P2 %s, weights %s), %d frame(s), stall %.2f\n",
        scene.name.c_str(), w, h, params.disparities, costModeName(params.mode), censusWindowName(params.census),
        presetName(params).c_str(), params.p1, params.p2, p2ModeName(params.p2Mode), pathWeightingName(params.weights),
        frames, stall);
    const long allPixels = pixels * long(inputs.size());
    std::printf("sgm-sim: bit-exact %s: %.2f%% of %ld pixels match the golden model%s%s\n", mismatches ? "NO" : "yes",
                100.0 * double(allPixels - mismatches) / double(allPixels), allPixels,
                firstMismatch.empty() ? "" : "; ", firstMismatch.c_str());
    if (calibrated)
      std::printf("sgm-sim: rectified in the core: lag %d, line buffer %d of %d rows, mesh error %.4f / %.4f px%s\n",
                  pairSpan.lag, lineBufferRows(pairSpan), int(Vsgm_top_sgm_top::RECTIFY_ROWS), meshError[0].maxPx,
                  meshError[1].maxPx, depthFrame ? ", one more frame of depth" : "");
    if (frames > 1)
      std::printf("sgm-sim: %d frames back to back: %.4f cycles/pixel a frame\n", frames, period / double(pixels));
    std::printf(
        "sgm-sim: %llu cycles for the frame, %.4f cycles/pixel (latency %lld cycles), %.0f simulated cycles/s\n",
        (unsigned long long)cycles, double(cycles) / double(pixels), (long long)(cycles)-pixels,
        double(core.top().cycles()) / seconds);
    if (figures)
      std::printf("sgm-sim: bad-1.0 nonocc %.2f%%, all %.2f%%, density %.2f%%\n", figures->errNonocc, figures->errAll,
                  figures->density);
    std::string written;
    for (const auto& file : pictures) written += std::filesystem::path(file.first).filename().string() + " ";
    std::printf("sgm-sim: wrote %s in %s/\n", (written + "report.json").c_str(), out.c_str());
    return mismatches == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    return reportError("sgm-sim", e);
  }
}
