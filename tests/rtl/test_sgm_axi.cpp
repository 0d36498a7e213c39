// SPDX-License-Identifier: Apache-2.0
// sgm_axi (sgm_top + AXI4-Lite registers) configured THROUGH the driver
// (sw/sgm_driver.cpp) over an AXI4-Lite master with random delays on all five
// channels, which presents each request while the previous response of its kind
// may still wait, every bus cycle checked by the protocol checker; the streams go
// through the core harness (random stalls, stream checker) and every frame is
// compared with the golden model. The register map is sw/include/sgm_regs.h.
#include "Vsgm_axi.h"
#include "Vsgm_axi_sgm_axi.h"
#include "axil_bfm.hpp"
#include "core_harness.hpp"
#include "malformed_frames.hpp"
#include "rectify_meshes.hpp"
#include "sgm_driver.hpp"
#include "sgm_mesh_file.hpp"
#include "sgm_regs.h"
#include "synthetic_scene.hpp"

#include "sgm/pipeline.hpp"
#include "sgm/rectify.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <random>

namespace {

using sgm::tb::AxilMaster;
using sgm::tb::FrameInput;
using Harness = sgm::tb::CoreHarness<Vsgm_axi>;
using Rtl = Vsgm_axi_sgm_axi;
namespace drv = sgm::driver;

constexpr int kD = Rtl::D;
// The run-time levers of the build (sgm_axi UNIQUENESS, AD_TERM; axi-d16-lean builds neither),
// as FEATURES must read them: the header's bits.
constexpr uint32_t log2Of(uint32_t v) { return v > 1 ? 1 + log2Of(v / 2) : 0; }
constexpr uint32_t kFeatures =
    (Rtl::UNIQUENESS ? SGM_FEATURES_UNIQUENESS : 0u) | (Rtl::AD_TERM ? SGM_FEATURES_AD_TERM : 0u) |
    (Rtl::RIGHT_BLOCK ? SGM_FEATURES_RIGHT_PATH | log2Of(Rtl::RIGHT_BLOCK) << SGM_FEATURES_RIGHT_BLOCK_SHIFT : 0u) |
    (Rtl::EDGE_RESET ? SGM_FEATURES_EDGE_RESET : 0u) | (Rtl::DEPTH ? SGM_FEATURES_DEPTH : 0u) |
    (Rtl::MIN_DISPARITY ? SGM_FEATURES_MIN_DISPARITY : 0u) | (Rtl::CONFIDENCE ? SGM_FEATURES_CONFIDENCE : 0u) |
    (Rtl::RECTIFY ? SGM_FEATURES_RECTIFY | log2Of(Rtl::RECTIFY_ROWS) << SGM_FEATURES_RECTIFY_ROWS_SHIFT |
                        uint32_t(Rtl::RECTIFY_GRID_LOG2) << SGM_FEATURES_RECTIFY_GRID_SHIFT
                  : 0u);

// The settings with every lever the build lacks off (bit-exact frames run what the build has).
sgm::Params withBuildLevers(sgm::Params p) {
  if (!Rtl::UNIQUENESS) p.uniqueness = 0;
  if (!Rtl::AD_TERM) p.adWeight = 0;
  if (!Rtl::RIGHT_BLOCK) p.rightPathWeight = 0;
  if (!Rtl::EDGE_RESET) p.edgeReset.threshold = 0;
  if (!Rtl::DEPTH) p.output = sgm::OutputMode::kDisparity;
  if (!Rtl::MIN_DISPARITY) p.minDisparity = 0;
  if (!Rtl::RECTIFY) p.rectify = false, p.rectifyLag = 0;
  return p;
}

// The build's defaults (sgm::buildDefaults), which its registers reset to.
constexpr bool kFullDefaults = Rtl::RIGHT_BLOCK && Rtl::UNIQUENESS && Rtl::AD_TERM && Rtl::EDGE_RESET;
sgm::Params defaults() {
  sgm::BuildLevers build;
  build.rightBlock = Rtl::RIGHT_BLOCK, build.uniqueness = Rtl::UNIQUENESS, build.adTerm = Rtl::AD_TERM;
  build.edgeReset = Rtl::EDGE_RESET;
  build.census9x9 = Rtl::CENSUS_H == 9;
  return sgm::buildDefaults(build, kD);
}
constexpr uint32_t kPenaltyReset = kFullDefaults ? SGM_PENALTY_RESET : SGM_PENALTY_RESET_FOUR_PATH;
constexpr uint32_t kConfigReset = kFullDefaults ? SGM_CONFIG_RESET : SGM_CONFIG_RESET_FOUR_PATH;
constexpr uint32_t kEdgeResetReset = kFullDefaults ? SGM_EDGE_RESET_RESET : SGM_EDGE_RESET_RESET_FOUR_PATH;

// A synthetic scene of w x h, widened to the build's MIN_WIDTH where that is set and wider.
FrameInput scene(int w, int h, uint32_t seed, const sgm::Params& p) {
  const sgm::synth::SyntheticScene s = sgm::synth::makeSyntheticScene(std::max(w, int(Rtl::MIN_WIDTH)), h, kD, seed);
  return FrameInput{s.left, s.right, p};
}

// The driver's configuration of a golden parameter set and frame size: the registers that
// hold its frame configuration word (tb/hardware_config.hpp, by the generated table of the
// word) decoded by the driver. The driver must carry every field of the word: its encoding
// of what it decoded gives the same registers back (a field the driver lacks stops the test).
drv::FrameConfig frameConfig(const sgm::Params& p, cv::Size size) {
  const sgm::tb::HardwareConfig c = sgm::tb::hardwareConfig(p, size.width, size.height);
  constexpr int kRegs = 9;
  const uint32_t regs[kRegs] = {c.reg(SGM_REG_FRAME_SIZE),     c.reg(SGM_REG_PENALTY),       c.reg(SGM_REG_CONFIG),
                                c.reg(SGM_REG_EDGE_RESET),     c.reg(SGM_REG_OUTPUT),        c.reg(SGM_REG_DEPTH_FOCAL),
                                c.reg(SGM_REG_DEPTH_BASELINE), c.reg(SGM_REG_MIN_DISPARITY), c.reg(SGM_REG_RECTIFY)};
  const drv::FrameConfig f = drv::Driver::decode(regs[0], regs[1], regs[2], regs[3], regs[4], regs[5], regs[6], regs[7],
                                                 regs[8]);
  const uint32_t back[kRegs] = {drv::Driver::encodeSize(f.width, f.height),
                                drv::Driver::encodePenalty(f),
                                drv::Driver::encodeConfig(f),
                                drv::Driver::encodeEdgeReset(f),
                                drv::Driver::encodeOutput(f),
                                drv::Driver::encodeDepthFocal(f),
                                drv::Driver::encodeDepthBaseline(f),
                                drv::Driver::encodeMinDisparity(f),
                                drv::Driver::encodeRectify(f)};
  const char* names[kRegs] = {"FRAME_SIZE",  "PENALTY",        "CONFIG",        "EDGE_RESET", "OUTPUT",
                              "DEPTH_FOCAL", "DEPTH_BASELINE", "MIN_DISPARITY", "RECTIFY"};
  for (int r = 0; r < kRegs; ++r)
    if (back[r] != regs[r]) {
      char what[160];
      std::snprintf(what, sizeof what, "%s 0x%08X encoded back by the driver as 0x%08X", names[r], regs[r], back[r]);
      throw sgm::Error(std::string("the driver's FrameConfig lacks a field of the frame configuration word: ") + what);
    }
  return f;
}

// The core behind its bus: harness (streams), AXI4-Lite master, driver. Each
// frame's configuration is written by the driver where the harness says it is
// due (after the previous frame's first beat, so in the middle of that frame);
// the first one also enables the core.
struct AxiCore {
  Harness core;
  AxilMaster<Vsgm_axi> bus;
  drv::Driver driver;
  sgm::tb::AxisSource<Vsgm_axi> extra;  // hand-made beats outside run()
  bool enabled = false;
  std::vector<bool> busyWhenConfigured;

