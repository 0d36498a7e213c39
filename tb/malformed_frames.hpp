// SPDX-License-Identifier: Apache-2.0
// Malformed input frames for the whole-core tests and the regression: each
// kind breaks one framing rule of the input stream, and says which error_o bit
// the core must raise for it (docs/rtl.md, "Malformed frames"). The core still
// owes W x H output beats for every frame it started.
#pragma once

#include "core_harness.hpp"

#include <string>
#include <vector>

namespace sgm::tb {

enum class Malformation {
  kLongLine,        // one line longer than the configured width (at most MAX_WIDTH)
  kBeyondMaxWidth,  // one line longer than MAX_WIDTH
  kMissingLast,     // no tlast on the last beat of a line (the next line runs on)
  kEarlyLast,       // tlast before the last column, the line ends there
  kStartInside,     // the next frame's tuser arrives in the middle of this frame
  kStrayStart,      // a beat inside the frame carries tuser, the frame's other beats follow
  kFewLines,        // the frame stops after fewer than H lines
};

constexpr Malformation kAllMalformations[] = {
    Malformation::kLongLine,    Malformation::kBeyondMaxWidth, Malformation::kMissingLast, Malformation::kEarlyLast,
    Malformation::kStartInside, Malformation::kStrayStart,     Malformation::kFewLines};

// error_o bits (sgm_stream_ctrl).
constexpr unsigned kErrorLastEarly = 1u << 0, kErrorLastMissing = 1u << 1, kErrorStartInside = 1u << 2;

inline const char* malformationName(Malformation kind) {
  switch (kind) {
    case Malformation::kLongLine: return "long-line";
    case Malformation::kBeyondMaxWidth: return "line-beyond-max-width";
    case Malformation::kMissingLast: return "missing-tlast";
    case Malformation::kEarlyLast: return "early-tlast";
    case Malformation::kStartInside: return "tuser-mid-frame";
    case Malformation::kStrayStart: return "stray-tuser";
    case Malformation::kFewLines: return "too-few-lines";
  }
  return "?";
}

// The frames the source sends for one malformed frame, and the error_o each
// of them must end with (a stray tuser starts a second, truncated frame).
struct MalformedFrames {
  std::vector<FrameInput> frames;
  std::vector<unsigned> errors;
  std::string description;  // what was broken where
};

// Breaks `frame` (a well-formed W x H frame, H >= 2) as `kind` says at a place
// chosen by `at` (any number: reduced to a legal line / beat) with `extra`
// (>= 1) additional beats for the long lines. Must be followed by a good frame.
inline MalformedFrames malform(const FrameInput& frame, Malformation kind, int maxWidth, unsigned at, unsigned extra) {
  const int w = frame.left.cols, h = frame.left.rows;
  const std::vector<Beat> good = frameBeats(frame.left.data, frame.right.data, w, h, frame.left.step, frame.right.step);
  const auto line = [&](int y) {
    return std::vector<Beat>(good.begin() + size_t(y) * w, good.begin() + size_t(y + 1) * w);
  };
  const int row = int(at % unsigned(h));
  const size_t cut = 1 + at % (good.size() - 1);  // 1 .. W H - 1 beats kept
  MalformedFrames m{{frame}, {0}, std::string(malformationName(kind))};
  std::vector<Beat>& beats = m.frames[0].rawBeats;
  switch (kind) {
    case Malformation::kLongLine:
    case Malformation::kBeyondMaxWidth: {
      const int length = kind == Malformation::kLongLine ? std::min(maxWidth, w + 1 + int(extra % unsigned(maxWidth)))
                                                         : maxWidth + int(1 + extra % 64u);
      if (length <= w) throw Error("a long line needs a width below MAX_WIDTH");
      for (int y = 0; y < h; ++y) {
        std::vector<Beat> l = line(y);
        if (y == row) {
          l.back().last = false;
          for (int x = w; x < length; ++x) l.push_back(Beat{uint16_t(x * 0x0101), false, x == length - 1});
        }
        beats.insert(beats.end(), l.begin(), l.end());
      }
      m.errors[0] = kErrorLastMissing;
      m.description += " (line " + std::to_string(row) + " has " + std::to_string(length) + " beats)";
      break;
    }
    case Malformation::kMissingLast:
      beats = good;
      beats[size_t(row + 1) * w - 1].last = false;
      m.errors[0] = kErrorLastMissing;
      m.description += " (line " + std::to_string(row) + ")";
      break;
    case Malformation::kEarlyLast: {
      const int column = int(extra % unsigned(w - 1));  // 0 .. W-2
      for (int y = 0; y < h; ++y) {
        std::vector<Beat> l = line(y);
        if (y == row) l.resize(size_t(column) + 1), l.back().last = true;
        beats.insert(beats.end(), l.begin(), l.end());
      }
      m.errors[0] = kErrorLastEarly;
      m.description += " (line " + std::to_string(row) + " ends at column " + std::to_string(column) + ")";
      break;
    }
    case Malformation::kStartInside:
      beats.assign(good.begin(), good.begin() + cut);
      m.errors[0] = kErrorStartInside;
      m.description += " (after " + std::to_string(cut) + " beats)";
      break;
    case Malformation::kStrayStart: {
      beats.assign(good.begin(), good.begin() + cut);
      // The tuser beat starts a frame of the same configuration made of the
      // rest: its first line is short (early tlast) unless the cut is at a line
      // start, then it has too few lines.
      FrameInput rest = frame;
      rest.rawBeats.assign(good.begin() + cut, good.end());
      rest.rawBeats[0].user = true;
      m.frames.push_back(rest);
      m.errors = {kErrorStartInside, cut % w ? kErrorLastEarly : kErrorStartInside};
      m.description += " (at beat " + std::to_string(cut) + ")";
      break;
    }
    case Malformation::kFewLines: {
      const int lines = 1 + row % (h - 1);  // 1 .. H-1
      beats.assign(good.begin(), good.begin() + size_t(lines) * w);
      m.errors[0] = kErrorStartInside;
      m.description += " (" + std::to_string(lines) + " of " + std::to_string(h) + " lines)";
      break;
    }
  }
  return m;
}

}  // namespace sgm::tb
