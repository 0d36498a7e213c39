// SPDX-License-Identifier: Apache-2.0
#include "sgm/cli_args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sgm {

CliArgs::CliArgs(int argc, char** argv, const std::set<std::string>& valueOptions, const std::set<std::string>& flags) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      std::string name = arg.substr(2), value;
      const size_t eq = name.find('=');
      const bool inlineValue = eq != std::string::npos;
      if (inlineValue) value = name.substr(eq + 1), name = name.substr(0, eq);
      if (flags.count(name) && !inlineValue) {
        flags_.insert(name);
      } else if (valueOptions.count(name)) {
        if (!inlineValue) {
          if (i + 1 >= argc) throw Error("option --" + name + " needs a value");
          value = argv[++i];
        }
        values_[name] = value;
      } else {
        throw Error("unknown option --" + name + " (see --help)");
      }
    } else {
      positional_.push_back(arg);
    }
  }
}

std::string CliArgs::text(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

long CliArgs::integer(const std::string& name, long fallback, long min, long max) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE)
    throw Error("option --" + name + " expects an integer, got '" + s + "'");
  if (v < min || v > max)
    throw Error("option --" + name + "=" + s + " out of range " + std::to_string(min) + ".." + std::to_string(max));
  return v;
}

double CliArgs::real(const std::string& name, double fallback, double min, double max) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v))
    throw Error("option --" + name + " expects a number, got '" + s + "'");
  if (v < min || v > max)
    throw Error("option --" + name + "=" + s + " out of range " + std::to_string(min) + ".." + std::to_string(max));
  return v;
}

bool CliArgs::onOff(const std::string& name, bool fallback) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  if (it->second == "on" || it->second == "1") return true;
  if (it->second == "off" || it->second == "0") return false;
  throw Error("option --" + name + " expects on or off, got '" + it->second + "'");
}

const std::set<std::string>& CliArgs::pipelineOptions() {
  static const std::set<std::string> names = {
      "d", "p1", "p2", "mode", "subpixel", "lr", "fill", "snap", "median", "census", "p2-mode", "weights", "preset",
      "uniqueness", "ad-weight", "ad-cap", "right-path", "right-block", "edge-reset", "edge-reset-len", "dmin",
      "edge-reset-paths", "output", "output-confidence", "focal", "baseline",
      // golden-only experiments (not in the RTL)
      "subpixel-fit", "mgm", "median-gate", "p1-paths", "snap-edge", "lr-store-bits"};
  return names;
}

Params CliArgs::pipelineParams(Params p) const {
  if (has("preset")) {  // a preset replaces the base configuration except D; the options below override it
    const int disparities = p.disparities;
    p = presetParams(text("preset", ""));
    p.disparities = disparities;
  }
  if (has("mode")) {  // a mode brings its own measured penalties; --p1/--p2 override them
    const Params modeDefaults = defaultParams(parseCostMode(text("mode", "")));
    p.mode = modeDefaults.mode, p.p1 = modeDefaults.p1, p.p2 = modeDefaults.p2;
    if (!isHardwareMode(p.mode)) p.adWeight = 0;  // the AD term needs a census mode (--ad-weight after it is checked)
  }
  p.disparities = int(integer("d", p.disparities, kMinDisparities, kMaxDisparities));
  p.minDisparity = int(integer("dmin", p.minDisparity, 0, kMaxMinDisparity));
  if (has("output")) p.output = parseOutputMode(text("output", ""));
  p.outputConfidence = onOff("output-confidence", p.outputConfidence);
  p.focalQ8 = int(integer("focal", p.focalQ8, 0, (1 << kDepthParamBits) - 1));
  p.baselineUm = int(integer("baseline", p.baselineUm, 0, (1 << kDepthParamBits) - 1));
  p.p1 = int(integer("p1", p.p1, 0, kMaxPenalty));
  p.p2 = int(integer("p2", p.p2, 0, kMaxPenalty));
  p.subpixel = onOff("subpixel", p.subpixel);
  if (text("lr", "") == "off")
    p.lrTolerance = -1;
  else
    p.lrTolerance = int(integer("lr", p.lrTolerance, 0, kMaxDisparities));
  p.fill = onOff("fill", p.fill);
  p.snap = onOff("snap", p.snap);
  p.median = onOff("median", p.median);
  if (has("census")) p.census = parseCensusWindow(text("census", ""));
  if (has("p2-mode")) p.p2Mode = parseP2Mode(text("p2-mode", ""));
  if (has("weights")) p.weights = parsePathWeighting(text("weights", ""));
  p.rightPathWeight = int(integer("right-path", p.rightPathWeight, 0, kMaxRightPathWeight));
  p.rightPathBlock = int(integer("right-block", p.rightPathBlock, 0, kMaxRightPathBlock));
  p.uniqueness = int(integer("uniqueness", p.uniqueness, 0, 99));
  p.medianGate = int(integer("median-gate", p.medianGate, 0, 255));
  p.snapEdge = int(integer("snap-edge", p.snapEdge, 0, 255));
  p.lrStoreBits = int(integer("lr-store-bits", p.lrStoreBits, 0, kMaxLrStoreBits));
  p.adWeight = int(integer("ad-weight", p.adWeight, 0, kMaxAdWeight));
  p.adCap = int(integer("ad-cap", p.adCap, 0, kMaxAdCap));
  if (const std::string fit = text("subpixel-fit", p.linearSubpixel ? "linear" : "parabola");
      fit == "linear" || fit == "parabola")
    p.linearSubpixel = fit == "linear";
  else
    throw Error("option --subpixel-fit expects parabola or linear, got '" + fit + "'");
  p.mgm = onOff("mgm", p.mgm);
  if (has("p1-paths")) p.p1PathPercent = perPath("p1-paths", kMinP1PathPercent, kMaxP1PathPercent, "five percentages");
  p.edgeReset.threshold = int(integer("edge-reset", p.edgeReset.threshold, 0, 255));
  p.edgeReset.length = int(integer("edge-reset-len", p.edgeReset.length, 1, kMaxEdgeResetLength));
  if (has("edge-reset-paths")) p.edgeReset.paths = perPath("edge-reset-paths", 0, 1, "five flags");
  p.validate();
  return p;
}

std::array<int, kPathCount + 1> CliArgs::perPath(const std::string& name, int min, int max,
                                                 const std::string& what) const {
  const std::string list = text(name, "");
  std::array<int, kPathCount + 1> values{};
  size_t at = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    const size_t comma = i + 1 < values.size() ? list.find(',', at) : list.size();
    const std::string item = comma == std::string::npos ? std::string() : list.substr(at, comma - at);
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || v < min || v > max)
      throw Error("option --" + name + " expects " + what + " " + std::to_string(min) + ".." + std::to_string(max) +
                  " (0, 45, 90, 135 degrees, the fifth path), got '" + list + "'");
    values[i] = int(v);
    at = comma + 1;
  }
  return values;
}

std::string oneLine(const std::string& text) {
  constexpr size_t kMaxLine = 4096;  // absurdly long option values are cut
  std::string out;
  for (const char c : text) {
    if (out.size() > kMaxLine) return out + "...";
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

int reportError(const char* tool, const std::exception& error) {
  std::fprintf(stderr, "%s: error: %s\n", tool, oneLine(error.what()).c_str());
  return 2;
}

}  // namespace sgm