  explicit AxiCore(const std::string& name, uint32_t seed = 1, sgm::tb::Stalls stalls = {0.1, 0.1},
                   sgm::tb::AxilDelays delays = {})
      : core(name, seed, stalls),
        bus(core.top().model(), seed * 7 + 1, delays, [this] { core.step(); }),
        driver(drv::Bus{[this](uint32_t a) { return okay(bus.read(a), a).data; },
                        [this](uint32_t a, uint32_t v) { okay(bus.write(a, v), a); }}),
        extra(seed * 13 + 5, 0.2) {
    core.setCycleHooks(
        [this] {
          bus.drive();
          if (!extra.empty()) extra.drive(core.top().model());
        },
        [this] {
          bus.sample(core.top().cycles());
          extra.sample(core.top().model());
        });
    core.setPresenter([this](const sgm::Params& p, cv::Size size) {
      // Busy once the writes are done: the harness presents a frame's configuration
      // after the previous frame's first beat, so the writes fell inside that frame
      // (busy right at the call may still read 0: the controller leaves IDLE two
      // cycles after the beat).
      driver.configure(frameConfig(p, size));
      busyWhenConfigured.push_back(driver.busy());
      if (!enabled) driver.enable(enabled = true);
    });
    // A calibration's meshes as a user loads them: the mesh file's bytes (sgm-eval calib-mesh
    // writes them with the golden model's encodeMeshFile) read by the driver's parser
    // (sw/include/sgm_mesh_file.hpp), then through the MESH_* registers (docs/registers.md).
    core.setMeshLoader([this](const sgm::StereoMesh& mesh) {
      const std::string bytes = sgm::encodeMeshFile(mesh);
      drv::MeshFile file;
      const std::string error = drv::parseMeshFile(bytes.data(), bytes.size(), &file);
      if (!error.empty()) throw sgm::Error("the driver's mesh file parser: " + error);
      if (file.focalQ8 != mesh.focalQ8 || file.baselineUm != mesh.baselineUm)
        throw sgm::Error("the driver's mesh file parser: f or B differ from the file's");
      if (!driver.loadMeshes(file.left(), file.right(), 200000))
        throw sgm::Error("the driver could not load the meshes (MESH_CTRL.PENDING stayed 1)");
    });
  }

