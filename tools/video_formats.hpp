// SPDX-License-Identifier: Apache-2.0
// The one table of video formats the reports use (pnr-summary's clock per format,
// sgm-bench's simulated frames and clocks, the datasheet): the paper's Table II
// sizes (its clock at 9 cycles per pixel) and the HD formats this core aims at.
// Active pixels only.
#pragma once

namespace sgm::eval {

struct VideoFormat {
  const char* name;
  int width, height, fps;
  double paperMhz;  // the paper's clock (Table II, 9 cycles per pixel); 0 where it has no column
};

inline constexpr VideoFormat kVideoFormats[] = {
    {"450x375p30", 450, 375, 30, 45.6},  {"450x375p60", 450, 375, 60, 91.1},    {"640x480p30", 640, 480, 30, 82.9},
    {"640x480p60", 640, 480, 60, 165.9}, {"1280x720p30", 1280, 720, 30, 248.8}, {"1280x720p60", 1280, 720, 60, 0},
    {"1920x1080p30", 1920, 1080, 30, 0}, {"1920x1080p60", 1920, 1080, 60, 0},
};

// The clock (MHz) the format needs at cyclesPerPixel cycles per active pixel.
inline double neededMhz(const VideoFormat& f, double cyclesPerPixel) {
  return double(f.width) * f.height * f.fps * cyclesPerPixel / 1e6;
}

}  // namespace sgm::eval
