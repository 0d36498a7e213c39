// SPDX-License-Identifier: Apache-2.0
// Golden-only experiments of issue 15 (docs/algorithm.md section 12, not in the RTL):
// the gated median, per-path P1, the gated edge snap, MGM and the others below;
// the fifth path from the right, the AD term; their defaults leave the pipeline
// unchanged, and the streaming pipeline equals the staged one. Also the uniqueness
// ratio's golden rule (section 7, in the RTL since issue 15's first lever).
#include "sgm/aggregate.hpp"
#include "sgm/cli_args.hpp"
#include "sgm/cost.hpp"
#include "sgm/disparity.hpp"
#include "sgm/params.hpp"
#include "sgm/pipeline.hpp"

#include "expect_error.hpp"
#include "eval_lib.hpp"
#include "report_confidence.hpp"
#include "synthetic_scene.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using sgm::CostVolume;
using sgm::PathVolume;

// A random W x H x D cost volume (0 .. 44) and gray image, from one seed.
std::pair<CostVolume, cv::Mat> randomCostAndGray(unsigned seed, int w, int h, int nd) {
  std::mt19937 rng(seed);
  CostVolume c(w, h, nd);
  for (auto& v : c.data) v = uint8_t(rng() % 45);
  cv::Mat gray(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) gray.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  return {c, gray};
}

