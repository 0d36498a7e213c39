// SPDX-License-Identifier: Apache-2.0
// sgm-bench: the `make bench` report. bench/bench.mk runs the verilated core
// (sgm-sim, which checks every output pixel against the golden model in the
// same process) on every scene and on one frame of each video format, and the
// simulation-speed variants on Cones; this tool then runs OpenCV StereoSGBM
// (three modes) and the golden-vs-OpenCV timing on the same pairs, reads the
// simulator's reports, and writes build/bench/report.{md,json} and the charts.
//
//   sgm-bench formats --source IMAGE --out DIR   writes DIR/<format>_{left,right}.png
//   sgm-bench report  --data DIR --bench DIR [--repeats N] [--pool DIR]
// With --pool, the report adds the scene pool: the golden model (= the core, bit-exact)
// and OpenCV on every pool scene at its ndisp (the `make eval-pool` summary), and the
// core's own runs on pool scenes that bench.mk made (BENCH_DIR/pool-rtl/<scene>/).
#include "eval_lib.hpp"
#include "report_bench.hpp"
#include "report_chart.hpp"
#include "report_json.hpp"
#include "report_pool.hpp"
#include "report_table.hpp"
#include "report_util.hpp"
#include "video_formats.hpp"

#include "sgm/cli_args.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace sgm;
using namespace sgm::eval;

namespace {

const char* kUsage =
    "usage: sgm-bench formats --source IMAGE --out DIR\n"
    "       sgm-bench report --data DIR --bench DIR [--repeats N] [--pool DIR]\n";

// The simulated frame sizes (one per distinct width x height).
std::string frameName(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// The accuracy goals of issue 6 (nonocc, delta 1, invalid = error).
const std::map<std::string, double> kGoals = {{"cones", 3.5}, {"teddy", 7.0}, {"sawtooth", 2.0}, {"venus", 1.5}};

struct OpenCvMode {
  const char* key;
  const char* label;
  int mode;
};
const OpenCvMode kOpenCvModes[] = {
    {"opencv-sgbm", "OpenCV MODE_SGBM", cv::StereoSGBM::MODE_SGBM},
    {"opencv-hh", "OpenCV MODE_HH", cv::StereoSGBM::MODE_HH},
    {"opencv-3way", "OpenCV MODE_SGBM_3WAY", cv::StereoSGBM::MODE_SGBM_3WAY},
};

// A simulator report (sgm-sim --out DIR writes DIR/report.json).
struct SimReport {
  std::map<std::string, std::string> fields;
  std::string path;
  const std::string& at(const std::string& key) const {
    const auto it = fields.find(key);
    if (it == fields.end()) throw Error("'" + path + "' has no field '" + key + "'");
    return it->second;
  }
  double number(const std::string& key) const { return std::stod(at(key)); }
  bool flag(const std::string& key) const { return at(key) == "true"; }
};

SimReport readSimReport(const std::string& dir) {
  const std::string path = dir + "/report.json";
  if (!fs::exists(path)) throw Error("missing simulator report '" + path + "' (run `make bench`, not sgm-bench alone)");
  return SimReport{readFlatJson(path), path};
}

int commandFormats(const CliArgs& args) {
  const std::string source = args.text("source", "");
  const std::string out = args.text("out", "");
  if (source.empty() || out.empty()) throw Error("formats needs --source IMAGE and --out DIR");
  const cv::Mat left = readGray(source);
  fs::create_directories(out);
  std::vector<std::pair<std::string, cv::Mat>> files;
  std::map<std::string, bool> done;
  for (const VideoFormat& f : kVideoFormats) {
    const std::string name = frameName(f.width, f.height);
    if (done[name]) continue;
    done[name] = true;
    // Any content works for timing (the core's cycles do not depend on it);
    // a resized real image keeps the golden comparison meaningful.
    cv::Mat l, r;
    cv::resize(left, l, cv::Size(f.width, f.height), 0, 0, cv::INTER_AREA);
    const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, -8, 0, 1, 0);  // right view: 8 px disparity
    cv::warpAffine(l, r, shift, l.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    files.push_back({out + "/" + name + "_left.png", l});
    files.push_back({out + "/" + name + "_right.png", r});
  }
  writePngs(files);
  std::printf("sgm-bench: wrote %zu format images in %s/\n", files.size(), out.c_str());
  return 0;
}

// One Verilator build option set, run BENCH_REPEATS times on Cones in
// interleaved rounds (simspeed/<variant>/run<k>/): one frame's simulation speed
// varies by some 10 % from run to run, so the report gives the median and the spread.
struct SimVariant {
  std::string name, flags;
  std::vector<double> cyclesPerSecond;  // one per run, sorted
  double cyclesPerFrame = 0;            // the same in every run
  double median() const { return eval::median(cyclesPerSecond); }
  double min() const { return cyclesPerSecond.front(); }
  double max() const { return cyclesPerSecond.back(); }
};

SimVariant readSimVariant(const fs::path& dir) {
  SimVariant v;
  v.name = dir.filename().string();
  const fs::path flags = dir / "flags.txt";
  if (!fs::exists(flags)) throw Error("missing '" + flags.string() + "' (run `make bench`, not sgm-bench alone)");
  v.flags = readFirstLine(flags.string());
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!entry.is_directory()) continue;  // flags.txt and the runs' logs sit beside the run directories
    const SimReport run = readSimReport(entry.path().string());
    v.cyclesPerSecond.push_back(run.number("sim_cycles_per_second"));
    v.cyclesPerFrame = run.number("cycles");
  }
  if (v.cyclesPerSecond.empty()) throw Error("no simulation-speed run under '" + dir.string() + "'");
  std::sort(v.cyclesPerSecond.begin(), v.cyclesPerSecond.end());
  return v;
}

