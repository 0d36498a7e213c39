// SPDX-License-Identifier: Apache-2.0
// The slot driver shared by the module fixtures: a verilated model with an
// en_i input is stepped one enabled slot at a time, each slot preceded by the
// disabled cycles of a seeded random enable pattern. While en_i = 0 every other
// input carries random junk and every output must hold; each enabled slot is
// recorded (a caller-chosen tag), so that a check can find the slot whose
// result the outputs show after a pipeline latency.
#pragma once

#include "port_bits.hpp"
#include "verilated_top.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sgm::tb {

// Enable pattern: mostly on (a cycle is enabled with probability onRate, so
// single-cycle gaps), and with probability longStallRate per cycle a long stall
// of up to 39 disabled cycles. longStallRate = 0 with onRate = 1 never stalls.
class EnablePattern {
 public:
  static constexpr double kLongStallRate = 0.002;

  EnablePattern(uint32_t seed, double onRate, double longStallRate = kLongStallRate)
      : seed_(seed), rng_(seed), on_(onRate), longStall_(longStallRate) {}
  bool next() {
    if (stall_ > 0) return --stall_, false;
    if (longStall_(rng_)) stall_ = int(rng_() % 40);
    return on_(rng_);
  }
  uint32_t seed() const { return seed_; }

 private:
  uint32_t seed_;
  std::mt19937 rng_;
  std::bernoulli_distribution on_, longStall_;
  int stall_ = 0;
};

template <class Model, class Tag>
class SlotDriver {
 public:
  using Top = VerilatedTop<Model>;
  // Sets every input but clk_i / rst_ni / en_i to junk.
  using JunkInputs = std::function<void(Model&, std::mt19937&)>;
  // The output ports that en_i = 0 must hold (portWords(...) of them).
  using Outputs = std::function<std::vector<uint32_t>(Model&)>;

  // The junk generator is seeded from the pattern's seed.
  SlotDriver(Top& top, const EnablePattern& enable, JunkInputs junkInputs, Outputs outputs)
      : top_(top),
        enable_(enable),
        junk_(enable.seed() ^ 0x9e3779b9u),
        junkInputs_(std::move(junkInputs)),
        outputs_(std::move(outputs)),
        held_(outputs_(top.model())) {}

  // Reset with en_i = 0 and junk on the inputs; the outputs after it are held.
  void reset(int cycles = 2) {
    top_->en_i = 0;
    junkInputs_(top_.model(), junk_);
    top_.reset(cycles);
    held_ = outputs_(top_.model());
  }

  // One enabled slot: first the disabled cycles the pattern asks for (junk
  // inputs; the outputs must not change, else a fatal failure naming where()),
  // then the tag is recorded, drive(model) sets the slot's inputs and one
  // cycle runs with en_i = 1. False after a fatal failure.
  template <class Drive, class Where>
  bool slot(const Tag& tag, Drive&& drive, Where&& where) {
    while (!enable_.next()) {
      junkInputs_(top_.model(), junk_);
      top_->en_i = 0;
      top_.tick();
      if (!holds(where)) return false;
    }
    history_.push_back(tag);
    drive(top_.model());
    top_->en_i = 1;
    top_.tick();
    held_ = outputs_(top_.model());
    return true;
  }

  // Tag of the slot whose result the outputs show after the last enabled slot
  // in a pipeline of `latency` slots (the input just sampled is one of them);
  // nullptr before the first such slot.
  const Tag* source(int latency) const {
    const long i = long(history_.size()) - latency;
    return i >= 0 ? &history_[size_t(i)] : nullptr;
  }
  const std::vector<Tag>& history() const { return history_; }
  long slots() const { return long(history_.size()); }
  std::mt19937& junk() { return junk_; }

 private:
  template <class Where>
  bool holds(Where& where) {
    const std::vector<uint32_t> now = outputs_(top_.model());
    if (now == held_) return true;
    size_t i = 0;
    while (now[i] == held_[i]) ++i;
    [&] {
      FAIL() << where() << ": outputs changed while en_i = 0 (output word " << i << ": " << held_[i] << " -> " << now[i]
             << ", cycle " << top_.cycles() << ")";
    }();
    return false;
  }

  Top& top_;
  EnablePattern enable_;
  std::mt19937 junk_;
  JunkInputs junkInputs_;
  Outputs outputs_;
  std::vector<uint32_t> held_;
  std::vector<Tag> history_;
};

// "first mismatch at (x, y) = (X, Y) of WHAT: expected E, got G [stage: S]",
// the one-line report of a fixture's first wrong pixel.
inline std::string firstMismatch(int x, int y, const std::string& what, const std::string& expected,
                                 const std::string& got, const std::string& stage) {
  std::ostringstream s;
  s << "first mismatch at (x, y) = (" << x << ", " << y << ") of " << what << ": expected " << expected << ", got "
    << got;
  if (!stage.empty()) s << " [stage: " << stage << "]";
  return s.str();
}

}  // namespace sgm::tb