// A random W x H disparity map (0 .. 1023 in 1/16 px, a quarter invalid) and gray image, from one seed.
std::pair<sgm::DisparityMap, cv::Mat> randomMapAndGray(unsigned seed, int w, int h) {
  std::mt19937 rng(seed);
  sgm::DisparityMap m{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  cv::Mat gray(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      m.disp.at<uint16_t>(y, x) = uint16_t(rng() % 1024), m.valid.at<uint8_t>(y, x) = uint8_t(rng() % 4 != 0),
                             gray.at<uint8_t>(y, x) = uint8_t(rng() % 256);
  return {m, gray};
}

TEST(Experiments, OffByDefaultAndNotInAnyPreset) {
  for (const std::string& name : sgm::presetNames()) EXPECT_FALSE(sgm::presetParams(name).experimental()) << name;
  const sgm::Params p = sgm::presetParams("four-path");  // no fifth path
  sgm::Params q = p;
  q.rightPathWeight = 3;
  EXPECT_NE(q, p);
  EXPECT_EQ(sgm::presetName(q), "custom");
  EXPECT_TRUE(q.experimental());  // the fifth path over the whole row: golden-only
  q.rightPathBlock = 64;          // in blocks it is in the core (sgm_top RIGHT_BLOCK)
  EXPECT_FALSE(q.experimental());
  sgm::Params g = p;  // the gated median and per-path P1: golden-only
  g.medianGate = 32;
  EXPECT_TRUE(g.experimental());
  g = p;  // the narrower stored Lr: golden-only
  g.lrStoreBits = 8;
  EXPECT_TRUE(g.experimental());
  g = p;
  g.p1PathPercent[2] = 200;
  EXPECT_TRUE(g.experimental());
  g = p;  // the gated edge snap: golden-only
  g.snapEdge = 96;
  EXPECT_TRUE(g.experimental());
  g = p;  // the path restart at strong edges is in the core (sgm_top EDGE_RESET): not an experiment
  g.edgeReset = sgm::EdgeReset{48, 3, {0, 0, 0, 1, 1}};
  EXPECT_FALSE(g.experimental());
  EXPECT_NE(g, p);
  g.edgeReset.threshold = 0;  // off
  EXPECT_FALSE(g.experimental());
  sgm::Params u = p;  // the uniqueness ratio and the AD term are in the core: not experiments
  u.uniqueness = 15, u.adWeight = 3;
  EXPECT_FALSE(u.experimental());
  EXPECT_EQ(sgm::presetName(u), "custom");
}

// The fifth path on a row is the 0-degree path (left to right) of the mirrored row.
TEST(RightPath, IsTheMirroredLeftPath) {
  std::mt19937 rng(5);
  const int w = 37, nd = 12, p1 = 9, p2 = 120;
  CostVolume c(w, 1, nd), mirrored(w, 1, nd);
  cv::Mat gray(1, w, CV_8UC1), grayMirrored(1, w, CV_8UC1);
  for (int x = 0; x < w; ++x) {
    gray.at<uint8_t>(0, x) = uint8_t(rng() % 256);
    grayMirrored.at<uint8_t>(0, w - 1 - x) = gray.at<uint8_t>(0, x);
    for (int d = 0; d < nd; ++d) c.at(x, 0)[d] = mirrored.at(w - 1 - x, 0)[d] = uint8_t(rng() % 45);
  }
  const sgm::P2Table table = sgm::makeP2Table(p1, p2);
  std::vector<uint16_t> sum(size_t(w) * nd, 7);  // the path is added to what is there
  sgm::addRightPath(c.at(0, 0), gray.ptr<uint8_t>(0), w, nd, p1, table, 2, sum.data());
  const PathVolume left = sgm::pathCost(mirrored, grayMirrored, 0, p1, p2);
  for (int x = 0; x < w; ++x)
    for (int d = 0; d < nd; ++d)
      ASSERT_EQ(sum[size_t(x) * nd + d], 7 + 2 * left.at(w - 1 - x, 0)[d]) << "x " << x << " d " << d;
}

// In blocks of B: block [x0, x0 + B) holds the whole-row path of the row cut at
// x0 + 2B (its first pixel beyond the block's look-ahead), i.e. the path started at
// x0 + 2B - 1; a block at least as wide as the row is the whole row.
TEST(RightPath, BlocksAreTheRowCutOneBlockAhead) {
  std::mt19937 rng(11);
  const int w = 41, nd = 8, p1 = 7, p2 = 110;
  CostVolume c(w, 1, nd);
  for (auto& v : c.data) v = uint8_t(rng() % 45);
  cv::Mat gray(1, w, CV_8UC1);
  for (int x = 0; x < w; ++x) gray.at<uint8_t>(0, x) = uint8_t(rng() % 256);
  const sgm::P2Table table = sgm::makeP2Table(p1, p2);
  for (const int block : {1, 3, 8, 20, 41, 64}) {
    std::vector<uint16_t> sum(size_t(w) * nd, 0);
    sgm::addRightPath(c.at(0, 0), gray.ptr<uint8_t>(0), w, nd, p1, table, 1, sum.data(), block);
    for (int x0 = 0; x0 < w; x0 += block) {
      const int cut = std::min(w, x0 + 2 * block);  // the row as the block's path sees it
      std::vector<uint16_t> whole(size_t(cut) * nd, 0);
      sgm::addRightPath(c.at(0, 0), gray.ptr<uint8_t>(0), cut, nd, p1, table, 1, whole.data());
      for (int x = x0; x < std::min(w, x0 + block); ++x)
        for (int d = 0; d < nd; ++d)
          ASSERT_EQ(sum[size_t(x) * nd + d], whole[size_t(x) * nd + d])
              << "block " << block << " x " << x << " d " << d;
    }
  }
  std::vector<uint16_t> row(size_t(w) * nd, 0), wide(size_t(w) * nd, 0);
  sgm::addRightPath(c.at(0, 0), gray.ptr<uint8_t>(0), w, nd, p1, table, 1, row.data());
  sgm::addRightPath(c.at(0, 0), gray.ptr<uint8_t>(0), w, nd, p1, table, 1, wide.data(), w);
  EXPECT_EQ(row, wide);
}

TEST(RightPath, AggregateAddsItToTheFourPaths) {
  const int w = 30, h = 7, nd = 10, p1 = 8, p2 = 90;
  const std::pair<CostVolume, cv::Mat> scene = randomCostAndGray(9, w, h, nd);
  const CostVolume& c = scene.first;
  const cv::Mat& gray = scene.second;
  const PathVolume four = sgm::aggregateCost(c, gray, p1, p2);
  const PathVolume five = sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 3);
  const sgm::P2Table table = sgm::makeP2Table(p1, p2);
  for (int y = 0; y < h; ++y) {
    std::vector<uint16_t> row(four.at(0, y), four.at(0, y) + size_t(w) * nd);
    sgm::addRightPath(c.at(0, y), gray.ptr<uint8_t>(y), w, nd, p1, table, 3, row.data());
    for (int i = 0; i < w * nd; ++i) ASSERT_EQ(five.at(0, y)[i], row[size_t(i)]) << "y " << y << " i " << i;
  }
}

// The path restart at strong edges (Params::edgeReset, a default; in the core with
// EDGE_RESET = 1) against a direct reading of its definition: pixel p of a marked path
// starts again (Lr = C) when one of the steps p - k r -> p - (k + 1) r, k = 0 .. R - 1,
// both ends inside the path, crosses a gray step of at least T; otherwise eq. (1). Each
// path, the fifth over the row and in blocks.
TEST(EdgeReset, MatchesItsDefinitionOnEveryPath) {
  const int w = 29, h = 9, nd = 7, p1 = 8, p2 = 90, threshold = 48, length = 3;
  std::mt19937 rng(21);
  CostVolume c(w, h, nd);
  for (auto& v : c.data) v = uint8_t(rng() % 45);
  cv::Mat gray(h, w, CV_8UC1);  // weak texture (steps 0 .. 16), one pixel in six raised by 48: steps 32 .. 64
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) gray.at<uint8_t>(y, x) = uint8_t(8 * (rng() % 3) + (rng() % 6 == 0 ? threshold : 0));
  const sgm::P2Table table = sgm::makeP2Table(p1, p2);
  const auto dI = [&](int ax, int ay, int bx, int by) {
    return std::abs(int(gray.at<uint8_t>(ay, ax)) - int(gray.at<uint8_t>(by, bx)));
  };
  // Lr of forward path i over the image, restarting or not.
  const auto forward = [&](int i, bool restart) {
    const sgm::PathDirection r = sgm::kPathDirections[i];
    PathVolume lr(w, h, nd);
    std::vector<uint16_t> prev(size_t(nd) + 2, sgm::kPathSentinel);
    std::vector<uint16_t> mins(size_t(w) * h, 0);
    const auto inside = [&](int x, int y) { return x >= 0 && x < w && y >= 0 && y < h; };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int px = x + r.dx, py = y + r.dy;
        bool edge = false;
        for (int k = 0; k < length && restart; ++k) {
          const int ax = x + k * r.dx, ay = y + k * r.dy;
          if (!inside(ax + r.dx, ay + r.dy)) break;
          edge = edge || dI(ax, ay, ax + r.dx, ay + r.dy) >= threshold;
        }
        uint16_t* out = lr.at(x, y);
        if (!inside(px, py) || edge) {
          mins[size_t(y) * w + x] = sgm::pathStart(c.at(x, y), nd, out);
          continue;
        }
        std::copy_n(lr.at(px, py), nd, prev.data() + 1);
        mins[size_t(y) * w + x] = sgm::pathStep(c.at(x, y), prev.data() + 1, mins[size_t(py) * w + px], nd, p1,
                                                table[size_t(dI(x, y, px, py))], out);
      }
    return lr;
  };
  // Lr of the fifth path on row y over [x0, x1), started at `start` (>= x1 - 1).
  const auto fifth = [&](int y, int x0, int start, bool restart, PathVolume& into) {
    std::vector<uint16_t> prev(size_t(nd) + 2, sgm::kPathSentinel), cur(size_t(nd) + 2, sgm::kPathSentinel);
    uint16_t minPrev = 0;
    for (int x = start; x >= x0; --x) {
      bool edge = false;
      for (int k = 0; k < length && restart && x + k + 1 <= start; ++k)
        edge = edge || dI(x + k, y, x + k + 1, y) >= threshold;
      const uint16_t m = x == start || edge ? sgm::pathStart(c.at(x, y), nd, cur.data() + 1)
                                            : sgm::pathStep(c.at(x, y), prev.data() + 1, minPrev, nd, p1,
                                                            table[size_t(dI(x, y, x + 1, y))], cur.data() + 1);
      std::copy_n(cur.data() + 1, nd, into.at(x, y));
      std::swap(prev, cur), minPrev = m;
    }
  };
  int restarted = 0;
  for (const std::array<int, 5> paths :
       {std::array<int, 5>{1, 1, 1, 1, 1}, std::array<int, 5>{0, 1, 0, 1, 0}, std::array<int, 5>{1, 0, 1, 0, 1}})
    for (const int block : {0, 4}) {
      sgm::EdgeReset reset;
      reset.threshold = threshold, reset.length = length, reset.paths = paths;
      const PathVolume s = sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 2, false,
                                              block, nullptr, reset);
      PathVolume expected(w, h, nd), l5(w, h, nd);
      const int* weight = sgm::pathWeights(sgm::PathWeighting::k3232);
      for (int i = 0; i < sgm::kPathCount; ++i) {
        const PathVolume l = forward(i, paths[size_t(i)] != 0);
        restarted += l.data != forward(i, false).data;
        for (size_t j = 0; j < l.data.size(); ++j)
          expected.data[j] = uint16_t(expected.data[j] + weight[i] * l.data[j]);
      }
      for (int y = 0; y < h; ++y) {
        // Blocks [jB, (j + 1)B), the last one [(m - 1)B, W); each block's pass starts one block to its right.
        const int span = block ? block : w, blocks = std::max(1, w / span);
        for (int j = 0; j < blocks; ++j) {
          const bool last = j == blocks - 1;
          PathVolume pass(w, h, nd);
          fifth(y, j * span, last ? w - 1 : j * span + 2 * span - 1, paths[4] != 0, pass);
          for (int x = j * span; x < (last ? w : j * span + span); ++x) std::copy_n(pass.at(x, y), nd, l5.at(x, y));
        }
      }
      for (size_t j = 0; j < l5.data.size(); ++j) expected.data[j] = uint16_t(expected.data[j] + 2 * l5.data[j]);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          for (int d = 0; d < nd; ++d)
            ASSERT_EQ(s.at(x, y)[d], expected.at(x, y)[d])
                << "paths " << paths[0] << paths[1] << paths[2] << paths[3] << paths[4] << " block " << block
                << " (x, y) (" << x << ", " << y << ") d " << d;
    }
  EXPECT_GT(restarted, 0);  // the scene has strong steps: the restart changes the paths
  // Off (threshold 0) is the plain aggregation whatever the other fields say.
  sgm::EdgeReset off;
  off.length = 7;
  EXPECT_EQ(
      sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 2, false, 4, nullptr, off)
          .data,
      sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 2, false, 4).data);
}

