// SPDX-License-Identifier: Apache-2.0
// Command-line behaviour: the CliArgs parser in-process, and the sgm-golden /
// sgm-eval binaries (from $SGM_BIN) run as child processes. Every user error
// must exit non-zero with exactly one stderr line "<tool>: error: ..." and
// leave no output file behind.
#include "sgm/cli_args.hpp"
#include "sgm/depth.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include "fuzz/cli_fixture.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <set>

namespace fs = std::filesystem;

namespace {

using sgm::test::ChildResult;
using sgm::test::dirEntries;
using sgm::test::shiftedPair;
using sgm::test::textLines;
using sgm::test::texture;

// ------------------------------------------------------------------ CliArgs in-process

sgm::CliArgs parse(std::vector<std::string> args) {
  args.insert(args.begin(), "prog");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  auto options = sgm::CliArgs::pipelineOptions();
  options.insert("out");
  return sgm::CliArgs(int(args.size()), argv.data(), options, {"help"});
}

template <typename F>
void expectError(F&& f, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "no sgm::Error thrown (expected one mentioning '" << needle << "')";
  } catch (const sgm::Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(CliArgs, PositionalsOptionsAndFlags) {
  const sgm::CliArgs a = parse({"left.png", "--d", "32", "--p1=5", "right.png", "--mode", "rsad", "--lr", "off",
                                "--subpixel", "off", "--median=0", "--help"});
  EXPECT_EQ(a.positional(), (std::vector<std::string>{"left.png", "right.png"}));
  EXPECT_TRUE(a.has("help"));
  EXPECT_TRUE(a.has("d"));
  EXPECT_FALSE(a.has("out"));
  EXPECT_EQ(a.text("out", "fallback"), "fallback");
  const sgm::Params p = a.pipelineParams();
  EXPECT_EQ(p.disparities, 32);
  EXPECT_EQ(p.p1, 5);
  EXPECT_EQ(p.p2, sgm::defaultParams(sgm::CostMode::kRsad).p2);  // --mode brings its P2'
  EXPECT_EQ(p.mode, sgm::CostMode::kRsad);
  EXPECT_EQ(p.lrTolerance, -1);
  EXPECT_FALSE(p.subpixel);
  EXPECT_FALSE(p.median);
  EXPECT_TRUE(p.fill);
}

TEST(CliArgs, ModeBringsItsDefaultPenaltiesUnlessOverridden) {
  // cli_args.hpp: --mode also brings that mode's default P1 / P2' (defaultParams);
  // explicit --p1 / --p2 override them whatever the order.
  for (sgm::CostMode m : sgm::allCostModes()) {
    const sgm::Params def = sgm::defaultParams(m);
    const sgm::Params p = parse({"--mode", sgm::costModeName(m)}).pipelineParams();
    EXPECT_EQ(p.mode, m);
    EXPECT_EQ(p.p1, def.p1) << sgm::costModeName(m);
    EXPECT_EQ(p.p2, def.p2) << sgm::costModeName(m);
  }
  const sgm::Params a = parse({"--p1", "3", "--mode", "bt"}).pipelineParams();
  EXPECT_EQ(a.p1, 3);
  EXPECT_EQ(a.p2, sgm::defaultParams(sgm::CostMode::kBt).p2);
  // (P2' 5000 on the four-path preset: with the fifth path S would leave 16 bits.)
  const sgm::Params b = parse({"--mode", "bt", "--p2", "5000"}).pipelineParams(sgm::presetParams("four-path"));
  EXPECT_EQ(b.p1, sgm::defaultParams(sgm::CostMode::kBt).p1);
  EXPECT_EQ(b.p2, 5000);
  // A mode without a census switches a base AD term off; --ad-weight is then checked.
  sgm::Params withAd;
  withAd.adWeight = 3;
  for (sgm::CostMode m : sgm::allCostModes()) {
    const sgm::Params p = parse({"--mode", sgm::costModeName(m)}).pipelineParams(withAd);
    EXPECT_EQ(p.adWeight, sgm::isHardwareMode(m) ? 3 : 0) << sgm::costModeName(m);
    EXPECT_NO_THROW(p.validate()) << sgm::costModeName(m);
  }
  EXPECT_THROW(parse({"--mode", "sad", "--ad-weight", "3"}).pipelineParams().validate(), sgm::Error);
  // Without --mode the base parameters are kept.
  const sgm::Params c = parse({"--d", "16"}).pipelineParams();
  EXPECT_EQ(c.p1, sgm::Params{}.p1);
  EXPECT_EQ(c.p2, sgm::Params{}.p2);
  EXPECT_EQ(c.mode, sgm::Params{}.mode);
}

TEST(CliArgs, LrToleranceAndOnOffValues) {
  EXPECT_EQ(parse({"--lr", "3"}).pipelineParams().lrTolerance, 3);
  EXPECT_TRUE(parse({"--subpixel", "1"}).pipelineParams().subpixel);
  EXPECT_TRUE(parse({"--subpixel", "on"}).pipelineParams().subpixel);
  EXPECT_FALSE(parse({"--fill", "off"}).pipelineParams().fill);
  EXPECT_FALSE(parse({"--snap", "off"}).pipelineParams().snap);
}

TEST(CliArgs, Errors) {
  expectError([] { parse({"--frobnicate", "3"}); }, "unknown option --frobnicate");
  expectError([] { parse({"--d"}); }, "--d needs a value");
  expectError([] { parse({"--help=1"}); }, "unknown option --help");
  expectError([] { parse({"--d", "abc"}).pipelineParams(); }, "--d expects an integer");
  expectError([] { parse({"--d", "12x"}).pipelineParams(); }, "--d expects an integer");
  expectError([] { parse({"--d", ""}).pipelineParams(); }, "--d expects an integer");
  expectError([] { parse({"--d", "1"}).pipelineParams(); }, "--d=1 out of range 2..256");
  expectError([] { parse({"--d", "999"}).pipelineParams(); }, "--d=999 out of range");
  expectError([] { parse({"--d", "99999999999999999999999"}).pipelineParams(); }, "--d expects an integer");
  expectError([] { parse({"--p1", "-1"}).pipelineParams(); }, "--p1=-1 out of range");
  expectError([] { parse({"--p1", "50", "--p2", "10"}).pipelineParams(); }, "P2'=10");
  expectError([] { parse({"--mode", "census"}).pipelineParams(); }, "census");
  expectError([] { parse({"--subpixel", "yes"}).pipelineParams(); }, "--subpixel expects on or off");
  expectError([] { parse({"--lr", "-1"}).pipelineParams(); }, "--lr=-1 out of range");
  expectError([] { parse({"--d", "4", "--lr", "5"}).pipelineParams(); }, "LR tolerance 5");
}

TEST(CliArgs, RealOption) {
  std::vector<std::string> args = {"prog", "--delta", "1.5", "--bad", "x"};
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  const sgm::CliArgs a(int(argv.size()), argv.data(), {"delta", "bad"});
  EXPECT_DOUBLE_EQ(a.real("delta", 1.0, 0.0, 10.0), 1.5);
  EXPECT_DOUBLE_EQ(a.real("other", 2.0, 0.0, 10.0), 2.0);
  expectError([&] { a.real("bad", 1.0, 0.0, 10.0); }, "--bad expects a number");
  expectError([&] { a.real("delta", 1.0, 2.0, 10.0); }, "out of range");
}

TEST(CliArgs, OneLineEscapesControlCharacters) {
  EXPECT_EQ(sgm::oneLine("plain text"), "plain text");
  EXPECT_EQ(sgm::oneLine("a\nb\tc\rd\x01"
                         "e\x7f"),
            "a\\nb\\tc\\rd\\x01e\\x7f");
  const std::string cut = sgm::oneLine(std::string(100000, 'x'));
  EXPECT_LT(cut.size(), 5000u);
  EXPECT_EQ(cut.substr(cut.size() - 3), "...");
}

// ------------------------------------------------------------------ child processes

// Fixture: $SGM_BIN with sgm-golden and sgm-eval, a 40x30 pair in the input directory.
class CliTest : public sgm::test::ToolTest {
 protected:
  void SetUp() override {
    requireBinary("sgm-golden", "run via make unit-test");
    if (IsSkipped()) return;
    requireBinary("sgm-eval", "run via make unit-test");
    if (IsSkipped()) return;
    ToolTest::SetUp();
    auto [l, r] = shiftedPair(40, 30, 3, 42);
    writeImage("left.png", l);
    writeImage("right.png", r);
  }
  std::set<std::string> entries(const std::string& dir) const { return dirEntries(dir); }
};

using SgmGoldenCli = CliTest;

TEST_F(SgmGoldenCli, MissingFile) {
  expectOneLineError(run("sgm-golden", {in("nope.png"), in("right.png"), "--out", out_ + "/res"}), "sgm-golden",
                     "nope.png");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("nope.png")}), "sgm-golden", "nope.png");
}

