// SPDX-License-Identifier: Apache-2.0
// AXI4-Stream protocol checker for a video stream (tuser = start of frame,
// tlast = end of line), fed cycle by cycle with what the sink sees. Rules:
//   handshake: once tvalid is high it stays high, and tdata/tuser/tlast stay
//              unchanged, until the cycle with tready (the transfer);
//   framing:   for every announced W x H frame, exactly W x H beats, tuser on
//              the first beat and on no other, tlast on every beat at x = W-1
//              and on no other; no beat beyond the announced frames.
// Framing is checked once a frame has been announced (expectFrame); a module
// test that only wants the handshake rules announces none. The first broken
// rule is kept, naming the cycle, the beat and the rule.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::tb {

struct Beat {
  uint32_t data = 0;  // tdata: 16 bits in, 16 or 24 out (sgm_top OUT_W)
  bool user = false;  // start of frame
  bool last = false;  // end of line
  bool operator==(const Beat& o) const { return data == o.data && user == o.user && last == o.last; }
};

class AxisChecker {
 public:
  // Announces the next frame's size (frames are checked in announcement order).
  void expectFrame(int width, int height) {
    frames_.push_back({width, height});
    checksFraming_ = true;
  }

  // One cycle, before the clock edge: tvalid, tready and the beat on the bus.
  // Returns true when a beat is transferred.
  bool observe(uint64_t cycle, bool valid, bool ready, const Beat& beat) {
    if (waiting_ && !valid)
      fail(cycle, "tvalid dropped before its handshake");
    else if (waiting_ && !(beat == held_))
      fail(cycle, "tdata/tuser/tlast changed while tvalid was high and tready low");
    const bool fire = valid && ready;
    waiting_ = valid && !ready;
    held_ = beat;
    if (fire) {
      if (checksFraming_) checkFraming(cycle, beat);
      ++beats_;
    }
    return fire;
  }

  // The bus was reset: nothing is owed any more, neither the held beat nor the
  // rest of the announced frames.
  void reset() {
    waiting_ = false;
    frames_.clear();
    position_ = 0;
  }

  // "" or the first broken rule, including frames still owed beats.
  std::string finish() const {
    if (!violation_.empty() || frames_.empty()) return violation_;
    const Frame& f = frames_.front();
    std::ostringstream msg;
    msg << "frame " << framesDone_ << " ended after " << position_ << " of " << f.width << " x " << f.height
        << " output beats";
    return msg.str();
  }

  const std::string& violation() const { return violation_; }
  uint64_t beats() const { return beats_; }
  uint64_t framesDone() const { return framesDone_; }
  size_t framesOwed() const { return frames_.size(); }

 private:
  struct Frame {
    int width, height;
  };

  void checkFraming(uint64_t cycle, const Beat& beat) {
    if (frames_.empty()) return fail(cycle, "beat after the last announced frame (more than W x H beats)");
    const Frame& f = frames_.front();
    const int x = int(position_ % f.width);
    const bool first = position_ == 0, lineEnd = x == f.width - 1;
    if (beat.user != first)
      fail(cycle, first ? "tuser missing on the first beat of a frame" : "tuser on a beat inside a frame");
    else if (beat.last != lineEnd)
      fail(cycle, lineEnd ? "tlast missing on the last beat of a line" : "tlast before the last beat of a line");
    if (++position_ == uint64_t(f.width) * f.height) {
      frames_.pop_front();
      position_ = 0;
      ++framesDone_;
    }
  }

  void fail(uint64_t cycle, const std::string& rule) {
    if (!violation_.empty()) return;
    std::ostringstream msg;
    msg << "cycle " << cycle << ", output beat " << beats_;
    if (checksFraming_ && !frames_.empty())
      msg << " (frame " << framesDone_ << ", x=" << position_ % frames_.front().width
          << ", y=" << position_ / frames_.front().width << ")";
    msg << ": " << rule;
    violation_ = msg.str();
  }

  std::deque<Frame> frames_;
  bool checksFraming_ = false;
  bool waiting_ = false;
  Beat held_;
  uint64_t position_ = 0;  // beats of the current frame so far
  uint64_t beats_ = 0, framesDone_ = 0;
  std::string violation_;
};

// The framing rules over `W x H` recorded beats from `first` (no handshake
// information): "" or the first broken rule ("cycle" is then the beat index).
inline std::string checkFraming(const std::vector<Beat>& beats, size_t first, int width, int height) {
  AxisChecker checker;
  checker.expectFrame(width, height);
  const size_t end = std::min(beats.size(), first + size_t(width) * height);
  for (size_t i = first; i < end && checker.violation().empty(); ++i) checker.observe(i, true, true, beats[i]);
  return checker.finish();
}

}  // namespace sgm::tb
