// Command-line behaviour: the CliArgs parser in-process, and the sgm-golden /
// sgm-eval binaries (from $SGM_BIN) run as child processes. Every user error
// must exit non-zero with exactly one stderr line "<tool>: error: ..." and
// leave no output file behind.
#include "sgm/cli_args.hpp"
#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <stdlib.h>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

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
  const sgm::Params b = parse({"--mode", "bt", "--p2", "5000"}).pipelineParams();
  EXPECT_EQ(b.p1, sgm::defaultParams(sgm::CostMode::kBt).p1);
  EXPECT_EQ(b.p2, 5000);
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

// ------------------------------------------------------------------ child processes

struct RunResult {
  int rc = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

std::set<std::string> entries(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

cv::Mat texture(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  return img;
}

// right(x) = left(x + shift): a pair with constant disparity `shift`.
std::pair<cv::Mat, cv::Mat> shiftedPair(int w, int h, int shift, unsigned seed) {
  const cv::Mat wide = texture(w + shift, h, seed);
  return {wide(cv::Rect(0, 0, w, h)).clone(), wide(cv::Rect(shift, 0, w, h)).clone()};
}

// Fixture: $SGM_BIN, an input directory and an (empty) output / working directory.
class CliTest : public testing::Test {
 protected:
  void SetUp() override {
    const char* bin = std::getenv("SGM_BIN");
    if (!bin || !*bin || !fs::exists(std::string(bin) + "/sgm-golden"))
      GTEST_SKIP() << "SGM_BIN not set or without sgm-golden (got '" << (bin ? bin : "") << "'); run via make unit-test";
    bin_ = bin;
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string tmpl = base + "sgm_cli_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    root_ = tmpl;
    in_ = root_ + "/in";
    out_ = root_ + "/out";
    fs::create_directory(in_);
    fs::create_directory(out_);
    auto [l, r] = shiftedPair(40, 30, 3, 42);
    writeImage("left.png", l);
    writeImage("right.png", r);
  }
  void TearDown() override {
    if (!root_.empty()) {
      std::error_code ec;
      fs::remove_all(root_, ec);
    }
  }

  void writeImage(const std::string& name, const cv::Mat& img) {
    ASSERT_TRUE(cv::imwrite(in_ + "/" + name, img));
    inputs_.insert(name);
  }
  void writeRaw(const std::string& name, const std::string& bytes) {
    std::ofstream(in_ + "/" + name, std::ios::binary) << bytes;
    inputs_.insert(name);
  }
  std::string in(const std::string& name) const { return in_ + "/" + name; }

  // Runs BIN/tool with args in the output directory.
  RunResult run(const std::string& tool, const std::vector<std::string>& args) const {
    std::string cmd = "cd " + quote(out_) + " && " + quote(bin_ + "/" + tool);
    for (const auto& a : args) cmd += " " + quote(a);
    const std::string outFile = root_ + "/stdout.txt", errFile = root_ + "/stderr.txt";
    cmd += " >" + quote(outFile) + " 2>" + quote(errFile);
    RunResult r;
    const int status = std::system(cmd.c_str());
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(outFile);
    r.err = slurp(errFile);
    fs::remove(outFile);
    fs::remove(errFile);
    return r;
  }

  // The common contract of a user error. Returns the stderr lines.
  std::vector<std::string> expectUserError(const RunResult& r, const std::string& tool, const std::string& needle) {
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.rc, -1) << "killed by a signal";
    const std::vector<std::string> errLines = lines(r.err);
    const std::string prefix = tool + ": error: ";
    EXPECT_FALSE(errLines.empty()) << "nothing on stderr";
    if (!errLines.empty()) {
      const std::string& last = errLines.back();
      EXPECT_EQ(last.rfind(prefix, 0), 0u) << "stderr: " << r.err;
      EXPECT_NE(last.find(needle), std::string::npos) << "'" << needle << "' not in: " << last;
    }
    EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
    EXPECT_TRUE(entries(out_).empty()) << "output files were created";
    EXPECT_EQ(entries(in_), inputs_) << "input directory changed";
    return errLines;
  }

  // Exactly one stderr line, the error line.
  void expectOneLineError(const RunResult& r, const std::string& tool, const std::string& needle) {
    const auto errLines = expectUserError(r, tool, needle);
    EXPECT_EQ(errLines.size(), 1u) << "stderr:\n" << r.err;
    EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << "stderr line not terminated";
  }

  std::string bin_, root_, in_, out_;
  std::set<std::string> inputs_;
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
  // A directory given as an image.
  expectOneLineError(run("sgm-golden", {in_, in("right.png")}), "sgm-golden", "cannot");
}

// Truncated image files: the decoder libraries' own diagnostics must not reach stderr.
TEST_F(SgmGoldenCli, TruncatedPng) {
  std::vector<uchar> buf;
  ASSERT_TRUE(cv::imencode(".png", texture(40, 30, 1), buf));
  writeRaw("cut.png", std::string(buf.begin(), buf.begin() + 200));
  const RunResult r = run("sgm-golden", {in("cut.png"), in("right.png")});
  const auto errLines = expectUserError(r, "sgm-golden", "cut.png");
  EXPECT_EQ(errLines.size(), 1u) << r.err;
}

TEST_F(SgmGoldenCli, TruncatedJpeg) {
  std::vector<uchar> buf;
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>{texture(40, 30, 1), texture(40, 30, 2), texture(40, 30, 3)}, colour);
  ASSERT_TRUE(cv::imencode(".jpg", colour, buf));
  writeRaw("cut.jpg", std::string(buf.begin(), buf.begin() + 300));
  const RunResult r = run("sgm-golden", {in("cut.jpg"), in("right.png")});
  const auto errLines = expectUserError(r, "sgm-golden", "cut.jpg");
  EXPECT_EQ(errLines.size(), 1u) << r.err;
}

