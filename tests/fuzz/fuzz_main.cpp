// SPDX-License-Identifier: Apache-2.0
// sgm-fuzz: seeded random-corruption fuzzing of the tools' input handling.
//
//   images  mutated PNG / JPEG / PGM / PPM / BMP files (synthetic and Aloe
//           seeds) through the image loading every tool uses (readImage,
//           readGray, readSingleChannel, eval::loadSceneFiles)
//   args    random argv from a dictionary of option names and absurd values
//           through the shared parser (CliArgs and its typed getters)
//   tools   a few mutated files and random argv through the real binaries
//           (sgm-golden, sgm-eval, sgm-sim) as child processes
//
// Every case must end in a value or a clean sgm::Error (one line naming the
// problem); a tool run in a non-zero exit with one stderr line and no output
// file. A crash or a case over the time limit stops the run with the line to
// replay it. Deterministic: case i depends only on --seed and i.
#include "bad_images.hpp"
#include "child_process.hpp"
#include "mutate.hpp"

#include "eval_lib.hpp"
#include "sgm/cli_args.hpp"
#include "sgm/image_io.hpp"

#include <opencv2/imgcodecs.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <stdlib.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace sgm;

namespace {

const char* kUsage =
    "usage: sgm-fuzz [--seed S] [--iters N] [--tool-runs K] [--bin DIR] [--sim NAME] [--only I] [--timeout SEC]\n"
    "                [--verbose]\n"
    "Runs N image cases and N argument cases in-process, then K runs of each tool binary in\n"
    "DIR (default build/bin; NAME is an sgm-sim build there, e.g. sgm-sim-d16-w128; none without\n"
    "--sim). --only I replays case I of each phase. A case over SEC seconds (default 20) is a hang.\n"
    "--verbose prints every tool run (arguments and the first output line).\n"
    "Prints one line per phase and 'sgm-fuzz: PASS' or 'sgm-fuzz: FAIL ...'; exit 0 on PASS.\n";

// ------------------------------------------------------------------ crash and hang reporting

char gReplay[1024] = "";  // the case under way, preformatted for the signal handler

void onFatalSignal(int sig) {
  const char* what = sig == SIGALRM ? "sgm-fuzz: FAIL: time limit exceeded (hang) in " : "sgm-fuzz: FAIL: crash in ";
  if (::write(STDERR_FILENO, what, std::strlen(what)) < 0 || ::write(STDERR_FILENO, gReplay, std::strlen(gReplay)) < 0)
    ::_exit(3);
  ::_exit(1);
}

void installHandlers() {
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) std::signal(sig, onFatalSignal);
}

// Marks the start of a case: what to print if it crashes or hangs, and the time limit.
void beginCase(const char* phase, long index, uint64_t seed, const std::string& keep, unsigned timeoutSeconds) {
  std::snprintf(gReplay, sizeof gReplay, "%s case %ld (replay: sgm-fuzz --seed %llu --only %ld%s%s)\n", phase, index,
                (unsigned long long)seed, index, keep.empty() ? "" : "; input kept in ", keep.c_str());
  ::alarm(timeoutSeconds);
}

std::mt19937_64 caseRng(uint64_t seed, uint64_t phase, long index) {
  return std::mt19937_64(seed * 0x9e3779b97f4a7c15ull + phase * 0xbf58476d1ce4e5b9ull + uint64_t(index));
}

uint64_t below(std::mt19937_64& rng, uint64_t n) { return n ? rng() % n : 0; }

// ------------------------------------------------------------------ seeds and dictionaries

struct SeedFile {
  std::string ext;
  std::string bytes;
};

std::vector<SeedFile> makeSeeds() {
  using test::encodeImage;
  using test::texture;
  std::vector<SeedFile> seeds;
  const cv::Mat gray = texture(64, 48, 1), colour = texture(64, 48, 2, CV_8UC3);
  const auto add = [&](const std::string& ext, const cv::Mat& img) { seeds.push_back({ext, encodeImage(ext, img)}); };
  add(".png", gray), add(".png", colour), add(".jpg", colour), add(".jpg", gray);
  add(".pgm", gray), add(".ppm", colour), add(".bmp", colour), add(".bmp", gray);
  add(".png", texture(64, 48, 3, CV_16UC1)), add(".png", texture(64, 48, 4, CV_8UC4));  // valid but rejected
  const std::string aloe = "/usr/share/doc/opencv-doc/examples/data/aloeL.jpg";
  if (fs::exists(aloe)) {  // real photographic content, cropped so a case stays cheap
    const cv::Mat crop = readImage(aloe)(cv::Rect(400, 300, 96, 80)).clone();
    add(".jpg", crop), add(".png", crop), add(".ppm", crop);
  }
  return seeds;
}

