// SPDX-License-Identifier: Apache-2.0
// Small command-line parser shared by the project's tools: positional
// arguments plus "--name value" options, every error a one-line sgm::Error.
#pragma once

#include "sgm/params.hpp"

#include <array>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sgm {

class CliArgs {
 public:
  // valueOptions take a value ("--d 64"); flags take none ("--help").
  CliArgs(int argc, char** argv, const std::set<std::string>& valueOptions, const std::set<std::string>& flags = {});

  const std::vector<std::string>& positional() const { return positional_; }
  bool has(const std::string& name) const { return values_.count(name) || flags_.count(name); }
  std::string text(const std::string& name, const std::string& fallback) const;
  long integer(const std::string& name, long fallback, long min, long max) const;
  double real(const std::string& name, double fallback, double min, double max) const;
  bool onOff(const std::string& name, bool fallback) const;

  // Reads --d, --p1, --p2, --mode, --subpixel, --lr, --uniqueness, --ad-weight W, --ad-cap T,
  // --fill, --snap, --median, --census, --p2-mode, --weights and --preset into params, and the
  // golden-only experiments (not in the RTL, off by default): --right-path W, --right-block B,
  // --subpixel-fit parabola|linear, --mgm on|off, --median-gate T, --p1-paths A,B,C,D,E,
  // --snap-edge T, --lr-store-bits N, --edge-reset T, --edge-reset-len R, --edge-reset-paths A,B,C,D,E. --preset (default | four-path | paper) replaces
  // base (D excepted) before the other options apply, so they override it; --mode also
  // brings that mode's default P1 / P2' (defaultParams), which --p1 / --p2 override,
  // and a mode without a census switches the AD term off.
  static const std::set<std::string>& pipelineOptions();
  Params pipelineParams(Params base = Params{}) const;

 private:
  // Option `name` as five comma-separated integers min .. max, one per path (0, 45, 90,
  // 135 degrees, the fifth path); `what` names them in the error ("five percentages").
  std::array<int, kPathCount + 1> perPath(const std::string& name, int min, int max, const std::string& what) const;

  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
};

// The text with control characters shown as \n, \t, \xNN: one printable
// line even when a file name or an option value holds a newline.
std::string oneLine(const std::string& text);

// A tool's error exit: prints "TOOL: error: MESSAGE" as one line on stderr
// and returns 2, the exit status of every user error.
int reportError(const char* tool, const std::exception& error);

}  // namespace sgm