// MGM on a 2 x 2 volume with D = 1: every step term is 0 (one disparity), so Lr = C
// wherever a neighbour exists; with D = 2 the averaging shows.
TEST(Mgm, HandExampleTwoByTwo) {
  // D = 2, P1 = 10, P2 = 100 (gray flat: P2r = 100). C(x, y) = {c0, c1}:
  //   (0,0) {0, 20}   (1,0) {30, 0}
  //   (0,1) {5, 5}    (1,1) {0, 40}
  CostVolume c(2, 2, 2);
  const int costs[2][2][2] = {{{0, 20}, {30, 0}}, {{5, 5}, {0, 40}}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int d = 0; d < 2; ++d) c.at(x, y)[d] = uint8_t(costs[y][x][d]);
  const cv::Mat gray(2, 2, CV_8UC1, cv::Scalar(50));
  const PathVolume s = sgm::aggregateCost(c, gray, 10, 100, sgm::P2Mode::kKnee, sgm::PathWeighting::kEqual, 0, true);
  // Path 0 (left, perpendicular above): (0,0) start {0,20}; (1,0) left only: prev {0,20}, min 0:
  //   t = {min(0, 20+10), min(20, 0+10)} = {0, 10} -> {30, 10}. (0,1) above only: prev {0,20} -> {5, 15}.
  //   (1,1): left (0,1) {5,15} min 5: t = {0, min(15, 15)-5 = 10}... = {min(5,25)-5, min(15,15)-5} = {0, 10};
  //   above (1,0) {30,10} min 10: t = {min(30, 20)-10, min(10, 40)-10} = {10, 0}; mean {5, 5} -> {5, 45}.
  // Path 90 (above, perpendicular left) is the same pair of neighbours at (1,1): {5, 45}; at (1,0) it has the
  // left neighbour only: {30, 10}; at (0,1) above only: {5, 15}.
  // Path 45 (above-left, perpendicular above-right): (1,1) above-left (0,0) {0,20} min 0: t = {0, 10};
  //   above-right (2,0) outside -> {0, 50}. (0,1): above-right (1,0) {30, 0} (its own start) min 0:
  //   t = {min(30, 10), 0} = {10, 0} -> {15, 5}. (1,0): both outside -> start {30, 0}.
  // Path 135 (above-right, perpendicular above-left): (0,1) above-right (1,0) start {30,0}: t {10, 0} -> {15, 5};
  //   (1,1): above-right outside, above-left (0,0) {0,20}: {0, 10} -> {0, 50}. (1,0): left-above outside... start.
  // Sum at (1,1) over the four (equal weights): {5+0+5+0, 45+50+45+50} = {10, 190}.
  EXPECT_EQ(s.at(1, 1)[0], 10);
  EXPECT_EQ(s.at(1, 1)[1], 190);
  // At (0,0) every path starts: 4 C.
  EXPECT_EQ(s.at(0, 0)[0], 0);
  EXPECT_EQ(s.at(0, 0)[1], 80);
}

