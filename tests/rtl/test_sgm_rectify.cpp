// SPDX-License-Identifier: Apache-2.0
// sgm_rectify against the golden sgm::rectify (docs/algorithm.md section 13): random smooth
// meshes (an affine map, a radial term, a row tilt), one per channel, loaded through the mesh
// port into the copy not in use while earlier frames still stream, and swapped in at a start
// of frame; frames of several sizes and lags streamed back to back (the next frame's input
// overlapping the previous frame's last output rows), with random input gaps and output
// back-pressure; every output pixel's gray and outside flag of every channel against the
// golden model, tuser, tlast and the frame's info_o; frames that pass through; framing errors
// flagged and recovered at the next start of frame; row_miss_o quiet while the calibration
// fits the build's ROWS and raised when it does not. The build's parameters come from the
// model.
#include "Vsgm_rectify.h"
#include "Vsgm_rectify_sgm_rectify.h"
#include "rectify_meshes.hpp"
#include "verilated_top.hpp"

#include "sgm/rectify.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <cmath>
#include <deque>
#include <random>
#include <string>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_rectify>;
using Rtl = Vsgm_rectify_sgm_rectify;

constexpr int kRows = int(Rtl::ROWS);
constexpr int kGridLog2 = int(Rtl::GRID_LOG2);
constexpr int kMaxWidth = int(Rtl::MAX_WIDTH);
constexpr int kMaxHeight = int(Rtl::MAX_HEIGHT);
constexpr int kChannels = int(Rtl::CHANNELS);
constexpr uint32_t kInfoMask = Rtl::INFO_W >= 32 ? 0xffffffffu : (1u << Rtl::INFO_W) - 1;

sgm::Mesh randomMesh(int w, int h, double strength, std::mt19937& rng) {
  return sgm::tb::smoothMesh(w, h, kGridLog2, strength, rng);
}

cv::Mat texture(int w, int h, std::mt19937& rng) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at<uint8_t>(y, x) = uint8_t(rng());
  return img;
}

struct Beat {
  uint32_t data = 0;  // channel c in bits 8c + 7 .. 8c
  bool user = false, last = false;
};

struct Frame {
  int w = 0, h = 0, lag = 0;
  bool enable = true;
  uint32_t info = 0;
  std::vector<cv::Mat> source;  // one per channel
  std::vector<sgm::Mesh> mesh;  // one per channel
  bool loadMesh = true;         // written and swapped in before the frame's start
  std::vector<Beat> beats;      // the input, as sent (malformed on purpose or not)
  bool check = true;            // compare the output pixels
  unsigned errors = 0;          // m_error_o on the frame's last beat (framing errors of its input)
  std::string name;
};

std::vector<Beat> wellFormed(const Frame& f) {
  std::vector<Beat> beats;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      Beat b;
      for (int c = 0; c < kChannels; ++c) b.data |= uint32_t(f.source[size_t(c)].at<uint8_t>(y, x)) << (8 * c);
      b.user = x == 0 && y == 0, b.last = x == f.w - 1;
      beats.push_back(b);
    }
  return beats;
}

// A frame whose meshes fit the build at one lag for all channels: the largest of the meshes'
// own, or `lag` when given; each mesh reads rows y + back .. y + lag_m with lag_m <= lag and
// back >= lag + 2 - ROWS (the strongest meshes that do).
Frame fittingFrame(int w, int h, double strength, std::mt19937& rng, const std::string& name, int lag = -1) {
  Frame f;
  f.w = w, f.h = h, f.name = name, f.info = uint32_t(rng()) & kInfoMask;
  for (;; strength *= 0.8) {
    f.mesh.clear();
    int frameLag = lag;
    std::vector<sgm::RowSpan> spans;
    for (int c = 0; c < kChannels; ++c) {
      f.mesh.push_back(randomMesh(w, h, strength, rng));
      spans.push_back(sgm::meshRowSpan(f.mesh.back()));
      if (lag < 0) frameLag = std::max(frameLag, spans.back().lag);
    }
    bool fits = true;
    for (const sgm::RowSpan& span : spans)
      fits = fits && span.lag >= 0 && span.lag <= frameLag && span.back >= frameLag + 2 - kRows;
    if (fits) {
      f.lag = frameLag;
      break;
    }
  }
  for (int c = 0; c < kChannels; ++c) f.source.push_back(texture(w, h, rng));
  f.beats = wellFormed(f);
  return f;
}

