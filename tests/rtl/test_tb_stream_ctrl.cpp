// SPDX-License-Identifier: Apache-2.0
// sgm_stream_ctrl (through tb_stream_ctrl, a stand-in pipeline of fixed
// latency): AXI4-Stream framing, random stalls on both sides, back-to-back
// frames of different sizes, malformed frames and recovery at the next start
// of frame, configuration out of range (width, height, penalties, mode) and at its limits.
#include "Vtb_stream_ctrl.h"
#include "axis_bfm.hpp"
#include "hardware_config.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

namespace {

using Model = Vtb_stream_ctrl;
using Top = sgm::tb::VerilatedTop<Model>;
using sgm::tb::Beat;

constexpr int kDisparityBits = 12;

// What the stand-in pipeline makes of an input pixel pair.
uint16_t expectedData(uint8_t left, uint8_t right) {
  const uint16_t pair = uint16_t(left | right << 8);
  return uint16_t((left & 1) << 15 | (pair & ((1 << kDisparityBits) - 1)));
}

struct FrameCase {
  int width, height;
  std::vector<Beat> beats;          // what the source sends
  std::vector<uint16_t> expected;   // expected output data (width x height), empty if dropped
  unsigned errors = 0;              // expected error_o after the frame
  int p1 = 20, p2 = 200, mode = 1;  // PENALTY.P1, PENALTY.P2, CONFIG.MODE of the word (the others 0)
};

FrameCase goodFrame(int w, int h, std::mt19937& rng) {
  FrameCase f{w, h, {}, {}, 0};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t l = uint8_t(rng()), r = uint8_t(rng());
      f.beats.push_back(Beat{uint16_t(l | r << 8), x == 0 && y == 0, x == w - 1});
      f.expected.push_back(expectedData(l, r));
    }
  return f;
}

// Keeps the first `kept` beats of a good frame; the rest of the output is padding.
FrameCase truncated(FrameCase f, size_t kept, unsigned errors) {
  f.beats.resize(kept);
  for (size_t i = kept; i < f.expected.size(); ++i) f.expected[i] = 0;
  f.errors = errors;
  return f;
}

class StreamCtrl {
 public:
  StreamCtrl(const std::string& name, uint32_t seed, sgm::tb::Stalls stalls)
      : top_(name), source_(seed, stalls.sourceIdle), sink_(seed + 1, stalls.sinkBusy) {
    top_->s_tvalid_i = 0;
    top_->m_tready_i = 0;
    top_.reset();
  }

  // Sends the frames back to back and checks the output of each.
  void run(const std::vector<FrameCase>& frames) {
    std::vector<size_t> sofIndex;  // index of each frame's first beat in the source order
    size_t total = 0;
    for (const FrameCase& f : frames) {
      sofIndex.push_back(total);
      source_.push(f.beats);
      total += f.beats.size();
    }
    size_t expectedBeats = 0;
    for (const FrameCase& f : frames) expectedBeats += f.expected.size();
    size_t frame = 0;  // frame whose configuration is presented
    std::vector<unsigned> errorsAtDone;
    long idleCycles = 0;
    setConfig(frames[0]);
    while (sink_.beats().size() < expectedBeats || !source_.empty()) {
      source_.drive(top_.model());
      sink_.drive(top_.model());
      top_->eval();
      source_.sample(top_.model());
      sink_.sample(top_.model());
      top_.tick();
      // Once frame k's first beat is in, present frame k+1's configuration.
      while (frame + 1 < frames.size() && source_.accepted() > sofIndex[frame]) setConfig(frames[++frame]);
      if (top_->frame_done_o) errorsAtDone.push_back(top_->error_o);
      ASSERT_LT(++idleCycles, 50L * long(total + 1000)) << "no progress: hang";
    }
    for (int i = 0; i < 200; ++i) {  // nothing more may come out
      sink_.drive(top_.model());
      top_->eval();
      sink_.sample(top_.model());
      top_.tick();
    }
    ASSERT_EQ(sink_.violation(), "");
    if (sink_.beats().size() != expectedBeats) {
      std::ostringstream where;
      for (size_t i = 0; i < sink_.beats().size(); ++i)
        if (sink_.beats()[i].user) where << " tuser@" << i;
      FAIL() << "output beat count " << sink_.beats().size() << ", expected " << expectedBeats << ";" << where.str();
    }
    size_t first = 0, done = 0;
    for (size_t k = 0; k < frames.size(); ++k) {
      const FrameCase& f = frames[k];
      if (f.expected.empty()) continue;
      ASSERT_EQ(sgm::tb::checkFraming(sink_.beats(), first, f.width, f.height), "") << "frame " << k;
      for (size_t i = 0; i < f.expected.size(); ++i)
        ASSERT_EQ(sink_.beats()[first + i].data, f.expected[i])
            << "frame " << k << " first mismatch at (x=" << i % f.width << ", y=" << i / f.width << ")";
      ASSERT_LT(done, errorsAtDone.size());
      EXPECT_EQ(errorsAtDone[done++], f.errors) << "error_o after frame " << k;
      first += f.expected.size();
    }
  }

  Top& top() { return top_; }