TEST(Uniqueness, HandCases) {
  // Winner d = 2 (cost 100); its neighbours d = 1, 3 never count as rivals.
  const uint16_t s[] = {200, 101, 100, 101, 120, 111};
  EXPECT_FALSE(sgm::isUnique(s, 6, 2, 10));  // d = 5: 111 * 90 = 9990 < 100 * 100
  EXPECT_TRUE(sgm::isUnique(s, 6, 2, 5));    // 111 * 95 = 10545, 120 * 95 = 11400: unique
  EXPECT_TRUE(sgm::isUnique(s, 6, 2, 0));    // ratio 0: only a strictly smaller cost is a rival
  const uint16_t tie[] = {100, 300, 100};
  EXPECT_TRUE(sgm::isUnique(tie, 3, 0, 0));
  EXPECT_FALSE(sgm::isUnique(tie, 3, 0, 1));  // 100 * 99 < 100 * 100
}

TEST(LinearSubpixel, HandCases) {
  // a = 20, m = 10, b = 30: V fit (20 - 30) / (2 (30 - 10)) = -0.25 px = -4/16.
  EXPECT_EQ(sgm::subpixelOffsetLinear(20, 10, 30), -4);
  EXPECT_EQ(sgm::subpixelOffsetLinear(30, 10, 20), 4);
  EXPECT_EQ(sgm::subpixelOffsetLinear(10, 10, 30), -8);  // a = m: half a pixel
  EXPECT_EQ(sgm::subpixelOffsetLinear(25, 10, 25), 0);
  EXPECT_EQ(sgm::subpixelOffsetLinear(10, 10, 10), 0);  // flat: no offset
  // V: (13 - 10) / (2 * 13) * 16 = 1.85 -> 2; the parabola: (13 - 10) / (2 * 23) * 16 = 1.04 -> 1.
  EXPECT_EQ(sgm::subpixelOffsetLinear(13, 0, 10), 2);
  EXPECT_EQ(sgm::subpixelOffset(13, 0, 10), 1);
}

TEST(AdTerm, HandRow) {
  // Left row 10 50 90, right row 10 20 30; D = 3, weight 8 (x 1), cap 20.
  const cv::Mat gl = (cv::Mat_<uint8_t>(1, 3) << 10, 50, 90), gr = (cv::Mat_<uint8_t>(1, 3) << 10, 20, 30);
  std::vector<uint8_t> row(9, 5);
  sgm::addAdTerm(gl, gr, 0, 0, 3, 3, 8, 20, row.data());
  // x=0: d0 |10-10| = 0; d1, d2 outside: cap 20. x=1: |50-20| -> 20, |50-10| -> 20, outside 20.
  // x=2: |90-30|, |90-20|, |90-10| -> 20 each.
  EXPECT_EQ(row, (std::vector<uint8_t>{5, 25, 25, 25, 25, 25, 25, 25, 25}));
  std::vector<uint8_t> half(9, 0);
  const cv::Mat gr2 = (cv::Mat_<uint8_t>(1, 3) << 13, 47, 90);
  sgm::addAdTerm(gl, gr2, 0, 1, 3, 3, 4, 20, half.data());  // x0 = 1: pixel 0 untouched; weight 4 = x 1/2
  // x=1: |50-47| = 3 -> 1, |50-13| -> 20 -> 10, outside -> 10. x=2: 0, |90-47| -> 10, |90-13| -> 10.
  EXPECT_EQ(half, (std::vector<uint8_t>{0, 0, 0, 1, 10, 10, 0, 10, 10}));
}