TEST_F(SgmGoldenCli, EmptyFile) {
  writeRaw("empty.png", "");
  expectOneLineError(run("sgm-golden", {in("empty.png"), in("right.png")}), "sgm-golden", "empty");
}

TEST_F(SgmGoldenCli, NonImageFile) {
  writeRaw("text.png", "this is not an image\n");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("text.png"), "--out", out_ + "/res"}), "sgm-golden",
                     "text.png");
}

TEST_F(SgmGoldenCli, DirectoryOrSpecialFileGivenAsImage) {
  expectOneLineError(run("sgm-golden", {in_, in("right.png")}), "sgm-golden", "is a directory");
  expectOneLineError(run("sgm-golden", {in("left.png"), "/dev/null"}), "sgm-golden", "not a regular file");
}

// Truncated image files: the decoder libraries' own diagnostics must not reach stderr.
TEST_F(SgmGoldenCli, TruncatedPng) {
  const std::string png = sgm::test::encodeImage(".png", texture(40, 30, 1));
  writeRaw("cut.png", png.substr(0, 200));
  expectOneLineError(run("sgm-golden", {in("cut.png"), in("right.png")}), "sgm-golden", "cut.png");
}

TEST_F(SgmGoldenCli, TruncatedJpeg) {
  const std::string jpeg = sgm::test::encodeImage(".jpg", texture(40, 30, 1, CV_8UC3));
  writeRaw("cut.jpg", jpeg.substr(0, 300));  // inside the headers
  expectOneLineError(run("sgm-golden", {in("cut.jpg"), in("right.png")}), "sgm-golden", "cut.jpg");
  // Inside the scan data: libjpeg would decode it with made-up pixels and a warning.
  writeRaw("cut2.jpg", jpeg.substr(0, jpeg.size() * 3 / 4));
  expectOneLineError(run("sgm-golden", {in("left.png"), in("cut2.jpg")}), "sgm-golden",
                     "'" + in("cut2.jpg") + "': truncated");
}

