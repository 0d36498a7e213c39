// SPDX-License-Identifier: Apache-2.0
// sgm-regress: constrained-random regression of the verilated sgm_top against
// the golden model. From a master seed, case K (seed mixSeed(master, K)) draws
// a few frames streamed back to back through a freshly reset core: synthetic
// scenes with exact ground truth (tools/synthetic_scene.hpp) at random sizes
// from the smallest legal frame up to MAX_WIDTH, random parameters, a stall
// profile per stream side; some cases reset the core in the middle of a frame
// or send a malformed frame, each followed by a clean frame. Every good frame
// must equal the golden model on every pixel, every malformed frame must raise
// its error_o bit, and every output cycle passes the stream checker of the
// harness (handshake, framing, W x H beats, no hang). Failing cases print the
// one command that replays them.
#include "regress_cases.hpp"

#include "sgm/cli_args.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace sgm;
using namespace sgm::regress;

namespace {

constexpr int kDefaultMaxHeight = 40;

const char* kUsage =
    "usage: sgm-regress [--seed S] [--frames N] [--case K] [--max-height H] [--xml FILE] [--quiet]\n"
    "Runs random cases of the master seed S (default: from the clock) until N good frames\n"
    "(default 500) were checked, or only case K. Frame heights go up to H (default 40).\n"
    "--xml writes a GoogleTest-style report (one test per case). Exit 1 when a case fails.\n";

void writeXml(const std::string& path, const std::vector<std::pair<std::string, std::string>>& results) {
  long failures = 0;
  for (const auto& r : results) failures += !r.second.empty();
  const auto escape = [](const std::string& s) {
    std::string o;
    for (const char ch : s)
      o += ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : ch == '&' ? "&amp;" : ch == '"' ? "&quot;" : std::string(1, ch);
    return o;
  };
  const std::string tmp = path + ".tmp";
  {
    std::ofstream xml(tmp);
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"" << results.size() << "\" failures=\""
        << failures << "\" disabled=\"0\" errors=\"0\" name=\"sgm-regress\">\n  <testsuite name=\"Regress\" tests=\""
        << results.size() << "\" failures=\"" << failures << "\" disabled=\"0\" errors=\"0\">\n";
    for (const auto& [name, failure] : results) {
      xml << "    <testcase name=\"" << escape(name) << "\" classname=\"Regress\"";
      if (failure.empty())
        xml << " />\n";
      else
        xml << ">\n      <failure message=\"" << escape(failure) << "\" />\n    </testcase>\n";
    }
    xml << "  </testsuite>\n</testsuites>\n";
    if (!xml) throw Error("cannot write " + path);
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const CliArgs args(argc, argv, {"seed", "frames", "case", "max-height", "xml"}, {"quiet", "help"});
    if (args.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (!args.positional().empty()) throw Error("unexpected argument '" + args.positional()[0] + "' (see --help)");
    const uint64_t master = args.has("seed")
                                ? uint64_t(args.integer("seed", 0, 0, 0x7fffffffffffffffL))
                                : uint64_t(std::chrono::system_clock::now().time_since_epoch().count()) % 1000000007u;
    const long frames = args.integer("frames", 500, 1, 100000000);
    const int maxHeight = int(args.integer("max-height", kDefaultMaxHeight, kMinHeight, 1024));
    const bool quiet = args.has("quiet");
    const bool oneCase = args.has("case");
    const long only = args.integer("case", 0, 0, 0x7fffffffL);
    const std::string xmlPath = args.text("xml", "");
    if (!xmlPath.empty() && !std::filesystem::is_directory(std::filesystem::absolute(xmlPath).parent_path()))
      throw Error("--xml: no directory for " + xmlPath);

    std::cout << "sgm-regress: D=" << kD << " MAX_WIDTH=" << kMaxWidth << " LANES=" << Vsgm_top_sgm_top::LANES
              << ", master seed " << master
              << (oneCase ? ", case " + std::to_string(only) : ", " + std::to_string(frames) + " good frames") << "\n";
    Totals totals;
    std::vector<std::pair<std::string, std::string>> results;
    const auto start = std::chrono::steady_clock::now();
    for (long k = oneCase ? only : 0; oneCase ? k == only : totals.goodFrames < frames; ++k) {
      const Case c = drawCase(master, uint64_t(k), maxHeight);
      std::string failure;
      try {
        failure = runCase(c, totals);
      } catch (const std::exception& e) {
        failure = e.what();
      }
      ++totals.cases;
      totals.kinds.insert(c.kind);
      totals.sourceStalls.insert(c.sourceStalls);
      totals.sinkStalls.insert(c.sinkStalls);
      std::ostringstream line;
      line << "case " << k << " (seed " << c.seed << "): " << c.kind << ", " << c.frames.size()
           << (c.frames.size() == 1 ? " frame, " : " frames, ") << c.stallText;
      results.push_back({"case" + std::to_string(k), failure});
      if (!failure.empty()) {
        ++totals.failed;
        std::cout << line.str() << ": FAILED\n  " << failure << "\n";
        for (size_t i = 0; i < c.frames.size(); ++i) std::cout << "  frame " << i << ": " << c.frames[i].text << "\n";
        std::cout << "  replay: " << argv[0] << " --seed " << master << " --case " << k
                  << (maxHeight != kDefaultMaxHeight ? " --max-height " + std::to_string(maxHeight) : "") << "\n";
      } else if (!quiet || oneCase) {
        std::cout << line.str() << ": ok\n";
        if (oneCase)
          for (size_t i = 0; i < c.frames.size(); ++i) std::cout << "  frame " << i << ": " << c.frames[i].text << "\n";
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "sgm-regress: " << totals.cases << " cases, " << totals.failed << " failed; " << totals.goodFrames
              << " good frames bit-exact (" << totals.pixels << " pixels, " << totals.widths.size() << " widths in "
              << kMinWidth << ".." << kMaxWidth << ", heights " << totals.minHeight << ".." << totals.maxHeight << "), "
              << totals.malformed << " malformed frames flagged, " << totals.resets
              << " resets mid-frame; mean bad-1.0 (non-occluded) vs the scenes' ground truth "
              << (totals.scoredFrames ? totals.badNonocc / double(totals.scoredFrames) : 0.0) << " %; "
              << totals.combinations.size()
              << " of 96 switch combinations (mode x sub-pixel x LR x fill x median x snap); " << totals.depthFrames
              << " depth frames, " << totals.minDisparityFrames << " with a minimum disparity, "
              << totals.rectifiedFrames << " rectified, " << totals.confidenceFrames
              << " with the confidence; stalls: source " << totals.sourceStalls.size() << " of 5, sink "
              << totals.sinkStalls.size() << " of 5 profiles; case kinds " << totals.kinds.size() << "; " << seconds
              << " s; master seed " << master << "\n";
    if (!xmlPath.empty()) writeXml(xmlPath, results);
    return totals.failed ? 1 : 0;
  } catch (const std::exception& e) {
    return reportError("sgm-regress", e);
  }
}
