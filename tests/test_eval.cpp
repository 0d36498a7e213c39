// SPDX-License-Identifier: Apache-2.0
// The evaluator (tools/eval_lib.hpp): the paper's eq. (5) error ratios on a
// hand-made scene, the derived non-occluded mask, scene loading.
#include "eval_lib.hpp"
#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <stdlib.h>

namespace fs = std::filesystem;

namespace {

using sgm::eval::ErrorFigures;
using sgm::eval::Scene;

cv::Mat floats(int rows, int cols, std::initializer_list<float> v) {
  cv::Mat m(rows, cols, CV_32FC1);
  auto it = v.begin();
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) m.at<float>(y, x) = *it++;
  return m;
}

cv::Mat bytes(int rows, int cols, std::initializer_list<int> v) {
  cv::Mat m(rows, cols, CV_8UC1);
  auto it = v.begin();
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) m.at<uint8_t>(y, x) = uint8_t(*it++);
  return m;
}

std::vector<int> row(const cv::Mat& m, int y) {
  std::vector<int> r;
  for (int x = 0; x < m.cols; ++x) r.push_back(m.at<uint8_t>(y, x));
  return r;
}

// 5 x 2 scene:
//   gt      [10 10 10   10 10]    [0   20    20  20  20]
//   disp    [10 11 11.5 -1  8]    [5   20.25 -1  30  19]
//   nonocc  [ 1  1  1    1  0]    [1    1     0   1   1]
//   all     [ 1  1  1    1  1]    [1    1     1   1   0]
Scene handScene() {
  Scene s;
  s.name = "hand";
  s.gt = floats(2, 5, {10, 10, 10, 10, 10, 0, 20, 20, 20, 20});
  s.nonocc = bytes(2, 5, {255, 255, 255, 255, 0, 255, 255, 0, 255, 255});
  s.all = bytes(2, 5, {255, 255, 255, 255, 255, 255, 255, 255, 255, 0});
  return s;
}
const cv::Mat kHandDisp = floats(2, 5, {10, 11, 11.5f, -1, 8, 5, 20.25f, -1, 30, 19});

TEST(Evaluate, HandMadeScene) {
  const ErrorFigures f = sgm::eval::evaluate(kHandDisp, handScene());
  // nonocc with known gt: row 0 x0..x3, row 1 x1, x3, x4 -> 7 pixels.
  // Bad: 11.5 (1.5 off), invalid (row 0 x3), 30 vs 20 -> 3. |11 - 10| = 1 and
  // |19 - 20| = 1 are not errors (> delta is strict).
  EXPECT_NEAR(f.errNonocc, 100.0 * 3 / 7, 1e-9);
  // Valid nonocc: 6 pixels, of which 11.5 and 30 are bad.
  EXPECT_NEAR(f.errNonoccValid, 100.0 * 2 / 6, 1e-9);
  // all with known gt: row 0 (5) + row 1 x1..x3 (3) = 8; bad: 11.5, invalid,
  // 8 vs 10, invalid, 30 -> 5; valid: 6.
  EXPECT_NEAR(f.errAll, 100.0 * 5 / 8, 1e-9);
  EXPECT_NEAR(f.density, 100.0 * 6 / 8, 1e-9);
  EXPECT_FALSE(f.errDisc.has_value());
}

TEST(Evaluate, DeltaThreshold) {
  // delta 2: only the two invalid pixels and 30 vs 20 remain bad.
  ErrorFigures f = sgm::eval::evaluate(kHandDisp, handScene(), 2.0);
  EXPECT_NEAR(f.errNonocc, 100.0 * 2 / 7, 1e-9);
  EXPECT_NEAR(f.errAll, 100.0 * 3 / 8, 1e-9);
  // delta 0.5: 11 and 19 become bad too (20.25 stays good).
  f = sgm::eval::evaluate(kHandDisp, handScene(), 0.5);
  EXPECT_NEAR(f.errNonocc, 100.0 * 5 / 7, 1e-9);
}