// Everything `report` measures, then rendered.
struct BenchData {
  std::vector<std::string> scenes;
  std::map<std::string, Scene> sceneData;
  std::map<std::string, SimReport> rtl;                                // scene -> sgm-sim report
  std::map<std::string, std::map<std::string, ErrorFigures>> figures;  // method -> scene -> figures
  std::map<std::string, BenchResult> speed;                            // scene -> golden vs OpenCV
  std::vector<SimVariant> simVariants;                                 // by name (cones)
  std::map<std::string, SimReport> formats;                            // WxH -> report
  int d = 64, maxWidth = 0;
  std::optional<PoolReport> pool;            // --pool: the golden model on the pool
  std::map<std::string, SimReport> poolRtl;  // pool scene -> sgm-sim report
};

ErrorFigures rtlFigures(const SimReport& r) {
  ErrorFigures f;
  f.errNonocc = r.number("err_nonocc");
  f.errAll = r.number("err_all");
  if (r.at("err_disc") != "null") f.errDisc = r.number("err_disc");
  f.density = r.number("density");
  f.errNonoccValid = r.number("err_nonocc_valid");
  return f;
}

// The scene pool: the golden model and OpenCV on every scene (each at its ndisp), and the
// core's reports of the pool scenes bench.mk simulated (BENCH_DIR/pool-rtl/<scene>/).
void measurePool(const std::string& pool, const std::string& bench, BenchData& b) {
  std::vector<Scene> scenes;
  for (const std::string& dir : listScenes(pool)) scenes.push_back(loadScene(dir));
  if (scenes.empty()) throw Error("no scenes (left.png, right.png, gt.png) under --pool '" + pool + "'");
  PoolOptions options;  // the hardware defaults, D per scene
  options.halves = poolHalves(pool);
  std::fprintf(stderr, "sgm-bench: the scene pool (%zu scenes): golden model, four-path preset, OpenCV\n",
               scenes.size());
  b.pool = computePool(scenes, options);
  const std::string rtl = bench + "/pool-rtl";
  if (fs::is_directory(rtl))
    for (const auto& entry : fs::directory_iterator(rtl))
      if (entry.is_directory())
        b.poolRtl.emplace(entry.path().filename().string(), readSimReport(entry.path().string()));
}