 private:
  // The frame configuration word of the frame: its size, penalties and mode, every other field 0.
  void setConfig(const FrameCase& f) {
    sgm::tb::HardwareConfig c;
    c.set("FRAME_SIZE_WIDTH", uint32_t(f.width));
    c.set("FRAME_SIZE_HEIGHT", uint32_t(f.height));
    c.set("PENALTY_P1", uint32_t(f.p1));
    c.set("PENALTY_P2", uint32_t(f.p2));
    c.set("CONFIG_MODE", uint32_t(f.mode));
    const std::vector<uint32_t> word = c.word();
    for (size_t i = 0; i < word.size(); ++i) sgm::tb::setWord(top_->cfg_i, int(i), word[i]);
  }
  Top top_;
  sgm::tb::AxisSource<Model> source_;
  sgm::tb::AxisSink<Model> sink_;
};

TEST(SgmStreamCtrl, BackToBackFramesUnderStalls) {
  for (const sgm::tb::Stalls stalls : {sgm::tb::Stalls{0, 0}, {0.3, 0.3}, {0.7, 0.1}, {0.05, 0.8}}) {
    std::mt19937 rng(42);
    StreamCtrl ctrl("stream_ctrl_stalls", 7, stalls);
    ctrl.run({goodFrame(16, 9, rng), goodFrame(37, 12, rng), goodFrame(16, 9, rng), goodFrame(64, 10, rng)});
  }
}

TEST(SgmStreamCtrl, MalformedFramesAreFlaggedPaddedAndRecovered) {
  std::mt19937 rng(5);
  FrameCase early = goodFrame(20, 10, rng);
  early.beats[2 * 20 + 5].last = true;  // tlast at column 5 of row 2
  early = truncated(early, 2 * 20 + 6, 0x1);
  early.beats.push_back(Beat{1, false, false});  // rest of the broken line: dropped
  FrameCase missing = goodFrame(20, 10, rng);
  missing.beats[3 * 20 + 19].last = false;  // no tlast at the end of row 3
  missing = truncated(missing, 3 * 20 + 20, 0x2);
  FrameCase cut = truncated(goodFrame(20, 10, rng), 57, 0x4);  // next tuser after 57 beats
  StreamCtrl ctrl("stream_ctrl_malformed", 9, {0.2, 0.2});
  ctrl.run({goodFrame(20, 10, rng), early, goodFrame(20, 10, rng), missing, goodFrame(24, 9, rng), cut,
            goodFrame(18, 11, rng)});
}

TEST(SgmStreamCtrl, StrayBeatsAndBadConfigurationAreDropped) {
  std::mt19937 rng(8);
  FrameCase junk{16, 9, {Beat{7, false, false}, Beat{9, false, true}}, {}, 0};
  FrameCase tooNarrow = goodFrame(8, 9, rng);  // below MIN_WIDTH = 16
  tooNarrow.expected.clear();
  FrameCase tooShort = goodFrame(16, 5, rng);  // below 9 rows
  tooShort.expected.clear();
  StreamCtrl ctrl("stream_ctrl_dropped", 3, {0.1, 0.1});
  ctrl.run({junk, goodFrame(16, 9, rng), tooNarrow, tooShort, goodFrame(17, 9, rng)});
  EXPECT_EQ(ctrl.top()->busy_o, 0);
}

// The configuration limits of tb_stream_ctrl (MIN_WIDTH 16, MAX_WIDTH = MAX_HEIGHT = 200):
// frames exactly at them pass (MAX_WIDTH x MAX_HEIGHT at once), one beyond each is
// dropped whole, as are P2' < P1 and cost mode 3; P2' = P1 and mode 2 pass. A frame size
// beyond the position counters (XW = YW = 8 bits) that cut to them would be legal (272,
// 265) is dropped too: the word's frame size is checked whole.
TEST(SgmStreamCtrl, FramesAtTheConfigurationLimits) {
  constexpr int kMinWidth = 16, kMaxWidth = 200, kMaxHeight = 200;
  std::mt19937 rng(11);
  const auto dropped = [&](int w, int h, int p1, int p2, int mode) {
    FrameCase f = goodFrame(w, h, rng);
    f.expected.clear();
    f.p1 = p1, f.p2 = p2, f.mode = mode;
    return f;
  };
  FrameCase equal = goodFrame(kMinWidth, 9, rng);
  equal.p1 = equal.p2 = 77, equal.mode = 2;
  StreamCtrl ctrl("stream_ctrl_limits", 4, {0.1, 0.1});
  ctrl.run({goodFrame(kMaxWidth, kMaxHeight, rng), dropped(kMaxWidth + 1, 9, 20, 200, 1), goodFrame(kMaxWidth, 9, rng),
            dropped(kMinWidth - 1, 9, 20, 200, 1), goodFrame(kMinWidth, kMaxHeight, rng),
            dropped(kMinWidth, kMaxHeight + 1, 20, 200, 1), dropped(kMinWidth, 8, 20, 200, 1), equal,
            dropped(kMinWidth, 9, 21, 20, 0), dropped(kMinWidth, 9, 20, 200, 3), goodFrame(kMinWidth + 1, 9, rng),
            dropped(256 + kMinWidth, 9, 20, 200, 1), dropped(kMinWidth, 256 + 9, 20, 200, 1),
            goodFrame(kMinWidth, 9, rng)});
  EXPECT_EQ(ctrl.top()->busy_o, 0);
}

}  // namespace