TEST(Evaluate, DiscontinuityMask) {
  Scene s = handScene();
  // 255 at row 0 x2 (bad), x3 (invalid), row 1 x0 (gt unknown: ignored), row 1 x1 (good);
  // 128 (non-disc) at row 0 x0.
  s.disc = bytes(2, 5, {128, 0, 255, 255, 0, 255, 255, 0, 0, 0});
  const ErrorFigures f = sgm::eval::evaluate(kHandDisp, s);
  ASSERT_TRUE(f.errDisc.has_value());
  EXPECT_NEAR(*f.errDisc, 100.0 * 2 / 3, 1e-9);
}

TEST(Evaluate, PerfectAndEmpty) {
  Scene s = handScene();
  cv::Mat perfect = s.gt.clone();
  const ErrorFigures f = sgm::eval::evaluate(perfect, s);
  EXPECT_EQ(f.errNonocc, 0.0);
  EXPECT_EQ(f.errAll, 0.0);
  EXPECT_EQ(f.density, 100.0);
  // No evaluated pixel at all: 0, not NaN.
  s.nonocc.setTo(0);
  s.all.setTo(0);
  const ErrorFigures g = sgm::eval::evaluate(kHandDisp, s);
  EXPECT_EQ(g.errNonocc, 0.0);
  EXPECT_EQ(g.density, 0.0);
}

TEST(ToFloat, SixteenthsAndInvalid) {
  sgm::DisparityMap m{cv::Mat(1, 4, CV_16UC1), cv::Mat(1, 4, CV_8UC1)};
  const uint16_t d[] = {24, 0, 16, 1000};
  const uint8_t v[] = {1, 1, 0, 1};
  for (int x = 0; x < 4; ++x) m.disp.at<uint16_t>(0, x) = d[x], m.valid.at<uint8_t>(0, x) = v[x];
  const cv::Mat f = sgm::eval::toFloat(m);
  ASSERT_EQ(f.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(f.at<float>(0, 0), 1.5f);
  EXPECT_FLOAT_EQ(f.at<float>(0, 1), 0.f);  // valid d = 0 stays valid
  EXPECT_FLOAT_EQ(f.at<float>(0, 2), -1.f);
  EXPECT_FLOAT_EQ(f.at<float>(0, 3), 62.5f);
}

TEST(ErrorMap, Colours) {
  const cv::Mat e = sgm::eval::errorMap(kHandDisp, handScene());
  ASSERT_EQ(e.type(), CV_8UC3);
  EXPECT_EQ(e.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 160, 0));   // correct
  EXPECT_EQ(e.at<cv::Vec3b>(0, 2), cv::Vec3b(0, 0, 255));   // wrong
  EXPECT_EQ(e.at<cv::Vec3b>(0, 3), cv::Vec3b(255, 64, 0));  // invalid
  const cv::Vec3b dimmed = e.at<cv::Vec3b>(0, 4);           // wrong, occluded: red halved
  EXPECT_EQ(dimmed[0], 0);
  EXPECT_EQ(dimmed[1], 0);
  EXPECT_NEAR(dimmed[2], 127.5, 0.5);
  EXPECT_EQ(e.at<cv::Vec3b>(1, 0), cv::Vec3b(0, 0, 0));  // gt unknown
  EXPECT_EQ(e.at<cv::Vec3b>(1, 4), cv::Vec3b(0, 0, 0));  // not in `all`
}

// ------------------------------------------------------------------ deriveNonOccluded

TEST(DeriveNonOccluded, HandRowScaleOne) {
  // x:     0  1  2  3  4  5  6  7
  // g:     0  2  1  1  3  3  1  1
  // match  -  -1 1  2  1  2  5  6      (x - g)
  // x=0 unknown; x=1 matches outside the image; x=3 is hidden by x=4 (1 < 2),
  // x=2 by x=4 landing exactly on its match (1 == 1); x=4..7 are visible.
  const cv::Mat gt = bytes(1, 8, {0, 2, 1, 1, 3, 3, 1, 1});
  const cv::Mat m = sgm::eval::deriveNonOccluded(gt, 1.0);
  ASSERT_EQ(m.type(), CV_8UC1);
  EXPECT_EQ(row(m, 0), (std::vector<int>{0, 0, 0, 0, 255, 255, 255, 255}));
}