TEST(Experiments, StreamingPipelineEqualsStagesAndChangesTheResult) {
  const sgm::eval::Scene scene = sgm::synth::toEvalScene(sgm::synth::makeSyntheticScene(96, 48, 14, 3), "s");
  sgm::Params p;
  p.disparities = 16;
  const sgm::DisparityMap today = sgm::runPipeline(scene.left, scene.right, p);
  p.rightPathWeight = 3, p.uniqueness = 15, p.adWeight = 8, p.adCap = 16, p.linearSubpixel = true, p.mgm = true;
  p.edgeReset.threshold = 0;  // MGM does not combine with the path restart
  const sgm::DisparityMap streamed = sgm::runPipeline(scene.left, scene.right, p);
  const sgm::PipelineStages staged = sgm::runPipelineStages(scene.left, scene.right, p);
  EXPECT_EQ(cv::countNonZero(streamed.disp != staged.result.disp), 0);
  EXPECT_EQ(cv::countNonZero(streamed.valid != staged.result.valid), 0);
  EXPECT_GT(cv::countNonZero(streamed.disp != today.disp) + cv::countNonZero(streamed.valid != today.valid), 0);
  p.rightPathBlock = 2;  // the blocks of the fifth path, streamed and staged alike
  const sgm::DisparityMap blocks = sgm::runPipeline(scene.left, scene.right, p);
  const sgm::PipelineStages blocksStaged = sgm::runPipelineStages(scene.left, scene.right, p);
  EXPECT_EQ(cv::countNonZero(blocks.disp != blocksStaged.result.disp), 0);
  EXPECT_EQ(cv::countNonZero(blocks.valid != blocksStaged.result.valid), 0);
  EXPECT_GT(cv::countNonZero(blocks.disp != streamed.disp) + cv::countNonZero(blocks.valid != streamed.valid), 0);
}

// The gated median: a window pixel counts only within `gate` gray levels of the centre.
TEST(MedianGate, HandWindowAndWideGateIsThePlainMedian) {
  const int w = 9, h = 9;
  sgm::DisparityMap in{cv::Mat(h, w, CV_16UC1, cv::Scalar(16)), cv::Mat(h, w, CV_8UC1, cv::Scalar(1))};
  cv::Mat gray(h, w, CV_8UC1, cv::Scalar(100));
  // Centre (4, 4) on a bright 2 x 3 patch (disparity 48) inside a dark field (16): the plain
  // median sees 6 of 25 at 48 and gives 16; gated at 10 it sees the patch only.
  for (int y = 3; y <= 4; ++y)
    for (int x = 3; x <= 5; ++x) in.disp.at<uint16_t>(y, x) = 48, gray.at<uint8_t>(y, x) = 200;
  EXPECT_EQ(sgm::median5x5(in).disp.at<uint16_t>(4, 4), 16);
  EXPECT_EQ(sgm::median5x5(in, gray, 255).disp.at<uint16_t>(4, 4), 16);  // 255: every pixel counts
  EXPECT_EQ(sgm::median5x5(in, gray, 10).disp.at<uint16_t>(4, 4), 48);
  EXPECT_EQ(sgm::median5x5(in, gray, 100).disp.at<uint16_t>(4, 4), 16);  // |200 - 100| = 100 counts
  EXPECT_EQ(sgm::median5x5(in, gray, 99).disp.at<uint16_t>(4, 4), 48);   // ... and 99 does not
  EXPECT_EQ(sgm::median5x5(in, gray, 10).disp.at<uint16_t>(1, 1), 16);   // the dark field: unchanged
  // A wide gate is the plain median on a random map.
  const auto [r, rg] = randomMapAndGray(3, 41, 23);
  EXPECT_EQ(cv::countNonZero(sgm::median5x5(r).disp != sgm::median5x5(r, rg, 255).disp), 0);
  EXPECT_GT(cv::countNonZero(sgm::median5x5(r).disp != sgm::median5x5(r, rg, 20).disp), 0);
}

// Per-path P1: 100 % everywhere is the plain aggregation; a path's own P1 changes only that path.
TEST(P1PerPath, HundredIsPlainAndOnePathScalesItsOwnP1) {
  const int w = 26, h = 6, nd = 9, p1 = 10, p2 = 90;
  const std::pair<CostVolume, cv::Mat> scene = randomCostAndGray(11, w, h, nd);
  const CostVolume& c = scene.first;
  const cv::Mat& gray = scene.second;
  const int hundred[5] = {100, 100, 100, 100, 100}, vertical[5] = {100, 100, 250, 100, 100};
  const auto sum = [&](const int* percent) {
    return sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 0, false, 0, percent);
  };
  const PathVolume plain = sgm::aggregateCost(c, gray, p1, p2), same = sum(hundred), scaled = sum(vertical);
  EXPECT_EQ(plain.data, same.data);
  // S with the vertical path at P1 25 = S - 3 L(90 deg, P1 10) + 3 L(90 deg, P1 25).
  const PathVolume l10 = sgm::pathCost(c, gray, 2, p1, p2), l25 = sgm::pathCost(c, gray, 2, 25, p2);
  for (size_t i = 0; i < plain.data.size(); ++i)
    ASSERT_EQ(scaled.data[i], plain.data[i] - 3 * l10.data[i] + 3 * l25.data[i]) << "i " << i;
}