BenchData measure(const std::string& data, const std::string& bench, int repeats, const std::string& pool) {
  BenchData b;
  if (!pool.empty()) measurePool(pool, bench, b);
  // The scenes the core ran on in this bench run (BENCH_SCENES, and Aloe unless BENCH_ALOE=0).
  const auto simulated = [&](const std::string& name) { return fs::exists(bench + "/rtl/" + name + "/report.json"); };
  for (const std::string& name : paperScenes()) {
    if (!fs::exists(data + "/" + name + "/left.png") || !simulated(name)) {
      std::fprintf(stderr, "sgm-bench: note: scene '%s' not found under %s or not simulated, skipped\n", name.c_str(),
                   data.c_str());
      continue;
    }
    b.sceneData[name] = loadScene(data + "/" + name);
    b.scenes.push_back(name);
  }
  if (aloeAvailable() && simulated("aloe")) {
    b.sceneData["aloe"] = loadAloe();
    b.scenes.push_back("aloe");
  }
  if (b.scenes.empty()) throw Error("no simulated scene under '" + bench + "/rtl' (run `make bench`)");

  const Params params;  // the hardware defaults, as sgm-sim runs them
  b.d = params.disparities;
  for (const std::string& name : b.scenes) {
    const Scene& scene = b.sceneData.at(name);
    std::fprintf(stderr, "sgm-bench: %s: RTL report, golden, OpenCV x3, timing\n", name.c_str());
    b.rtl.emplace(name, readSimReport(bench + "/rtl/" + name));
    b.figures["rtl"][name] = rtlFigures(b.rtl.at(name));
    b.figures["golden"][name] = evaluate(toFloat(runPipeline(scene.left, scene.right, params)), scene);
    for (const OpenCvMode& m : kOpenCvModes)
      b.figures[m.key][name] = evaluate(
          runOpenCvSgbm(scene.leftColor, scene.rightColor, opencvDisparities(b.d), m.mode), scene);
    b.speed[name] = runBench(scene, repeats);
  }
  for (const auto& entry : fs::directory_iterator(bench + "/simspeed")) {
    if (!entry.is_directory()) continue;
    b.simVariants.push_back(readSimVariant(entry.path()));
  }
  std::sort(b.simVariants.begin(), b.simVariants.end(),
            [](const SimVariant& x, const SimVariant& y) { return x.name < y.name; });
  for (const VideoFormat& f : kVideoFormats) {  // the frame sizes of BENCH_FRAMES
    const std::string name = frameName(f.width, f.height);
    if (!b.formats.count(name) && fs::exists(bench + "/formats/" + name + "/report.json"))
      b.formats.emplace(name, readSimReport(bench + "/formats/" + name));
  }
  if (b.formats.empty())
    throw Error("no video-format frame simulated under '" + bench + "/formats' (run `make bench`)");
  b.maxWidth = std::stoi(readFirstLine(bench + "/max_width.txt"));
  return b;
}

double clockMhz(const SimReport& frame, int fps) { return frame.number("cycles") * fps / 1e6; }

std::string optional(const std::optional<double>& v) { return v ? fixed(*v, 2) : "-"; }

// The pool's means in report order: groups, halves, sets.
std::vector<PoolMean> allMeans(const PoolReport& p) {
  std::vector<PoolMean> means = p.groups;
  means.insert(means.end(), p.halves.begin(), p.halves.end());
  means.insert(means.end(), p.sets.begin(), p.sets.end());
  return means;
}

const PoolRow* poolRow(const PoolReport& report, const std::string& scene) {
  for (const PoolRow& row : report.rows)
    if (row.scene == scene) return &row;
  return nullptr;
}

