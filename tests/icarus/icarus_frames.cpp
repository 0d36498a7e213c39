// SPDX-License-Identifier: Apache-2.0
// sgm-icarus-frames: the files of the Icarus Verilog run (make icarus) and its
// verdict. tb/icarus/tb_sgm_top_files.sv streams the frames through sgm_top.
//
//   sgm-icarus-frames write DIR   synthetic scenes (tools/synthetic_scene) ->
//                                 DIR/cfg.txt (each frame's configuration word
//                                 in hexadecimal, tb/hardware_config.hpp),
//                                 DIR/in.txt, DIR/expected.txt (the golden
//                                 model's output beats)
//   sgm-icarus-frames check DIR   DIR/out.txt (the testbench's) against
//                                 DIR/expected.txt: framing, every pixel,
//                                 error_o of every frame; one line, exit 1 on
//                                 the first difference, naming (x, y),
//                                 expected and got.
#include "hardware_config.hpp"
#include "synthetic_scene.hpp"

#include "sgm/params.hpp"
#include "sgm/pipeline.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kD = 16;  // the Icarus build (make icarus: -Ptb_sgm_top_files.D=16)
#ifndef ICARUS_RIGHT_BLOCK
#error "ICARUS_RIGHT_BLOCK: the Icarus build's fifth-path block (tests/icarus.mk)"
#endif

struct Frame {
  int width, height;
  sgm::Params params;
};

// Two frames back to back with different parameter sets (the second one
// checks that the configuration is taken at its start of frame).
std::vector<Frame> frames() {
  sgm::BuildLevers build;  // the Icarus build: all levers, the fifth path in blocks of ICARUS_RIGHT_BLOCK
  build.rightBlock = ICARUS_RIGHT_BLOCK;
  const sgm::Params defaults = sgm::buildDefaults(build, kD);
  sgm::Params other = defaults;
  other.mode = sgm::CostMode::kUnified, other.p1 = 40, other.p2 = 200, other.median = false, other.lrTolerance = 0;
  other.p2Mode = sgm::P2Mode::kPaper, other.weights = sgm::PathWeighting::kEqual;  // the paper's run-time options
  return {{40, 14, defaults}, {33, 10, other}};
}

cv::Mat scene(const Frame& f, int k, bool right) {
  const sgm::synth::SyntheticScene s = sgm::synth::makeSyntheticScene(f.width, f.height, kD, 1000 + k);
  return right ? s.right : s.left;
}

void write(const std::string& dir) {
  std::ofstream cfg(dir + "/cfg.txt"), in(dir + "/in.txt"), expected(dir + "/expected.txt");
  const std::vector<Frame> all = frames();
  cfg << all.size() << "\n";
  for (size_t k = 0; k < all.size(); ++k) {
    const Frame& f = all[k];
    cfg << sgm::tb::hardwareConfig(f.params, f.width, f.height).hex() << "\n";
    const cv::Mat left = scene(f, int(k), false), right = scene(f, int(k), true);
    const sgm::DisparityMap golden = sgm::runPipeline(left, right, f.params);
    char line[32];
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        const bool sof = x == 0 && y == 0, eol = x == f.width - 1;
        std::snprintf(line, sizeof line, "%04x %d %d\n", left.at<uint8_t>(y, x) | right.at<uint8_t>(y, x) << 8, sof,
                      eol);
        in << line;
        const int tdata = golden.valid.at<uint8_t>(y, x) << 15 | golden.disp.at<uint16_t>(y, x);
        std::snprintf(line, sizeof line, "%04x %d %d\n", tdata, sof, eol);
        expected << line;
      }
  }
  if (!cfg || !in || !expected) throw sgm::Error("cannot write the files in " + dir);
  std::cout << "icarus: " << all.size() << " frames (D = " << kD << ") written to " << dir << "\n";
}

// 0 when out.txt equals expected.txt beat for beat and every frame ended with error_o = 0.
int check(const std::string& dir) {
  std::ifstream expected(dir + "/expected.txt"), out(dir + "/out.txt");
  if (!expected || !out) throw sgm::Error("cannot read " + dir + "/expected.txt or " + dir + "/out.txt");
  const std::vector<Frame> all = frames();
  std::vector<std::string> done;  // "done <error_o> <width> <height>" lines
  std::string line;
  long beats = 0;
  for (size_t k = 0; k < all.size(); ++k)
    for (int y = 0; y < all[k].height; ++y)
      for (int x = 0; x < all[k].width; ++x) {
        std::string want, got;
        std::getline(expected, want);
        while (std::getline(out, got) && got.rfind("done ", 0) == 0) done.push_back(got);
        if (!out) {
          std::cout << "icarus: FAIL: the output ends after " << beats << " beats (frame " << k << ", x=" << x
                    << ", y=" << y << ")\n";
          return 1;
        }
        if (got != want) {
          std::cout << "icarus: FAIL: stage sgm_top output (Icarus), frame " << k << ", first mismatch at (x=" << x
                    << ", y=" << y << "): expected \"" << want << "\", got \"" << got
                    << "\" (tdata = valid << 15 | disparity x 16, tuser, tlast)\n";
          return 1;
        }
        ++beats;
      }
  while (std::getline(out, line)) {
    if (line.rfind("done ", 0) != 0) {
      std::cout << "icarus: FAIL: output beat after the last frame: " << line << "\n";
      return 1;
    }
    done.push_back(line);
  }
  if (done.size() != all.size()) {
    std::cout << "icarus: FAIL: " << done.size() << " frame_done_o pulses for " << all.size() << " frames\n";
    return 1;
  }
  for (size_t k = 0; k < done.size(); ++k) {
    const std::string want = "done 0 " + std::to_string(all[k].width) + " " + std::to_string(all[k].height);
    if (done[k] != want) {
      std::cout << "icarus: FAIL: frame " << k << " ended with \"" << done[k] << "\", expected \"" << want
                << "\" (error_o, frame_width_o, frame_height_o)\n";
      return 1;
    }
  }
  std::cout << "icarus: PASS: " << all.size() << " frames, " << beats << " pixels bit-exact against the golden model\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string cmd = argc == 3 ? argv[1] : "";
    if (cmd == "write") return write(argv[2]), 0;
    if (cmd == "check") return check(argv[2]);
    std::cerr << "usage: sgm-icarus-frames write|check DIR\n";
    return 2;
  } catch (const std::exception& e) {
    std::cout << "icarus: FAIL: " << e.what() << "\n";
    return 1;
  }
}