// The gated edge snap: a drop snaps only when its strongest intensity step reaches the gate;
// gate 0 is the plain snap (docs/algorithm.md section 8b).
TEST(SnapEdge, GateLeavesWeakEdgesAndZeroIsThePlainSnap) {
  const int w = 8;
  sgm::DisparityMap in{cv::Mat(2, w, CV_16UC1), cv::Mat(2, w, CV_8UC1, cv::Scalar(1))};
  cv::Mat gray(2, w, CV_8UC1);
  const int d[w] = {640, 640, 640, 640, 640, 640, 160, 160};   // a drop between x = 5 and 6
  const int steps[2][w] = {{10, 10, 10, 90, 90, 90, 90, 90},   // strongest step 80 at k = 3
                           {10, 10, 10, 10, 10, 10, 10, 10}};  // no step: the edge stays at k = 6
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < w; ++x)
      in.disp.at<uint16_t>(y, x) = uint16_t(d[x]), gray.at<uint8_t>(y, x) = uint8_t(steps[y][x]);
  const auto row0 = [](const sgm::DisparityMap& m) {
    std::vector<int> v;
    for (int x = 0; x < m.disp.cols; ++x) v.push_back(m.disp.at<uint16_t>(0, x));
    return v;
  };
  const std::vector<int> snapped = {640, 640, 640, 160, 160, 160, 160, 160}, kept(d, d + w);
  EXPECT_EQ(row0(sgm::snapEdges(in, gray, 80)), snapped);  // step 80 reaches a gate of 80
  EXPECT_EQ(row0(sgm::snapEdges(in, gray, 81)), kept);     // ... not one of 81
  EXPECT_EQ(row0(sgm::snapEdges(in, gray, 0)), snapped);
  // Gate 0 is the plain snap on a random map; a high gate leaves some drops alone.
  const auto [r, rg] = randomMapAndGray(5, 45, 17);
  EXPECT_EQ(cv::countNonZero(sgm::snapEdges(r, rg).disp != sgm::snapEdges(r, rg, 0).disp), 0);
  EXPECT_GT(cv::countNonZero(sgm::snapEdges(r, rg).disp != sgm::snapEdges(r, rg, 200).disp), 0);
}

// The pipeline options of a command line (the program name first).
sgm::CliArgs pipelineCli(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return sgm::CliArgs(int(argv.size()), argv.data(), sgm::CliArgs::pipelineOptions());
}

// The narrower stored Lr: the 45/90/135-degree paths read the row above's Lr - min Lr saturated
// at 2^N - 1; exact from 2^N - 1 >= P2' on.
TEST(LrStoreBits, MatchesItsDefinitionAndWideIsTheWholeLr) {
  const int w = 23, h = 7, nd = 9, p1 = 10, p2 = 120;
  std::mt19937 rng(5);
  CostVolume c(w, h, nd);
  for (auto& v : c.data) v = uint8_t(rng() % 60);
  cv::Mat gray(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) gray.at<uint8_t>(y, x) = uint8_t(rng() % 64);
  const sgm::P2Table table = sgm::makeP2Table(p1, p2);
  const auto reference = [&](int bits) {
    const uint16_t cap = uint16_t((1 << bits) - 1);
    PathVolume sum(w, h, nd);
    const int weights[sgm::kPathCount] = {3, 2, 3, 2};
    for (int i = 0; i < sgm::kPathCount; ++i) {
      const sgm::PathDirection r = sgm::kPathDirections[i];
      PathVolume lr(w, h, nd);
      std::vector<uint16_t> mins(size_t(w) * h, 0), prev(size_t(nd) + 2, sgm::kPathSentinel);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int px = x + r.dx, py = y + r.dy;
          uint16_t& m = mins[size_t(y) * w + x];
          if (px < 0 || px >= w || py < 0) {
            m = sgm::pathStart(c.at(x, y), nd, lr.at(x, y));
          } else {
            const bool stored = r.dy != 0;
            const uint16_t minPrev = mins[size_t(py) * w + px];
            for (int d = 0; d < nd; ++d) {
              const uint16_t v = lr.at(px, py)[d];
              prev[size_t(d) + 1] = stored ? uint16_t(minPrev + std::min<int>(v - minPrev, cap)) : v;
            }
            const int dI = std::abs(int(gray.at<uint8_t>(y, x)) - int(gray.at<uint8_t>(py, px)));
            m = sgm::pathStep(c.at(x, y), prev.data() + 1, minPrev, nd, p1, table[dI], lr.at(x, y));
          }
          for (int d = 0; d < nd; ++d) sum.at(x, y)[d] = uint16_t(sum.at(x, y)[d] + weights[i] * lr.at(x, y)[d]);
        }
    }
    return sum;
  };
  const auto aggregate = [&](int bits) {
    return sgm::aggregateCost(c, gray, p1, p2, sgm::P2Mode::kKnee, sgm::PathWeighting::k3232, 0, false, 0, nullptr,
                              sgm::EdgeReset{}, bits);
  };
  const PathVolume whole = aggregate(0);
  EXPECT_EQ(aggregate(7).data, whole.data);  // 127 >= P2' = 120: exact
  for (int bits : {4, 5, 6}) {
    SCOPED_TRACE(bits);
    const PathVolume narrow = aggregate(bits);
    EXPECT_EQ(narrow.data, reference(bits).data);
    EXPECT_NE(narrow.data, whole.data);
  }
  const sgm::CliArgs cli = pipelineCli({"prog", "--lr-store-bits", "3"});
  expectError([&] { cli.pipelineParams().validate(); }, {"stored Lr bits 3 out of range"});
}

// The confidence map: the same from the streaming pipeline and the staged one.
TEST(Confidence, StreamingEqualsStagesAndRanksTheErrors) {
  const sgm::eval::Scene scene = sgm::synth::toEvalScene(sgm::synth::makeSyntheticScene(96, 48, 14, 3), "s");
  sgm::Params p;
  p.disparities = 16;
  cv::Mat streamed;
  sgm::runPipeline(scene.left, scene.right, p, &streamed);
  const sgm::PipelineStages staged = sgm::runPipelineStages(scene.left, scene.right, p);
  ASSERT_FALSE(streamed.empty());
  EXPECT_EQ(cv::countNonZero(streamed != staged.confidence), 0);
  EXPECT_EQ(cv::countNonZero(staged.confidence & (staged.selected.valid == 0)), 0);  // 0 where invalid
  EXPECT_GT(cv::countNonZero(staged.confidence), 0);
}

