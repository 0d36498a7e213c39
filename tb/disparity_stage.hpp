// SPDX-License-Identifier: Apache-2.0
// GoogleTest fixture for the disparity-map stages sgm_hole_fill,
// sgm_edge_snap and sgm_median5x5 (same ports: disp_i/valid_i/in_valid_i/col_i/row_i/width_i/
// height_i and the stage's enable in, disp_o/valid_o/col_o/row_o/out_valid_o
// out), against their golden function. Frames are streamed slot by slot in
// raster order, each followed by flush slots until its last output has left,
// back to back without reset, with en_i toggled by the seeded enable pattern
// (slot_driver.hpp: inputs are junk while en_i = 0 and the outputs must hold).
// Every output slot is checked against the latency contract (position and
// out_valid_o), every pixel's disp and valid against the golden model. The
// build's DW / MAX_WIDTH / RW / LATENCY_ROWS / LATENCY come from the model
// (public parameters), so one fixture serves every configuration.
//
// Stage describes the module:
//   using Model = Vsgm_x;  using Rtl = Vsgm_x_sgm_x;     verilated top, its parameters
//   static constexpr const char* kName = "sgm_x";        prefix of the trace names
//   static constexpr const char* kStage;                  "hole fill (sgm_hole_fill)"
//   static constexpr const char* kSwitch;                 "fill": the enable in frame names
//   static constexpr const char* kStructured;             what structured() makes ("runs")
//   static constexpr DisparityMap PipelineStages::* kConesInput;  the cones stage it reads
//   static constexpr const char* kConesInputName;         "selected"
//   static void setEnable(Model&, bool);                  the stage enable (fill_en_i, ...)
//   static DisparityMap golden(const DisparityMap&);      the golden stage
//   static DisparityMap structured(int w, int h, std::mt19937&);  the stage's hard cases
// A stage that also reads the left gray image (sgm_edge_snap) declares instead
//   static DisparityMap golden(const DisparityMap&, const cv::Mat& gray);
//   static void setGray(Model&, bool we, int x, int y, int gray);   its gray write port
// and gets each pixel's gray written in the pixel's own slot (frames without a
// gray image get a random one).
#pragma once

#include "cones.hpp"
#include "slot_driver.hpp"
#include "verilated_top.hpp"

#include "sgm/image_io.hpp"
#include "sgm/pipeline.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::tb {

// One frame through a disparity stage: the input map and the stage enable.
struct DisparityFrame {
  DisparityMap map;
  bool enable = true;
  std::string name;
  cv::Mat gray = {};  // left gray (CV_8U), for stages that read it; random when empty
};

template <class Stage, class = void>
struct StageReadsGray : std::false_type {};
template <class Stage>
struct StageReadsGray<Stage, std::void_t<decltype(&Stage::setGray)>> : std::true_type {};

template <class Stage>
class DisparityStageTest : public ::testing::Test {
 public:
  using Model = typename Stage::Model;
  using Rtl = typename Stage::Rtl;
  using Top = VerilatedTop<Model>;

  static constexpr int kDW = int(Rtl::DW);
  static constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
  static constexpr int kMaxDisp = (1 << kDW) - 1;
  static constexpr int kRowMask = (1 << int(Rtl::RW)) - 1;

  using Frame = DisparityFrame;

  // Total latency in slots for a frame of width w.
  static int latency(int w) { return int(Rtl::LATENCY_ROWS) * w + int(Rtl::LATENCY); }

  static DisparityMap blankMap(int w, int h) {
    return DisparityMap{cv::Mat(h, w, CV_16UC1, cv::Scalar(0)), cv::Mat(h, w, CV_8UC1, cv::Scalar(0))};
  }