TEST_F(SgmGoldenCli, UnsupportedImageFormats) {
  writeImage("d16.png", cv::Mat(30, 40, CV_16UC1, cv::Scalar(1000)));
  writeImage("rgba.png", cv::Mat(30, 40, CV_8UC4, cv::Scalar(1, 2, 3, 4)));
  expectOneLineError(run("sgm-golden", {in("d16.png"), in("right.png")}), "sgm-golden", "16-bit");
  expectOneLineError(run("sgm-golden", {in("left.png"), in("rgba.png")}), "sgm-golden", "4 channels");
}

TEST_F(SgmGoldenCli, SizeMismatch) {
  writeImage("wide.png", texture(41, 30, 3));
  expectOneLineError(run("sgm-golden", {in("left.png"), in("wide.png"), "--out", out_ + "/res"}), "sgm-golden",
                     "size mismatch");
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
      {{"--p1", "abc"}, "--p1"},         {{"--p2", "-5"}, "--p2"},
      {{"--mode", "census"}, "census"},  {{"--subpixel", "maybe"}, "--subpixel"},
      {{"--lr", "x"}, "--lr"},           {{"--median", "2"}, "--median"},
      {{"--p1", "50", "--p2", "10"}, "P2'"},
      {{"--d", "4", "--lr", "9"}, "LR tolerance"},
      {{"--d"}, "needs a value"},
  };
  for (const auto& [opts, needle] : cases) {
    SCOPED_TRACE(opts[0]);
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
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), in("left.png")}), "sgm-golden",
                     "two images");
}

TEST_F(SgmGoldenCli, UnwritableOutputLeavesNoFile) {
  expectOneLineError(run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/no/such/dir/res"}),
                     "sgm-golden", "cannot write");
}

TEST_F(SgmGoldenCli, HelpExitsZero) {
  const RunResult r = run("sgm-golden", {"--help"});
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.out.find("usage: sgm-golden"), std::string::npos);
  EXPECT_TRUE(r.err.empty());
  EXPECT_TRUE(entries(out_).empty());
}