// Params::outputConfidence: the map carries the selection's confidence through the fill, the
// snap and the median unchanged (the core's bits 23:16), from either pipeline; without it the
// streaming pipeline computes none.
TEST(Confidence, TheMapCarriesItUnchangedWithOutputConfidence) {
  const sgm::eval::Scene scene = sgm::synth::toEvalScene(sgm::synth::makeSyntheticScene(96, 48, 14, 5), "s");
  sgm::Params p;
  p.disparities = 16, p.snap = true;
  EXPECT_TRUE(sgm::runPipeline(scene.left, scene.right, p).confidence.empty());
  p.outputConfidence = true;
  EXPECT_EQ(sgm::presetName(p), "custom");  // snap on; the confidence changes no preset
  cv::Mat selected;
  const sgm::DisparityMap map = sgm::runPipeline(scene.left, scene.right, p, &selected);
  const sgm::PipelineStages staged = sgm::runPipelineStages(scene.left, scene.right, p);
  ASSERT_EQ(map.confidence.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(map.confidence != selected), 0);
  EXPECT_EQ(cv::countNonZero(staged.result.confidence != staged.confidence), 0);
  EXPECT_GT(cv::countNonZero(map.valid != staged.selected.valid), 0);  // the fill changed validity, not it
  sgm::Params plain;
  plain.disparities = 16, plain.outputConfidence = true;
  EXPECT_EQ(sgm::presetName(plain), "default");
}

TEST(Confidence, ErrorOfTheMostConfidentSharesTies) {
  // Confidences 9, 9, 5, 5, 5, 5, 1, 1; errors 0, 0, 1, 0, 0, 0, 1, 1.
  const std::vector<uint8_t> c = {9, 5, 1, 5, 9, 5, 1, 5}, e = {0, 1, 1, 0, 0, 0, 1, 0};
  EXPECT_DOUBLE_EQ(sgm::eval::errorOfMostConfident(c, e, 0.25), 0);
  // Half: both 9s and two of the four 5s (a quarter of them wrong): 0.5 errors in 4.
  EXPECT_DOUBLE_EQ(sgm::eval::errorOfMostConfident(c, e, 0.5), 100.0 * 0.5 / 4);
  EXPECT_DOUBLE_EQ(sgm::eval::errorOfMostConfident(c, e, 1.0), 100.0 * 3 / 8);
  EXPECT_DOUBLE_EQ(sgm::eval::errorOfMostConfident({}, {}, 0.5), 0);
}

// The minimum disparity (section 3): left x against right x - dmin - d, the output the true disparity.
TEST(MinDisparity, SearchesFromDminAndGivesTheTrueDisparity) {
  const sgm::synth::SyntheticScene base = sgm::synth::makeSyntheticScene(128, 64, 12, 9);
  const int shift = 10;  // every true disparity + 10: 10 .. 22
  cv::Mat right(base.right.size(), CV_8UC1);
  for (int y = 0; y < right.rows; ++y)
    for (int x = 0; x < right.cols; ++x) right.at<uint8_t>(y, x) = base.right.at<uint8_t>(y, std::min(127, x + shift));
  sgm::Params p;
  p.disparities = 16;
  p.minDisparity = shift;
  const sgm::PipelineStages staged = sgm::runPipelineStages(base.left, right, p);
  const sgm::DisparityMap streamed = sgm::runPipeline(base.left, right, p);
  EXPECT_EQ(cv::countNonZero(streamed.disp != staged.result.disp), 0);
  EXPECT_EQ(cv::countNonZero(streamed.valid != staged.result.valid), 0);
  // C(x, d) is the cost of a search over dmin + D at dmin + d (Cmax and the AD term's largest outside).
  sgm::Params wideParams = p;
  wideParams.minDisparity = 0, wideParams.disparities = shift + 16;
  const sgm::PipelineStages wide = sgm::runPipelineStages(base.left, right, wideParams);
  for (int y = 0; y < 64; y += 7)
    for (int x = 0; x < 128; x += 3)
      for (int d = 0; d < 16; ++d) ASSERT_EQ(staged.cost.at(x, y)[d], wide.cost.at(x, y)[shift + d]) << x << "," << y;
  // The selection (LR check on) has no pixel whose match x - dmin - d leaves the image.
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < shift; ++x) EXPECT_EQ(staged.selected.valid.at<uint8_t>(y, x), 0) << x << "," << y;
  // Against the ground truth (3 px; the scene's slants and noise make bad-1 high everywhere): dmin = 10
  // on the shifted pair does as well as dmin = 0 on the original one; dmin = 0 (0 .. 15) cannot.
  const auto bad = [&](const sgm::DisparityMap& m, int gtShift) {
    int wrong = 0, counted = 0;
    for (int y = 4; y < 60; ++y)
      for (int x = 32; x < 118; ++x) {
        if (!base.nonocc.at<uint8_t>(y, x)) continue;
        ++counted;
        const float d = m.valid.at<uint8_t>(y, x) ? m.disp.at<uint16_t>(y, x) / 16.f : -1.f;
        wrong += std::abs(d - (base.gt.at<float>(y, x) + gtShift)) > 3;
      }
    return 100.0 * wrong / counted;
  };
  sgm::Params zero = p;
  zero.minDisparity = 0;
  const double original = bad(sgm::runPipeline(base.left, base.right, zero), 0);
  const double found = bad(streamed, shift), missed = bad(sgm::runPipeline(base.left, right, zero), shift);
  EXPECT_NEAR(found, original, 2.0);
  EXPECT_GT(missed, found + 20.0);
  std::cout << "[ figures  ] error (3 px) on the original pair: " << original << " %; shifted by " << shift << ": dmin "
            << shift << " " << found << " %, dmin 0 " << missed << " %\n";
}

