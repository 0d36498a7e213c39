// SPDX-License-Identifier: Apache-2.0
// AXI4-Stream bus-functional models with seeded random stalls, for any
// verilated top with the core's port names (s_tdata_i/s_tuser_i/s_tlast_i/
// s_tvalid_i/s_tready_o in, m_tdata_o/m_tuser_o/m_tlast_o/m_tvalid_o/
// m_tready_i out). Call drive() before the clock edge and sample() after the
// model has evaluated its inputs (before the edge), then tick.
#pragma once

#include "axis_checker.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::tb {

// How a side of the stream stalls (the source idles, the sink is not ready).
// A plain number p means: each cycle stalls with probability p.
struct StallProfile {
  enum class Kind { kRandom, kBursts, kToggle };
  Kind kind = Kind::kRandom;
  double probability = 0;                         // kRandom: a cycle stalls; kBursts: a burst starts on a cycle
  int burstMin = 0, burstMax = 0;                 // kBursts: burst length in cycles
  StallProfile(double p = 0) : probability(p) {}  // NOLINT: implicit on purpose
  static StallProfile bursts(double start, int minCycles, int maxCycles) {
    StallProfile s(start);
    s.kind = Kind::kBursts, s.burstMin = minCycles, s.burstMax = maxCycles;
    return s;
  }
  // Every other cycle (valid or ready toggles each cycle).
  static StallProfile toggle() {
    StallProfile s;
    s.kind = Kind::kToggle;
    return s;
  }
  std::string describe() const {
    std::ostringstream text;
    if (kind == Kind::kToggle)
      text << "toggle";
    else if (kind == Kind::kBursts)
      text << "bursts " << burstMin << ".." << burstMax << "@" << probability;
    else
      text << probability;
    return text.str();
  }
};

// Stall densities of the two sides.
struct Stalls {
  StallProfile sourceIdle;
  StallProfile sinkBusy;
};

// Per-cycle stall decisions of one side from a seed.
class StallPattern {
 public:
  StallPattern(uint32_t seed, StallProfile profile) : rng_(seed), profile_(profile) {}
  void setProfile(StallProfile profile) { profile_ = profile, burstLeft_ = 0; }
  // Called once per cycle: does this cycle stall?
  bool next() {
    switch (profile_.kind) {
      case StallProfile::Kind::kToggle: return (phase_ ^= 1) != 0;
      case StallProfile::Kind::kBursts:
        if (burstLeft_ == 0 && chance(profile_.probability))
          burstLeft_ = std::uniform_int_distribution<int>(profile_.burstMin, profile_.burstMax)(rng_);
        if (burstLeft_ == 0) return false;
        --burstLeft_;
        return true;
      case StallProfile::Kind::kRandom: break;
    }
    return chance(profile_.probability);
  }

 private:
  bool chance(double p) { return p > 0 && std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::mt19937 rng_;
  StallProfile profile_;
  int burstLeft_ = 0;
  unsigned phase_ = 0;
};

template <class Model>
class AxisSource {
 public:
  AxisSource(uint32_t seed, StallProfile idle) : stalls_(seed, idle) {}

  void push(const Beat& b) { queue_.push_back(b); }
  void push(const std::vector<Beat>& beats) { queue_.insert(queue_.end(), beats.begin(), beats.end()); }
  bool empty() const { return queue_.empty() && !valid_; }
  size_t pending() const { return queue_.size() + (valid_ ? 1 : 0); }
  void setIdle(StallProfile idle) { stalls_.setProfile(idle); }
  // Bus reset: the beat on the bus and the queue are dropped.
  void clear() { queue_.clear(), valid_ = false; }
  // Beats from this count of accepted beats on are held back (not presented) until the limit
  // rises: a frame waits at its first beat for something the harness does first.
  void setLimit(uint64_t acceptedLimit) { limit_ = acceptedLimit; }

  // Before the edge: presents a beat (valid never drops before its handshake).
  void drive(Model& m) {
    const bool idle = stalls_.next();
    if (!valid_ && !queue_.empty() && !idle && accepted_ < limit_) {
      current_ = queue_.front();
      queue_.pop_front();
      valid_ = true;
    }
    m.s_tvalid_i = valid_;
    m.s_tdata_i = uint16_t(current_.data);
    m.s_tuser_i = current_.user;
    m.s_tlast_i = current_.last;
  }
  // Before the edge, after eval: did the handshake happen?
  bool sample(const Model& m) {
    const bool fire = valid_ && m.s_tready_o;
    if (fire) valid_ = false, ++accepted_;
    return fire;
  }
  uint64_t accepted() const { return accepted_; }

 private:
  StallPattern stalls_;
  std::deque<Beat> queue_;
  Beat current_;
  bool valid_ = false;
  uint64_t accepted_ = 0;
  uint64_t limit_ = UINT64_MAX;
};

// Records the output beats and checks the stream rules (AxisChecker: the
// handshake always, the framing of the frames announced with expectFrame).
template <class Model>
class AxisSink {
 public:
  AxisSink(uint32_t seed, StallProfile busy) : stalls_(seed, busy) {}
  void setBusy(StallProfile busy) { stalls_.setProfile(busy); }

  void drive(Model& m) { m.m_tready_i = !stalls_.next(); }

  // Before the edge, after eval: records a transfer and checks the rules.
  // `cycle` names the cycle in violations (default: count of sample calls).
  bool sample(const Model& m, std::optional<uint64_t> cycle = std::nullopt) {
    const Beat now{uint32_t(m.m_tdata_o), bool(m.m_tuser_o), bool(m.m_tlast_o)};
    const bool fire = checker_.observe(cycle.value_or(samples_), m.m_tvalid_o, m.m_tready_i, now);
    ++samples_;
    if (fire) beats_.push_back(now);
    return fire;
  }

  std::vector<Beat>& beats() { return beats_; }
  AxisChecker& checker() { return checker_; }
  const std::string& violation() const { return checker_.violation(); }

 private:
  StallPattern stalls_;
  AxisChecker checker_;
  std::vector<Beat> beats_;
  uint64_t samples_ = 0;
};

// The beats of one well-formed frame from a left/right gray pair (row-major,
// width x height bytes each).
inline std::vector<Beat> frameBeats(const uint8_t* left, const uint8_t* right, int width, int height, size_t leftStride,
                                    size_t rightStride) {
  std::vector<Beat> beats;
  beats.reserve(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      beats.push_back(
          Beat{uint16_t(left[y * leftStride + x] | right[y * rightStride + x] << 8), x == 0 && y == 0, x == width - 1});
  return beats;
}

}  // namespace sgm::tb