TEST_F(SgmGoldenCli, SuccessWritesThreePngsMatchingTheLibrary) {
  // Every pipeline parameter that the CLI could default differently is given explicitly.
  const RunResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/res", "--d", "16", "--mode",
                                         "rsad", "--p1", "11", "--p2", "150"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto outLines = lines(r.out);
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
  fs::create_directory(out_ + "/res_disp8.png");
  const RunResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--out", out_ + "/res", "--d", "8"});
  EXPECT_NE(r.rc, 0);
  const auto errLines = lines(r.err);
  ASSERT_EQ(errLines.size(), 1u) << r.err;
  EXPECT_EQ(errLines[0].rfind("sgm-golden: error: ", 0), 0u) << r.err;
  EXPECT_NE(errLines[0].find("res_disp8.png"), std::string::npos) << r.err;
  // All three outputs or none: only the blocking directory remains.
  EXPECT_EQ(entries(out_), (std::set<std::string>{"res_disp8.png"}));
}

TEST_F(SgmGoldenCli, DefaultPrefixInWorkingDirectory) {
  const RunResult r = run("sgm-golden", {in("left.png"), in("right.png"), "--d", "8"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(entries(out_),
            (std::set<std::string>{"disparity_disp16.png", "disparity_disp8.png", "disparity_color.png"}));
}

// ------------------------------------------------------------------ sgm-eval

using SgmEvalCli = CliTest;

TEST_F(SgmEvalCli, MissingDataDirectory) {
  const std::string missing = root_ + "/no-such-data";
  expectOneLineError(run("sgm-eval", {"run", "--data", missing}), "sgm-eval", missing);
  expectOneLineError(run("sgm-eval", {"run"}), "sgm-eval", "--data");
  expectOneLineError(run("sgm-eval", {"table", "--data", missing, "--out", out_ + "/report"}), "sgm-eval", missing);
  expectOneLineError(run("sgm-eval", {"bench", "--data", missing, "--out", out_ + "/report"}), "sgm-eval", missing);
  // An existing directory without scenes.
  expectOneLineError(run("sgm-eval", {"run", "--data", in_}), "sgm-eval", "no scenes");
}

TEST_F(SgmEvalCli, BadArguments) {
  expectOneLineError(run("sgm-eval", {"frobnicate"}), "sgm-eval", "unknown command");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--d", "1"}), "sgm-eval", "--d");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--bogus", "1"}), "sgm-eval", "unknown option --bogus");
  expectOneLineError(run("sgm-eval", {"run", "--data", in_, "--delta", "x"}), "sgm-eval", "--delta");
}

TEST_F(SgmEvalCli, SceneWithoutScaleIsAnError) {
  const std::string data = root_ + "/data", scene = data + "/synthetic";
  fs::create_directories(scene);
  auto [l, r] = shiftedPair(40, 30, 3, 9);
  ASSERT_TRUE(cv::imwrite(scene + "/left.png", l));
  ASSERT_TRUE(cv::imwrite(scene + "/right.png", r));
  ASSERT_TRUE(cv::imwrite(scene + "/gt.png", cv::Mat(30, 40, CV_8UC1, cv::Scalar(12))));
  expectOneLineError(run("sgm-eval", {"run", "--data", data}), "sgm-eval", "gt_scale");
}

TEST_F(SgmEvalCli, RunsOnASyntheticScene) {
  const std::string data = root_ + "/data", scene = data + "/synthetic";
  fs::create_directories(scene);
  auto [l, r] = shiftedPair(60, 40, 3, 9);
  ASSERT_TRUE(cv::imwrite(scene + "/left.png", l));
  ASSERT_TRUE(cv::imwrite(scene + "/right.png", r));
  ASSERT_TRUE(cv::imwrite(scene + "/gt.png", cv::Mat(40, 60, CV_8UC1, cv::Scalar(12))));  // 3 px at scale 4
  std::ofstream(scene + "/meta.txt") << "scene: synthetic\ngt_scale: 4\n";
  const RunResult res = run("sgm-eval", {"run", "--data", data, "--d", "16"});
  ASSERT_EQ(res.rc, 0) << res.err;
  EXPECT_TRUE(res.err.empty()) << res.err;
  EXPECT_NE(res.out.find("synthetic"), std::string::npos) << res.out;
  EXPECT_NE(res.out.find("mean nonocc"), std::string::npos) << res.out;
  EXPECT_TRUE(entries(out_).empty());
}

}  // namespace