TEST(Experiments, OptionsAndRanges) {
  const sgm::Params p = pipelineCli({"prog", "--right-path", "3", "--right-block", "48", "--uniqueness", "10",
                                     "--ad-weight", "8", "--ad-cap", "16", "--subpixel-fit", "linear"})
                            .pipelineParams();
  EXPECT_EQ(p.rightPathWeight, 3);
  EXPECT_EQ(p.rightPathBlock, 48);
  EXPECT_EQ(p.uniqueness, 10);
  EXPECT_EQ(p.adWeight, 8);
  EXPECT_EQ(p.adCap, 16);
  EXPECT_TRUE(p.linearSubpixel);
  EXPECT_FALSE(p.mgm);
  const sgm::Params q = pipelineCli(
                            {"prog", "--median-gate", "40", "--p1-paths", "200,100,150,50,100", "--snap-edge", "96"})
                            .pipelineParams();
  EXPECT_EQ(q.medianGate, 40);
  EXPECT_EQ(q.snapEdge, 96);
  EXPECT_EQ(q.p1PathPercent, (std::array<int, 5>{200, 100, 150, 50, 100}));
  EXPECT_EQ(q.pathP1(0), 48);
  EXPECT_EQ(q.pathP1(3), 12);
  for (const char* list : {"200,100,150,50", "200,100,150,50,100,1", "200,,150,50,100", "20,100,100,100,100", "x"}) {
    const sgm::CliArgs cli = pipelineCli({"prog", "--p1-paths", list});
    expectError([&] { cli.pipelineParams(); }, {"--p1-paths expects five percentages"});
  }
  const sgm::Params e = pipelineCli(
                            {"prog", "--edge-reset", "48", "--edge-reset-len", "4", "--edge-reset-paths", "0,0,0,1,1"})
                            .pipelineParams();
  EXPECT_EQ(e.edgeReset.threshold, 48);
  EXPECT_EQ(e.edgeReset.length, 4);
  EXPECT_EQ(e.edgeReset.paths, (std::array<int, 5>{0, 0, 0, 1, 1}));
  EXPECT_TRUE(e.edgeReset.on(3));
  EXPECT_FALSE(e.edgeReset.on(0));
  for (const char* list : {"0,0,0,1", "0,0,0,1,1,1", "0,2,0,1,1", "1,,1,1,1"}) {
    const sgm::CliArgs cli = pipelineCli({"prog", "--edge-reset-paths", list});
    expectError([&] { cli.pipelineParams(); }, {"--edge-reset-paths expects five flags 0..1"});
  }
  sgm::Params bad;
  bad.edgeReset.threshold = 256;
  expectError([&] { bad.validate(); }, {"edge reset 256"});
  bad = sgm::Params{};
  bad.edgeReset.length = 0;
  expectError([&] { bad.validate(); }, {"edge reset length 0"});
  bad = sgm::Params{};
  bad.edgeReset.paths[2] = 2;
  expectError([&] { bad.validate(); }, {"edge reset paths"});
  bad = sgm::Params{};
  bad.edgeReset.threshold = 48, bad.mgm = true;
  expectError([&] { bad.validate(); }, {"does not combine with --mgm"});
  bad = sgm::Params{};
  bad.p2 = 50, bad.p1PathPercent[4] = 300;  // P1 24 * 3 = 72 > P2' 50
  expectError([&] { bad.validate(); }, {"P1 of path 4"});
  bad = sgm::Params{};
  bad.rightPathWeight = sgm::kMaxRightPathWeight + 1;
  expectError([&] { bad.validate(); }, {"right-path"});
  bad = sgm::Params{};
  bad.rightPathBlock = sgm::kMaxRightPathBlock + 1;
  expectError([&] { bad.validate(); }, {"right-path block"});
  bad = sgm::Params{};
  bad.snapEdge = 256;
  expectError([&] { bad.validate(); }, {"snap edge 256"});
  bad = sgm::Params{};
  bad.adWeight = 16;
  expectError([&] { bad.validate(); }, {"AD term weight 16", "out of range 0..15"});
  bad = sgm::Params{};
  bad.adWeight = 15, bad.adCap = 45;  // rsad 44 + 15 * 45 / 8 = 128 > 127, the 9x5 cost word
  expectError([&] { bad.validate(); }, {"exceed 127"});
  bad.adCap = 44;  // 44 + 82 = 126: fits
  bad.validate();
  bad.census = sgm::CensusWindow::k9x9, bad.adCap = 255;  // 80 + 478 > 255
  expectError([&] { bad.validate(); }, {"exceed 255"});
  EXPECT_EQ(sgm::costLimit(sgm::CensusWindow::k9x5), 127);
  EXPECT_EQ(sgm::costLimit(sgm::CensusWindow::k9x9), 255);
  bad = sgm::Params{};
  bad.mode = sgm::CostMode::kSad, bad.adWeight = 8;
  expectError([&] { bad.validate(); }, {"census cost mode"});
  bad = sgm::Params{};
  bad.rightPathWeight = 8, bad.p2 = 4000;  // 18 * (255 + 4000) >= 65536
  expectError([&] { bad.validate(); }, {"16-bit"});
}

}  // namespace
