// SPDX-License-Identifier: Apache-2.0
// The scene pool's evaluation (tools/report_pool.hpp, eval_lib's meta.txt and D1):
// 16-bit ground truth and its scale, ndisp / set parsing and bad meta.txt, the
// derived non-occluded mask of a loaded scene, the KITTI D1 measure on a
// hand-made case, per-set / per-group / per-half means and the split.
#include "eval_lib.hpp"
#include "expect_error.hpp"
#include "report_pool.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <stdlib.h>

namespace fs = std::filesystem;

namespace {

using sgm::eval::ErrorFigures;
using sgm::eval::PoolReport;
using sgm::eval::PoolRow;
using sgm::eval::Scene;

struct TempDir {
  std::string path;
  TempDir() {
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string tmpl = base + "sgm_pool_XXXXXX";
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// A 12 x 10 scene directory with the given ground truth (8- or 16-bit) and meta.txt.
void writeScene(const std::string& dir, const cv::Mat& gt, const std::string& meta) {
  fs::create_directories(dir);
  const cv::Mat image(gt.size(), CV_8UC3, cv::Scalar(10, 20, 30));
  ASSERT_TRUE(cv::imwrite(dir + "/left.png", image));
  ASSERT_TRUE(cv::imwrite(dir + "/right.png", image));
  ASSERT_TRUE(cv::imwrite(dir + "/gt.png", gt));
  std::ofstream(dir + "/meta.txt") << meta;
}

// ------------------------------------------------------------------ meta.txt and 16-bit ground truth

TEST(PoolScene, SixteenBitGroundTruthScaleNdispSet) {
  TempDir t;
  // KITTI style: 16-bit, scale 256, 0 = no data. 12.5 px = 3200; 700.25 px would not fit 8 bits.
  cv::Mat gt(10, 12, CV_16UC1, cv::Scalar(3200));
  gt.at<uint16_t>(0, 11) = 0;
  gt.at<uint16_t>(9, 11) = uint16_t(40 * 256 + 64);  // 40.25 px
  writeScene(t.path + "/k", gt, "source: x\ngt_scale: 256\nset: kitti2015\nndisp: 128\nsize: 12x10\n");
  const Scene s = sgm::eval::loadScene(t.path + "/k");
  EXPECT_DOUBLE_EQ(s.gtScale, 256.0);
  EXPECT_EQ(s.ndisp, 128);
  EXPECT_EQ(s.set, "kitti2015");
  EXPECT_FLOAT_EQ(s.gt.at<float>(5, 5), 12.5f);
  EXPECT_FLOAT_EQ(s.gt.at<float>(9, 11), 40.25f);
  EXPECT_FLOAT_EQ(s.gt.at<float>(0, 11), 0.f);
  EXPECT_EQ(s.all.at<uint8_t>(0, 11), 0);
  EXPECT_NE(s.all.at<uint8_t>(5, 5), 0);
}

TEST(PoolScene, MetaWithoutNdispOrSetAndCommentedScale) {
  TempDir t;
  writeScene(t.path + "/m", cv::Mat(10, 12, CV_8UC1, cv::Scalar(8)),
             "gt_scale: 4 (disparity_px = gt_value / 4; 0 = unknown)\n");
  const Scene s = sgm::eval::loadScene(t.path + "/m");
  EXPECT_DOUBLE_EQ(s.gtScale, 4.0);
  EXPECT_EQ(s.ndisp, 0);
  EXPECT_EQ(s.set, "");
  EXPECT_FLOAT_EQ(s.gt.at<float>(3, 3), 2.f);
}

TEST(PoolScene, BadMetaIsOneLineNamingFileAndLine) {
  TempDir t;
  const cv::Mat gt(10, 12, CV_8UC1, cv::Scalar(8));
  const std::pair<std::string, std::vector<std::string>> cases[] = {
      {"gt_scale: 3\nndisp: lots\n", {"meta.txt:2", "ndisp", "lots"}},
      {"gt_scale: 3\nndisp: 1\n", {"meta.txt:2", "ndisp"}},
      {"gt_scale: 3\nndisp: 300\n", {"meta.txt:2", "ndisp"}},
      {"gt_scale: 3\nndisp: 64px\n", {"meta.txt:2", "ndisp"}},
      {"ndisp: 64\ngt_scale: -3\n", {"meta.txt:2", "gt_scale"}},
      {"gt_scale: 3\nset: middlebury 2006\n", {"meta.txt:2", "set"}},
      {"gt_scale: 3\nndisp: 64\nndisp: 32\n", {"meta.txt:3", "twice"}},
      {"ndisp: 64\nset: a\n", {"no gt_scale"}},
  };
  int i = 0;
  for (const auto& [meta, needles] : cases) {
    SCOPED_TRACE(meta);
    const std::string dir = t.path + "/bad" + std::to_string(i++);
    writeScene(dir, gt, meta);
    for (const std::string& n : needles) expectError([&] { sgm::eval::loadScene(dir); }, {n});
  }
}

// ------------------------------------------------------------------ derived non-occluded mask

TEST(PoolScene, DerivedNonOccludedMaskOfALoadedScene) {
  TempDir t;
  // One row of interest at scale 3 (gt units): x = 0..11, value 6 (2 px) everywhere
  // except x = 6: 15 (5 px, a foreground pixel). Matches 3x - g:
  // x=0: -6 (outside), x=1: -3 (outside), x=2: 0 (inside), x=3: 3, x=4: 6, x=5: 9,
  // x=6: 3 (foreground), x=7: 15 ... The foreground's match 3 hides x=3 (3 >= 3, on)
  // and x=4, x=5 (6, 9 >= 3); x=2 (match 0) stays visible.
  cv::Mat gt(10, 12, CV_8UC1, cv::Scalar(6));
  gt.at<uint8_t>(4, 6) = 15;
  writeScene(t.path + "/d", gt, "gt_scale: 3\nndisp: 16\nset: middlebury2006\n");
  const Scene s = sgm::eval::loadScene(t.path + "/d");
  ASSERT_TRUE(s.nonoccDerived);
  std::vector<int> row, expected = {0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255, 255};
  for (int x = 0; x < 12; ++x) row.push_back(s.nonocc.at<uint8_t>(4, x));
  EXPECT_EQ(row, expected);
  // Other rows: only the border columns 0 and 1 are occluded.
  EXPECT_EQ(s.nonocc.at<uint8_t>(3, 1), 0);
  EXPECT_EQ(s.nonocc.at<uint8_t>(3, 3), 255);
}

// ------------------------------------------------------------------ D1

TEST(D1, PixelRule) {
  using sgm::eval::isD1Error;
  EXPECT_FALSE(isD1Error(23.f, 20.f));    // 3 px: not > 3
  EXPECT_TRUE(isD1Error(23.5f, 20.f));    // 3.5 px > 3 and > 1 (5 % of 20)
  EXPECT_TRUE(isD1Error(16.5f, 20.f));    // either side
  EXPECT_FALSE(isD1Error(104.f, 100.f));  // 4 px > 3 but not > 5 (5 % of 100)
  EXPECT_TRUE(isD1Error(105.5f, 100.f));  // 5.5 > 5
  EXPECT_FALSE(isD1Error(95.f, 100.f));   // 5: not > 5
}

TEST(D1, HandMadeScene) {
  // 6 x 1: gt 20 20 100 100 0 20; all = known gt. Output 23.5 (D1 error), 20.9 (fine),
  // 104 (fine: 4 <= 5), invalid, 50 (unknown gt: not counted), 10 (error).
  Scene s;
  s.name = "hand";
  s.gt = (cv::Mat_<float>(1, 6) << 20, 20, 100, 100, 0, 20);
  s.all = (cv::Mat_<uint8_t>(1, 6) << 255, 255, 255, 255, 255, 255);
  s.nonocc = s.all.clone();
  const cv::Mat disp = (cv::Mat_<float>(1, 6) << 23.5f, 20.9f, 104, -1, 50, 10);
  const ErrorFigures f = sgm::eval::evaluate(disp, s);
  // 5 pixels with gt; D1 errors: 23.5, invalid, 10 -> 3 / 5 strict; valid: 2 of 4.
  EXPECT_NEAR(f.d1All, 100.0 * 3 / 5, 1e-9);
  EXPECT_NEAR(f.d1Valid, 100.0 * 2 / 4, 1e-9);
  // bad-1.0 over the same pixels: 23.5, 104, invalid, 10 -> 4 / 5.
  EXPECT_NEAR(f.errAll, 100.0 * 4 / 5, 1e-9);
  EXPECT_EQ(sgm::eval::strictFigure("kitti2015", f), f.d1All);
  EXPECT_EQ(sgm::eval::strictFigure("middlebury2006", f), f.errNonocc);
  EXPECT_EQ(sgm::eval::validFigure("kitti2012", f), f.d1Valid);
  EXPECT_EQ(sgm::eval::validFigure("", f), f.errNonoccValid);
}

// ------------------------------------------------------------------ split and means

TEST(PoolSplit, AlternatesWithinEachSetByName) {
  const std::vector<std::string> names = {"wood1", "aloe", "kitti_b", "baby1", "map", "kitti_a", "barn1", "cloth1"};
  const std::vector<std::string> sets = {"m06", "m06", "kitti", "m06", "m01", "kitti", "m01", "m06"};
  // m06 sorted: aloe A, baby1 B, cloth1 A, wood1 B; m01: barn1 A, map B; kitti: kitti_a A, kitti_b B.
  EXPECT_EQ(sgm::eval::crossValidationHalves(names, sets), (std::vector<char>{'B', 'A', 'B', 'B', 'B', 'A', 'A', 'A'}));
}

PoolRow row(const std::string& scene, const std::string& set, char half, double ours, double today, double opencvStrict,
            double opencvValid, double density) {
  PoolRow r;
  r.scene = scene, r.set = set, r.half = half;
  const bool kitti = sgm::eval::isKittiSet(set);
  (kitti ? r.ours.d1All : r.ours.errNonocc) = ours;
  ErrorFigures t, o;
  (kitti ? t.d1All : t.errNonocc) = today;
  (kitti ? o.d1All : o.errNonocc) = opencvStrict;
  (kitti ? o.d1Valid : o.errNonoccValid) = opencvValid;
  o.density = density;
  r.today = t, r.opencv = o;
  return r;
}

TEST(PoolMeans, PerSetGroupAndHalf) {
  PoolReport r;
  r.comparesToday = true;
  r.rows = {row("a", "middlebury2006", 'A', 10, 12, 30, 8, 70), row("b", "middlebury2006", 'B', 20, 19, 40, 10, 60),
            row("c", "middlebury2001", 'A', 1, 1, 9, 2, 90), row("k1", "kitti2015", 'A', 8, 9, 20, 7, 85),
            row("k2", "kitti2012", 'A', 6, 5.5, 16, 5, 88)};
  sgm::eval::summarize(r);
  ASSERT_EQ(r.sets.size(), 4u);  // sorted by name
  EXPECT_EQ(r.sets[0].name, "kitti2012");
  EXPECT_EQ(r.sets[3].name, "middlebury2006");
  EXPECT_EQ(r.sets[3].scenes, 2);
  EXPECT_DOUBLE_EQ(r.sets[3].ours, 15);
  EXPECT_DOUBLE_EQ(*r.sets[3].today, 15.5);
  EXPECT_DOUBLE_EQ(*r.sets[3].opencvStrict, 35);
  EXPECT_DOUBLE_EQ(*r.sets[3].opencvValid, 9);
  EXPECT_DOUBLE_EQ(*r.sets[3].opencvDensity, 65);
  ASSERT_EQ(r.groups.size(), 2u);
  EXPECT_EQ(r.groups[0].name, "middlebury");
  EXPECT_EQ(r.groups[0].scenes, 3);
  EXPECT_DOUBLE_EQ(r.groups[0].ours, 31.0 / 3);
  EXPECT_EQ(r.groups[1].name, "kitti");
  EXPECT_DOUBLE_EQ(r.groups[1].ours, 7);
  EXPECT_DOUBLE_EQ(*r.groups[1].today, 7.25);
  // Halves: middlebury A (a, c), middlebury B (b), kitti A (k1, k2); no kitti B.
  ASSERT_EQ(r.halves.size(), 3u);
  EXPECT_EQ(r.halves[0].name, "middlebury A");
  EXPECT_DOUBLE_EQ(r.halves[0].ours, 5.5);
  EXPECT_EQ(r.halves[1].name, "middlebury B");
  EXPECT_DOUBLE_EQ(r.halves[1].ours, 20);
  EXPECT_EQ(r.halves[2].name, "kitti A");
  // Worst regression: b +1 and k2 +0.5 -> b.
  ASSERT_TRUE(r.worstRegression.has_value());
  EXPECT_DOUBLE_EQ(*r.worstRegression, 1.0);
  EXPECT_EQ(r.worstScene, "b");
  // The JSON carries the same figures under its stable names.
  const std::string json = sgm::eval::poolJson(r);
  for (const char* key : {"\"groups\"", "\"halves\"", "\"sets\"", "\"opencv_valid\"", "\"worst_regression\"",
                          "\"measure\": \"d1\"", "\"measure\": \"bad_nonocc\"", "\"ours\": 15.000"})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

TEST(PoolMeans, MissingOpenCvOrTodayLeavesThoseMeansEmpty) {
  PoolReport r;
  r.rows = {row("a", "s", 'A', 4, 0, 0, 0, 0), row("b", "s", 'B', 6, 0, 0, 0, 0)};
  r.rows[1].opencv.reset();
  r.rows[0].today.reset(), r.rows[1].today.reset();
  sgm::eval::summarize(r);
  ASSERT_EQ(r.sets.size(), 1u);
  EXPECT_DOUBLE_EQ(r.sets[0].ours, 5);
  EXPECT_FALSE(r.sets[0].opencvStrict.has_value());  // one scene without OpenCV: no mean
  EXPECT_FALSE(r.sets[0].today.has_value());
  EXPECT_FALSE(r.worstRegression.has_value());
}

}  // namespace