TEST_F(SgmGoldenCli, HeaderAnnouncingAHugeImage) {
  // Rejected from the header, before a decoder allocates 30000 x 30000 pixels.
  const cv::Mat img = texture(40, 30, 5, CV_8UC3);
  writeRaw("huge.png", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".png", img), 30000, 30000));
  writeRaw("huge.jpg", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".jpg", img), 30000, 30000));
  expectOneLineError(run("sgm-golden", {in("huge.png"), in("right.png")}), "sgm-golden", "30000x30000: too large");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("huge.jpg")}), "sgm-golden", "30000x30000: too large");
}

TEST_F(SgmGoldenCli, SixteenBitImagesAreRejected) {
  writeImage("d16.png", texture(40, 30, 6, CV_16UC1));
  writeImage("c16.png", texture(40, 30, 7, CV_16UC3));
  expectOneLineError(run("sgm-golden", {in("d16.png"), in("right.png")}), "sgm-golden",
                     "'" + in("d16.png") + "': 16-bit samples (8-bit gray or colour required)");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("c16.png")}), "sgm-golden", "c16.png': 16-bit");
}

TEST_F(SgmGoldenCli, FourChannelImagesAreRejected) {
  // docs/algorithm.md, section 1: 8-bit gray or 3-channel colour only; an alpha channel is an error.
  writeImage("rgba.png", texture(40, 30, 8, CV_8UC4));
  expectOneLineError(run("sgm-golden", {in("left.png"), in("rgba.png")}), "sgm-golden", "rgba.png': 4 channels");
}

TEST_F(SgmGoldenCli, ColourPairIsConvertedToGray) {
  // The pinned behaviour for 3-channel input: the documented integer gray conversion,
  // i.e. the same result as the gray pair made by sgm::toGray.
  auto [l, r] = shiftedPair(40, 30, 2, 11, CV_8UC3);
  writeImage("cl.png", l);
  writeImage("cr.png", r);
  writeImage("gl.png", sgm::toGray(l));
  writeImage("gr.png", sgm::toGray(r));
  ASSERT_EQ(run("sgm-golden", {in("cl.png"), in("cr.png"), "--d", "8", "--out", "colour"}).rc, 0);
  ASSERT_EQ(run("sgm-golden", {in("gl.png"), in("gr.png"), "--d", "8", "--out", "gray"}).rc, 0);
  const cv::Mat colour = cv::imread(out_ + "/colour_disp16.png", cv::IMREAD_UNCHANGED);
  const cv::Mat gray = cv::imread(out_ + "/gray_disp16.png", cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(colour.empty());
  ASSERT_EQ(colour.size(), gray.size());
  EXPECT_EQ(cv::countNonZero(colour != gray), 0);
}

TEST_F(SgmGoldenCli, SizeMismatch) {
  writeImage("wide.png", texture(41, 30, 3));
  expectOneLineError(run("sgm-golden", {in("left.png"), in("wide.png"), "--out", out_ + "/res"}), "sgm-golden",
                     "size mismatch: 40x30 vs 41x30");
}

TEST_F(SgmGoldenCli, ImageSmallerThanTheWindow) {
  writeImage("tiny_l.png", texture(8, 8, 4));
  writeImage("tiny_r.png", texture(8, 8, 5));
  expectOneLineError(run("sgm-golden", {in("tiny_l.png"), in("tiny_r.png")}), "sgm-golden", "smaller");
  writeImage("flat_l.png", texture(40, 8, 4));
  writeImage("flat_r.png", texture(40, 8, 5));
  expectOneLineError(run("sgm-golden", {in("flat_l.png"), in("flat_r.png")}), "sgm-golden", "smaller");
}

TEST_F(SgmGoldenCli, UnsupportedDisparityCount) {
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--d", "1"}), "sgm-golden", "--d");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--d", "999"}), "sgm-golden", "--d");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--d=0"}), "sgm-golden", "--d");
}

