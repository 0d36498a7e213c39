#include "sgm/params.hpp"

namespace sgm {

namespace {
struct ModeInfo {
  CostMode mode;
  const char* name;
  int maxCost;
  bool hardware;
};
constexpr ModeInfo kModes[] = {
    {CostMode::kRt, "rt", kCensusBits, true},
    {CostMode::kRsad, "rsad", kCensusBits, true},
    {CostMode::kUnified, "unified", 2 * kCensusBits, true},
    {CostMode::kSad, "sad", 255, false},
    {CostMode::kBt, "bt", 255, false},
    {CostMode::kSadRt, "sad+rt", kCensusBits, false},
};

const ModeInfo& info(CostMode mode) {
  for (const ModeInfo& m : kModes)
    if (m.mode == mode) return m;
  throw Error("internal: unknown cost mode");
}
}  // namespace

bool isHardwareMode(CostMode mode) { return info(mode).hardware; }
const char* costModeName(CostMode mode) { return info(mode).name; }
int maxCost(CostMode mode) { return info(mode).maxCost; }

CostMode parseCostMode(const std::string& name) {
  for (const ModeInfo& m : kModes)
    if (name == m.name) return m.mode;
  throw Error("unknown cost mode '" + name + "' (expected rt, rsad, unified, sad, bt or sad+rt)");
}

std::vector<CostMode> allCostModes() {
  std::vector<CostMode> modes;
  for (const ModeInfo& m : kModes) modes.push_back(m.mode);
  return modes;
}

void Params::validate() const {
  if (disparities < kMinDisparities || disparities > kMaxDisparities)
    throw Error("unsupported disparity count D=" + std::to_string(disparities) + " (expected " +
                std::to_string(kMinDisparities) + ".." + std::to_string(kMaxDisparities) + ")");
  if (p1 < 0 || p1 > kMaxPenalty)
    throw Error("P1=" + std::to_string(p1) + " out of range 0.." + std::to_string(kMaxPenalty));
  if (p2 < p1 || p2 > kMaxPenalty)
    throw Error("P2'=" + std::to_string(p2) + " out of range P1.." + std::to_string(kMaxPenalty) +
                " (P1=" + std::to_string(p1) + ")");
  if (lrTolerance > disparities)
    throw Error("LR tolerance " + std::to_string(lrTolerance) + " exceeds D=" +
                std::to_string(disparities));
}

Params defaultParams(CostMode mode) {
  Params p;
  p.mode = mode;
  switch (mode) {
    // Measured on cones, teddy, sawtooth, venus: docs/algorithm.md, section 11.
    case CostMode::kRt: p.p1 = 28, p.p2 = 130; break;
    case CostMode::kRsad: p.p1 = 18, p.p2 = 100; break;
    case CostMode::kUnified: p.p1 = 40, p.p2 = 200; break;
    case CostMode::kSad: p.p1 = 8, p.p2 = 80; break;
    case CostMode::kBt: p.p1 = 14, p.p2 = 200; break;
    case CostMode::kSadRt: p.p1 = 20, p.p2 = 100; break;
  }
  return p;
}

Params Params::rawSgm() const {
  Params raw = *this;
  raw.subpixel = false;
  raw.lrTolerance = -1;
  raw.fill = false;
  raw.snap = false;
  raw.median = false;
  return raw;
}

}  // namespace sgm
