// Streams stereo frames through a verilated sgm_top (or any top with its
// ports) with seeded random stalls, collects the output frames, and measures
// cycles. The golden comparison is done by the caller (compareMaps).
#pragma once

#include "axis_bfm.hpp"
#include "verilated_top.hpp"

#include "sgm/image_io.hpp"
#include "sgm/params.hpp"

#include <opencv2/core.hpp>

#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::tb {

struct FrameInput {
  cv::Mat left, right;  // 8-bit gray, same size
  Params params;
  // When not empty, sent instead of the frame's well-formed beats (malformed
  // frames); the core still owes width x height output beats.
  std::vector<Beat> rawBeats = {};
};

struct FrameOutput {
  DisparityMap map;          // what the core produced
  uint64_t firstInCycle = 0;  // cycle of the frame's first input handshake
  uint64_t lastOutCycle = 0;  // cycle of its last output handshake
  unsigned errors = 0;        // error_o when the frame was done
};

// Hardware encoding of the cost modes (cfg_mode_i).
inline int hardwareModeCode(CostMode mode) {
  switch (mode) {
    case CostMode::kRt: return 0;
    case CostMode::kRsad: return 1;
    case CostMode::kUnified: return 2;
    default: throw Error(std::string("cost mode ") + costModeName(mode) + " is not in the hardware");
  }
}

// First differing pixel of two disparity maps as one line, or "" when equal.
inline std::string compareMaps(const DisparityMap& expected, const DisparityMap& got, const std::string& stage,
                               long* mismatches = nullptr) {
  std::string first;
  long count = 0;
  for (int y = 0; y < expected.disp.rows; ++y)
    for (int x = 0; x < expected.disp.cols; ++x) {
      const int ev = expected.valid.at<uint8_t>(y, x), gv = got.valid.at<uint8_t>(y, x);
      const int ed = expected.disp.at<uint16_t>(y, x), gd = got.disp.at<uint16_t>(y, x);
      if (ev == gv && ed == gd) continue;
      if (count++ == 0) {
        std::ostringstream msg;
        msg << "stage " << stage << ": first mismatch at (x=" << x << ", y=" << y << "): expected disparity " << ed
            << "/16 valid " << ev << ", got " << gd << "/16 valid " << gv;
        first = msg.str();
      }
    }
  if (mismatches) *mismatches = count;
  return first;
}

template <class Model>
class CoreHarness {
 public:
  CoreHarness(const std::string& name, uint32_t seed, Stalls stalls)
      : top_(name), source_(seed, stalls.sourceIdle), sink_(seed ^ 0x9e3779b9u, stalls.sinkBusy) {
    top_->s_tvalid_i = 0;
    top_->m_tready_i = 0;
    top_.reset();
  }

  // Streams the frames back to back (no gap, no reset) and returns their outputs.
  // progress(done, total) is called now and then on long runs.
  std::vector<FrameOutput> run(const std::vector<FrameInput>& frames,
                               const std::function<void(uint64_t, uint64_t)>& progress = {}) {
    std::vector<size_t> firstBeat;
    size_t inputBeats = 0, outputBeats = 0;
    for (const FrameInput& f : frames) {
      firstBeat.push_back(inputBeats);
      const std::vector<Beat> beats = f.rawBeats.empty() ? frameBeats(f.left.data, f.right.data, f.left.cols,
                                                                      f.left.rows, f.left.step, f.right.step)
                                                         : f.rawBeats;
      source_.push(beats);
      inputBeats += beats.size();
      outputBeats += f.left.total();
    }
    std::vector<FrameOutput> out(frames.size());
    std::vector<size_t> outFirst;
    for (size_t k = 0, n = 0; k < frames.size(); n += frames[k].left.total(), ++k) outFirst.push_back(n);
    size_t frame = 0, done = 0, doneFrames = 0;
    present(frames[0].params, frames[0].left.size());
    const size_t sinkStart = sink_.beats().size();
    uint64_t guard = 0;
    while (sink_.beats().size() - sinkStart < outputBeats) {
      source_.drive(top_.model());
      sink_.drive(top_.model());
      top_->eval();
      const uint64_t before = source_.accepted();
      source_.sample(top_.model());
      if (sink_.sample(top_.model())) {
        const size_t i = sink_.beats().size() - 1 - sinkStart;
        while (done + 1 < frames.size() && i >= outFirst[done + 1]) ++done;
        if (i == outFirst[done] + frames[done].left.total() - 1) out[done].lastOutCycle = top_.cycles();
      }
      if (source_.accepted() != before) {
        const size_t i = source_.accepted() - 1;
        for (size_t k = 0; k < frames.size(); ++k)
          if (i == firstBeat[k]) out[k].firstInCycle = top_.cycles();
      }
      top_.tick();
      if (top_->frame_done_o && doneFrames < frames.size()) out[doneFrames++].errors = top_->error_o;
      while (frame + 1 < frames.size() && source_.accepted() > firstBeat[frame]) {
        ++frame;
        present(frames[frame].params, frames[frame].left.size());
      }
      if (progress && (top_.cycles() & 0xfffff) == 0) progress(sink_.beats().size() - sinkStart, outputBeats);
      if (++guard > 100 * (inputBeats + 100000)) throw Error("core made no progress (hang)");
    }
    if (!sink_.violation().empty()) throw Error("output stream protocol: " + sink_.violation());
    for (size_t k = 0; k < frames.size(); ++k) {
      const int w = frames[k].left.cols, h = frames[k].left.rows;
      const std::string framing = checkFraming(sink_.beats(), sinkStart + outFirst[k], w, h);
      if (!framing.empty()) throw Error("frame " + std::to_string(k) + ": " + framing);
      out[k].map = decode(sinkStart + outFirst[k], w, h);
    }
    return out;
  }

  VerilatedTop<Model>& top() { return top_; }

 private:
  void present(const Params& p, cv::Size size) {
    top_->cfg_width_i = size.width;
    top_->cfg_height_i = size.height;
    top_->cfg_p1_i = p.p1;
    top_->cfg_p2_i = p.p2;
    top_->cfg_mode_i = hardwareModeCode(p.mode);
    top_->cfg_subpixel_i = p.subpixel;
    top_->cfg_lr_en_i = p.lrTolerance >= 0;
    top_->cfg_lr_tol_i = p.lrTolerance >= 0 ? p.lrTolerance : 0;
    top_->cfg_fill_i = p.fill;
    top_->cfg_snap_i = p.snap;
    top_->cfg_median_i = p.median;
  }

  DisparityMap decode(size_t first, int w, int h) {
    DisparityMap map{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
    for (int i = 0; i < w * h; ++i) {
      const Beat& b = sink_.beats()[first + i];
      map.disp.at<uint16_t>(i / w, i % w) = uint16_t(b.data & 0x7fff);
      map.valid.at<uint8_t>(i / w, i % w) = uint8_t(b.data >> 15);
    }
    return map;
  }

  VerilatedTop<Model> top_;
  AxisSource<Model> source_;
  AxisSink<Model> sink_;
};

}  // namespace sgm::tb
