// SPDX-License-Identifier: Apache-2.0
// The census window's slot raster, shared by the sgm_census_unit and
// sgm_cost_volume fixtures (docs/rtl.md "Window and census"): every frame is
// streamed in raster order, followed by flush slots (rows height, height+1,
// ..., pixel 0) until its last centre has entered the window; the centre of
// the slot at input (x, y) is (x - 4, y - 2), or (w + x - 4, y - 3) for x < 4.
#pragma once

#include "port_bits.hpp"
#include "slot_driver.hpp"

#include "sgm/census.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace sgm::tb {

// How a frame's flush ends: right after the slot of its last centre, (3, H+2)
// (the next frame enters while this one is still in the pipeline), or after
// complete flush rows H .. H+2.
enum class Flush { kMinimal, kFullRows };

struct CensusStreamOptions {
  Flush flush = Flush::kMinimal;
  uint32_t seed = 1;
  // Enable pattern (slot_driver.hpp): 30 % of the cycles disabled, and about
  // one long stall every 200 slots; longStallRate 0 with onRate 1: no stalls.
  double onRate = 0.7;
  double longStallRate = 0.0035;
  bool reset = true;  // start with a reset (en_i = 0, junk inputs), else continue from the model's state
  EnablePattern enablePattern() const { return EnablePattern(seed, onRate, longStallRate); }

  static CensusStreamOptions seeded(uint32_t seed, Flush flush = Flush::kMinimal) {
    CensusStreamOptions o;
    o.seed = seed;
    o.flush = flush;
    return o;
  }
  // idlePercent % of the cycles disabled, with frequent long stalls; 0: never disabled.
  static CensusStreamOptions idle(uint32_t seed, int idlePercent) {
    CensusStreamOptions o = seeded(seed);
    o.onRate = 1.0 - idlePercent / 100.0;
    o.longStallRate = idlePercent ? 0.015 : 0.0;
    return o;
  }
};

struct RasterSlot {
  int frame;  // index into the frame list
  int x, y;   // position in the virtual raster (y >= height: flush, pixel 0)
};

struct Centre {
  int x, y;
};
inline Centre centreOf(int x, int y, int w) { return x >= 4 ? Centre{x - 4, y - 2} : Centre{w + x - 4, y - 3}; }

// Every slot of the frames of these sizes, back to back; after the last frame
// `trailing` more flush slots so that its last outputs leave the pipeline.
inline std::vector<RasterSlot> censusRaster(const std::vector<cv::Size>& sizes, Flush flush, int trailing) {
  std::vector<RasterSlot> slots;
  for (int f = 0; f < int(sizes.size()); ++f) {
    const int w = sizes[f].width, h = sizes[f].height;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) slots.push_back({f, x, y});
    int extra = f + 1 == int(sizes.size()) ? trailing : 0;
    for (int x = 0, y = h;;) {
      const bool done = y > h + 2 || (y == h + 2 && flush == Flush::kMinimal && x > 3);
      if (done && extra-- <= 0) break;
      slots.push_back({f, x, y});
      if (++x == w) x = 0, ++y;
    }
  }
  return slots;
}

// Pixel of the slot: the image's at (x, y) inside the frame, 0 on flush rows.
inline uint8_t pixelOf(const cv::Mat& img, const RasterSlot& s) {
  return s.y < img.rows ? img.at<uint8_t>(s.y, s.x) : 0;
}

// Empty when the 44-bit census port (2 words) holds `want`, else
// "expected <hex> got <hex>".
template <typename Port>
std::string censusMismatch(const Port& port, const sgm::Census& want) {
  const uint64_t got = uint64_t(wordOf(port, 0)) | uint64_t(wordOf(port, 1) & 0xfffu) << 32;
  if (got == want.bits) return "";
  auto hex = [](uint64_t v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%011llx", static_cast<unsigned long long>(v));
    return std::string(buf);
  };
  return "expected " + hex(want.bits) + " got " + hex(got);
}

}  // namespace sgm::tb