  // Random disparities (full DW range, also under invalid pixels) with validity
  // probability `density`.
  static DisparityMap randomMap(int w, int h, double density, std::mt19937& rng) {
    DisparityMap m = blankMap(w, h);
    std::uniform_int_distribution<int> value(0, kMaxDisp);
    std::bernoulli_distribution valid(density);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        m.disp.at<uint16_t>(y, x) = uint16_t(value(rng));
        m.valid.at<uint8_t>(y, x) = valid(rng);
      }
    return m;
  }

  static constexpr bool kReadsGray = StageReadsGray<Stage>::value;

  static DisparityMap expected(const Frame& f) {
    if (!f.enable) return f.map;
    if constexpr (kReadsGray)
      return Stage::golden(f.map, f.gray);
    else
      return Stage::golden(f.map);
  }

  static std::string describe(const Frame& f) {
    std::ostringstream s;
    s << "frame '" << f.name << "' " << f.map.disp.cols << "x" << f.map.disp.rows << " " << Stage::kSwitch << " "
      << (f.enable ? "on" : "off") << " (DW=" << kDW << ", MAX_WIDTH=" << kMaxWidth << ")";
    return s.str();
  }

  // Streams the frames back to back on one model and checks everything. Before
  // each frame's first slot come, as in the core, (1) slots of the previous
  // frame still in flight upstream: they continue its flush raster (not real)
  // but arrive after the switch, with the new frame's width / height / enable,
  // and (2) the new frame's lead-in: the raster slots just before (0, 0),
  // negative rows wrapped to RW bits, not real.
  static void runFrames(Top& top, const std::vector<Frame>& frames, uint32_t seed, double onRate = 0.7) {
    // Input position of every enabled slot: frame index and (x, y).
    struct Slot {
      int frame, x, y;
      bool real;
    };
    SlotDriver<Model, Slot> driver(top, EnablePattern(seed, onRate), junkInputs, outputs);
    std::mt19937& junk = driver.junk();
    driver.reset();

    // State of the frame being streamed.
    int fi = 0, w = 0, h = 0, lat = 0, received = 0;
    Frame frame;  // the frame being streamed, with its gray image
    DisparityMap got;
    cv::Mat seen;

    // One enabled slot (after the disabled cycles the pattern asks for), then the output checks.
    auto slot = [&](int x, int y, bool real, int disp, int valid) {
      const Frame& f = frames[fi];
      const bool ok = driver.slot(
          {fi, x, y, real},
          [&](Model& m) {
            m.col_i = x;
            m.row_i = y & kRowMask;
            m.width_i = w;
            m.height_i = h;
            Stage::setEnable(m, f.enable);
            m.in_valid_i = real;
            m.disp_i = disp;
            m.valid_i = valid;
            if constexpr (kReadsGray)
              Stage::setGray(m, real || (junk() & 1), x, y & kRowMask,
                             real ? frame.gray.at<uint8_t>(y, x) : int(junk() & 0xff));
          },
          [&] { return describe(f); });
      if (!ok) return;

      const Slot* src = driver.source(lat);
      const bool expectOut = src && src->frame == fi && src->real;
      ASSERT_EQ(bool(top->out_valid_o), expectOut)
          << describe(f) << ": out_valid_o at slot " << driver.slots() - 1 << " (latency " << lat << ")";
      if (!expectOut) return;
      const int ox = src->x, oy = src->y;
      ASSERT_EQ(int(top->col_o), ox) << describe(f) << ": col_o of pixel (" << ox << ", " << oy << ")";
      ASSERT_EQ(int(top->row_o), oy) << describe(f) << ": row_o of pixel (" << ox << ", " << oy << ")";
      ASSERT_FALSE(seen.at<uint8_t>(oy, ox)) << describe(f) << ": pixel (" << ox << ", " << oy << ") output twice";
      seen.at<uint8_t>(oy, ox) = 1;
      got.disp.at<uint16_t>(oy, ox) = uint16_t(top->disp_o);
      got.valid.at<uint8_t>(oy, ox) = uint8_t(top->valid_o);
      ++received;
    };

    int prevX = 0, prevY = 0, prevW = 0;  // next raster position of the previous frame
    for (; fi < int(frames.size()); ++fi) {
      frame = frames[fi];
      const Frame& f = frame;
      w = f.map.disp.cols, h = f.map.disp.rows, lat = latency(w), received = 0;
      if (kReadsGray && f.gray.empty()) {
        frame.gray = cv::Mat(h, w, CV_8UC1);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) frame.gray.at<uint8_t>(y, x) = uint8_t(junk() & 0xff);
      }
      ASSERT_LE(w, kMaxWidth) << describe(f);
      ASSERT_GE(w, 16) << describe(f);
      ASSERT_GE(h, 9) << describe(f);
      const DisparityMap want = expected(f);
      got = blankMap(w, h);
      seen = cv::Mat(h, w, CV_8UC1, cv::Scalar(0));

      if (fi > 0) {  // the previous frame's slots still in flight upstream
        for (int n = int(junk() % (3 * prevW + 1)); n > 0; --n) {
          slot(prevX, prevY, false, junk() & kMaxDisp, junk() & 1);
          if (::testing::Test::HasFatalFailure()) return;
          if (++prevX == prevW) prevX = 0, ++prevY;
        }
      }
      for (int p = -int(junk() % (2 * w + 1)); p < 0; ++p) {  // lead-in, negative rows
        const int y = -((-p + w - 1) / w), x = p - y * w;
        slot(x, y, false, junk() & kMaxDisp, junk() & 1);
        if (::testing::Test::HasFatalFailure()) return;
      }
      int x = 0, y = 0;
      for (; received < w * h; x = x + 1 == w ? 0 : x + 1, y += x == 0) {
        ASSERT_LT(y, h + 4) << describe(f) << ": outputs missing after " << y - h << " flush rows (" << received
                            << " of " << w * h << " received)";
        const bool real = y < h;  // flush slots carry junk the module must ignore
        slot(x, y, real, real ? f.map.disp.at<uint16_t>(y, x) : junk() & kMaxDisp,
             real ? f.map.valid.at<uint8_t>(y, x) : junk() & 1);
        if (::testing::Test::HasFatalFailure()) return;
      }
      prevX = x, prevY = y, prevW = w;

      // First mismatch in raster order.
      int mismatches = 0;
      std::string first;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int ed = want.disp.at<uint16_t>(y, x), ev = want.valid.at<uint8_t>(y, x);
          const int gd = got.disp.at<uint16_t>(y, x), gv = got.valid.at<uint8_t>(y, x);
          if (ed == gd && ev == gv) continue;
          if (mismatches++ == 0)
            first = firstMismatch(x, y, describe(f), pixel(ed, ev), pixel(gd, gv),
                                  std::string(Stage::kStage) + "; input " +
                                      pixel(f.map.disp.at<uint16_t>(y, x), f.map.valid.at<uint8_t>(y, x)));
        }
      EXPECT_EQ(mismatches, 0) << first << "; " << mismatches << " mismatching pixels";
    }
  }

  // The map itself when it fits MAX_WIDTH, else full-height tiles (left, middle, right).
  static std::vector<Frame> tiles(const DisparityMap& m, const std::string& name, const cv::Mat& gray = {}) {
    const int w = m.disp.cols;
    if (w <= kMaxWidth) return {{m, true, name, gray}};
    std::vector<Frame> out;
    for (int x0 : {0, (w - kMaxWidth) / 2, w - kMaxWidth}) {
      const cv::Rect r(x0, 0, kMaxWidth, m.disp.rows);
      out.push_back({{m.disp(r).clone(), m.valid(r).clone()},
                     true,
                     name + " columns " + std::to_string(x0) + "..",
                     gray.empty() ? cv::Mat() : gray(r).clone()});
    }
    return out;
  }

  // ---------------------------------------------------------------- the cases
  // Every case below runs in both stages' tests (same seeds, same sizes; the
  // stage's structured() maps where a case wants hard structure).

  static std::string percent(double v) { return std::to_string(int(v * 100 + 0.5)) + "%"; }
  static std::string topName(const std::string& what) { return std::string(Stage::kName) + "_" + what; }

  static void smallestFrameAllDensities() {
    Top top(topName("densities"));
    std::mt19937 rng(1);
    std::vector<Frame> frames;
    for (double d : {0.0, 0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 1.0})
      frames.push_back({randomMap(16, 9, d, rng), true, "16x9 " + percent(d) + " valid"});
    runFrames(top, frames, 101);
  }

  static void oddSizes() {
    Top top(topName("odd"));
    std::mt19937 rng(3);
    std::vector<Frame> frames;
    for (auto [w, h] : {std::pair{17, 9}, {23, 11}, {31, 15}, {45, 13}, {kMaxWidth - 3, 9}})
      for (double d : {0.1, 0.6})
        frames.push_back({randomMap(w, h, d, rng), true, std::to_string(w) + "x" + std::to_string(h)});
    runFrames(top, frames, 303);
  }

  static void passThroughWhenDisabled() {
    Top top(topName("off"));
    std::mt19937 rng(4);
    runFrames(top,
              {{randomMap(16, 9, 0.3, rng), false, "off 16x9"},
               {Stage::structured(41, 12, rng), false, std::string("off ") + Stage::kStructured},
               {randomMap(kMaxWidth, 10, 0.0, rng), false, "off all invalid"}},
              404);
  }

  // Two frames of different sizes (and then more) with no reset in between.
  static void backToBackFramesOfDifferentSizes() {
    Top top(topName("b2b"));
    std::mt19937 rng(5);
    runFrames(top,
              {{randomMap(kMaxWidth, 14, 0.4, rng), true, "first"},
               {Stage::structured(19, 11, rng), true, "second"},
               {randomMap(16, 9, 0.2, rng), false, "third (off)"},
               {randomMap(50, 10, 0.7, rng), true, "fourth"},
               {randomMap(16, 9, 0.5, rng), true, "fifth (smallest)"},
               {randomMap(kMaxWidth, 30, 0.5, rng), true, "sixth (wider and taller)"}},
              505);
  }

  // A long seeded sequence of frames of random size, density, structure and
  // enable, back to back on one model.
  static void randomFrameSequence() {
    Top top(topName("sequence"));
    std::mt19937 rng(7);
    std::vector<Frame> frames;
    for (int i = 0; i < 40; ++i) {
      const int w = 16 + int(rng() % (kMaxWidth - 15)), h = 9 + int(rng() % 24);
      const bool structured = rng() % 3 == 0, enable = rng() % 5 != 0;
      const double density = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
      frames.push_back({structured ? Stage::structured(w, h, rng) : randomMap(w, h, density, rng), enable,
                        "sequence #" + std::to_string(i)});
    }
    runFrames(top, frames, 707);
  }

  static void enablePatterns() {
    std::mt19937 rng(6);
    for (double rate : {0.05, 0.5, 1.0}) {
      Top top(topName("en"));
      runFrames(top, {{Stage::structured(29, 12, rng), true, "en rate " + percent(rate)}}, 606, rate);
    }
  }

  // The stage's input map of the golden pipeline on cones (four-path preset,
  // d disparities), in MAX_WIDTH tiles when wider.
  static void runCones(int d) {
    if (d * 16 > kMaxDisp + 1) {
      int need = 0;
      while ((1 << need) < d * 16) ++need;
      GTEST_SKIP() << "D=" << d << " disparities need DW >= " << need << "; this build has DW=" << kDW
                   << " (the DW=" << need << " build runs it)";
    }
    if (const std::string why = conesMissing(); !why.empty()) GTEST_SKIP() << why;
    Top top(topName("cones"));
    runFrames(top,
              tiles(conesStages(d).*Stage::kConesInput, "cones D=" + std::to_string(d) + " " + Stage::kConesInputName,
                    kReadsGray ? conesGray("left") : cv::Mat()),
              700 + d);
  }

 private:
  static std::string pixel(int disp, int valid) {
    return "disp " + std::to_string(disp) + " valid " + std::to_string(valid);
  }

  static void junkInputs(Model& m, std::mt19937& junk) {
    m.disp_i = junk() & kMaxDisp;
    m.valid_i = junk() & 1;
    m.in_valid_i = junk() & 1;
    m.col_i = junk() % (kMaxWidth + 1);
    m.row_i = junk() & kRowMask;
    m.width_i = junk() % (kMaxWidth + 1);
    m.height_i = junk() & kRowMask;
    Stage::setEnable(m, junk() & 1);
    if constexpr (kReadsGray)
      Stage::setGray(m, junk() & 1, int(junk() % (kMaxWidth + 1)), int(junk() & kRowMask), int(junk() & 0xff));
  }

  static std::vector<uint32_t> outputs(Model& m) {
    return portWords(m.disp_o, m.valid_o, m.col_o, m.row_o, m.out_valid_o);
  }
};

}  // namespace sgm::tb