TEST_F(SgmGoldenCli, BadOptionValues) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--p1", "abc"}, "--p1"},
      {{"--p2", "-5"}, "--p2"},
      {{"--mode", "census"}, "census"},
      {{"--subpixel", "maybe"}, "--subpixel"},
      {{"--lr", "x"}, "--lr"},
      {{"--median", "2"}, "--median"},
      {{"--p1", "50", "--p2", "10"}, "P2'"},
      {{"--d", "4", "--lr", "9"}, "LR tolerance"},
      {{"--d"}, "needs a value"},
      {{"--d", "99999999999999999999"}, "--d expects an integer"},
      {{"--p2", "1e9"}, "--p2 expects an integer"},
      {{"--p2", "6001"}, "--p2=6001 out of range"},
      {{"--lr", "1000"}, "--lr=1000 out of range"},
      {{"--mode", "a\nb"}, "'a\\nb'"},  // a newline in a value stays on one line
      {{"--out", ""}, "empty --out"},
      {{"--out", "no/such/dir/res"}, "directory 'no/such/dir' does not exist"},
  };
  for (const auto& [opts, needle] : cases) {
    SCOPED_TRACE(opts[0] + " " + (opts.size() > 1 ? opts[1] : ""));
    std::vector<std::string> args = {in("left.png"), in("right.png")};
    args.insert(args.end(), opts.begin(), opts.end());
    expectOneLineError(run("sgm-golden", args), "sgm-golden", needle);
  }
}

TEST_F(SgmGoldenCli, UnknownOptionAndWrongArgumentCount) {
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--frobnicate", "3"}), "sgm-golden",
                     "unknown option --frobnicate");
  expectOneLineError(run("sgm-golden", {in("left.png")}), "sgm-golden", "two images");
  expectOneLineError(run("sgm-golden", {}), "sgm-golden", "two images");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), in("left.png")}), "sgm-golden", "two images");
}

TEST_F(SgmGoldenCli, UnwritableOutputLeavesNoFile) {
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/no/such/dir/res"}),
                     "sgm-golden", "cannot write");
}

TEST_F(SgmGoldenCli, HelpExitsZero) {
  const ChildResult r = run("sgm-golden", {"--help"});
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.out.find("usage: sgm-golden"), std::string::npos);
  EXPECT_TRUE(r.err.empty());
  EXPECT_TRUE(entries(out_).empty());
}

// --output depth (the core's OUTPUT.MODE) also writes PREFIX_depth16.png: the library's
// outputWords for f = F/256 px and B um.
TEST_F(SgmGoldenCli, DepthOutputWritesTheDepthWords) {
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/bad", "--output", "range"}),
                     "sgm-golden", "unknown output 'range'");
  expectOneLineError(
      run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/bad", "--focal", "16777216"}), "sgm-golden",
      "--focal");
  const ChildResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/res", "--d", "16",
                                           "--output", "depth", "--focal", "179200", "--baseline", "60000"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(entries(out_),
            (std::set<std::string>{"res_disp16.png", "res_disp8.png", "res_color.png", "res_depth16.png"}));
  sgm::Params p;
  p.disparities = 16, p.output = sgm::OutputMode::kDepth, p.focalQ8 = 179200, p.baselineUm = 60000;
  const cv::Mat expected = sgm::outputWords(
      sgm::runPipeline(sgm::readGray(in("left.png")), sgm::readGray(in("right.png")), p), p);
  const cv::Mat z = cv::imread(out_ + "/res_depth16.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(z.type(), CV_16UC1);
  EXPECT_EQ(cv::countNonZero(z != expected), 0);
  EXPECT_GT(cv::countNonZero(z == 14000), 40 * 30 / 2);  // 700 px x 60 mm / 3 px
}