const std::vector<std::string>& optionNames() {  // of the three tools, plus strangers
  static const std::vector<std::string> names = {
      "d",       "p1",    "p2", "mode",     "subpixel", "lr",   "fill",   "snap",    "median",  "out",
      "left",    "right", "gt", "gt-scale", "stall",    "seed", "frames", "data",    "delta",   "scene",
      "repeats", "help",  "",   "bogus",    "D",        "d=",   "census", "p2-mode", "weights", "preset"};
  return names;
}

const std::vector<std::string>& absurdValues() {
  static const std::vector<std::string> values = {"",
                                                  "0",
                                                  "1",
                                                  "-1",
                                                  "2",
                                                  "7",
                                                  "8",
                                                  "9",
                                                  "16",
                                                  "64",
                                                  "255",
                                                  "256",
                                                  "257",
                                                  "6000",
                                                  "6001",
                                                  "4294967295",
                                                  "4294967296",
                                                  "99999999999999999999",
                                                  "-99999999999999999999",
                                                  "0.5",
                                                  "0.95",
                                                  "1e309",
                                                  "-1e309",
                                                  "nan",
                                                  "inf",
                                                  "-0",
                                                  "0x10",
                                                  " 16",
                                                  "16 ",
                                                  "on",
                                                  "off",
                                                  "yes",
                                                  "rt",
                                                  "rsad",
                                                  "unified",
                                                  "sad",
                                                  "bt",
                                                  "sad+rt",
                                                  "RT",
                                                  "9x9",
                                                  "9x5",
                                                  "paper",
                                                  "knee",
                                                  "equal",
                                                  "3,2,3,2",
                                                  "default",
                                                  "a\nb",
                                                  "--d",
                                                  "=",
                                                  "%s%n%s",
                                                  std::string(5000, '9'),
                                                  "\xff\xfe\x01"};
  return values;
}

// An argument as printed in a report: one line, long ones cut.
std::string shortText(const std::string& text) {
  const std::string line = oneLine(text);
  return line.size() <= 80 ? line : line.substr(0, 60) + "...(" + std::to_string(text.size()) + " chars)";
}

std::string pick(std::mt19937_64& rng, const std::vector<std::string>& v) { return v[below(rng, v.size())]; }

// ------------------------------------------------------------------ outcomes

// "" when f returned or threw a clean sgm::Error (one line, naming needle when given).
// Option values may hold newlines that a message quotes: the tools print it through oneLine.
template <typename F>
std::string cleanOutcome(F&& f, const std::string& needle, bool newlinesFromInput = false) {
  try {
    f();
    return "";
  } catch (const Error& e) {
    const std::string msg = e.what();
    if (msg.empty()) return "empty error message";
    if (!newlinesFromInput && msg.find('\n') != std::string::npos) return "multi-line error: " + msg;
    if (!needle.empty() && msg.find(needle) == std::string::npos) return "error not naming '" + needle + "': " + msg;
    return "";
  } catch (const std::exception& e) {
    return std::string("exception other than sgm::Error: ") + e.what();
  } catch (...) {
    return "unknown exception";
  }
}

std::string checkDecoded(const cv::Mat& m, bool gray) {
  if (gray ? m.type() != CV_8UC1 : (m.type() != CV_8UC1 && m.type() != CV_8UC3))
    return "returned an image of type " + std::to_string(m.type());
  if (m.empty() || m.cols > kMaxImageSide || m.rows > kMaxImageSide || long(m.cols) * m.rows > kMaxImagePixels)
    return "returned an image of " + std::to_string(m.cols) + "x" + std::to_string(m.rows);
  return "";
}

struct Failure {
  std::string phase;
  long index;
  std::string problem;
};

// ------------------------------------------------------------------ phases

class Fuzzer {
 public:
  Fuzzer(uint64_t seed, std::string dir, unsigned timeout, bool verbose)
      : seed_(seed), dir_(std::move(dir)), timeout_(timeout), verbose_(verbose), seeds_(makeSeeds()) {
    auto [l, r] = test::shiftedPair(64, 48, 2, 5);
    goodLeft_ = dir_ + "/good_left.png", goodRight_ = dir_ + "/good_right.png";
    cv::imwrite(goodLeft_, l), cv::imwrite(goodRight_, r);
  }