// What the output beat (x, y) of the frame must carry.
struct Expected {
  uint32_t data = 0, outside = 0;
};
std::vector<Expected> expected(const Frame& f) {
  std::vector<Expected> out(size_t(f.w) * f.h);
  for (int c = 0; c < kChannels; ++c) {
    if (!f.enable) {
      for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < f.w; ++x)
          out[size_t(y) * f.w + x].data |= uint32_t(f.source[size_t(c)].at<uint8_t>(y, x)) << (8 * c);
      continue;
    }
    const sgm::RectifiedImage want = sgm::rectify(f.source[size_t(c)], f.mesh[size_t(c)]);
    for (int y = 0; y < f.h; ++y)
      for (int x = 0; x < f.w; ++x) {
        Expected& e = out[size_t(y) * f.w + x];
        e.data |= uint32_t(want.gray.at<uint8_t>(y, x)) << (8 * c);
        e.outside |= uint32_t(want.valid.at<uint8_t>(y, x) ? 0 : 1) << c;
      }
  }
  return out;
}

struct RunResult {
  std::string mismatch;                // "" when every checked pixel matched
  std::vector<bool> rowMiss;           // per frame: row_miss_o seen while its output left
  std::vector<uint64_t> firstInCycle;  // per frame
  uint64_t cycles = 0;
  unsigned errorEvents[3] = {0, 0, 0};  // error_set_o pulses by bit
};

// Streams the frames back to back. A frame's meshes are written (one node per cycle) once the
// frame before it has started at the input and mesh_swap_pending_o is low, while earlier frames
// stream, and swapped in; its first beat is offered after the swap. Input gaps and output
// stalls with the given probabilities.
RunResult runStream(Top& top, const std::vector<Frame>& frames, std::mt19937& rng, double gap, double stall) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RunResult r;
  r.rowMiss.assign(frames.size(), false);
  r.firstInCycle.assign(frames.size(), 0);
  size_t inFrame = 0, inBeat = 0, outFrame = 0;
  long outPixel = 0;
  size_t meshFrame = 0;                // the next frame whose meshes are written
  int meshChannel = 0, meshNode = -1;  // the node being written, -1: not started
  size_t swapped = frames.size();      // the frame whose meshes were swapped in last
  std::vector<Expected> want = frames.empty() ? std::vector<Expected>{} : expected(frames[0]);
  long total = 0;
  for (const Frame& f : frames) total += long(f.w) * f.h;
  const uint64_t limit = uint64_t(total) * 30 + 200000;
  for (uint64_t cycle = 0; outFrame < frames.size(); ++cycle) {
    if (cycle > limit) {
      r.mismatch = "stalled in frame " + std::to_string(outFrame) + " after " + std::to_string(outPixel) + " pixels";
      return r;
    }
    top->mesh_we_i = 0, top->mesh_swap_i = 0, top->s_tvalid_i = 0, top->s_tuser_i = 0, top->s_tlast_i = 0;
    top->s_tdata_i = uint32_t(rng());
    // The mesh writer: frame meshFrame's meshes, once every frame before it has started.
    const bool previousStarted = meshFrame == 0 || inFrame > meshFrame - 1 || (inFrame == meshFrame - 1 && inBeat > 0);
    if (meshFrame < frames.size() && previousStarted) {
      const Frame& f = frames[meshFrame];
      if (!f.loadMesh) {
        ++meshFrame;
      } else {
        if (meshNode < 0 && !top->mesh_swap_pending_o) meshNode = 0, meshChannel = 0;
        if (meshNode >= 0) {
          const sgm::Mesh& m = f.mesh[size_t(meshChannel)];
          const int nodes = m.nodesX * m.nodesY;
          if (meshNode < nodes) {
            top->mesh_we_i = 1;
            top->mesh_channel_i = uint32_t(meshChannel);
            top->mesh_row_i = uint32_t(meshNode / m.nodesX), top->mesh_col_i = uint32_t(meshNode % m.nodesX);
            top->mesh_u_i = uint32_t(m.u[size_t(meshNode)]) & 0x3ffffu;
            top->mesh_v_i = uint32_t(m.v[size_t(meshNode)]) & 0x3ffffu;
            if (++meshNode == nodes && meshChannel + 1 < kChannels) meshNode = 0, ++meshChannel;
          } else {
            top->mesh_swap_i = 1;
            swapped = meshFrame++;
            meshNode = -1;
          }
        }
      }
    }
    bool offer = false;
    if (inFrame < frames.size()) {
      const Frame& f = frames[inFrame];
      const bool ready = inBeat > 0 || !f.loadMesh || swapped == inFrame;
      if (ready && unit(rng) >= gap) {
        offer = true;
        const Beat& b = f.beats[inBeat];
        top->s_tvalid_i = 1, top->s_tdata_i = b.data, top->s_tuser_i = b.user, top->s_tlast_i = b.last;
        top->width_i = uint32_t(f.w), top->height_i = uint32_t(f.h), top->lag_i = uint32_t(f.lag);
        top->enable_i = f.enable, top->info_i = f.info;
      }
    }
    top->m_tready_i = unit(rng) >= stall;
    top->eval();
    const bool took = offer && top->s_tready_o;
    if (top->m_tvalid_o && top->m_tready_i) {
      const Frame& f = frames[outFrame];
      const int y = int(outPixel / f.w), x = int(outPixel % f.w);
      const std::string where = f.name + " stage sgm_rectify pixel (x=" + std::to_string(x) +
                                ", y=" + std::to_string(y) + ")";
      const Expected& e = want[size_t(outPixel)];
      if (r.mismatch.empty() && f.check && (top->m_tdata_o != e.data || top->m_outside_o != e.outside))
        r.mismatch = where + ": expected gray(s) " + std::to_string(e.data) + " outside " + std::to_string(e.outside) +
                     ", got " + std::to_string(top->m_tdata_o) + " outside " + std::to_string(top->m_outside_o);
      if (r.mismatch.empty() && (bool(top->m_tuser_o) != (outPixel == 0) || bool(top->m_tlast_o) != (x == f.w - 1)))
        r.mismatch = where + ": tuser " + std::to_string(int(top->m_tuser_o)) + " tlast " +
                     std::to_string(int(top->m_tlast_o));
      if (r.mismatch.empty() && (top->info_o & kInfoMask) != f.info)
        r.mismatch = where + ": info_o " + std::to_string(top->info_o) + ", expected " + std::to_string(f.info);
      const unsigned errors = outPixel + 1 == long(f.w) * f.h ? f.errors : 0u;
      if (r.mismatch.empty() && top->m_error_o != errors)
        r.mismatch = where + ": m_error_o " + std::to_string(top->m_error_o) + ", expected " + std::to_string(errors);
      r.rowMiss[outFrame] = r.rowMiss[outFrame] || top->row_miss_o;
      if (++outPixel == long(f.w) * f.h) {
        outPixel = 0;
        if (++outFrame < frames.size()) want = expected(frames[outFrame]);
      }
    }
    top.tick();
    for (int bit = 0; bit < 3; ++bit) r.errorEvents[bit] += (top->error_set_o >> bit) & 1u;
    if (took) {
      if (inBeat == 0) r.firstInCycle[inFrame] = cycle;
      if (++inBeat == frames[inFrame].beats.size()) inBeat = 0, ++inFrame;
    }
    r.cycles = cycle + 1;
  }
  return r;
}