TEST_F(SgmGoldenCli, SuccessWritesThreePngsMatchingTheLibrary) {
  // Every pipeline parameter that the CLI could default differently is given explicitly.
  const ChildResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/res", "--d", "16",
                                           "--mode", "rsad", "--p1", "11", "--p2", "150"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto outLines = textLines(r.out);
  ASSERT_EQ(outLines.size(), 1u) << r.out;
  EXPECT_EQ(outLines[0].rfind("sgm-golden: 40x30 D=16 mode=rsad", 0), 0u) << outLines[0];
  EXPECT_EQ(entries(out_), (std::set<std::string>{"res_disp16.png", "res_disp8.png", "res_color.png"}));

  const cv::Mat d16 = cv::imread(out_ + "/res_disp16.png", cv::IMREAD_UNCHANGED);
  const cv::Mat d8 = cv::imread(out_ + "/res_disp8.png", cv::IMREAD_UNCHANGED);
  const cv::Mat col = cv::imread(out_ + "/res_color.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(d16.type(), CV_16UC1);
  ASSERT_EQ(d8.type(), CV_8UC1);
  ASSERT_EQ(col.type(), CV_8UC3);
  EXPECT_EQ(d16.size(), cv::Size(40, 30));
  EXPECT_EQ(d8.size(), cv::Size(40, 30));
  EXPECT_EQ(col.size(), cv::Size(40, 30));

  // The CLI writes exactly what the library computes for the same parameters.
  sgm::Params p;
  p.disparities = 16;
  p.mode = sgm::CostMode::kRsad;
  p.p1 = 11;
  p.p2 = 150;
  const sgm::DisparityMap map = sgm::runPipeline(sgm::readGray(in("left.png")), sgm::readGray(in("right.png")), p);
  EXPECT_EQ(cv::countNonZero(d16 != sgm::encodeDisparity16(map)), 0);
  EXPECT_EQ(cv::countNonZero(d8 != sgm::encodeDisparity8(map, 16)), 0);
  // Constant disparity 3: the bulk of the map is 3 px = 768 in the 16-bit PNG.
  EXPECT_GT(cv::countNonZero(d16 == 768), 40 * 30 / 2);
}

TEST_F(SgmGoldenCli, FailedLaterOutputLeavesNoEarlierOutput) {
  // res_disp8.png is a directory: the second of the three writes fails. A run
  // that reports an error should not leave a fresh res_disp16.png behind that a
  // caller could take for a result.
  std::filesystem::create_directory(out_ + "/res_disp8.png");
  const ChildResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/res", "--d", "8"});
  EXPECT_EQ(sgm::test::userErrorProblem(r, "sgm-golden", "res_disp8.png"), "");
  // All three outputs or none: only the blocking directory remains.
  EXPECT_EQ(entries(out_), (std::set<std::string>{"res_disp8.png"}));
}

TEST_F(SgmGoldenCli, DefaultPrefixInWorkingDirectory) {
  const ChildResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--d", "8"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(entries(out_),
            (std::set<std::string>{"disparity_disp16.png", "disparity_disp8.png", "disparity_color.png"}));
}

// ------------------------------------------------------------------ sgm-eval

class SgmEvalCli : public CliTest {
 protected:
  // A scene directory data/NAME with the given left, right and ground truth
  // (gt_scale 4 in meta.txt); returns the data directory.
  std::string makeScene(const std::string& name, const cv::Mat& left, const cv::Mat& right, const cv::Mat& gt) {
    const std::string data = root_ + "/data", scene = data + "/" + name;
    std::filesystem::create_directories(scene);
    EXPECT_TRUE(cv::imwrite(scene + "/left.png", left));
    EXPECT_TRUE(cv::imwrite(scene + "/right.png", right));
    EXPECT_TRUE(cv::imwrite(scene + "/gt.png", gt));
    std::ofstream(scene + "/meta.txt") << "scene: " << name << "\ngt_scale: 4\n";
    return data;
  }
  std::string goodScene(const std::string& name = "synthetic") {
    auto [l, r] = shiftedPair(60, 40, 3, 9);
    return makeScene(name, l, r, cv::Mat(40, 60, CV_8UC1, cv::Scalar(12)));  // 3 px at scale 4
  }
  // Every subcommand on data: the same one-line error naming needle, nothing written.
  void expectErrorInEveryCommand(const std::string& data, const std::string& needle) {
    for (const std::string command : {"run", "table", "bench", "pool"}) {
      SCOPED_TRACE(command);
      std::vector<std::string> args = {command, command == "pool" ? "--pool" : "--data", data, "--out",
                                       out_ + "/report"};
      if (command == "run") args.resize(3);
      if (command == "bench") args.insert(args.end(), {"--scene", "synthetic"});
      expectOneLineError(run("sgm-eval", args), "sgm-eval", needle);
    }
  }
};

