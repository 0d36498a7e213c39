// SPDX-License-Identifier: Apache-2.0
// Streams stereo frames through a verilated sgm_top (or any top with its
// ports) with seeded stalls, collects the output frames, and measures cycles.
// Every output cycle goes through the stream checker (axis_checker.hpp): a
// broken handshake or framing rule, or a core that stops moving, throws
// sgm::Error naming the cycle and the rule. A frame may reset the core in its
// middle (FrameInput::resetAfterBeats). The golden comparison is done by the
// caller (compareMaps, compareOutput).
//
// The harness drives sgm_top's frame configuration word cfg_i when the model has it
// (packed by tb/hardware_config.hpp from the generated table of the word); a model
// configured another way (sgm_axi: registers on an AXI4-Lite bus) sets a
// presenter (called where the next frame's configuration is due: before the
// first frame, then after each frame's first input beat) and cycle hooks (a bus
// model driven and sampled every cycle). step() clocks one cycle with every
// model, for blocking bus transfers made from inside the presenter.
//
// A frame with a calibration (FrameInput::mesh: its pair is raw, sgm_top RECTIFY = 1) has its
// two meshes loaded before its first beat is offered: at the point its configuration is
// presented, once mesh_swap_pending_o is low, one node per cycle through sgm_top's mesh
// port (or by the mesh loader a model configured another way sets), then a swap; the input
// stream holds at the frame's first beat until then, while the frames before it stream.
#pragma once

#include "axis_bfm.hpp"
#include "hardware_config.hpp"
#include "port_bits.hpp"
#include "verilated_top.hpp"

#include "sgm/depth.hpp"
#include "sgm/image_io.hpp"
#include "sgm/params.hpp"
#include "sgm/rectify.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sgm::tb {

// Does the model have sgm_top's configuration word and status ports?
template <class M, class = void>
struct HasConfigPorts : std::false_type {};
template <class M>
struct HasConfigPorts<M, std::void_t<decltype(std::declval<M&>().cfg_i)>> : std::true_type {};
template <class M, class = void>
struct HasMeshPorts : std::false_type {};
template <class M>
struct HasMeshPorts<M, std::void_t<decltype(std::declval<M&>().mesh_we_i)>> : std::true_type {};
template <class M, class = void>
struct HasStatusPorts : std::false_type {};
template <class M>
struct HasStatusPorts<M, std::void_t<decltype(std::declval<M&>().error_o)>> : std::true_type {};

struct FrameInput {
  cv::Mat left, right;  // 8-bit gray, same size
  Params params;
  // When not empty, sent instead of the frame's well-formed beats (malformed
  // frames); the core still owes width x height output beats.
  std::vector<Beat> rawBeats = {};
  // >= 0: once this many of the frame's input beats are in (and every earlier
  // frame is out), rst_ni goes low for a few cycles; the frame owes no output
  // and the next frame starts on a freshly reset core.
  long resetAfterBeats = -1;
  // Fields of the configuration word (REGISTER_FIELD, e.g. "CONFIG_MODE") presented with
  // these values instead of params' (an out-of-range value on purpose: cost mode 3, a
  // uniqueness ratio above 99, a restart of length 0, ...).
  std::map<std::string, uint32_t> fieldCodes = {};
  // The configuration is out of range: the core drops the frame whole (no output,
  // no frame_done_o); FrameOutput::errors is error_o once its last beat is in.
  bool dropped = false;
  // When set, the calibration's meshes are loaded and swapped in for this frame (and kept for
  // the frames after it); left and right are then the raw pair.
  std::shared_ptr<const StereoMesh> mesh = nullptr;
};

struct FrameOutput {
  DisparityMap map;           // what the core produced, read as disparity words (OUTPUT.MODE = DISPARITY)
  cv::Mat words;              // the output words' bits 15:0 as they came (CV_16UC1)
  cv::Mat confidence;         // their bits 23:16 (CV_8UC1; 0 in a word of 16 bits)
  uint64_t firstInCycle = 0;  // cycle of the frame's first input handshake
  uint64_t lastOutCycle = 0;  // cycle of its last output handshake
  unsigned errors = 0;        // error_o when the frame was done
  bool aborted = false;       // the frame was cut by a reset (no map)
};

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