  // A mutated (now and then intact) seed; sets ext to its extension.
  std::string mutatedFile(std::mt19937_64& rng, std::string& ext) {
    const SeedFile& s = seeds_[below(rng, seeds_.size())];
    const SeedFile& other = seeds_[below(rng, seeds_.size())];
    static const std::vector<std::string> exts = {".png", ".jpg", ".pgm", ".bmp", ".tif", ".webp", ".txt", ""};
    ext = below(rng, 8) ? s.ext : pick(rng, exts);
    test::Mutator mutator(rng);
    return below(rng, 16) ? mutator.mutate(s.bytes, other.bytes) : s.bytes;
  }

  void imageCase(long i) {
    std::mt19937_64 rng = caseRng(seed_, 1, i);
    std::string ext;
    const std::string bytes = mutatedFile(rng, ext);
    const std::string path = dir_ + "/case" + ext;
    test::writeBytes(path, bytes);
    beginCase("images", i, seed_, path, timeout_);
    const auto check = [&](const std::string& problem) {
      if (!problem.empty()) failures_.push_back({"images", i, problem});
    };
    check(cleanOutcome([&] { fail(checkDecoded(readImage(path), false)), ++values_; }, path));
    check(cleanOutcome([&] { fail(checkDecoded(readGray(path), true)); }, path));
    check(cleanOutcome(
        [&] {
          const cv::Mat m = readSingleChannel(path);
          if (m.channels() != 1 || (m.depth() != CV_8U && m.depth() != CV_16U)) fail("single channel of wrong type");
        },
        path));
    if (i % 4 == 0)  // as sgm-sim and sgm-eval load a scene: errors may name either file or the sizes
      check(cleanOutcome([&] { eval::loadSceneFiles(path, goodRight_, "", 0); }, ""));
    ::alarm(0);
  }

  void argsCase(long i) {
    std::mt19937_64 rng = caseRng(seed_, 2, i);
    std::vector<std::string> argvText = {"tool"};
    const int count = int(below(rng, 9));
    for (int k = 0; k < count; ++k) {
      const uint64_t kind = below(rng, 10);
      if (kind < 5)
        argvText.push_back("--" + pick(rng, optionNames()));
      else if (kind < 6)
        argvText.push_back("--" + pick(rng, optionNames()) + "=" + pick(rng, absurdValues()));
      else
        argvText.push_back(pick(rng, absurdValues()));
    }
    std::set<std::string> valueOptions;
    for (const std::string& name : optionNames())
      if (name != "help" && below(rng, 10) < 7) valueOptions.insert(name);
    std::vector<char*> argv;
    for (std::string& a : argvText) argv.push_back(a.data());
    argv.push_back(nullptr);

    beginCase("args", i, seed_, "", timeout_);
    const auto check = [&](const std::string& problem) {
      if (!problem.empty()) failures_.push_back({"args", i, problem});
    };
    std::unique_ptr<CliArgs> args;
    check(cleanOutcome(
        [&] {
          args = std::make_unique<CliArgs>(int(argvText.size()), argv.data(), valueOptions,
                                           std::set<std::string>{"help"});
        },
        "", true));
    if (args) {
      static const long bounds[][2] = {{-10, 10}, {0, 255}, {2, 256}, {0, 0xffffffffL}, {1, 100}};
      for (const std::string& name : optionNames()) {
        const auto& b = bounds[below(rng, 5)];
        check(cleanOutcome([&] { args->has(name), args->text(name, "fallback"); }, "", true));
        check(cleanOutcome(
            [&] {
              const long v = args->integer(name, b[0], b[0], b[1]);
              if (v < b[0] || v > b[1]) fail("integer out of its bounds");
            },
            "--" + name, true));
        check(cleanOutcome(
            [&] {
              const double v = args->real(name, 0.0, 0.0, 0.95);
              if (!(v >= 0.0 && v <= 0.95)) fail("real out of its bounds");
            },
            "--" + name, true));
        check(cleanOutcome([&] { args->onOff(name, true); }, "--" + name, true));
      }
      Params base;
      base.disparities = 2 + int(below(rng, 255));
      check(cleanOutcome([&] { args->pipelineParams(base).validate(); }, "", true));
    }
    ::alarm(0);
  }