TEST_F(SgmEvalCli, MissingDataDirectory) {
  const std::string missing = root_ + "/no-such-data";
  expectOneLineError(run("sgm-eval", {"run", "--data", missing}), "sgm-eval", missing);
  expectOneLineError(run("sgm-eval", {"run"}), "sgm-eval", "--data");
  expectOneLineError(run("sgm-eval", {"table", "--data", missing, "--out", out_ + "/report"}), "sgm-eval", missing);
  expectOneLineError(run("sgm-eval", {"bench", "--data", missing, "--out", out_ + "/report"}), "sgm-eval", missing);
  // An existing directory without scenes, a file instead of a directory.
  expectOneLineError(run("sgm-eval", {"run", "--data", in_}), "sgm-eval", "no scenes");
  expectOneLineError(run("sgm-eval", {"table", "--data", in("left.png")}), "sgm-eval", "is not a directory");
}

TEST_F(SgmEvalCli, BadArguments) {
  expectOneLineError(run("sgm-eval", {}), "sgm-eval", "missing command");
  expectOneLineError(run("sgm-eval", {"frobnicate"}), "sgm-eval", "unknown command");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--d", "1"}), "sgm-eval", "--d");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--bogus", "1"}), "sgm-eval", "unknown option --bogus");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--delta", "x"}), "sgm-eval", "--delta");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--delta", "nan"}), "sgm-eval", "--delta");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "extra"}), "sgm-eval", "unexpected argument 'extra'");
  expectOneLineError(run("sgm-eval", {"table", "--data", in_, "--d", "100000"}), "sgm-eval", "--d=100000");
  expectOneLineError(run("sgm-eval", {"table", "--data", in_, "--mode", "rt"}), "sgm-eval", "unknown option --mode");
  expectOneLineError(run("sgm-eval", {"bench", "--data", in_, "--repeats", "0"}), "sgm-eval", "--repeats=0");
  expectOneLineError(run("sgm-eval", {"bench", "--data", in_, "--repeats", "-99999999999999999999"}), "sgm-eval",
                     "--repeats");
}

TEST_F(SgmEvalCli, SceneWithoutScaleIsAnError) {
  const std::string data = goodScene();
  std::filesystem::remove(data + "/synthetic/meta.txt");
  expectOneLineError(run("sgm-eval", {"run", "--data", data}), "sgm-eval", "gt_scale");
}

TEST_F(SgmEvalCli, BadSceneImagesInEveryCommand) {
  auto [l, r] = shiftedPair(60, 40, 3, 9);
  const cv::Mat gt(40, 60, CV_8UC1, cv::Scalar(12));
  const std::string data = makeScene("synthetic", l, r, gt);
  const std::string scene = data + "/synthetic";
  sgm::test::writeBytes(scene + "/left.png", sgm::test::encodeImage(".png", l).substr(0, 100));
  expectErrorInEveryCommand(data, scene + "/left.png");
  ASSERT_TRUE(cv::imwrite(scene + "/left.png", texture(60, 40, 1, CV_16UC1)));
  expectErrorInEveryCommand(data, "left.png': 16-bit samples");
  ASSERT_TRUE(cv::imwrite(scene + "/left.png", texture(60, 40, 1, CV_8UC4)));
  expectErrorInEveryCommand(data, "left.png': 4 channels");
  ASSERT_TRUE(cv::imwrite(scene + "/left.png", l));
  ASSERT_TRUE(cv::imwrite(scene + "/right.png", texture(61, 40, 1)));
  expectErrorInEveryCommand(data, "size mismatch: 60x40 vs 61x40");
  ASSERT_TRUE(cv::imwrite(scene + "/right.png", r));
  ASSERT_TRUE(cv::imwrite(scene + "/gt.png", cv::Mat(41, 60, CV_8UC1, cv::Scalar(12))));
  expectErrorInEveryCommand(data, "ground truth size");
  ASSERT_TRUE(cv::imwrite(scene + "/gt.png", cv::Mat(40, 60, CV_8UC3, cv::Scalar::all(12))));
  expectErrorInEveryCommand(data, "gt.png");
  sgm::test::writeBytes(scene + "/gt.png", "");
  expectErrorInEveryCommand(data, "gt.png': file is empty");
}

TEST_F(SgmEvalCli, SceneSmallerThanTheWindow) {
  const std::string data = makeScene("synthetic", texture(8, 8, 1), texture(8, 8, 2),
                                     cv::Mat(8, 8, CV_8UC1, cv::Scalar(4)));
  expectOneLineError(run("sgm-eval", {"run", "--data", data}), "sgm-eval", "smaller than the 9x9 minimum frame");
}