// First differing confidence (the output word's bits 23:16) of a frame as one line, or ""
// when equal: the golden map's confidence with Params::outputConfidence, else 0 everywhere.
inline std::string compareConfidence(const DisparityMap& golden, const Params& params, const FrameOutput& got,
                                     const std::string& stage, long* mismatches = nullptr) {
  if (params.outputConfidence && golden.confidence.empty())
    throw Error("internal: the golden map has no confidence (Params::outputConfidence not set when it was run)");
  std::string first;
  long count = 0;
  for (int y = 0; y < got.confidence.rows; ++y)
    for (int x = 0; x < got.confidence.cols; ++x) {
      const int e = params.outputConfidence ? golden.confidence.at<uint8_t>(y, x) : 0;
      const int g = got.confidence.at<uint8_t>(y, x);
      if (e == g) continue;
      if (count++ == 0) {
        std::ostringstream msg;
        msg << "stage " << stage << " (confidence, bits 23:16"
            << (params.outputConfidence ? "" : ", OUTPUT.CONFIDENCE 0") << "): first mismatch at (x=" << x
            << ", y=" << y << "): expected " << e << ", got " << g;
        first = msg.str();
      }
    }
  if (mismatches) *mismatches += count;
  return first;
}

// The output word's bits 15:0 (compareOutput).
inline std::string compareWord(const DisparityMap& golden, const Params& params, const FrameOutput& got,
                               const std::string& stage, long* mismatches) {
  if (params.output != OutputMode::kDepth) return compareMaps(golden, got.map, stage, mismatches);
  const cv::Mat expected = outputWords(golden, params);
  std::string first;
  long count = 0;
  for (int y = 0; y < expected.rows; ++y)
    for (int x = 0; x < expected.cols; ++x) {
      const int e = expected.at<uint16_t>(y, x), g = got.words.at<uint16_t>(y, x);
      if (e == g) continue;
      if (count++ == 0) {
        std::ostringstream msg;
        msg << "stage " << stage << " (sgm_depth, F " << params.focalQ8 << "/256 px, B " << params.baselineUm
            << " um): first mismatch at (x=" << x << ", y=" << y << "): expected depth " << e << " mm (disparity "
            << golden.disp.at<uint16_t>(y, x) << "/16 valid " << int(golden.valid.at<uint8_t>(y, x)) << "), got " << g;
        first = msg.str();
      }
    }
  if (mismatches) *mismatches = count;
  return first;
}

// First differing output word of a frame against the golden model's map and the frame's
// output mode (sgm::outputWords), as one line, or "" when equal. In disparity mode the
// same as compareMaps; in depth mode the words, naming the stage sgm_depth; then the
// confidence (compareConfidence).
inline std::string compareOutput(const DisparityMap& golden, const Params& params, const FrameOutput& got,
                                 const std::string& stage, long* mismatches = nullptr) {
  const std::string word = compareWord(golden, params, got, stage, mismatches);
  const std::string confidence = compareConfidence(golden, params, got, stage, mismatches);
  return word.empty() ? confidence : word;
}

template <class Model>
class CoreHarness {
 public:
  // A core moving no beat in either direction for this many cycles hangs (the
  // longest legal pause is the P2 table fill, about 512 cycles, plus stalls).
  static constexpr uint64_t kHangCycles = 100000;
  // Cycles watched after the last frame: no further output beat may appear.
  static constexpr int kDrainCycles = 64;

  // initialState: VerilatedTop's power-up state (2 random, 0 zeros, 1 ones).
  CoreHarness(const std::string& name, uint32_t seed, Stalls stalls, int initialState = 2)
      : top_(name, initialState), source_(seed, stalls.sourceIdle), sink_(seed ^ 0x9e3779b9u, stalls.sinkBusy) {
    top_->s_tvalid_i = 0;
    top_->m_tready_i = 0;
    if constexpr (HasMeshPorts<Model>::value) top_->mesh_we_i = 0, top_->mesh_swap_i = 0;
    top_.reset();
  }

