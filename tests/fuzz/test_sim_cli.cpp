// SPDX-License-Identifier: Apache-2.0
// sgm-sim fed bad input: every case must end before the simulation with a
// non-zero exit, exactly one stderr line "sgm-sim: error: ..." naming the
// problem, and no output file. Runs the small build sgm-sim-d16-w128 from
// $SGM_BIN (make fuzz-ci builds it); skipped when it is absent.
#include "cli_fixture.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace {

using sgm::test::ChildResult;
using sgm::test::texture;

constexpr const char* kSim = "sgm-sim-d16-w128";  // D = 16, MAX_WIDTH = 128, MAX_HEIGHT = 1024 (sgm_top default)

class SgmSimCli : public sgm::test::ToolTest {
 protected:
  void SetUp() override {
    requireBinary(kSim, "build it with: make build/bin/sgm-sim-d16-w128 D=16 MAX_WIDTH=128 (or make fuzz-ci)");
    if (IsSkipped()) return;
    ToolTest::SetUp();
    pair("left.png", "right.png", 40, 20);
  }
  // A 8-bit gray stereo pair of w x h (disparity 2).
  void pair(const std::string& left, const std::string& right, int w, int h) {
    auto [l, r] = sgm::test::shiftedPair(w, h, 2, unsigned(w * 1000 + h));
    writeImage(left, l);
    writeImage(right, r);
  }
  // Runs the simulator on LEFT RIGHT (files in the input directory) plus options, writing into out/res.
  ChildResult sim(const std::string& left, const std::string& right, std::vector<std::string> options = {}) {
    std::vector<std::string> args = {"--left", in(left), "--right", in(right), "--out", out_ + "/res"};
    args.insert(args.end(), options.begin(), options.end());
    return run(kSim, args);
  }
  void expectSimError(const ChildResult& r, const std::string& needle) { expectOneLineError(r, "sgm-sim", needle); }
};

TEST_F(SgmSimCli, ValidPairIsSimulatedBitExact) {
  // The reference run: the same binary accepts a good pair, so the errors below come from the checks.
  const ChildResult r = sim("left.png", "right.png", {"--d", "16"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("bit-exact yes"), std::string::npos) << r.out;
  EXPECT_EQ(sgm::test::dirEntries(out_ + "/res"),
            (std::set<std::string>{"disparity16.png", "disparity8.png", "disparity_color.png", "report.json"}));
}

TEST_F(SgmSimCli, FrameSizesOutsideTheBuild) {
  pair("wide_l.png", "wide_r.png", 129, 20);
  expectSimError(sim("wide_l.png", "wide_r.png"), "width 129 exceeds this simulator's MAX_WIDTH=128");
  pair("narrow_l.png", "narrow_r.png", 15, 20);
  expectSimError(sim("narrow_l.png", "narrow_r.png"), "width 15 is below the core's minimum 16");
  pair("tall_l.png", "tall_r.png", 16, 1025);
  expectSimError(sim("tall_l.png", "tall_r.png"), "height 1025 exceeds MAX_HEIGHT=1024");
  pair("flat_l.png", "flat_r.png", 40, 8);
  expectSimError(sim("flat_l.png", "flat_r.png"), "smaller than the 9x9 minimum frame");
}

TEST_F(SgmSimCli, BadImageFiles) {
  expectSimError(sim("nope.png", "right.png"), "nope.png");
  writeRaw("empty.png", "");
  expectSimError(sim("left.png", "empty.png"), "empty.png': file is empty");
  writeRaw("text.png", "not an image\n");
  expectSimError(sim("text.png", "right.png"), "text.png': not a readable image");
  const std::string jpeg = sgm::test::encodeImage(".jpg", texture(40, 20, 3, CV_8UC3));
  writeRaw("cut.jpg", jpeg.substr(0, jpeg.size() * 3 / 4));
  expectSimError(sim("cut.jpg", "right.png"), "cut.jpg': truncated");
  writeRaw("huge.png", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".png", texture(40, 20, 3)), 16, 90000));
  expectSimError(sim("left.png", "huge.png"), "16x90000: too large");
  writeImage("d16.png", texture(40, 20, 4, CV_16UC1));
  expectSimError(sim("d16.png", "right.png"), "d16.png': 16-bit samples");
  writeImage("rgba.png", texture(40, 20, 5, CV_8UC4));
  expectSimError(sim("left.png", "rgba.png"), "rgba.png': 4 channels");
  writeImage("other.png", texture(41, 20, 6));
  expectSimError(sim("left.png", "other.png"), "size mismatch: 40x20 vs 41x20");
  writeImage("gt.png", cv::Mat(21, 40, CV_8UC1, cv::Scalar(8)));
  expectSimError(sim("left.png", "right.png", {"--gt", in("gt.png")}), "ground truth size");
  expectSimError(sim("left.png", "right.png", {"--gt", in("nope_gt.png")}), "nope_gt.png");
}