TEST_F(SgmEvalCli, UnusableOutputDirectoryFailsBeforeTheWork) {
  const std::string data = goodScene();
  sgm::test::writeBytes(out_ + "/file", "x");
  for (const std::string command : {"table", "bench"}) {
    const ChildResult r = run("sgm-eval", {command, "--data", data, "--out", out_ + "/file/sub"});
    EXPECT_EQ(sgm::test::userErrorProblem(r, "sgm-eval", "is not a directory"), "") << command;
    EXPECT_EQ(entries(out_), (std::set<std::string>{"file"}));
  }
}

TEST_F(SgmEvalCli, BenchSceneNotFound) {
  const std::string data = goodScene();
  expectOneLineError(run("sgm-eval", {"bench", "--data", data, "--scene", "nope", "--out", out_ + "/r"}), "sgm-eval",
                     "scene 'nope'");
}

TEST_F(SgmEvalCli, PoolBadMetaIsOneLine) {
  const std::string data = goodScene();
  std::ofstream(data + "/synthetic/meta.txt") << "gt_scale: 4\nndisp: sixty\n";
  expectOneLineError(run("sgm-eval", {"pool", "--pool", data, "--out", out_ + "/r"}), "sgm-eval",
                     "synthetic/meta.txt:2: bad ndisp 'sixty'");
  expectOneLineError(run("sgm-eval", {"pool", "--pool", root_ + "/none", "--out", out_ + "/r"}), "sgm-eval",
                     "pool directory");
  expectOneLineError(run("sgm-eval", {"pool", "--data", data, "--out", out_ + "/r"}), "sgm-eval", "--data");
  expectOneLineError(run("sgm-eval", {"pool", "--pool", data, "--half", "C", "--out", out_ + "/r"}), "sgm-eval",
                     "--half");
}

TEST_F(SgmEvalCli, PoolWritesItsReports) {
  const std::string data = goodScene();
  std::ofstream(data + "/synthetic/meta.txt") << "gt_scale: 4\nndisp: 16\nset: synth\n";
  const ChildResult res = run("sgm-eval", {"pool", "--pool", data, "--out", out_ + "/r", "--p1", "20"});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_TRUE(res.err.empty()) << res.err;
  EXPECT_EQ(entries(out_ + "/r"), (std::set<std::string>{"pool.json", "pool.md", "pool.png"}));
  std::ifstream in(out_ + "/r/pool.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"scene\": \"synthetic\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"disparities\": 16"), std::string::npos) << json;
  // --p1 20 is not today's defaults: today's figures are computed beside ours.
  EXPECT_NE(res.out.find("today"), std::string::npos) << res.out;
  EXPECT_NE(res.out.find("middlebury"), std::string::npos) << res.out;
}

TEST_F(SgmEvalCli, ConfidenceWritesItsReports) {
  const std::string data = goodScene();
  std::ofstream(data + "/synthetic/meta.txt") << "gt_scale: 4\nndisp: 16\nset: synth\n";
  const ChildResult res = run("sgm-eval", {"confidence", "--pool", data, "--out", root_ + "/r"});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_EQ(entries(root_ + "/r"), (std::set<std::string>{"confidence.json", "confidence.md", "confidence.png"}));
  EXPECT_NE(res.out.find("most confident 50 %"), std::string::npos) << res.out;
  expectOneLineError(run("sgm-eval", {"confidence", "--pool", data, "--half", "A", "--out", out_ + "/q"}), "sgm-eval",
                     "--half");
}

TEST_F(SgmEvalCli, RunsOnASyntheticScene) {
  const std::string data = goodScene();
  const ChildResult res = run("sgm-eval", {"run", "--data", data, "--d", "16"});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_TRUE(res.err.empty()) << res.err;
  EXPECT_NE(res.out.find("synthetic"), std::string::npos) << res.out;
  EXPECT_NE(res.out.find("mean nonocc"), std::string::npos) << res.out;
  EXPECT_TRUE(entries(out_).empty());
}