  // Streams the frames back to back (no gap, no reset unless a frame asks for
  // one) and returns their outputs. progress(done, total) is called now and
  // then on long runs.
  std::vector<FrameOutput> run(const std::vector<FrameInput>& frames,
                               const std::function<void(uint64_t, uint64_t)>& progress = {}) {
    std::vector<FrameOutput> out(frames.size());
    for (size_t begin = 0; begin < frames.size();) {
      size_t end = begin;  // a segment ends after the first frame that resets the core
      while (end < frames.size() && frames[end].resetAfterBeats < 0) ++end;
      end = std::min(end + 1, frames.size());
      runSegment(frames, begin, end, out, progress);
      begin = end;
    }
    for (int i = 0; i < kDrainCycles; ++i) cycle();
    const std::string violation = sink_.checker().finish();
    if (!violation.empty()) throw Error("output stream protocol: " + violation);
    return out;
  }

  VerilatedTop<Model>& top() { return top_; }
  // Every error_event_o pulse (its bits, one entry per cycle it was not 0) since construction.
  const std::vector<unsigned>& errorEvents() const { return errorEvents_; }

  // Replaces the cfg_i port as the way a frame's configuration is given.
  void setPresenter(std::function<void(const Params&, cv::Size)> presenter) { presenter_ = std::move(presenter); }
  // Replaces sgm_top's mesh port as the way a calibration's meshes are loaded (blocking: it
  // steps the clock until the meshes are written and swapped in).
  void setMeshLoader(std::function<void(const StereoMesh&)> loader) { meshLoader_ = std::move(loader); }
  // Called every cycle before the model evaluates its inputs (drive) and
  // after (sample: the handshakes of this cycle), before the clock edge.
  void setCycleHooks(std::function<void()> drive, std::function<void()> sample) {
    driveHook_ = std::move(drive), sampleHook_ = std::move(sample);
  }
  // One clock cycle with every model (the streams keep moving).
  void step() { cycle(); }

 private:
  static std::vector<Beat> inputBeats(const FrameInput& f) {
    return f.rawBeats.empty()
               ? frameBeats(f.left.data, f.right.data, f.left.cols, f.left.rows, f.left.step, f.right.step)
               : f.rawBeats;
  }