TEST_F(SgmSimCli, ParametersTheBuildOrTheCoreCannotTake) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--d", "32"}, "built for D=16"},
      {{"--d", "100000"}, "--d=100000 out of range"},
      {{"--mode", "bt"}, "cost mode bt is software only"},
      {{"--p1", "100", "--p2", "300"}, "P2'=300 exceeds the core's 8-bit input"},
      {{"--lr", "8"}, "LR tolerance 8 exceeds the core's 3-bit input"},
      {{"--preset", "paper"}, "built for the 9x5 census, not 9x9 (make sim CENSUS=9x9"},
      {{"--census", "9x9"}, "built for the 9x5 census, not 9x9"},
      {{"--census", "9x7"}, "unknown census window '9x7'"},
      {{"--preset", "fast"}, "unknown preset 'fast'"},
      {{"--p2-mode", "steep"}, "unknown P2 mode 'steep'"},
      {{"--weights", "1111"}, "unknown path weights '1111'"},
      {{"--right-path", "3", "--right-block", "0"}, "golden-only experiments, not in the core"},
      {{"--right-path", "3", "--right-block", "32"}, "this simulator's fifth path runs in blocks of 64"},
      {{"--uniqueness", "100"}, "--uniqueness=100 out of range"},
      {{"--ad-weight", "16"}, "--ad-weight=16 out of range"},
      {{"--ad-weight", "15", "--ad-cap", "45"}, "makes rsad costs exceed 127"},
      {{"--subpixel-fit", "linear"}, "golden-only experiments, not in the core"},
      {{"--mgm", "on", "--edge-reset", "0"}, "golden-only experiments, not in the core"},
      {{"--mgm", "on"}, "does not combine with --mgm: give --edge-reset 0"},
      {{"--median-gate", "32"}, "golden-only experiments, not in the core"},
      {{"--p1-paths", "200,100,200,100,100"}, "golden-only experiments, not in the core"},
      {{"--p1-paths", "200,100"}, "--p1-paths expects five percentages"},
      {{"--snap", "on", "--snap-edge", "96"}, "golden-only experiments, not in the core"},
      {{"--snap-edge", "256"}, "--snap-edge=256 out of range"},
      {{"--lr-store-bits", "8"}, "golden-only experiments, not in the core"},
      {{"--dmin", "4"}, "built without the minimum disparity (make sim MIN_DISPARITY=1"},
      {{"--output", "depth"}, "built without the depth output (make sim DEPTH=1"},
      {{"--output", "range"}, "unknown output 'range'"},
      {{"--calib", "somewhere"}, "built without the rectification (make sim RECTIFY=1"},
      {{"--output-confidence", "on"}, "built without the confidence (make sim CONFIDENCE=1"},
      {{"--output-confidence", "maybe"}, "option --output-confidence expects on or off"},
      {{"--focal", "16777216"}, "--focal=16777216 out of range"},
      {{"--dmin", "256"}, "--dmin=256 out of range"},
      {{"--lr-store-bits", "3"}, "stored Lr bits 3 out of range"},
      {{"--edge-reset", "256"}, "--edge-reset=256 out of range"},
      {{"--edge-reset", "48", "--edge-reset-len", "0"}, "--edge-reset-len=0 out of range"},
      {{"--edge-reset", "48", "--edge-reset-paths", "1,1,2,1,1"}, "--edge-reset-paths expects five flags 0..1"},
      {{"--frames", "0"}, "--frames=0 out of range"},
      {{"--frames", "1e9"}, "--frames expects an integer"},
      {{"--stall", "1"}, "--stall=1 out of range"},
      {{"--stall", "nan"}, "--stall expects a number"},
      {{"--seed", "-1"}, "--seed=-1 out of range"},
      {{"--gt-scale", "-1"}, "--gt-scale=-1 out of range"},
      {{"--frobnicate"}, "unknown option --frobnicate"},
      {{"extra"}, "unexpected argument 'extra'"},
  };
  for (const auto& [opts, needle] : cases) {
    SCOPED_TRACE(opts[0]);
    expectSimError(sim("left.png", "right.png", opts), needle);
  }
  expectSimError(run(kSim, {"--left", in("left.png")}), "give both --left and --right");
  expectSimError(run(kSim, {"--calib", in("calib")}), "--calib needs the raw pair: --left and --right");
}

TEST_F(SgmSimCli, UnusableOutputDirectoryFailsBeforeSimulating) {
  sgm::test::writeBytes(out_ + "/file", "x");
  const ChildResult r = run(kSim, {"--left", in("left.png"), "--right", in("right.png"), "--out", out_ + "/file/res"});
  EXPECT_EQ(sgm::test::userErrorProblem(r, "sgm-sim", "'" + out_ + "/file' is not a directory"), "");
  EXPECT_EQ(sgm::test::dirEntries(out_), (std::set<std::string>{"file"}));
}

}  // namespace
