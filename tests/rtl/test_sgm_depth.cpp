// SPDX-License-Identifier: Apache-2.0
// sgm_depth against the golden model's depth (docs/algorithm.md section 10b) word by word:
// every disparity word of the build's width, valid and invalid, for f and B that reach
// the saturation boundary floor(N / 2^16) = V exactly (f = 2^20 / 256 px, B = k mm: at
// dq = k), saturate everything, give 1 mm everywhere, f = 0, and random ones; idle slots
// (en_i low) between them, and the disparity mode's word.
#include "Vsgm_depth.h"
#include "Vsgm_depth_sgm_depth.h"
#include "verilated_top.hpp"

#include "sgm/depth.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <vector>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_depth>;
constexpr int kDw = Vsgm_depth_sgm_depth::DW;

struct Pixel {
  uint32_t dq;
  bool valid;
};

// One frame's constants, then every pixel through the stage with random idle slots; returns
// "" or the first differing word.
std::string runFrame(Top& top, uint32_t focal, uint32_t baseline, bool depth, const std::vector<Pixel>& pixels,
                     std::mt19937& rng) {
  top->focal_i = focal, top->baseline_i = baseline, top->depth_en_i = depth, top->ready_i = 1;
  top->en_i = 0, top->start_i = 1;
  top.tick();
  top->start_i = 0;
  for (int cycles = 0; !top->ready_o; ++cycles) {
    if (cycles > 30) return "the product K = F B did not finish in 30 cycles";
    top.tick();
  }
  std::vector<uint16_t> got;
  size_t next = 0;
  for (long cycle = 0; got.size() < pixels.size(); ++cycle) {
    if (cycle > 4 * long(pixels.size()) + 200) return "only " + std::to_string(got.size()) + " words came out";
    top->en_i = rng() % 4 != 0;
    top->in_valid_i = top->en_i && next < pixels.size();
    top->disp_i = top->in_valid_i ? pixels[next].dq : rng() & ((1u << kDw) - 1);
    top->valid_i = top->in_valid_i ? pixels[next].valid : rng() & 1;
    const bool enabled = top->en_i;
    if (top->in_valid_i) ++next;
    top.tick();
    if (enabled && top->out_valid_o) got.push_back(uint16_t(top->word_o));
  }
  for (size_t i = 0; i < pixels.size(); ++i) {
    const Pixel& p = pixels[i];
    const uint16_t expected = depth ? (p.valid ? sgm::depthMm(focal, baseline, p.dq) : 0)
                                    : uint16_t((p.valid ? 0x8000u : 0u) | p.dq);
    if (got[i] != expected) {
      std::ostringstream m;
      m << "stage sgm_depth (" << (depth ? "depth" : "disparity") << " mode, F " << focal << ", B " << baseline
        << "): first mismatch at pixel " << i << " (dq " << p.dq << ", valid " << p.valid << "): expected " << expected
        << ", got " << got[i];
      return m.str();
    }
  }
  return "";
}

// Every disparity word 0 .. 2^DW - 1, valid ones and invalid ones, in random order.
std::vector<Pixel> everyWord(std::mt19937& rng) {
  std::vector<Pixel> pixels;
  for (uint32_t dq = 0; dq < (1u << kDw); ++dq) pixels.push_back({dq, rng() % 5 != 0});
  std::shuffle(pixels.begin(), pixels.end(), rng);
  return pixels;
}

TEST(SgmDepth, EveryWordAgainstTheGoldenDepth) {
  Top top("sgm_depth");
  top.reset();
  std::mt19937 rng(10);
  std::vector<std::pair<uint32_t, uint32_t>> constants = {
      {700 * 256, 60000},                // 700 px, 60 mm
      {(1u << 24) - 1, (1u << 24) - 1},  // K near 2^48: 65535 everywhere
      {1, 1},                            // 1 mm everywhere
      {0, 120000},                       // f = 0: 1 mm
      {1000 * 256 + 17, 1003},           // about 1000 / d mm
  };
  for (uint32_t k = 1; k <= 8; ++k) constants.push_back({1u << 20, 1000 * k});  // floor(N / 2^16) = V at dq = k
  for (int i = 0; i < 6; ++i) constants.push_back({rng() % (1u << 24), rng() % (1u << 24)});
  for (const auto& [f, b] : constants) EXPECT_EQ(runFrame(top, f, b, true, everyWord(rng), rng), "");
  EXPECT_EQ(runFrame(top, 700 * 256, 60000, false, everyWord(rng), rng), "");
}

// The boundary constants do reach floor(N / 2^16) = V: the golden depth saturates there
// and not one disparity step further.
TEST(SgmDepth, BoundaryConstantsReachTheSaturation) {
  for (uint32_t k = 1; k <= 8; ++k) {
    const uint64_t K = uint64_t(1u << 20) * (1000 * k), n = K + 8000 * k, v = 16000 * k;
    EXPECT_EQ(n >> 16, v) << k;
    EXPECT_EQ(sgm::depthMm(1u << 20, 1000 * k, k), sgm::kDepthMax) << k;
  }
}

}  // namespace