  // Frames [begin, end); the last one may reset the core.
  void runSegment(const std::vector<FrameInput>& frames, size_t begin, size_t end, std::vector<FrameOutput>& out,
                  const std::function<void(uint64_t, uint64_t)>& progress) {
    const bool resets = frames[end - 1].resetAfterBeats >= 0;
    const size_t owing = resets ? end - 1 : end;         // frames [begin, owing) produce output
    std::vector<size_t> firstBeat, outFirst, beatCount;  // per frame, counted from the segment start
    size_t inputCount = 0, outputCount = 0;
    // The first frame's configuration before any of its beats (a presenter may take cycles).
    present(frames[begin]);
    for (size_t k = begin; k < end; ++k) {
      std::vector<Beat> beats = inputBeats(frames[k]);
      if (k + 1 == end && resets) {
        if (size_t(frames[k].resetAfterBeats) > beats.size())
          throw Error("frame " + std::to_string(k) + ": reset after beat " + std::to_string(frames[k].resetAfterBeats) +
                      " of a " + std::to_string(beats.size()) + "-beat frame");
        beats.resize(size_t(frames[k].resetAfterBeats));
        out[k].aborted = true;
      }
      firstBeat.push_back(inputCount);
      outFirst.push_back(outputCount);
      beatCount.push_back(beats.size());
      source_.push(beats);
      inputCount += beats.size();
      if (frames[k].dropped) continue;
      if (k < owing) outputCount += frames[k].left.total();
      sink_.checker().expectFrame(frames[k].left.cols, frames[k].left.rows);
    }
    const uint64_t acceptedStart = source_.accepted();
    const size_t sinkStart = sink_.beats().size();
    size_t presented = 0, doneFrames = 0;
    // The input holds at the first beat of the next frame whose meshes are not loaded yet.
    const auto holdFrom = [&](size_t k) {
      size_t j = k;
      while (j < firstBeat.size() && !frames[begin + j].mesh) ++j;
      source_.setLimit(j < firstBeat.size() ? acceptedStart + firstBeat[j] : UINT64_MAX);
    };
    holdFrom(0);
    if (frames[begin].mesh) loadMesh(*frames[begin].mesh);
    holdFrom(1);
    // What each cycle's transfers and status mean for the frames (every cycle: also those a
    // presenter or the mesh loading clock).
    observer_ = [&](bool in, bool outBeat) {
      if (in) {
        const size_t i = source_.accepted() - 1 - acceptedStart;
        for (size_t k = 0; k < firstBeat.size(); ++k)
          if (i == firstBeat[k] && !out[begin + k].firstInCycle) out[begin + k].firstInCycle = top_.cycles() - 1;
        if constexpr (HasStatusPorts<Model>::value)  // a dropped frame's error bits, at its last beat
          for (size_t k = 0; k < firstBeat.size(); ++k)
            if (frames[begin + k].dropped && beatCount[k] && i + 1 == firstBeat[k] + beatCount[k])
              out[begin + k].errors = top_->error_o;
      }
      if (outBeat) {
        const size_t i = sink_.beats().size() - 1 - sinkStart;
        for (size_t k = 0; k + begin < owing; ++k)
          if (!frames[begin + k].dropped && i + 1 == outFirst[k] + frames[begin + k].left.total())
            out[begin + k].lastOutCycle = top_.cycles() - 1;
      }
      if constexpr (HasStatusPorts<Model>::value)
        if (top_->frame_done_o) {
          while (begin + doneFrames < owing && frames[begin + doneFrames].dropped) ++doneFrames;
          if (begin + doneFrames < owing) out[begin + doneFrames++].errors = top_->error_o;
        }
    };
    while (sink_.beats().size() - sinkStart < outputCount || source_.accepted() - acceptedStart < inputCount) {
      cycle();
      while (presented + 1 < firstBeat.size() && source_.accepted() - acceptedStart > firstBeat[presented]) {
        ++presented;
        present(frames[begin + presented]);
        if (frames[begin + presented].mesh) {
          loadMesh(*frames[begin + presented].mesh);
          holdFrom(presented + 1);
        }
      }
      if (progress && (top_.cycles() & 0xfffff) == 0) progress(sink_.beats().size() - sinkStart, outputCount);
    }
    observer_ = nullptr;
    for (size_t k = begin; k < owing; ++k)
      if (!frames[k].dropped) decode(sinkStart + outFirst[k - begin], frames[k].left.cols, frames[k].left.rows, out[k]);
    source_.setLimit(UINT64_MAX);
    if (resets) {
      top_->s_tvalid_i = 0;
      top_.reset();
      source_.clear();
      sink_.checker().reset();
      sink_.beats().resize(sinkStart + outputCount);  // whatever the cut frame had emitted
    }
  }

  // One clock cycle with both stream models; returns {input transfer, output transfer}
  // and throws on a protocol violation or a core that stopped moving.
  std::pair<bool, bool> cycle() {
    source_.drive(top_.model());
    sink_.drive(top_.model());
    if (driveHook_) driveHook_();
    top_->eval();
    if (sampleHook_) sampleHook_();
    const bool in = source_.sample(top_.model());
    const bool out = sink_.sample(top_.model(), top_.cycles());
    if constexpr (HasStatusPorts<Model>::value)
      if (top_->error_event_o) errorEvents_.push_back(unsigned(top_->error_event_o));
    if (!sink_.violation().empty()) throw Error("output stream protocol: " + sink_.violation());
    top_.tick();
    if (observer_) observer_(in, out);
    lastMove_ = in || out ? top_.cycles() : lastMove_;
    if (top_.cycles() - lastMove_ > kHangCycles)
      throw Error("core hangs: no beat in or out for " + std::to_string(kHangCycles) + " cycles (cycle " +
                  std::to_string(top_.cycles()) + ", " + std::to_string(source_.accepted()) + " beats in, " +
                  std::to_string(sink_.beats().size()) + " out)");
    return {in, out};
  }