  // One run of a tool binary on a mutated input with random options, in an empty directory.
  void toolCase(const std::string& tool, const std::string& binary, uint64_t phaseId, long i) {
    std::mt19937_64 rng = caseRng(seed_, phaseId, i);
    const std::string work = dir_ + "/run", inputs = dir_ + "/inputs";
    fs::remove_all(work), fs::remove_all(inputs);
    fs::create_directories(work), fs::create_directories(inputs + "/scene");
    std::string ext;
    const std::string bytes = below(rng, 2) ? mutatedFile(rng, ext) : test::readWholeFile(goodLeft_);
    const std::string left = inputs + "/left" + (ext.empty() ? ".png" : ext);
    test::writeBytes(left, bytes);
    std::vector<std::string> args;
    const std::vector<std::string> pipelineOptions(CliArgs::pipelineOptions().begin(),
                                                   CliArgs::pipelineOptions().end());
    std::vector<std::string> names = pipelineOptions;
    if (tool == "sgm-golden") {
      args = {left, goodRight_};
      if (below(rng, 8) == 0) args.pop_back();
    } else if (tool == "sgm-eval") {
      const std::string scene = inputs + "/scene";
      test::writeBytes(scene + "/left.png", bytes);
      fs::copy_file(goodRight_, scene + "/right.png");
      cv::imwrite(scene + "/gt.png", cv::Mat(48, 64, CV_8UC1, cv::Scalar(8)));
      test::writeBytes(scene + "/meta.txt", "gt_scale: 4\n");
      args = {pick(rng, {"run", "table", "bench", "pool", "bogus"}), "--data", inputs, "--scene", "scene"};
      if (args[0] != "bench") args.resize(3);
      if (args[0] == "pool") {
        args[1] = "--pool";
        if (below(rng, 2))
          test::writeBytes(scene + "/meta.txt", pick(rng, {"gt_scale: 4\nndisp: 16\nset: x\n",
                                                           "gt_scale: 4\nndisp: 1e9\n", "gt_scale: 4\nset: a b\n"}));
      }
      names.insert(names.end(), {"delta", "repeats", "half", "opencv"});
    } else {
      args = {"--left", left, "--right", goodRight_, "--d", "16"};
      names.insert(names.end(), {"stall", "seed", "frames", "gt-scale"});
    }
    const uint64_t extra = below(rng, 3);
    for (uint64_t k = 0; k < extra; ++k) {
      std::string value = pick(rng, absurdValues());
      const std::string name = pick(rng, names);
      if (name == "repeats" || name == "frames") value = std::to_string(below(rng, 4));  // keep runs short
      args.insert(args.end(), {"--" + name, value});
    }
    args.insert(
        args.end(),
        {"--out", pick(rng, {"res", "res", "res", "res/sub", "", goodRight_ + "/res"})});  // the last under a file
    if (tool == "sgm-eval" && args[0] == "run") args.resize(args.size() - 2);              // run writes nothing

    beginCase(tool.c_str(), i, seed_, left, timeout_ + 30);
    const test::ChildResult r = test::runChild(binary, args, work, dir_, timeout_);
    ::alarm(0);
    values_ += r.rc == 0;
    if (verbose_) {
      std::string argLine;
      for (const std::string& a : args) argLine += " '" + shortText(a) + "'";
      std::printf("  %s case %ld: exit %d:%s -> %s\n", tool.c_str(), i, r.rc, argLine.c_str(),
                  oneLine(r.err.empty() ? r.out.substr(0, 200) : r.err).c_str());
    }
    std::string problem;
    if (tool == "sgm-sim" && r.rc == 1) {
      problem = "RTL and golden model differ: " + r.out;
    } else if (r.rc == 0) {
      if (!r.err.empty()) problem = "exit 0 with stderr: " + r.err;
    } else {
      problem = test::userErrorProblem(r, tool);
      if (problem.empty() && !test::dirEntries(work).empty()) problem = "output left behind after an error";
    }
    if (!problem.empty()) {
      std::string argLine;
      for (const std::string& a : args) argLine += " '" + shortText(a) + "'";
      failures_.push_back({tool, i, problem + " [args:" + argLine + "]"});
    }
  }