// The pool's means (as `make eval-pool`) and the core's runs on pool scenes.
std::string poolSection(const BenchData& b) {
  const PoolReport& p = *b.pool;
  std::ostringstream md;
  md << "\n## Scene pool (`make eval-pool`: golden model = the core, each scene at its `ndisp`)\n\n"
     << "Middlebury: bad-1.0 over the non-occluded pixels; KITTI: D1 (error > 3 px and > 5 %); invalid = error. "
        "`four-path`: the preset of the core without the fifth path, the AD term and the uniqueness ratio "
        "(docs/notes/accuracy-pool.md). OpenCV StereoSGBM strict (invalid = error) and on its valid pixels only, "
        "with its density.\n\n"
     << "| means | scenes | ours | four-path | OpenCV strict | OpenCV valid only | OpenCV density |\n"
        "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const PoolMean& m : allMeans(p))
    md << "| " << m.name << " | " << m.scenes << " | **" << fixed(m.ours, 2) << "** | " << optional(m.today) << " | "
       << optional(m.opencvStrict) << " | " << optional(m.opencvValid) << " | " << optional(m.opencvDensity) << " |\n";
  if (p.worstRegression)
    md << "\nWorst change against the four-path preset: " << p.worstScene << " " << (*p.worstRegression >= 0 ? "+" : "")
       << fixed(*p.worstRegression, 2) << " points. Per scene: build/eval/pool.md (`make eval-pool`).\n";
  md << "\n### The core on pool scenes (`BENCH_POOL_SCENES`, D = 128 build)\n\n";
  if (b.poolRtl.empty()) {
    md << "Not simulated in this run (BENCH_POOL_SCENES empty or POOL absent).\n";
    return md.str();
  }
  md << "| scene | size | D | bit-exact | cycles/pixel | figure (golden = RTL) |\n|---|---|---:|---|---:|---:|\n";
  for (const auto& [scene, r] : b.poolRtl) {
    const PoolRow* row = poolRow(p, scene);
    md << "| " << scene << " | " << r.at("width") << "x" << r.at("height") << " | " << r.at("disparities") << " | "
       << (r.flag("bit_exact") ? "yes" : "NO (" + r.at("mismatches") + " px, first " + r.at("first_mismatch") + ")")
       << " | " << fixed(r.number("cycles_per_pixel"), 4) << " | ";
    if (row && std::to_string(row->disparities) == r.at("disparities"))
      md << fixed(strictFigure(row->set, row->ours), 2) << (isKittiSet(row->set) ? " (D1)" : " (bad-1.0)");
    else
      md << "- (the pool runs it at D = " << (row ? std::to_string(row->disparities) : std::string("?")) << ")";
    md << " |\n";
  }
  md << "\nsgm-sim compared every output pixel of these frames with the golden model in the same run.\n";
  return md.str();
}