// Inputs quiet (the model's ports start random), then reset.
void start(Top& top) {
  top->s_tvalid_i = 0, top->s_tuser_i = 0, top->s_tlast_i = 0, top->m_tready_i = 1;
  top->mesh_we_i = 0, top->mesh_swap_i = 0, top->mesh_channel_i = 0;
  top->width_i = kMaxWidth, top->height_i = kMaxHeight, top->lag_i = 0, top->enable_i = 1, top->info_i = 0;
  top.reset();
}

class SgmRectify : public testing::Test {};

TEST_F(SgmRectify, FramesBackToBackEveryPixelAgainstTheGoldenModel) {
  Top top("sgm_rectify_frames");
  start(top);
  std::mt19937 rng(11);
  const int sizes[][2] = {
      {kMaxWidth, kMaxHeight}, {kMaxWidth - 3, kMaxHeight / 2 + 1}, {17, 9}, {kMaxWidth / 2 + 5, 24}};
  for (int pass = 0; pass < 2; ++pass) {
    const double gap = pass ? 0.3 : 0.0, stall = pass ? 0.3 : 0.0;
    std::vector<Frame> frames;
    for (const auto& size : sizes)
      frames.push_back(fittingFrame(size[0], size[1], 1.0 + pass, rng,
                                    std::to_string(size[0]) + "x" + std::to_string(size[1]) + (pass ? " stalls" : "")));
    // A frame that passes through, then one that keeps the mesh of the frame before it.
    Frame through = fittingFrame(kMaxWidth - 1, kMaxHeight - 2, 1.0, rng, "pass-through");
    through.enable = false, through.loadMesh = false;
    frames.push_back(through);
    Frame again = frames[3];
    again.name += ", mesh kept", again.loadMesh = false, again.info ^= 1;
    frames.insert(frames.begin() + 4, again);
    const RunResult r = runStream(top, frames, rng, gap, stall);
    EXPECT_EQ(r.mismatch, "");
    for (size_t k = 0; k < frames.size(); ++k)
      EXPECT_FALSE(r.rowMiss[k]) << frames[k].name << ": row_miss_o with a calibration that fits";
    EXPECT_EQ(r.errorEvents[0] + r.errorEvents[1] + r.errorEvents[2], 0u) << "framing errors on well-formed frames";
  }
}