TEST_F(SgmEvalCli, RawSceneToMeshToRectifiedPair) {
  auto [l, r] = shiftedPair(96, 64, 3, 5);
  writeImage("sl.png", l);
  writeImage("sr.png", r);
  const std::string raw = root_ + "/gen/raw", mesh = root_ + "/gen/mesh", rect = root_ + "/gen/rect";
  ChildResult res = run("sgm-eval", {"raw-scene", "--left", in("sl.png"), "--right", in("sr.png"), "--out", raw});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_EQ(entries(raw), (std::set<std::string>{"extrinsics.yml", "intrinsics.yml", "left.png", "right.png"}));
  res = run("sgm-eval", {"calib-mesh", "--calib", raw, "--size", "96x64", "--grid", "8", "--out", mesh});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_EQ(entries(mesh), (std::set<std::string>{"mesh.bin", "mesh.json"}));
  EXPECT_NE(res.out.find("f 96.000 px"), std::string::npos) << res.out;
  res = run("sgm-eval", {"rectify", "--mesh", mesh + "/mesh.bin", "--left", raw + "/left.png", "--right",
                         raw + "/right.png", "--out", rect});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_EQ(entries(rect), (std::set<std::string>{"left.png", "right.png"}));
  // sgm-golden on the raw pair through the mesh: rectified pair, disparity, confidence, depth.
  const std::string golden = root_ + "/gen/golden";
  std::filesystem::create_directories(golden);
  res = run("sgm-golden", {raw + "/left.png", raw + "/right.png", "--mesh", mesh + "/mesh.bin", "--d", "16",
                           "--confidence", "on", "--out", golden + "/r"});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_EQ(entries(golden), (std::set<std::string>{"r_color.png", "r_confidence.png", "r_depth16.png", "r_disp16.png",
                                                    "r_disp8.png", "r_rectified_left.png", "r_rectified_right.png"}));
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--mesh", mesh + "/mesh.bin"}), "sgm-golden",
                     "96x64");
  // sgm-eval run on a scene of the raw pair with its mesh.bin: rectified as the core does it, so
  // the figures of the pair sgm-eval rectify wrote, except the pixels whose left source falls
  // outside the raw image (a corner here), which are invalid; not those of the raw pair taken
  // as rectified.
  const cv::Mat gt(64, 96, CV_8UC1, cv::Scalar(12));  // 3 px at scale 4
  const auto image = [](const std::string& path) { return cv::imread(path, cv::IMREAD_UNCHANGED); };
  makeScene("asrect", image(rect + "/left.png"), image(rect + "/right.png"), gt);
  makeScene("rawmesh", image(raw + "/left.png"), image(raw + "/right.png"), gt);
  const std::string data = makeScene("rawonly", image(raw + "/left.png"), image(raw + "/right.png"), gt);
  std::filesystem::copy_file(mesh + "/mesh.bin", data + "/rawmesh/mesh.bin");
  res = run("sgm-eval", {"run", "--data", data, "--d", "16"});
  ASSERT_EQ(res.rc, 0) << res.err;
  struct Figures {
    double nonocc = -1, density = -1;
  };
  const auto figures = [&](const std::string& name) {
    Figures f;
    const size_t at = res.out.find(name + " ");
    if (at != std::string::npos)
      std::sscanf(res.out.c_str() + at + name.size(), " nonocc %lf%% all %*f%% disc %*f%% density %lf%%", &f.nonocc,
                  &f.density);
    return f;
  };
  const Figures asRect = figures("asrect"), rawMesh = figures("rawmesh"), rawOnly = figures("rawonly");
  ASSERT_GE(asRect.nonocc, 0) << res.out;
  ASSERT_GE(rawMesh.nonocc, 0) << res.out;
  EXPECT_LT(rawMesh.density, asRect.density) << "the outside pixels are invalid\n" << res.out;
  EXPECT_GE(rawMesh.nonocc, asRect.nonocc) << res.out;
  EXPECT_LT(rawMesh.nonocc, asRect.nonocc + 100 - rawMesh.density + 0.02) << "only the outside pixels differ\n"
                                                                          << res.out;
  EXPECT_GT(rawOnly.nonocc, rawMesh.nonocc + 10) << "the raw pair is not rectified\n" << res.out;
  // The errors: each one line, nothing written.
  const std::string none = out_ + "/none";
  expectOneLineError(run("sgm-eval", {"calib-mesh", "--calib", raw, "--out", none}), "sgm-eval", "--size");
  expectOneLineError(run("sgm-eval", {"calib-mesh", "--calib", raw, "--size", "96by64", "--out", none}), "sgm-eval",
                     "96by64");
  expectOneLineError(run("sgm-eval", {"calib-mesh", "--calib", raw, "--size", "96x64", "--grid", "12"}), "sgm-eval",
                     "power of two");
  expectOneLineError(run("sgm-eval", {"calib-mesh", "--calib", raw, "--size", "96x64", "--rows", "2", "--out", none}),
                     "sgm-eval", "rows");
  expectOneLineError(run("sgm-eval", {"calib-mesh", "--calib", in_, "--size", "96x64", "--out", none}), "sgm-eval",
                     "intrinsics.yml");
  expectOneLineError(run("sgm-eval", {"rectify", "--mesh", in("sl.png"), "--left", in("sl.png"), "--right",
                                      in("sr.png"), "--out", none}),
                     "sgm-eval", "not a mesh file");
  expectOneLineError(run("sgm-eval", {"rectify", "--mesh", mesh + "/mesh.bin", "--left", in("left.png"), "--right",
                                      in("right.png"), "--out", none}),
                     "sgm-eval", "96x64");
  EXPECT_FALSE(std::filesystem::exists(none));
}

}  // namespace