std::string markdown(const BenchData& b) {
  std::ostringstream md;
  md << "# Benchmark: accuracy and speed, one run\n\n"
     << "Core: D = " << b.d << ", MAX_WIDTH = " << b.maxWidth
     << ", hardware defaults (docs/algorithm.md). Figures: bad-1.0 error in %, invalid pixels counted as errors. "
     << "`RTL` is the verilated core's output; every pixel of it was compared with the golden model in the same run "
     << "(column *bit-exact*).\n\n";

  md << "## Accuracy (nonocc)\n\n| scene | RTL | bit-exact | paper (Rank SAD, Table I) | goal | OpenCV SGBM | OpenCV HH "
        "| OpenCV 3WAY |\n|---|---|---|---|---|---|---|---|\n";
  const std::map<std::string, double> paper = tableMethods(b.d)[3].paper;  // the Rank SAD row
  for (const std::string& s : b.scenes) {
    const SimReport& r = b.rtl.at(s);
    md << "| " << s << " | **" << fixed(b.figures.at("rtl").at(s).errNonocc, 2) << "** | "
       << (r.flag("bit_exact") ? "yes" : "NO (" + r.at("mismatches") + " px)") << " | "
       << (paper.count(s) ? fixed(paper.at(s), 1) : "-") << " | " << (kGoals.count(s) ? fixed(kGoals.at(s), 1) : "-");
    for (const OpenCvMode& m : kOpenCvModes) md << " | " << fixed(b.figures.at(m.key).at(s).errNonocc, 2);
    md << " |\n";
  }
  md << "\n## Every figure per scene\n\n| scene | method | nonocc | all | disc | density |\n|---|---|---|---|---|---|\n";
  std::vector<std::pair<std::string, std::string>> methods = {{"rtl", "RTL"}, {"golden", "golden model"}};
  for (const OpenCvMode& m : kOpenCvModes) methods.push_back({m.key, m.label});
  for (const std::string& s : b.scenes)
    for (const auto& [key, label] : methods) {
      const ErrorFigures& f = b.figures.at(key).at(s);
      md << "| " << s << " | " << label << " | " << fixed(f.errNonocc, 2) << " | " << fixed(f.errAll, 2) << " | "
         << optional(f.errDisc) << " | " << fixed(f.density, 2) << " |\n";
    }
  md << "\nSawtooth has no Middlebury masks here, so its nonocc mask is derived from the ground truth and it has no "
        "disc figure; Aloe (OpenCV's copy, downscaled 4x) has no masks either.\n";

  md << "\n## Speed: golden model vs OpenCV StereoSGBM (same run, same pairs)\n\n"
     << "| scene | size | golden ms | OpenCV MODE_SGBM ms | ratio golden/OpenCV |\n|---|---|---|---|---|\n";
  for (const std::string& s : b.scenes) {
    const BenchResult& r = b.speed.at(s);
    md << "| " << s << " | " << r.width << "x" << r.height << " | " << fixed(r.goldenMs, 1) << " | "
       << fixed(r.opencvMs(), 1) << " (" << r.opencvInput() << ") | " << fixed(r.ratio(), 2) << " |\n";
  }
  const BenchResult& any = b.speed.begin()->second;
  md << "\nMedian of " << any.repeats << " interleaved rounds after a warm-up. The golden model uses "
     << any.goldenThreads << " thread(s), OpenCV " << any.opencvThreads
     << "; its faster input (gray or colour) is the one compared. Ratios vary with machine load.\n";

  md << "\n## The core: cycles per pixel and latency (Verilator, no stalls)\n\n"
     << "| scene | size | cycles/pixel | latency (cycles) | sim cycles/s |\n|---|---|---|---|---|\n";
  for (const std::string& s : b.scenes) {
    const SimReport& r = b.rtl.at(s);
    md << "| " << s << " | " << r.at("width") << "x" << r.at("height") << " | "
       << fixed(r.number("cycles_per_pixel"), 4) << " | " << r.at("latency_cycles") << " | "
       << fixed(r.number("sim_cycles_per_second"), 0) << " |\n";
  }
  md << "\n## Simulation speed by Verilator build options (Cones, one frame)\n\n"
     << "| variant | Verilator options | runs | cycles/s (median) | min .. max | frames/s | seconds per frame "
        "|\n|---|---|---|---|---|---|---|\n";
  for (const SimVariant& v : b.simVariants) {
    md << "| " << v.name << " | `" << v.flags << "` | " << v.cyclesPerSecond.size() << " | " << fixed(v.median(), 0)
       << " | " << fixed(v.min(), 0) << " .. " << fixed(v.max(), 0) << " | " << fixed(v.median() / v.cyclesPerFrame, 3)
       << " | " << fixed(v.cyclesPerFrame / v.median(), 2) << " |\n";
  }
  md << "\nMedian of interleaved rounds (one run of each variant per round); where two variants' ranges overlap, "
        "this machine does not tell them apart. Every run is also a bit-exact check against the golden model. "
        "The verilated tests of `make test` use the `checked` options (random initial values).\n";

  md << "\n## Clock needed per video format (the paper's Table II)\n\n"
     << "| format | cycles per frame (simulated) | cycles/pixel | our clock (MHz) | paper's clock (MHz, 9 cycles/pixel) "
        "|\n|---|---|---|---|---|\n";
  for (const VideoFormat& f : kVideoFormats) {
    if (!b.formats.count(frameName(f.width, f.height))) {
      md << "| " << f.name << " | not simulated in this run (BENCH_FRAMES) | | | |\n";
      continue;
    }
    const SimReport& r = b.formats.at(frameName(f.width, f.height));
    md << "| " << f.name << " | " << r.at("cycles") << " | " << fixed(r.number("cycles_per_pixel"), 4) << " | "
       << fixed(clockMhz(r, f.fps), 1) << " | "
       << (f.paperMhz > 0 ? fixed(f.paperMhz, 1) : fixed(9.0 * f.width * f.height * f.fps / 1e6, 1) + " (derived)")
       << " |\n";
  }
  md << "\nCycles per frame are from the first input to the last output beat of one frame, including the flush "
        "and the P2 table fill; back-to-back frames need the same.\n";

  if (b.pool) md << poolSection(b);
  md << "\n## Pictures\n\n![error per scene](accuracy.png)\n\n";
  for (const std::string& s : b.scenes)
    md << "**" << s << "**: left | ground truth | RTL | error map (green correct, red wrong, blue invalid)\n\n"
       << "![" << s << "](rtl/" << s << "/sidebyside.png)\n\n";
  return md.str();
}