  template <typename F>
  void phase(const std::string& name, long from, long to, F&& runCase) {
    const auto start = std::chrono::steady_clock::now();
    const size_t before = failures_.size();
    values_ = 0;
    for (long i = from; i < to; ++i) runCase(i);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("sgm-fuzz: %-10s %6ld cases, %zu failures, %.1f s%s\n", name.c_str(), to - from,
                failures_.size() - before, s,
                name == "args" ? "" : (" (" + std::to_string(values_) + " accepted, the rest rejected)").c_str());
    std::fflush(stdout);
  }

  const std::vector<Failure>& failures() const { return failures_; }

 private:
  static void fail(const std::string& problem) {
    if (!problem.empty()) throw std::logic_error(problem);
  }

  uint64_t seed_;
  std::string dir_;
  unsigned timeout_;
  bool verbose_;
  std::vector<SeedFile> seeds_;
  std::string goodLeft_, goodRight_;
  std::vector<Failure> failures_;
  long values_ = 0;  // cases of the phase that ended in a value (images) or exit 0 (tools)
};

}  // namespace

int main(int argc, char** argv) {
  try {
    const CliArgs args(argc, argv, {"seed", "iters", "tool-runs", "bin", "sim", "only", "timeout"},
                       {"help", "verbose"});
    if (args.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (!args.positional().empty()) throw Error("unexpected argument '" + args.positional()[0] + "' (see --help)");
    const uint64_t seed = args.has("seed") ? uint64_t(args.integer("seed", 0, 0, 0x7fffffffffffffffL))
                                           : uint64_t(std::random_device{}()) << 16 ^ uint64_t(::getpid());
    const long iters = args.integer("iters", 2000, 0, 100000000);
    const long toolRuns = args.integer("tool-runs", 10, 0, 100000);
    const long only = args.integer("only", -1, 0, 100000000);
    const unsigned timeout = unsigned(args.integer("timeout", 20, 1, 3600));
    const std::string bin = args.text("bin", "build/bin"), sim = args.text("sim", "");
    std::vector<std::pair<std::string, std::string>> tools = {{"sgm-golden", bin + "/sgm-golden"},
                                                              {"sgm-eval", bin + "/sgm-eval"}};
    if (!sim.empty()) tools.push_back({"sgm-sim", bin + "/" + sim});
    for (const auto& [tool, path] : tools)
      if (toolRuns > 0 && ::access(path.c_str(), X_OK) != 0) throw Error("tool binary '" + path + "' not found");

    std::string tmpl = (fs::temp_directory_path() / "sgm_fuzz_XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw Error("cannot create a temporary directory");
    const std::string dir = tmpl;
    for (auto& [tool, path] : tools) path = fs::absolute(path).string();
    installHandlers();
    std::printf("sgm-fuzz: seed %llu, %ld image and %ld argument cases, %ld runs per tool (replay: --seed %llu)\n",
                (unsigned long long)seed, only >= 0 ? 1 : iters, only >= 0 ? 1 : iters, only >= 0 ? 1 : toolRuns,
                (unsigned long long)seed);
    std::fflush(stdout);

    Fuzzer fuzzer(seed, dir, timeout, args.has("verbose"));
    const long from = only >= 0 ? only : 0;
    fuzzer.phase("images", from, only >= 0 ? only + 1 : iters, [&](long i) { fuzzer.imageCase(i); });
    fuzzer.phase("args", from, only >= 0 ? only + 1 : iters, [&](long i) { fuzzer.argsCase(i); });
    for (size_t k = 0; k < tools.size(); ++k)
      fuzzer.phase(tools[k].first, from, only >= 0 ? only + 1 : toolRuns,
                   [&](long i) { fuzzer.toolCase(tools[k].first, tools[k].second, 3 + k, i); });

    std::error_code ec;
    fs::remove_all(dir, ec);
    const auto& failures = fuzzer.failures();
    for (size_t k = 0; k < failures.size() && k < 20; ++k)
      std::printf("sgm-fuzz: %s case %ld: %s (replay: --seed %llu --only %ld)\n", failures[k].phase.c_str(),
                  failures[k].index, oneLine(failures[k].problem).c_str(), (unsigned long long)seed, failures[k].index);
    if (!failures.empty()) {
      std::printf("sgm-fuzz: FAIL: %zu failing cases (seed %llu)\n", failures.size(), (unsigned long long)seed);
      return 1;
    }
    std::printf("sgm-fuzz: PASS (seed %llu)\n", (unsigned long long)seed);
    return 0;
  } catch (const std::exception& e) {
    return reportError("sgm-fuzz", e);
  }
}