TEST_F(SgmRectify, FramesOfOneLagStreamWithoutFlush) {
  // Four frames of one size and lag, meshes loaded while the frame before streams: the frame
  // period is the frame's pixels plus the row starts, not the lag's rows.
  Top top("sgm_rectify_period");
  start(top);
  std::mt19937 rng(3);
  const int w = kMaxWidth, h = kMaxHeight - 3;  // not a multiple of ROWS: each frame starts at another slot
  std::vector<Frame> frames;
  frames.push_back(fittingFrame(w, h, 2.0, rng, "frame 0"));
  const int lag = frames[0].lag;
  ASSERT_GT(lag, 0) << "the test wants a calibration with a lag";
  for (int k = 1; k < 4; ++k) frames.push_back(fittingFrame(w, h, 2.0, rng, "frame " + std::to_string(k), lag));
  for (Frame& f : frames) f.loadMesh = true;
  const RunResult r = runStream(top, frames, rng, 0.0, 0.0);
  ASSERT_EQ(r.mismatch, "");
  const double period = double(r.firstInCycle[3] - r.firstInCycle[1]) / 2.0;
  // Each row costs its pixels and 5 cycles of row start (plus a few per frame); the flush of
  // lag + 1 rows (the schedule without overlap) would cost (lag + 1) W more.
  EXPECT_LE(period, double(w * h + 5 * h + 4)) << "lag " << lag;
  std::cout << "[ figures  ] " << w << "x" << h << " lag " << lag << ": " << period / (w * h)
            << " cycles per pixel per frame, frames back to back\n";
}

void shrink(Frame& f, double factor) {
  for (sgm::Mesh& m : f.mesh) sgm::tb::shrinkMesh(m, factor);
}

TEST_F(SgmRectify, FramesOfTwoSizesBackToBackUnderStalls) {
  // Every pixel inside (the last one of each frame too, read while the next frame starts), the
  // frames' rows starting at other buffer slots, input gaps and output stalls.
  Top top("sgm_rectify_sizes");
  start(top);
  std::mt19937 rng(17);
  std::vector<Frame> frames;
  for (int k = 0; k < 6; ++k) {
    const int w = k % 2 ? kMaxWidth - 5 : kMaxWidth, h = k % 2 ? kMaxHeight - 7 : kMaxHeight - 3;
    Frame f;
    for (double strength = 1.0;; strength *= 0.7) {  // the strongest shrunk mesh that fits
      f = fittingFrame(w, h, strength, rng, "frame " + std::to_string(k));
      shrink(f, 0.9);
      f.lag = 0;
      for (const sgm::Mesh& m : f.mesh) f.lag = std::max(f.lag, sgm::meshRowSpan(m).lag);
      bool fits = true;
      for (const sgm::Mesh& m : f.mesh) fits = fits && sgm::meshRowSpan(m).back >= f.lag + 2 - kRows;
      if (fits) break;
    }
    frames.push_back(f);
  }
  const RunResult r = runStream(top, frames, rng, 0.3, 0.3);
  EXPECT_EQ(r.mismatch, "");
  for (size_t k = 0; k < frames.size(); ++k) EXPECT_FALSE(r.rowMiss[k]) << frames[k].name;
}

// The same mesh on every channel: source (x + du, y + dv + tilt x / (w - 1)), in px.
void setMesh(Frame& f, double du, double dv, double tilt) {
  for (sgm::Mesh& m : f.mesh)
    for (int i = 0; i < m.nodesY; ++i)
      for (int j = 0; j < m.nodesX; ++j) {
        const double x = j << kGridLog2, y = i << kGridLog2;
        m.u[size_t(i) * m.nodesX + j] = int32_t(std::lround((x + du) * 32));
        m.v[size_t(i) * m.nodesX + j] = int32_t(std::lround((y + dv + tilt * x / (f.w - 1)) * 32));
      }
}