void figuresJson(JsonWriter& j, const ErrorFigures& f) {
  j.beginObject();
  j.key("err_nonocc").real(f.errNonocc);
  j.key("err_all").real(f.errAll);
  j.key("err_disc").real(f.errDisc);
  j.key("density").real(f.density);
  j.endObject();
}

std::string json(const BenchData& b) {
  JsonWriter j;
  j.beginObject();
  j.key("d").integer(b.d);
  j.key("max_width").integer(b.maxWidth);
  j.key("delta").real(1.0);
  j.key("scenes").beginArray();
  for (const std::string& s : b.scenes) j.string(s);
  j.endArray();
  const std::map<std::string, double> paper = tableMethods(b.d)[3].paper;
  j.key("accuracy").beginObject();
  for (const std::string& s : b.scenes) {
    j.key(s).beginObject();
    j.key("rtl");
    figuresJson(j, b.figures.at("rtl").at(s));
    j.key("bit_exact").boolean(b.rtl.at(s).flag("bit_exact"));
    j.key("mismatches").integer(std::stol(b.rtl.at(s).at("mismatches")));
    j.key("golden");
    figuresJson(j, b.figures.at("golden").at(s));
    for (const OpenCvMode& m : kOpenCvModes) {
      j.key(m.key);
      figuresJson(j, b.figures.at(m.key).at(s));
    }
    j.key("paper_rank_sad");
    paper.count(s) ? j.real(paper.at(s)) : j.null();
    j.key("goal");
    kGoals.count(s) ? j.real(kGoals.at(s)) : j.null();
    j.endObject();
  }
  j.endObject();
  j.key("speed").beginArray();
  for (const std::string& s : b.scenes) {
    const BenchResult& r = b.speed.at(s);
    j.beginObject();
    j.key("scene").string(s);
    j.key("golden_ms").real(r.goldenMs);
    j.key("opencv_sgbm_ms").real(r.opencvMs());
    j.key("opencv_input").string(r.opencvInput());
    j.key("ratio").real(r.ratio());
    j.key("golden_threads").integer(r.goldenThreads);
    j.key("repeats").integer(r.repeats);
    j.endObject();
  }
  j.endArray();
  j.key("core").beginArray();
  for (const std::string& s : b.scenes) {
    const SimReport& r = b.rtl.at(s);
    j.beginObject();
    j.key("scene").string(s);
    j.key("cycles_per_pixel").real(r.number("cycles_per_pixel"));
    j.key("latency_cycles").integer(std::stol(r.at("latency_cycles")));
    j.key("sim_cycles_per_second").real(r.number("sim_cycles_per_second"));
    j.endObject();
  }
  j.endArray();
  j.key("simulation").beginArray();
  for (const SimVariant& v : b.simVariants) {
    j.beginObject();
    j.key("variant").string(v.name);
    j.key("verilator_flags").string(v.flags);
    j.key("cycles_per_second").real(v.median());
    j.key("frames_per_second").real(v.median() / v.cyclesPerFrame);
    j.key("cycles_per_second_min").real(v.min());
    j.key("cycles_per_second_max").real(v.max());
    j.key("runs").integer(long(v.cyclesPerSecond.size()));
    j.endObject();
  }
  j.endArray();
  j.key("pool");
  if (!b.pool) {
    j.null();
  } else {
    j.beginObject();
    j.key("means").beginArray();  // groups, halves, sets: as pool.json's
    const auto maybe = [&j](const std::optional<double>& v) { v ? j.real(*v) : j.null(); };
    for (const PoolMean& m : allMeans(*b.pool)) {
      j.beginObject();
      j.key("name").string(m.name);
      j.key("scenes").integer(m.scenes);
      j.key("ours").real(m.ours);
      j.key("four_path");
      maybe(m.today);
      j.key("opencv_strict");
      maybe(m.opencvStrict);
      j.key("opencv_valid");
      maybe(m.opencvValid);
      j.key("opencv_density");
      maybe(m.opencvDensity);
      j.endObject();
    }
    j.endArray();
    j.key("rtl").beginArray();
    for (const auto& [scene, r] : b.poolRtl) {
      j.beginObject();
      j.key("scene").string(scene);
      j.key("width").integer(std::stol(r.at("width")));
      j.key("height").integer(std::stol(r.at("height")));
      j.key("disparities").integer(std::stol(r.at("disparities")));
      j.key("bit_exact").boolean(r.flag("bit_exact"));
      j.key("mismatches").integer(std::stol(r.at("mismatches")));
      j.key("cycles_per_pixel").real(r.number("cycles_per_pixel"));
      j.endObject();
    }
    j.endArray();
    j.endObject();
  }
  j.key("formats").beginArray();
  for (const VideoFormat& f : kVideoFormats) {
    if (!b.formats.count(frameName(f.width, f.height))) continue;  // not in BENCH_FRAMES
    const SimReport& r = b.formats.at(frameName(f.width, f.height));
    j.beginObject();
    j.key("format").string(f.name);
    j.key("width").integer(f.width);
    j.key("height").integer(f.height);
    j.key("fps").integer(f.fps);
    j.key("cycles_per_frame").integer(std::stol(r.at("cycles")));
    j.key("cycles_per_pixel").real(r.number("cycles_per_pixel"));
    j.key("clock_mhz").real(clockMhz(r, f.fps));
    j.key("paper_mhz");
    f.paperMhz > 0 ? j.real(f.paperMhz) : j.null();
    j.endObject();
  }
  j.endArray();
  j.endObject();
  return j.str();
}