TEST(DeriveNonOccluded, MatchAtColumnZeroIsInside) {
  // x=1, g=1 -> match 0 (inside); x=2, g=1 -> 1; x=3 unknown is skipped; x=4, g=2 -> 2.
  const cv::Mat gt = bytes(1, 5, {1, 1, 1, 0, 2});
  // x=0, g=1 -> match -1: outside.
  EXPECT_EQ(row(sgm::eval::deriveNonOccluded(gt, 1.0), 0), (std::vector<int>{0, 255, 255, 0, 255}));
}

TEST(DeriveNonOccluded, SixteenBitScaledGroundTruth) {
  // Scale 4: match in gt units = 4x - g.
  // x:     0  1  2   3   4
  // g:     0  4  9   8   14
  // match  -  0  -1  4   2
  // x=4 visible (2); x=3 hidden (2 <= 4); x=2 outside; x=1 hidden: x=2 lands at
  // -1, left of its match 0 (an occluder that is itself cut off by the border).
  cv::Mat gt(1, 5, CV_16UC1);
  const uint16_t g[] = {0, 4, 9, 8, 14};
  for (int x = 0; x < 5; ++x) gt.at<uint16_t>(0, x) = g[x];
  EXPECT_EQ(row(sgm::eval::deriveNonOccluded(gt, 4.0), 0), (std::vector<int>{0, 0, 0, 0, 255}));
  // Rows are independent.
  cv::Mat two(2, 5, CV_16UC1, cv::Scalar(4));  // 1 px everywhere: match 4x - 4
  gt.copyTo(two.row(0));
  const cv::Mat m = sgm::eval::deriveNonOccluded(two, 4.0);
  EXPECT_EQ(row(m, 0), (std::vector<int>{0, 0, 0, 0, 255}));
  EXPECT_EQ(row(m, 1), (std::vector<int>{0, 255, 255, 255, 255}));
}

// ------------------------------------------------------------------ loadScene / listScenes