TEST_F(SgmRectify, LagsAtTheBufferLimits) {
  // A frame that reads ROWS - 3 rows back (lag 0), then frames that read rows y .. y + ROWS - 2
  // (lag ROWS - 2) given lags of ROWS - 1 and 200: the input of the second may not run ahead
  // of the first's last rows, and the lags above ROWS - 2 are taken as ROWS - 2 (the input
  // never overwrites a row of the frame before it is read).
  Top top("sgm_rectify_lag");
  start(top);
  std::mt19937 rng(23);
  Frame back = fittingFrame(kMaxWidth, kMaxHeight, 0.0, rng, "reads ROWS - 3 rows back");
  setMesh(back, 0, -(kRows - 3), 0);
  ASSERT_EQ(sgm::meshRowSpan(back.mesh[0]).back, -(kRows - 3));
  back.lag = 0;
  Frame ahead = fittingFrame(kMaxWidth, kMaxHeight, 0.0, rng, "lag ROWS - 1");
  setMesh(ahead, 0, 0, kRows - 2.5);
  ASSERT_EQ(sgm::meshRowSpan(ahead.mesh[0]).lag, kRows - 2);
  ASSERT_EQ(sgm::meshRowSpan(ahead.mesh[0]).back, 0);
  ahead.lag = kRows - 1;
  Frame far = ahead;
  far.name = "lag 200", far.lag = 200, far.loadMesh = false, far.info ^= 1;
  Frame g = fittingFrame(kMaxWidth, kMaxHeight, 1.0, rng, "after them");
  const RunResult r = runStream(top, {back, ahead, far, g}, rng, 0.0, 0.2);
  EXPECT_EQ(r.mismatch, "");
  for (int k = 0; k < 4; ++k) EXPECT_FALSE(r.rowMiss[size_t(k)]) << "frame " << k;
}

TEST_F(SgmRectify, MalformedInputIsFlaggedAndTheNextFrameIsExact) {
  Top top("sgm_rectify_malformed");
  start(top);
  std::mt19937 rng(21);
  const int w = kMaxWidth, h = 16;
  Frame early = fittingFrame(w, h, 1.0, rng, "tlast early");
  early.check = false, early.errors = 1;
  early.beats.erase(early.beats.begin() + 2 * w + w - 3, early.beats.begin() + 2 * w + w - 1);  // row 2: w - 2 beats
  early.beats[size_t(2 * w + w - 3)].last = true;
  Frame missing = fittingFrame(w, h, 1.0, rng, "tlast missing");
  missing.check = false, missing.errors = 2;
  missing.beats[size_t(w + w - 1)].last = false;  // row 1 ends at its last column without tlast
  Frame cut = fittingFrame(w, h, 1.0, rng, "cut by a tuser");
  cut.check = false, cut.errors = 4;
  cut.beats.resize(size_t(3 * w + 5));  // the next frame's tuser comes inside it
  Frame extra = fittingFrame(w, h, 1.0, rng, "beats after the last row");
  for (int k = 0; k < 7; ++k) extra.beats.push_back(Beat{uint32_t(k), false, k == 6});
  Frame after = fittingFrame(w, h, 1.0, rng, "after the malformed frames");
  const RunResult r = runStream(top, {early, missing, cut, extra, after}, rng, 0.2, 0.2);
  EXPECT_EQ(r.mismatch, "");
  EXPECT_EQ(r.errorEvents[0], 1u) << "LAST_EARLY events";
  EXPECT_EQ(r.errorEvents[1], 1u) << "LAST_MISSING events";
  EXPECT_EQ(r.errorEvents[2], 1u) << "START_INSIDE events";
}

TEST_F(SgmRectify, RowMissWhenTheCalibrationNeedsMoreRows) {
  Top top("sgm_rectify_miss");
  start(top);
  std::mt19937 rng(9);
  // A vertical squeeze: the bottom rows read far behind (back much below lag + 2 - ROWS).
  Frame f = fittingFrame(kMaxWidth, kMaxHeight, 0.0, rng, "squeezed rows");
  for (sgm::Mesh& m : f.mesh)
    for (int32_t& v : m.v) v = v / 2;
  const sgm::RowSpan span = sgm::meshRowSpan(f.mesh[0]);
  ASSERT_GT(span.rows + 1, kRows) << "the test mesh must not fit";
  f.lag = std::max(0, span.lag);
  f.check = false;
  // The next frame (another lag: it waits for the squeezed frame's output) starts clean.
  Frame g = fittingFrame(kMaxWidth, 12, 1.0, rng, "after the miss");
  const RunResult r = runStream(top, {f, g}, rng, 0.0, 0.0);
  EXPECT_EQ(r.mismatch, "");
  EXPECT_TRUE(r.rowMiss[0]);
  EXPECT_FALSE(top->row_miss_o) << "after the miss";
}

}  // namespace