  static sgm::tb::AxilResponse okay(sgm::tb::AxilResponse r, uint32_t addr) {
    if (r.resp != sgm::tb::kAxilOkay) throw sgm::Error("register 0x" + std::to_string(addr) + " answered SLVERR");
    return r;
  }
  Vsgm_axi& model() { return core.top().model(); }
  void steps(int n) {
    for (int i = 0; i < n; ++i) core.step();
  }
  // Every frame bit-exact against the golden model (a rectified frame: against the meshes
  // loaded last, `calibration`).
  void expectBitExact(const std::vector<FrameInput>& frames, const std::string& what) {
    const std::vector<sgm::tb::FrameOutput> out = core.run(frames);
    std::shared_ptr<const sgm::StereoMesh> calibration;
    for (size_t k = 0; k < frames.size(); ++k) {
      if (frames[k].mesh) calibration = frames[k].mesh;
      const sgm::Params& p = frames[k].params;
      const sgm::DisparityMap golden = p.rectify
                                           ? sgm::runRectifiedPipeline(frames[k].left, frames[k].right, *calibration, p)
                                           : sgm::runPipeline(frames[k].left, frames[k].right, p);
      EXPECT_EQ(sgm::tb::compareOutput(golden, p, out[k], "sgm_axi output"), "") << what << ", frame " << k;
    }
  }
  ~AxiCore() { EXPECT_EQ(bus.finish(), "") << "AXI4-Lite protocol"; }
};

// A bus without delays: every request is taken in the first cycle it is presented
// (no response waits), so a test can time a write to the cycle.
constexpr sgm::tb::AxilDelays kNoBusDelays{0, 0, 0, 0};

// The bits of the byte lanes a write's strobes enable.
uint32_t strobedBits(uint32_t strobes) {
  uint32_t bits = 0;
  for (int lane = 0; lane < 4; ++lane)
    if (strobes >> lane & 1) bits |= 0xFFu << (8 * lane);
  return bits;
}

// ---------------------------------------------------------------- the map
TEST(SgmAxi, RtlOffsetsAndResetValuesMatchTheHeader) {
  const std::map<std::string, std::pair<uint32_t, uint32_t>> pairs = {
      {"ID", {Rtl::ADDR_ID, SGM_REG_ID}},
      {"D", {Rtl::ADDR_D, SGM_REG_D}},
      {"MAX_WIDTH", {Rtl::ADDR_MAX_WIDTH, SGM_REG_MAX_WIDTH}},
      {"MAX_HEIGHT", {Rtl::ADDR_MAX_HEIGHT, SGM_REG_MAX_HEIGHT}},
      {"CENSUS", {Rtl::ADDR_CENSUS, SGM_REG_CENSUS}},
      {"MIN_WIDTH", {Rtl::ADDR_MIN_WIDTH, SGM_REG_MIN_WIDTH}},
      {"LANES", {Rtl::ADDR_LANES, SGM_REG_LANES}},
      {"FEATURES", {Rtl::ADDR_FEATURES, SGM_REG_FEATURES}},
      {"CTRL", {Rtl::ADDR_CTRL, SGM_REG_CTRL}},
      {"FRAME_SIZE", {Rtl::ADDR_FRAME_SIZE, SGM_REG_FRAME_SIZE}},
      {"PENALTY", {Rtl::ADDR_PENALTY, SGM_REG_PENALTY}},
      {"CONFIG", {Rtl::ADDR_CONFIG, SGM_REG_CONFIG}},
      {"STATUS", {Rtl::ADDR_STATUS, SGM_REG_STATUS}},
      {"FRAMES", {Rtl::ADDR_FRAMES, SGM_REG_FRAMES}},
      {"ERROR", {Rtl::ADDR_ERROR, SGM_REG_ERROR}},
      {"ERROR_COUNT", {Rtl::ADDR_ERROR_COUNT, SGM_REG_ERROR_COUNT}},
      {"LAST_SIZE", {Rtl::ADDR_LAST_SIZE, SGM_REG_LAST_SIZE}},
      {"EDGE_RESET", {Rtl::ADDR_EDGE_RESET, SGM_REG_EDGE_RESET}},
      {"IRQ_ENABLE", {Rtl::ADDR_IRQ_ENABLE, SGM_REG_IRQ_ENABLE}},
      {"IRQ_STATUS", {Rtl::ADDR_IRQ_STATUS, SGM_REG_IRQ_STATUS}},
      {"OUTPUT", {Rtl::ADDR_OUTPUT, SGM_REG_OUTPUT}},
      {"DEPTH_FOCAL", {Rtl::ADDR_DEPTH_FOCAL, SGM_REG_DEPTH_FOCAL}},
      {"DEPTH_BASELINE", {Rtl::ADDR_DEPTH_BASELINE, SGM_REG_DEPTH_BASELINE}},
      {"MIN_DISPARITY", {Rtl::ADDR_MIN_DISPARITY, SGM_REG_MIN_DISPARITY}},
      {"RECTIFY", {Rtl::ADDR_RECTIFY, SGM_REG_RECTIFY}},
      {"MESH_ADDR", {Rtl::ADDR_MESH_ADDR, SGM_REG_MESH_ADDR}},
      {"MESH_U", {Rtl::ADDR_MESH_U, SGM_REG_MESH_U}},
      {"MESH_V", {Rtl::ADDR_MESH_V, SGM_REG_MESH_V}},
      {"MESH_CTRL", {Rtl::ADDR_MESH_CTRL, SGM_REG_MESH_CTRL}},
      {"ID_VALUE", {Rtl::ID_VALUE, SGM_ID_VALUE}},
      {"FEATURES_UNIQUENESS", {1u << Rtl::FEATURES_UNIQUENESS_LSB, SGM_FEATURES_UNIQUENESS}},
      {"FEATURES_AD_TERM", {1u << Rtl::FEATURES_AD_TERM_LSB, SGM_FEATURES_AD_TERM}},
      {"FEATURES_RIGHT_PATH", {1u << Rtl::FEATURES_RIGHT_PATH_LSB, SGM_FEATURES_RIGHT_PATH}},
      {"FEATURES_RIGHT_BLOCK", {uint32_t(Rtl::FEATURES_RIGHT_BLOCK_LSB), SGM_FEATURES_RIGHT_BLOCK_SHIFT}},
      {"FEATURES_EDGE_RESET", {1u << Rtl::FEATURES_EDGE_RESET_LSB, SGM_FEATURES_EDGE_RESET}},
      {"FEATURES_DEPTH", {1u << Rtl::FEATURES_DEPTH_LSB, SGM_FEATURES_DEPTH}},
      {"FEATURES_MIN_DISPARITY", {1u << Rtl::FEATURES_MIN_DISPARITY_LSB, SGM_FEATURES_MIN_DISPARITY}},
      {"FEATURES_RECTIFY", {1u << Rtl::FEATURES_RECTIFY_LSB, SGM_FEATURES_RECTIFY}},
      {"FEATURES_CONFIDENCE", {1u << Rtl::FEATURES_CONFIDENCE_LSB, SGM_FEATURES_CONFIDENCE}},
      {"FEATURES_RECTIFY_ROWS", {uint32_t(Rtl::FEATURES_RECTIFY_ROWS_LSB), SGM_FEATURES_RECTIFY_ROWS_SHIFT}},
      {"FEATURES_RECTIFY_GRID", {uint32_t(Rtl::FEATURES_RECTIFY_GRID_LSB), SGM_FEATURES_RECTIFY_GRID_SHIFT}},
      {"EDGE_RESET_RESET", {Rtl::EDGE_RESET_RESET, kEdgeResetReset}},
      {"FEATURES_VALUE", {Rtl::FEATURES_VALUE, kFeatures}},
      {"PENALTY_RESET", {Rtl::PENALTY_RESET, kPenaltyReset}},
      {"CONFIG_RESET", {Rtl::CONFIG_RESET, kConfigReset}},
  };
  for (const auto& [name, values] : pairs) EXPECT_EQ(values.first, values.second) << name << ": RTL vs sgm_regs.h";
  // The reset configuration is the golden model's defaults for the build, both forms
  // (the header's two pairs) the golden model's "default" and "four-path" presets.
  const drv::FrameConfig golden = frameConfig(defaults(), {0, 0});
  EXPECT_EQ(drv::Driver::encodePenalty(golden), kPenaltyReset);
  EXPECT_EQ(drv::Driver::encodeConfig(golden), kConfigReset);
  EXPECT_EQ(drv::Driver::encodeEdgeReset(golden), kEdgeResetReset);
  EXPECT_EQ(drv::Driver::encodeEdgeReset(drv::FrameConfig{}), uint32_t(SGM_EDGE_RESET_RESET));
  EXPECT_EQ(drv::Driver::encodeEdgeReset(drv::FrameConfig::fourPath()), uint32_t(SGM_EDGE_RESET_RESET_FOUR_PATH));
  const drv::FrameConfig ours = frameConfig(sgm::presetParams("default"), {0, 0});
  const drv::FrameConfig four = frameConfig(sgm::presetParams("four-path"), {0, 0});
  EXPECT_EQ(drv::Driver::encodePenalty(ours), uint32_t(SGM_PENALTY_RESET));
  EXPECT_EQ(drv::Driver::encodeConfig(ours), uint32_t(SGM_CONFIG_RESET));
  EXPECT_EQ(drv::Driver::encodePenalty(four), uint32_t(SGM_PENALTY_RESET_FOUR_PATH));
  EXPECT_EQ(drv::Driver::encodeConfig(four), uint32_t(SGM_CONFIG_RESET_FOUR_PATH));
  EXPECT_EQ(drv::Driver::encodeEdgeReset(ours), uint32_t(SGM_EDGE_RESET_RESET));
  EXPECT_EQ(drv::Driver::encodeEdgeReset(four), uint32_t(SGM_EDGE_RESET_RESET_FOUR_PATH));
  // The driver's FrameConfig{} is the golden model's defaults too.
  EXPECT_EQ(drv::Driver::encodePenalty(drv::FrameConfig{}), uint32_t(SGM_PENALTY_RESET));
  EXPECT_EQ(drv::Driver::encodeConfig(drv::FrameConfig{}), uint32_t(SGM_CONFIG_RESET));
  EXPECT_EQ(drv::Driver::encodePenalty(drv::FrameConfig::fourPath()), uint32_t(SGM_PENALTY_RESET_FOUR_PATH));
  EXPECT_EQ(drv::Driver::encodeConfig(drv::FrameConfig::fourPath()), uint32_t(SGM_CONFIG_RESET_FOUR_PATH));
}

// Offset, reset value and the bits that read back (0: read-only).
struct RegisterSpec {
  const char* name;
  uint32_t offset, reset, writable;
};

// The build's census window (sgm_axi's CENSUS_H, passed to sgm_top).
constexpr sgm::CensusShape kCensus = sgm::censusShape(Rtl::CENSUS_H == 9 ? sgm::CensusWindow::k9x9
                                                                         : sgm::CensusWindow::k9x5);

// MIN_WIDTH of a one-lane build is the MIN_WIDTH parameter where it is set, else
// max(D, 16) (sgm_top MIN_FRAME_WIDTH; the fixture's builds have one lane).
// SizeFitsAgreesWithTheCore checks the value by behaviour: a frame one column
// narrower is dropped.
static_assert(Rtl::LANES == 1, "kOneLaneMinWidth holds for one-lane builds");
constexpr uint32_t kOneLaneMinWidth = Rtl::MIN_WIDTH != 0 ? uint32_t(Rtl::MIN_WIDTH)
                                      : Rtl::D > 16       ? uint32_t(Rtl::D)
                                                          : 16u;
// A small frame's width, widened to the build's narrowest where that is wider.
constexpr int smallWidth(int w) { return std::max(w, int(kOneLaneMinWidth)); }

std::vector<RegisterSpec> registers() {
  return {
      {"ID", SGM_REG_ID, SGM_ID_VALUE, 0},
      {"D", SGM_REG_D, uint32_t(Rtl::D), 0},
      {"MAX_WIDTH", SGM_REG_MAX_WIDTH, uint32_t(Rtl::MAX_WIDTH), 0},
      {"MAX_HEIGHT", SGM_REG_MAX_HEIGHT, uint32_t(Rtl::MAX_HEIGHT), 0},
      {"CENSUS", SGM_REG_CENSUS,
       uint32_t(kCensus.width) << SGM_CENSUS_WIDTH_SHIFT | uint32_t(kCensus.height) << SGM_CENSUS_HEIGHT_SHIFT, 0},
      {"MIN_WIDTH", SGM_REG_MIN_WIDTH, kOneLaneMinWidth, 0},
      {"LANES", SGM_REG_LANES, uint32_t(Rtl::LANES), 0},
      {"FEATURES", SGM_REG_FEATURES, kFeatures, 0},
      {"CTRL", SGM_REG_CTRL, 0, SGM_CTRL_MASK},
      {"FRAME_SIZE", SGM_REG_FRAME_SIZE, 0, SGM_FRAME_SIZE_MASK},
      {"PENALTY", SGM_REG_PENALTY, kPenaltyReset, SGM_PENALTY_MASK},
      {"CONFIG", SGM_REG_CONFIG, kConfigReset, SGM_CONFIG_MASK},
      {"STATUS", SGM_REG_STATUS, 0, 0},
      {"FRAMES", SGM_REG_FRAMES, 0, 0},
      {"ERROR", SGM_REG_ERROR, 0, 0},              // W1C: its own test
      {"ERROR_COUNT", SGM_REG_ERROR_COUNT, 0, 0},  // cleared by writes: its own test
      {"LAST_SIZE", SGM_REG_LAST_SIZE, 0, 0},
      {"EDGE_RESET", SGM_REG_EDGE_RESET, kEdgeResetReset, SGM_EDGE_RESET_MASK},
      {"IRQ_ENABLE", SGM_REG_IRQ_ENABLE, 0, SGM_IRQ_ENABLE_MASK},
      {"IRQ_STATUS", SGM_REG_IRQ_STATUS, 0, 0},  // W1C: its own test
      {"OUTPUT", SGM_REG_OUTPUT, 0, SGM_OUTPUT_MASK},
      {"DEPTH_FOCAL", SGM_REG_DEPTH_FOCAL, 0, SGM_DEPTH_FOCAL_MASK},
      {"DEPTH_BASELINE", SGM_REG_DEPTH_BASELINE, 0, SGM_DEPTH_BASELINE_MASK},
      {"MIN_DISPARITY", SGM_REG_MIN_DISPARITY, 0, SGM_MIN_DISPARITY_MASK},
      {"RECTIFY", SGM_REG_RECTIFY, 0, SGM_RECTIFY_MASK},
      {"MESH_ADDR", SGM_REG_MESH_ADDR, 0, SGM_MESH_ADDR_MASK},
      {"MESH_U", SGM_REG_MESH_U, 0, SGM_MESH_U_MASK},
      {"MESH_V", SGM_REG_MESH_V, 0, 0},  // a write stores a node and steps MESH_ADDR: its own test
      {"MESH_CTRL", SGM_REG_MESH_CTRL, 0, 0},
  };
}

TEST(SgmAxi, ResetValuesAndIdentification) {
  AxiCore c("sgm_axi_reset");
  for (const RegisterSpec& r : registers()) EXPECT_EQ(c.bus.read(r.offset).data, r.reset) << r.name;
  drv::Identity id;
  EXPECT_TRUE(c.driver.identify(&id));
  EXPECT_EQ(id.disparities, uint32_t(kD));
  EXPECT_EQ(id.censusWidth * id.censusHeight, uint32_t(kCensus.bits + 1));
  EXPECT_EQ(id.features, kFeatures);
  EXPECT_EQ(id.features & ~uint32_t(SGM_FEATURES_MASK), 0u) << "reserved FEATURES bits";
  EXPECT_EQ(c.model().irq_o, 0);
}

// The identification's frame limits (MIN_WIDTH, MAX_WIDTH, MAX_HEIGHT, the
// shortest frame) through the driver's sizeFits agree with what the core takes:
// a frame just outside is dropped with ERROR.CONFIG, as is one beyond the build's
// counters, one on the border streams.
TEST(SgmAxi, SizeFitsAgreesWithTheCore) {
  AxiCore c("sgm_axi_sizefits", 3, {0, 0});
  drv::Identity id;
  ASSERT_TRUE(c.driver.identify(&id));
  EXPECT_EQ(id.lanes, uint32_t(Rtl::LANES));
  ASSERT_GE(id.minWidth, 16u);
  const uint32_t w = id.minWidth, h = SGM_FRAME_SIZE_HEIGHT_MIN;
  EXPECT_TRUE(drv::Driver::sizeFits(id, w, h));
  EXPECT_TRUE(drv::Driver::sizeFits(id, id.maxWidth, id.maxHeight));
  EXPECT_FALSE(drv::Driver::sizeFits(id, id.maxWidth + 1, h));
  EXPECT_FALSE(drv::Driver::sizeFits(id, w, id.maxHeight + 1));
  // Beside the sizes just outside the limits, a size beyond the build's counters that
  // would alias to a legal one cut to them (the word carries the registers' 16 bits and
  // the core checks them whole).
  const auto bitsFor = [](uint32_t v) {
    int b = 0;
    while ((uint64_t(1) << b) <= v) ++b;
    return b;
  };
  const int aliasWidth = (1 << bitsFor(id.maxWidth)) + int(w);
  const int aliasHeight = (1 << bitsFor(id.maxHeight + 15)) + int(h);
  const cv::Size bads[] = {{int(w) - 1, int(h)},           {int(w), int(h) - 1},
                           {int(id.maxWidth) + 1, int(h)}, {int(w), int(id.maxHeight) + 1},
                           {aliasWidth, int(h)},           {int(w), aliasHeight}};
  for (const cv::Size bad : bads) {
    EXPECT_FALSE(drv::Driver::sizeFits(id, uint32_t(bad.width), uint32_t(bad.height))) << bad;
    c.driver.configure(frameConfig(defaults(), bad));
    c.driver.enable(c.enabled = true);
    const uint32_t before = c.driver.errors().counts[3];
    const FrameInput f = scene(bad.width, bad.height, 21, defaults());
    c.extra.push(sgm::tb::frameBeats(f.left.data, f.right.data, bad.width, bad.height, f.left.step, f.right.step));
    while (!c.extra.empty()) c.steps(1);
    c.steps(20);
    EXPECT_EQ(c.driver.errors().counts[3], before + 1) << "a " << bad << " frame is dropped";
  }
  c.driver.clearErrors();
  c.expectBitExact({scene(int(w), int(h), 22, defaults())}, "the narrowest, shortest frame");
  EXPECT_EQ(c.driver.errors().sticky, 0u);
}

// FEATURES through the driver against what the core does: a frame that sets a lever
// FEATURES lacks (CONFIG.UNIQUENESS, PENALTY.AD_WEIGHT) is dropped with ERROR.CONFIG
// (Driver::featuresFit says so beforehand), one it has streams bit-exact; a frame
// without the levers streams in every build.
TEST(SgmAxi, FeaturesAgreeWithTheCore) {
  AxiCore c("sgm_axi_features", 5, {0, 0});
  drv::Identity id;
  ASSERT_TRUE(c.driver.identify(&id));
  ASSERT_EQ(id.features, kFeatures);
  sgm::Params unique = defaults();
  unique.uniqueness = 30;
  sgm::Params ad = defaults();
  ad.adWeight = 5, ad.adCap = 24;
  sgm::Params right = defaults();  // the fifth path in the build's blocks (any block when it has none)
  right.rightPathWeight = 4, right.rightPathBlock = Rtl::RIGHT_BLOCK ? Rtl::RIGHT_BLOCK : 16, right.p1 = 24,
  right.p2 = 200;
  sgm::Params restart = withBuildLevers(defaults());  // the path restart at strong edges
  restart.edgeReset = sgm::EdgeReset{30, 6, {1, 1, 0, 1, 1}};
  sgm::Params depth = withBuildLevers(defaults());  // the depth output
  depth.output = sgm::OutputMode::kDepth, depth.focalQ8 = 600 * 256, depth.baselineUm = 75000;
  sgm::Params dmin = withBuildLevers(defaults());  // the minimum disparity
  dmin.minDisparity = 5;
  sgm::Params confidence = withBuildLevers(defaults());  // the confidence in the word
  confidence.outputConfidence = true;
  EXPECT_EQ(drv::Driver::rightBlock(id), uint32_t(Rtl::RIGHT_BLOCK));
  const int w = smallWidth(40), h = 11;
  uint32_t seed = 30;
  for (const sgm::Params& p : {unique, ad, right, restart, depth, dmin, confidence}) {
    const drv::FrameConfig config = frameConfig(p, {w, h});
    const bool fits = drv::Driver::featuresFit(id, config);
    const bool asksDepth = p.output == sgm::OutputMode::kDepth;
    const uint32_t lever = p.outputConfidence      ? SGM_FEATURES_CONFIDENCE
                           : p.minDisparity        ? SGM_FEATURES_MIN_DISPARITY
                           : asksDepth             ? SGM_FEATURES_DEPTH
                           : p.edgeReset.threshold ? SGM_FEATURES_EDGE_RESET
                           : p.uniqueness          ? SGM_FEATURES_UNIQUENESS
                           : p.adWeight            ? SGM_FEATURES_AD_TERM
                                                   : SGM_FEATURES_RIGHT_PATH;
    EXPECT_EQ(fits, (kFeatures & lever) != 0);
    const std::string what = p.outputConfidence      ? "confidence in the word"
                             : p.minDisparity        ? "minimum disparity 5"
                             : asksDepth             ? "depth output"
                             : p.edgeReset.threshold ? "path restart T 30"
                             : p.uniqueness          ? "uniqueness 30"
                             : p.adWeight            ? "AD weight 5"
                                                     : "fifth path weight 4";
    if (fits) {
      c.expectBitExact({scene(w, h, ++seed, p)}, what + " in a build that has it");
      EXPECT_EQ(c.driver.errors().sticky, 0u) << what;
      continue;
    }
    c.driver.configure(config);
    c.driver.enable(c.enabled = true);
    const uint32_t before = c.driver.errors().counts[3];
    const FrameInput f = scene(w, h, ++seed, p);
    c.extra.push(sgm::tb::frameBeats(f.left.data, f.right.data, w, h, f.left.step, f.right.step));
    while (!c.extra.empty()) c.steps(1);
    c.steps(20);
    EXPECT_EQ(c.driver.errors().counts[3], before + 1) << what << " in a build without it is dropped";
    EXPECT_NE(c.driver.errors().sticky & SGM_ERROR_CONFIG, 0u) << what;
    c.driver.clearErrors();
  }
  EXPECT_TRUE(drv::Driver::featuresFit(id, frameConfig(defaults(), {w, h})));
  c.expectBitExact({scene(w + 2, h, 40, defaults())}, "a frame without the levers");
  EXPECT_EQ(c.driver.errors().sticky, 0u);
}

// Read-back of every writable bit, reserved bits reading 0, byte strobes,
// read-only registers ignoring writes (with OKAY).
TEST(SgmAxi, ReadBackReservedBitsAndWriteStrobes) {
  AxiCore c("sgm_axi_readback", 2, {0, 0}, {5, 0.5});
  std::mt19937 rng(9);
  for (const RegisterSpec& r : registers()) {
    const bool w1c = r.offset == SGM_REG_ERROR || r.offset == SGM_REG_IRQ_STATUS || r.offset == SGM_REG_ERROR_COUNT;
    // MESH_V stores a node, MESH_CTRL swaps: MeshRegistersAndRectifiedFrames.
    if (w1c || r.offset == SGM_REG_MESH_V || r.offset == SGM_REG_MESH_CTRL) continue;
    const uint32_t before = c.bus.read(r.offset).data;
    std::vector<uint32_t> patterns = {0xFFFFFFFFu, 0u, 0xA5A5A5A5u, 0x5A5A5A5Au};
    for (int i = 0; i < 6; ++i) patterns.push_back(uint32_t(rng()));
    for (const uint32_t v : patterns) {
      EXPECT_EQ(c.bus.write(r.offset, v).resp, sgm::tb::kAxilOkay) << r.name;
      const uint32_t expected = r.writable ? v & r.writable : before;
      EXPECT_EQ(c.bus.read(r.offset).data, expected) << r.name << " after writing 0x" << std::hex << v;
    }
    if (!r.writable) continue;
    // Byte strobes: only the enabled lanes change.
    for (unsigned strb = 0; strb < 16; ++strb) {
      c.bus.write(r.offset, 0);
      c.bus.write(r.offset, 0xFFFFFFFFu, strb);
      EXPECT_EQ(c.bus.read(r.offset).data, strobedBits(strb) & r.writable)
          << r.name << ", strobes 0x" << std::hex << strb;
    }
    c.bus.write(r.offset, r.reset);
  }
}

// Random register traffic with the bus model's random byte strobes: writes of random data
// under random strobes and reads, to random RW registers in random order, every read
// checked against a model that keeps the bytes a write leaves unstrobed. The bus model
// presents each request while the previous response of its kind may still wait, so a
// slave that takes a second write (read) before the first response is accepted fails the
// protocol checker.
TEST(SgmAxi, StrobedWritesKeepTheUnstrobedBytes) {
  AxiCore c("sgm_axi_strobes", 11, {0, 0});
  std::vector<RegisterSpec> writable;
  std::map<uint32_t, uint32_t> expected;  // offset -> what the register must read
  for (const RegisterSpec& r : registers())
    if (r.writable) writable.push_back(r), expected[r.offset] = r.reset;
  std::mt19937 rng(17);
  int partial = 0;
  std::string lastWrite = "none";
  for (int i = 0; i < 1500; ++i) {
    const RegisterSpec& r = writable[rng() % writable.size()];
    if (rng() % 2) {
      const uint32_t data = rng(), strobes = c.bus.randomStrobes();
      ASSERT_EQ(c.bus.write(r.offset, data, strobes).resp, sgm::tb::kAxilOkay) << r.name;
      const uint32_t lanes = strobedBits(strobes);
      expected[r.offset] = ((expected[r.offset] & ~lanes) | (data & lanes)) & r.writable;
      partial += strobes != 0 && strobes != 0xF;
      char text[80];
      std::snprintf(text, sizeof text, "0x%08X with strobes 0x%X to %s", data, strobes, r.name);
      lastWrite = text;
    } else {
      ASSERT_EQ(c.bus.read(r.offset).data, expected[r.offset])
          << r.name << " (transfer " << i << ", last write " << lastWrite << ")";
    }
  }
  for (const RegisterSpec& r : writable) EXPECT_EQ(c.bus.read(r.offset).data, expected[r.offset]) << r.name;
  EXPECT_GT(partial, 400) << "writes with some but not all byte lanes";
  EXPECT_GT(c.bus.writeCyclesBehindResponse(), 100u) << "writes presented while a write response waited";
  EXPECT_GT(c.bus.readCyclesBehindResponse(), 100u) << "reads presented while a read response waited";
}

// CTRL.SOFT_RESET (write 1 for a pulse) fires only when its byte lane is strobed: a
// write of all ones under each of the 16 strobe combinations, STATUS.RESETTING read
// right after it (the bus has no delays: the read is taken two cycles after the write,
// within the reset's cycles).
TEST(SgmAxi, SoftResetFiresOnlyFromItsStrobedByte) {
  AxiCore c("sgm_axi_soft_reset_strobes", 13, {0, 0}, kNoBusDelays);
  static_assert(SGM_CTRL_SOFT_RESET < 0x100u, "SOFT_RESET sits in byte lane 0");
  for (uint32_t strobes = 0; strobes < 16; ++strobes) {
    c.bus.write(SGM_REG_CTRL, 0xFFFFFFFFu, strobes);
    const bool resetting = c.bus.read(SGM_REG_STATUS).data & SGM_STATUS_RESETTING;
    EXPECT_EQ(resetting, (strobes & 1) != 0) << "CTRL written with all ones, strobes 0x" << std::hex << strobes;
    c.steps(10);  // past the reset
    EXPECT_EQ(c.bus.read(SGM_REG_STATUS).data & SGM_STATUS_RESETTING, 0u);
  }
}

TEST(SgmAxi, UndefinedAddressesAnswerSlverrAndChangeNothing) {
  AxiCore c("sgm_axi_badaddr", 3);
  std::vector<uint32_t> before;
  for (const RegisterSpec& r : registers()) before.push_back(c.bus.read(r.offset).data);
  int undefined = 0;
  for (uint32_t a = 0; a < 0x100; a += 4) {
    bool defined = false;
    for (const RegisterSpec& r : registers()) defined |= r.offset == a;
    if (defined) continue;
    ++undefined;
    const sgm::tb::AxilResponse read = c.bus.read(a);
    EXPECT_EQ(read.resp, sgm::tb::kAxilSlvErr) << "read 0x" << std::hex << a;
    EXPECT_EQ(read.data, 0u) << "read 0x" << std::hex << a;
    EXPECT_EQ(c.bus.write(a, 0xFFFFFFFFu).resp, sgm::tb::kAxilSlvErr) << "write 0x" << std::hex << a;
  }
  EXPECT_EQ(undefined, 64 - int(registers().size()));  // every register of regmap/sgm_regmap.def
  for (size_t k = 0; k < registers().size(); ++k)
    EXPECT_EQ(c.bus.read(registers()[k].offset).data, before[k]) << registers()[k].name;
  // Address bits [1:0] are ignored.
  for (uint32_t low = 1; low < 4; ++low) EXPECT_EQ(c.bus.read(SGM_REG_ID + low).data, SGM_ID_VALUE);
}

// ---------------------------------------------------------------- frames
// Four parameter sets back to back; each frame's configuration is written
// while the previous frame streams, and every frame is bit-exact with its own
// parameters: a write takes effect from the next start of frame only.
// The mesh registers: MESH_V stores the node and steps MESH_ADDR.COL (not ROW, not RIGHT),
// a write of MESH_ADDR sets it, MESH_V and MESH_U read back; in a build with the rectification
// (RECTIFY = 1) raw pairs through calibrations the driver loads (loadMeshes) while earlier
// frames stream are bit-exact, MESH_CTRL.PENDING drops once the core runs on the last one and
// ROW_MISS stays 0; in a build without it, a frame that asks for it is dropped (ERROR.CONFIG).
TEST(SgmAxi, MeshRegistersAndRectifiedFrames) {
  AxiCore c("sgm_axi_mesh");
  const uint32_t addr = SGM_PUT(MESH_ADDR_COL, 4094u) | SGM_PUT(MESH_ADDR_ROW, 7u) | SGM_PUT(MESH_ADDR_RIGHT, 1u);
  c.driver.enable(true);
  c.bus.write(SGM_REG_MESH_ADDR, addr);
  c.bus.write(SGM_REG_MESH_U, 0xFFFFFFFFu);
  for (int k = 0; k < 3; ++k) c.bus.write(SGM_REG_MESH_V, 0x12345u + uint32_t(k));
  EXPECT_EQ(c.bus.read(SGM_REG_MESH_U).data, uint32_t(SGM_MESH_U_MASK));
  EXPECT_EQ(c.bus.read(SGM_REG_MESH_V).data, (0x12345u + 2) & uint32_t(SGM_MESH_V_MASK));
  EXPECT_EQ(c.bus.read(SGM_REG_MESH_ADDR).data,
            SGM_PUT(MESH_ADDR_COL, 1u) | SGM_PUT(MESH_ADDR_ROW, 7u) | SGM_PUT(MESH_ADDR_RIGHT, 1u))
      << "three stores from column 4094: the column wraps at 12 bits, row and image stay";
  std::mt19937 rng(51);
  const sgm::Params base = withBuildLevers(defaults());
  if (!Rtl::RECTIFY) {
    sgm::Params p = base;
    p.rectify = true;
    FrameInput f = scene(40, 11, 61, p);
    f.dropped = true;
    c.core.run({f, scene(40, 11, 62, base)});
    EXPECT_TRUE(c.driver.errors().sticky & SGM_ERROR_CONFIG) << "a rectified frame in a build without it";
    return;
  }
  std::vector<FrameInput> frames;
  for (int k = 0; k < 4; ++k) {
    const int w = k == 2 ? 48 : 40, h = k == 2 ? 13 : 11;
    sgm::Params p = base;
    p.rectify = true;
    FrameInput f = scene(w, h, 70 + uint32_t(k), p);
    if (k != 1) {  // frame 1 keeps frame 0's calibration
      int lag = 0;
      f.mesh = sgm::tb::fittingCalibration(w, h, Rtl::RECTIFY_GRID_LOG2, Rtl::RECTIFY_ROWS, 1.0, 0.95, rng, &lag);
      f.params.rectifyLag = lag;
    } else {
      f.params.rectifyLag = frames[0].params.rectifyLag;
    }
    frames.push_back(f);
  }
  c.expectBitExact(frames, "rectified through the driver's meshes");
  c.steps(50);
  EXPECT_FALSE(c.driver.meshSwapPending());
  EXPECT_FALSE(c.driver.rectifyRowMiss());
  EXPECT_EQ(c.driver.errors().sticky, 0u);
}

TEST(SgmAxi, ConfigurationWrittenMidFrameActsFromTheNextFrame) {
  AxiCore c("sgm_axi_midframe", 4, {0.15, 0.15});
  sgm::Params unified = defaults();
  unified.mode = sgm::CostMode::kUnified, unified.p1 = 40, unified.p2 = 200, unified.median = false;
  sgm::Params rt = defaults();
  rt.mode = sgm::CostMode::kRt, rt.lrTolerance = -1, rt.fill = false, rt.subpixel = false;
  sgm::Params strict = defaults();
  strict.lrTolerance = 0, strict.p1 = 5, strict.p2 = 30, strict.snap = false, strict.uniqueness = 99;
  sgm::Params unique = defaults();
  unique.uniqueness = 20;
  const std::vector<FrameInput> frames = {scene(40, 14, 1, defaults()),
                                          scene(36, 12, 2, unified),
                                          scene(48, 11, 3, rt),
                                          scene(33, 15, 4, withBuildLevers(strict)),
                                          scene(38, 12, 6, withBuildLevers(unique)),
                                          scene(40, 10, 5, defaults().rawSgm())};
  c.expectBitExact(frames, "mid-frame configuration");
  ASSERT_EQ(c.busyWhenConfigured.size(), frames.size());
  for (size_t k = 1; k < frames.size(); ++k)
    EXPECT_TRUE(c.busyWhenConfigured[k]) << "frame " << k << "'s configuration was not written during frame " << k - 1;
  EXPECT_EQ(c.driver.framesDone(), frames.size());
  uint32_t w = 0, h = 0;
  c.driver.lastFrameSize(&w, &h);
  EXPECT_EQ(w, 40u);
  EXPECT_EQ(h, 10u);
  const drv::Errors e = c.driver.errors();
  EXPECT_EQ(e.sticky, 0u);
  EXPECT_EQ(c.driver.busy(), false);
}

// The largest frames the build takes, written through FRAME_SIZE: MAX_WIDTH wide,
// MAX_HEIGHT tall, and both at once; each bit-exact, LAST_SIZE reporting it.
TEST(SgmAxi, FramesOfTheLargestSizeThroughTheRegisters) {
  AxiCore c("sgm_axi_largest", 21, {0.05, 0.05});
  const int w = int(Rtl::MAX_WIDTH), h = int(Rtl::MAX_HEIGHT);
  const std::vector<FrameInput> frames = {scene(w, 12, 31, defaults()), scene(40, h, 32, defaults()),
                                          scene(w, h, 33, defaults())};
  c.expectBitExact(frames, "largest frames");
  EXPECT_EQ(c.driver.framesDone(), frames.size());
  uint32_t lw = 0, lh = 0;
  c.driver.lastFrameSize(&lw, &lh);
  EXPECT_EQ(lw, uint32_t(w));
  EXPECT_EQ(lh, uint32_t(h));
  EXPECT_EQ(c.driver.errors().sticky, 0u);
}

// CTRL.HOLD = 1 keeps the configuration released last: a frame started while
// it is set runs with the old one; clearing it releases the new one.
TEST(SgmAxi, HoldKeepsTheReleasedConfigurationUntilCleared) {
  AxiCore c("sgm_axi_hold", 8);
  const int w = smallWidth(38), h = 11;
  sgm::Params other = defaults();
  other.mode = sgm::CostMode::kRt, other.p1 = 10, other.p2 = 60, other.fill = false;
  c.driver.configure(frameConfig(defaults(), {w, h}));
  c.driver.enable(c.enabled = true);
  c.bus.write(SGM_REG_CTRL, SGM_CTRL_ENABLE | SGM_CTRL_HOLD);
  const drv::FrameConfig held = frameConfig(other, {w, h});
  c.bus.write(SGM_REG_PENALTY, drv::Driver::encodePenalty(held));
  c.bus.write(SGM_REG_CONFIG, drv::Driver::encodeConfig(held));
  c.core.setPresenter([](const sgm::Params&, cv::Size) {});  // the registers stay as written
  c.expectBitExact({scene(w, h, 40, defaults())}, "held: the released (default) configuration");
  c.bus.write(SGM_REG_CTRL, SGM_CTRL_ENABLE);
  c.expectBitExact({scene(w, h, 41, other)}, "released: the new configuration");
  EXPECT_EQ(c.driver.readConfig().p1, 10u);
}

// Sticky error kinds (write 1 to clear, strobes honoured), per-kind event
// counters (cleared per byte lane), the error interrupt.
TEST(SgmAxi, ErrorsAreStickyCountedAndClearedByWritingOne) {
  AxiCore c("sgm_axi_errors", 5, {0.1, 0.1});
  c.driver.enableInterrupts(SGM_IRQ_ENABLE_ERROR);
  std::mt19937 rng(2);
  const int w = smallWidth(36), h = 12;
  std::vector<FrameInput> frames = {scene(w, h, 10, defaults())};
  unsigned expected = 0;
  for (const sgm::tb::Malformation kind :
       {sgm::tb::Malformation::kEarlyLast, sgm::tb::Malformation::kMissingLast, sgm::tb::Malformation::kStartInside}) {
    const sgm::tb::MalformedFrames bad = malform(scene(w, h, 11, defaults()), kind, Rtl::MAX_WIDTH, rng(), rng());
    frames.insert(frames.end(), bad.frames.begin(), bad.frames.end());
    for (const unsigned e : bad.errors) expected |= e;
    frames.push_back(scene(w, h, 12, defaults()));
  }
  const std::vector<sgm::tb::FrameOutput> out = c.core.run(frames);
  EXPECT_EQ(sgm::tb::compareMaps(sgm::runPipeline(frames.back().left, frames.back().right, frames.back().params),
                                 out.back().map, "sgm_axi output"),
            "");
  drv::Errors e = c.driver.errors();
  EXPECT_EQ(e.sticky, expected);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(e.counts[k], 1u) << "kind " << k;
  EXPECT_EQ(e.counts[3], 0u);
  EXPECT_EQ(c.model().irq_o, 1);

  // A frame size out of range: the core drops the frame (error kind 3), twice.
  drv::FrameConfig bad = frameConfig(defaults(), {0, h});
  c.driver.configure(bad);
  for (int n = 0; n < 2; ++n) {
    const FrameInput f = scene(w, h, 13, defaults());
    c.extra.push(sgm::tb::frameBeats(f.left.data, f.right.data, w, h, f.left.step, f.right.step));
    while (!c.extra.empty()) c.steps(1);
    c.steps(20);
  }
  e = c.driver.errors();
  EXPECT_EQ(e.sticky, expected | SGM_ERROR_CONFIG);
  EXPECT_EQ(e.counts[3], 2u) << "an event is counted even while its sticky bit is set";

  // W1C: zeros, or ones without their byte strobe, clear nothing.
  c.bus.write(SGM_REG_ERROR, 0);
  c.bus.write(SGM_REG_ERROR, SGM_ERROR_MASK, 0x2);
  EXPECT_EQ(c.bus.read(SGM_REG_ERROR).data, expected | SGM_ERROR_CONFIG);
  c.bus.write(SGM_REG_ERROR, SGM_ERROR_CONFIG);
  EXPECT_EQ(c.bus.read(SGM_REG_ERROR).data, expected);
  // Counters: a write clears the counters of its byte lanes.
  c.bus.write(SGM_REG_ERROR_COUNT, 0, 0x8);
  EXPECT_EQ(c.bus.read(SGM_REG_ERROR_COUNT).data, 0x00010101u);
  EXPECT_EQ(c.model().irq_o, 1) << "the interrupt stays until IRQ_STATUS is cleared";
  c.driver.clearInterrupts(SGM_IRQ_STATUS_ERROR);
  EXPECT_EQ(c.model().irq_o, 0);
  c.driver.clearErrors();
  e = c.driver.errors();
  EXPECT_EQ(e.sticky, 0u);
  EXPECT_EQ(c.bus.read(SGM_REG_ERROR_COUNT).data, 0u);
  // The core works after all that.
  c.driver.configure(frameConfig(defaults(), {w, h}));
  c.expectBitExact({scene(w, h, 14, defaults())}, "after errors");
  EXPECT_EQ(c.driver.errors().sticky, 0u);
}

TEST(SgmAxi, FrameDoneInterruptRaisedMaskedAndCleared) {
  AxiCore c("sgm_axi_irq", 6);
  c.expectBitExact({scene(34, 10, 20, defaults())}, "first frame");
  EXPECT_EQ(c.driver.interrupts(), uint32_t(SGM_IRQ_STATUS_FRAME_DONE)) << "status is set whatever the enable";
  EXPECT_EQ(c.model().irq_o, 0) << "masked";
  c.driver.enableInterrupts(SGM_IRQ_ENABLE_FRAME_DONE);
  EXPECT_EQ(c.model().irq_o, 1);
  c.bus.write(SGM_REG_IRQ_STATUS, SGM_IRQ_STATUS_FRAME_DONE, 0x0);  // no strobe: nothing cleared
  EXPECT_EQ(c.model().irq_o, 1);
  c.driver.clearInterrupts(SGM_IRQ_STATUS_FRAME_DONE);
  EXPECT_EQ(c.model().irq_o, 0);
  EXPECT_EQ(c.driver.interrupts(), 0u);
  c.expectBitExact({scene(40, 12, 21, defaults())}, "second frame");
  EXPECT_EQ(c.model().irq_o, 1);
  EXPECT_EQ(c.driver.interrupts(), uint32_t(SGM_IRQ_STATUS_FRAME_DONE));
  c.driver.enableInterrupts(0);
  EXPECT_EQ(c.model().irq_o, 0);
  EXPECT_EQ(c.driver.framesDone(), 2u);
}

// ---------------------------------------------------------------- clears against events
// One frame streamed by hand into a core whose bus has no delays: a good frame (its end
// raises IRQ_STATUS.FRAME_DONE) or one of a size out of range (dropped: ERROR.CONFIG, its
// counter, IRQ_STATUS.ERROR). A run without a clearing write finds the event's cycle (the
// cycle whose clock edge raises irq_o); the runs are deterministic (same seeds, same bus
// traffic before the event), so another run times a clearing write to be taken in a chosen
// cycle. The registers are read once the frame has passed.
enum class Event { kFrameDone, kConfigError };

struct EventRun {
  uint64_t eventCycle = 0;  // found by a run without a clearing write
  uint64_t clearTaken = 0;  // the cycle in which the clearing write was taken
  uint32_t error = 0, errorCount = 0, irqStatus = 0;
};

struct TimedClear {
  uint32_t offset = 0, data = 0;
  uint64_t cycle = 0;  // 0: no clearing write
};

EventRun runEvent(Event event, TimedClear clear = {}) {
  AxiCore c("sgm_axi_clear_timing", 12, {0.1, 0.1}, kNoBusDelays);
  const int w = smallWidth(36), h = 12;
  const bool error = event == Event::kConfigError;
  c.driver.configure(frameConfig(defaults(), {error ? 0 : w, h}));
  c.driver.enableInterrupts(error ? SGM_IRQ_ENABLE_ERROR : SGM_IRQ_ENABLE_FRAME_DONE);
  c.driver.enable(c.enabled = true);
  const FrameInput f = scene(w, h, 50, defaults());
  c.extra.push(sgm::tb::frameBeats(f.left.data, f.right.data, w, h, f.left.step, f.right.step));
  EventRun run;
  const auto cycle = [&c] { return c.core.top().cycles(); };
  if (clear.cycle) {
    if (cycle() >= clear.cycle) throw sgm::Error("the clear is due before the setup's writes are done");
    while (cycle() < clear.cycle) c.steps(1);
    c.bus.write(clear.offset, clear.data);  // taken in its first cycle: the bus has no delays
    run.clearTaken = c.bus.lastWriteTaken();
  } else {
    for (long i = 0; !c.model().irq_o; ++i) {
      if (i > 100000) throw sgm::Error("no event in 100000 cycles");
      run.eventCycle = cycle();
      c.steps(1);
    }
  }
  const uint64_t settled = cycle() + 20;
  while (!c.extra.empty() || cycle() < settled) c.steps(1);
  run.error = c.bus.read(SGM_REG_ERROR).data;
  run.errorCount = c.bus.read(SGM_REG_ERROR_COUNT).data;
  run.irqStatus = c.bus.read(SGM_REG_IRQ_STATUS).data;
  return run;
}

// IRQ_STATUS and ERROR (write 1 to clear) and ERROR_COUNT (a write clears its byte lanes)
// against the events they record: a clear taken in the very cycle of the event keeps the
// event (its bit set, its count 1), as does one a cycle before it; one a cycle after
// clears it (which shows the write was timed to the cycle).
TEST(SgmAxi, AClearInTheCycleOfItsEventKeepsTheEvent) {
  struct Case {
    Event event;
    const char* what;
    uint32_t offset, data;
    uint32_t EventRun::*field;
    uint32_t bits;  // the field's bits of the event, as read after it
  };
  const Case cases[] = {
      {Event::kFrameDone, "IRQ_STATUS.FRAME_DONE", SGM_REG_IRQ_STATUS, SGM_IRQ_STATUS_FRAME_DONE, &EventRun::irqStatus,
       SGM_IRQ_STATUS_FRAME_DONE},
      {Event::kConfigError, "IRQ_STATUS.ERROR", SGM_REG_IRQ_STATUS, SGM_IRQ_STATUS_ERROR, &EventRun::irqStatus,
       SGM_IRQ_STATUS_ERROR},
      {Event::kConfigError, "ERROR.CONFIG", SGM_REG_ERROR, SGM_ERROR_CONFIG, &EventRun::error, SGM_ERROR_CONFIG},
      {Event::kConfigError, "ERROR_COUNT.CONFIG", SGM_REG_ERROR_COUNT, 0, &EventRun::errorCount,
       1u << SGM_ERROR_COUNT_CONFIG_SHIFT},
  };
  std::map<Event, EventRun> probes;
  for (const Case& k : cases) {
    if (!probes.count(k.event)) probes[k.event] = runEvent(k.event);
    const EventRun& probe = probes[k.event];
    const uint32_t mask = k.offset == SGM_REG_ERROR_COUNT ? uint32_t(SGM_ERROR_COUNT_CONFIG_MASK) : k.bits;
    ASSERT_GT(probe.eventCycle, 0u);
    EXPECT_EQ(probe.*k.field & mask, k.bits) << k.what << " without a clear";
    for (const int offset : {-1, 0, 1}) {
      const EventRun run = runEvent(k.event, {k.offset, k.data, probe.eventCycle + offset});
      EXPECT_EQ(run.clearTaken, probe.eventCycle + offset) << k.what << ": the clear's timing";
      const uint32_t expected = offset <= 0 ? k.bits : 0;
      EXPECT_EQ(run.*k.field & mask, expected) << k.what << " cleared "
                                               << (offset < 0    ? "a cycle before"
                                                   : offset == 0 ? "in the cycle of"
                                                                 : "a cycle after")
                                               << " its event (cycle " << probe.eventCycle << ")"
                                               << (offset == 0 ? ": the event in the cycle of its clear was lost" : "");
    }
  }
}

// CTRL.ENABLE = 0 holds the start-of-frame beat back; a soft reset in the
// middle of a frame leaves a core whose next frame is bit-exact.
TEST(SgmAxi, EnableHoldsTheStartOfFrameAndSoftResetRecovers) {
  AxiCore c("sgm_axi_enable", 7, {0, 0});
  const int w = smallWidth(36), h = 12;
  c.driver.configure(frameConfig(defaults(), {w, h}));
  const FrameInput f = scene(w, h, 30, defaults());
  c.extra.push(sgm::tb::frameBeats(f.left.data, f.right.data, w, h, f.left.step, f.right.step));
  c.steps(300);
  EXPECT_EQ(c.extra.accepted(), 0u) << "a start of frame passed a disabled core";
  EXPECT_FALSE(c.driver.busy());
  c.driver.enable(true);
  c.enabled = true;
  while (c.extra.accepted() < uint64_t(w * 6)) c.steps(1);  // half the frame in
  EXPECT_TRUE(c.driver.busy());
  EXPECT_TRUE(c.driver.softReset());
  c.extra.clear();
  EXPECT_FALSE(c.driver.busy());
  EXPECT_EQ(c.driver.framesDone(), 0u);
  c.steps(50);
  c.expectBitExact({scene(w + 4, h, 31, defaults())}, "after a soft reset in the middle of a frame");
  EXPECT_EQ(c.driver.framesDone(), 1u);
}

// The checker itself: quiet on a legal exchange, naming the cycle, the channel
// and the rule of each violation.
TEST(AxilChecker, NamesTheCycleChannelAndRuleOfEachViolation) {
  using sgm::tb::AxilChecker;
  using sgm::tb::AxilWires;
  AxilWires idle;
  AxilWires aw = idle;
  aw.awvalid = true, aw.awaddr = 0x20, aw.wvalid = true, aw.wdata = 1, aw.wstrb = 0xF;
  AxilWires taken = aw;
  taken.awready = taken.wready = true;
  AxilWires b = idle;
  b.bvalid = true, b.bready = true;
  {
    AxilChecker c;
    c.observe(0, aw), c.observe(1, taken), c.observe(2, b);
    EXPECT_EQ(c.finish(), "");
  }
  {
    AxilChecker c;
    c.observe(0, aw);
    AxilWires dropped = aw;
    dropped.awvalid = false;
    EXPECT_EQ(c.observe(1, dropped), "cycle 1, AW: VALID dropped before its handshake");
  }
  {
    AxilChecker c;
    c.observe(0, aw);
    AxilWires changed = aw;
    changed.wdata = 2;
    EXPECT_EQ(c.observe(1, changed), "cycle 1, W: payload changed while VALID was high and READY low");
  }
  {
    AxilChecker c;
    EXPECT_EQ(c.observe(5, b), "cycle 5, B: BVALID without an outstanding write");
  }
  {
    AxilChecker c;
    c.observe(0, taken);
    AxilWires sameCycle = idle;
    sameCycle.rvalid = true;
    EXPECT_EQ(c.observe(1, sameCycle), "cycle 1, R: RVALID without an outstanding read");
  }
  {
    AxilChecker c;
    c.observe(0, taken), c.observe(1, b), c.observe(2, b);
    EXPECT_EQ(c.violation(), "cycle 2, B: BVALID without an outstanding write");
  }
  {
    AxilChecker c;
    AxilWires ar = idle;
    ar.arvalid = ar.arready = true;
    c.observe(0, ar);
    EXPECT_EQ(c.finish(), "end: 0 write addresses, 0 write data, 0 write responses, 1 reads, 0 read responses");
  }
  {
    // A second write taken while the first one's response waits (BREADY low).
    AxilChecker c;
    AxilWires waiting = taken;
    waiting.bvalid = true;
    c.observe(0, taken);
    EXPECT_EQ(c.observe(1, waiting),
              "cycle 1, AW: write address taken while the write response before it still waits (too many writes in "
              "flight)");
    AxilChecker two(2);  // a slave that promises two writes in flight
    two.observe(0, taken);
    EXPECT_EQ(two.observe(1, waiting), "");
  }
  {
    // Accepted in the same cycle: the response still counts in that cycle.
    AxilChecker c;
    AxilWires sameCycle = taken;
    sameCycle.bvalid = sameCycle.bready = true;
    c.observe(0, taken);
    EXPECT_EQ(c.observe(1, sameCycle),
              "cycle 1, AW: write address taken while the write response before it still waits (too many writes in "
              "flight)");
  }
  {
    AxilChecker c;
    AxilWires ar = idle;
    ar.arvalid = ar.arready = true, ar.araddr = 4;
    AxilWires secondRead = ar;
    secondRead.rvalid = true;
    c.observe(0, ar);
    EXPECT_EQ(c.observe(1, secondRead),
              "cycle 1, AR: read address taken while the read response before it still waits (too many reads in "
              "flight)");
  }
}

}  // namespace