struct TempDir {
  std::string path;
  TempDir() {
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string tmpl = base + "sgm_eval_XXXXXX";
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void writeScene(const std::string& dir, const std::string& meta, cv::Size gtSize = {12, 10}) {
  fs::create_directories(dir);
  cv::Mat colour(10, 12, CV_8UC3, cv::Scalar(10, 20, 30));  // B, G, R -> gray 22
  ASSERT_TRUE(cv::imwrite(dir + "/left.png", colour));
  ASSERT_TRUE(cv::imwrite(dir + "/right.png", colour));
  cv::Mat gt(gtSize, CV_8UC1, cv::Scalar(12));
  gt.at<uint8_t>(0, 0) = 0;  // unknown
  ASSERT_TRUE(cv::imwrite(dir + "/gt.png", gt));
  if (!meta.empty()) std::ofstream(dir + "/meta.txt") << meta;
}

TEST(LoadScene, SyntheticSceneWithDerivedMask) {
  TempDir t;
  const std::string dir = t.path + "/synth";
  writeScene(dir, "scene: synth\ngt_scale: 4\n");
  const Scene s = sgm::eval::loadScene(dir);
  EXPECT_EQ(s.name, "synth");
  EXPECT_DOUBLE_EQ(s.gtScale, 4.0);
  ASSERT_EQ(s.left.type(), CV_8UC1);
  EXPECT_EQ(s.left.at<uint8_t>(5, 5), 22);
  EXPECT_EQ(s.leftColor.type(), CV_8UC3);
  ASSERT_EQ(s.gt.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(s.gt.at<float>(1, 1), 3.0f);
  EXPECT_FLOAT_EQ(s.gt.at<float>(0, 0), 0.0f);
  EXPECT_EQ(s.all.at<uint8_t>(0, 0), 0);
  EXPECT_NE(s.all.at<uint8_t>(1, 1), 0);
  EXPECT_TRUE(s.nonoccDerived);
  // 3 px everywhere: columns 0..2 match outside the right image.
  EXPECT_EQ(s.nonocc.at<uint8_t>(5, 2), 0);
  EXPECT_EQ(s.nonocc.at<uint8_t>(5, 3), 255);
  EXPECT_TRUE(s.disc.empty());

  const Scene s2 = sgm::eval::loadScene(dir, 2.0);  // explicit scale wins
  EXPECT_DOUBLE_EQ(s2.gtScale, 2.0);
  EXPECT_FLOAT_EQ(s2.gt.at<float>(1, 1), 6.0f);
}

TEST(LoadScene, MasksFromFiles) {
  TempDir t;
  const std::string dir = t.path + "/masked";
  writeScene(dir, "gt_scale: 4\n");
  cv::Mat nonocc(10, 12, CV_8UC1, cv::Scalar(255));
  nonocc.at<uint8_t>(4, 4) = 0;
  ASSERT_TRUE(cv::imwrite(dir + "/nonocc.png", nonocc));
  ASSERT_TRUE(cv::imwrite(dir + "/disc.png", cv::Mat(10, 12, CV_8UC1, cv::Scalar(128))));
  const Scene s = sgm::eval::loadScene(dir);
  EXPECT_FALSE(s.nonoccDerived);
  EXPECT_EQ(s.nonocc.at<uint8_t>(4, 4), 0);
  EXPECT_EQ(s.nonocc.at<uint8_t>(5, 0), 255);  // from the file, not derived
  ASSERT_FALSE(s.disc.empty());
  EXPECT_EQ(s.disc.at<uint8_t>(0, 0), 128);
}

TEST(LoadScene, Errors) {
  TempDir t;
  writeScene(t.path + "/nometa", "");
  EXPECT_THROW(sgm::eval::loadScene(t.path + "/nometa"), sgm::Error);
  EXPECT_NO_THROW(sgm::eval::loadScene(t.path + "/nometa", 4.0));
  writeScene(t.path + "/badmeta", "gt_scale: zero\n");
  EXPECT_THROW(sgm::eval::loadScene(t.path + "/badmeta"), sgm::Error);
  writeScene(t.path + "/badgt", "gt_scale: 4\n", {11, 10});
  EXPECT_THROW(sgm::eval::loadScene(t.path + "/badgt"), sgm::Error);
  writeScene(t.path + "/badmask", "gt_scale: 4\n");
  ASSERT_TRUE(cv::imwrite(t.path + "/badmask/all.png", cv::Mat(3, 3, CV_8UC1, cv::Scalar(255))));
  EXPECT_THROW(sgm::eval::loadScene(t.path + "/badmask"), sgm::Error);
  EXPECT_THROW(sgm::eval::loadScene(t.path + "/missing"), sgm::Error);
}

TEST(ListScenes, OnlyCompleteSceneDirectoriesSorted) {
  TempDir t;
  writeScene(t.path + "/b", "gt_scale: 1\n");
  writeScene(t.path + "/a", "gt_scale: 1\n");
  writeScene(t.path + "/c", "gt_scale: 1\n");
  fs::remove(t.path + "/c/gt.png");
  std::ofstream(t.path + "/file.txt") << "x";
  const auto scenes = sgm::eval::listScenes(t.path);
  ASSERT_EQ(scenes.size(), 2u);
  EXPECT_EQ(fs::path(scenes[0]).filename(), "a");
  EXPECT_EQ(fs::path(scenes[1]).filename(), "b");
  EXPECT_TRUE(sgm::eval::listScenes(t.path + "/nope").empty());
}

}  // namespace