 private:
  void present(const FrameInput& f) {
    if (presenter_) return presenter_(f.params, f.left.size());
    if constexpr (HasConfigPorts<Model>::value)
      presentPorts(f);
    else
      throw Error("the model has no cfg_i port: set a presenter");
  }

  // The word of the frame's parameters, with its fieldCodes in place of theirs.
  void presentPorts(const FrameInput& f) {
    HardwareConfig c = hardwareConfig(f.params, f.left.cols, f.left.rows);
    for (const auto& [name, value] : f.fieldCodes) c.set(name, value);
    const std::vector<uint32_t> word = c.word();
    for (size_t i = 0; i < word.size(); ++i) setWord(top_->cfg_i, int(i), word[i]);
  }

  // The calibration's two meshes into the copy not in use, then a swap (the frames before
  // keep streaming meanwhile).
  void loadMesh(const StereoMesh& mesh) {
    if (meshLoader_) return meshLoader_(mesh);
    if constexpr (HasMeshPorts<Model>::value) {
      for (uint64_t waited = 0; top_->mesh_swap_pending_o; ++waited) {
        if (waited > kHangCycles)
          throw Error("mesh_swap_pending_o stays high for " + std::to_string(kHangCycles) + " cycles (cycle " +
                      std::to_string(top_.cycles()) + ", " + std::to_string(source_.accepted()) + " beats in, " +
                      std::to_string(sink_.beats().size()) + " out)");
        cycle();
      }
      for (int image = 0; image < 2; ++image) {
        const Mesh& m = image ? mesh.right : mesh.left;
        for (int i = 0; i < m.nodesY; ++i)
          for (int j = 0; j < m.nodesX; ++j) {
            const size_t k = size_t(i) * m.nodesX + j;
            top_->mesh_we_i = 1, top_->mesh_channel_i = image, top_->mesh_row_i = i, top_->mesh_col_i = j;
            top_->mesh_u_i = uint32_t(m.u[k]) & 0x3ffffu, top_->mesh_v_i = uint32_t(m.v[k]) & 0x3ffffu;
            cycle();
          }
      }
      top_->mesh_we_i = 0, top_->mesh_swap_i = 1;
      cycle();
      top_->mesh_swap_i = 0;
    } else {
      throw Error("the model has no mesh port: set a mesh loader");
    }
  }

  void decode(size_t first, int w, int h, FrameOutput& out) {
    out.map = DisparityMap{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
    out.words = cv::Mat(h, w, CV_16UC1);
    out.confidence = cv::Mat(h, w, CV_8UC1);
    for (int i = 0; i < w * h; ++i) {
      const Beat& b = sink_.beats()[first + i];
      out.words.at<uint16_t>(i / w, i % w) = uint16_t(b.data);
      out.confidence.at<uint8_t>(i / w, i % w) = uint8_t(b.data >> 16);
      out.map.disp.at<uint16_t>(i / w, i % w) = uint16_t(b.data & 0x7fff);
      out.map.valid.at<uint8_t>(i / w, i % w) = uint8_t((b.data >> 15) & 1);
    }
  }

  VerilatedTop<Model> top_;
  AxisSource<Model> source_;
  AxisSink<Model> sink_;
  uint64_t lastMove_ = 0;  // cycle of the last transfer in either direction
  std::function<void(const Params&, cv::Size)> presenter_;
  std::function<void()> driveHook_, sampleHook_;
  std::function<void(const StereoMesh&)> meshLoader_;
  std::function<void(bool, bool)> observer_;  // the running segment's bookkeeping of a cycle
  std::vector<unsigned> errorEvents_;
};

}  // namespace sgm::tb