// The error chart: the RTL with the paper's Rank SAD figure beside it, then OpenCV.
cv::Mat accuracyChart(const BenchData& b) {
  TableReport t;
  t.disparities = b.d;
  t.scenes = b.scenes;
  t.present.insert(b.scenes.begin(), b.scenes.end());
  for (const auto& [name, scene] : b.sceneData)
    if (scene.nonoccDerived) t.derivedNonocc.insert(name);
  Method rtl;
  rtl.key = "rtl";
  rtl.label = "Full pipeline, this core (RTL)";
  rtl.kind = MethodKind::kFull;
  rtl.paper = tableMethods(b.d)[3].paper;
  rtl.hardwareDefault = true;
  t.methods.push_back(rtl);
  for (const OpenCvMode& m : kOpenCvModes) {
    Method om;
    om.key = m.key;
    om.label = m.label;
    om.kind = MethodKind::kOpenCv;
    t.methods.push_back(om);
  }
  for (const Method& m : t.methods) t.results[m.key] = b.figures.at(m.key);
  return table1Chart(t, "SGM core (RTL, bit-exact) vs Yao & Cheng and OpenCV");
}

int commandReport(const CliArgs& args) {
  const std::string data = args.text("data", "");
  const std::string bench = args.text("bench", "");
  if (data.empty() || bench.empty()) throw Error("report needs --data DIR and --bench DIR");
  const int repeats = int(args.integer("repeats", 3, 1, 100));
  const std::string pool = args.text("pool", "");
  if (!pool.empty() && !fs::is_directory(pool)) throw Error("--pool '" + pool + "' is not a directory");
  const BenchData b = measure(data, bench, repeats, pool);
  const std::string md = markdown(b), js = json(b);
  writePngs({{bench + "/accuracy.png", accuracyChart(b)}});
  writeTextFile(bench + "/report.json", js);
  writeTextFile(bench + "/report.md", md);
  std::printf("%s", md.substr(0, md.find("\n## Every figure")).c_str());
  std::printf("\nsgm-bench: wrote report.md, report.json, accuracy.png in %s/\n", bench.c_str());
  bool allExact = true;
  for (const auto& [scene, r] : b.rtl) allExact = allExact && r.flag("bit_exact");
  for (const auto& [name, r] : b.formats) allExact = allExact && r.flag("bit_exact");
  for (const auto& [name, r] : b.poolRtl) allExact = allExact && r.flag("bit_exact");
  if (!allExact)
    std::fprintf(stderr, "sgm-bench: error: the RTL output differs from the golden model (see report.md)\n");
  return allExact ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2 || std::string(argv[1]) == "--help") {
      std::fputs(kUsage, argc < 2 ? stderr : stdout);
      return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    if (command == "formats") return commandFormats(CliArgs(argc - 1, argv + 1, {"source", "out"}));
    if (command == "report") return commandReport(CliArgs(argc - 1, argv + 1, {"data", "bench", "repeats", "pool"}));
    throw Error("unknown command '" + command + "' (formats, report)");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sgm-bench: error: %s\n", e.what());
    return 2;
  }
}
