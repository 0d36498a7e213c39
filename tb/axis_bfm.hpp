// AXI4-Stream bus-functional models with seeded random stalls, for any
// verilated top with the core's port names (s_tdata_i/s_tuser_i/s_tlast_i/
// s_tvalid_i/s_tready_o in, m_tdata_o/m_tuser_o/m_tlast_o/m_tvalid_o/
// m_tready_i out). Call drive() before the clock edge and sample() after the
// model has evaluated its inputs (before the edge), then tick.
#pragma once

#include <cstdint>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sgm::tb {

struct Beat {
  uint16_t data = 0;
  bool user = false;  // start of frame
  bool last = false;  // end of line
  bool operator==(const Beat& o) const { return data == o.data && user == o.user && last == o.last; }
};

// Stall densities: probability that a cycle is idle (source) or not ready (sink).
struct Stalls {
  double sourceIdle = 0.0;
  double sinkBusy = 0.0;
};

template <class Model>
class AxisSource {
 public:
  AxisSource(uint32_t seed, double idle) : rng_(seed), idle_(idle) {}

  void push(const Beat& b) { queue_.push_back(b); }
  void push(const std::vector<Beat>& beats) { queue_.insert(queue_.end(), beats.begin(), beats.end()); }
  bool empty() const { return queue_.empty() && !valid_; }
  size_t pending() const { return queue_.size() + (valid_ ? 1 : 0); }
  void setIdle(double idle) { idle_ = idle; }

  // Before the edge: presents a beat (valid never drops before its handshake).
  void drive(Model& m) {
    if (!valid_ && !queue_.empty() && !chance(idle_)) {
      current_ = queue_.front();
      queue_.pop_front();
      valid_ = true;
    }
    m.s_tvalid_i = valid_;
    m.s_tdata_i = current_.data;
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
  bool chance(double p) { return p > 0 && std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::mt19937 rng_;
  double idle_;
  std::deque<Beat> queue_;
  Beat current_;
  bool valid_ = false;
  uint64_t accepted_ = 0;
};

template <class Model>
class AxisSink {
 public:
  AxisSink(uint32_t seed, double busy) : rng_(seed), busy_(busy) {}
  void setBusy(double busy) { busy_ = busy; }

  void drive(Model& m) { m.m_tready_i = !chance(busy_); }

  // Before the edge, after eval: records a handshake and checks the rules
  // (valid holds and data stays stable until the handshake).
  bool sample(const Model& m) {
    const Beat now{uint16_t(m.m_tdata_o), bool(m.m_tuser_o), bool(m.m_tlast_o)};
    if (waiting_ && violation_.empty()) {
      if (!m.m_tvalid_o) violation_ = "m_tvalid dropped before its handshake";
      else if (!(now == held_)) violation_ = "m_tdata/tuser/tlast changed before the handshake";
      if (!violation_.empty()) violation_ += " (beat " + std::to_string(beats_.size()) + ")";
    }
    const bool fire = m.m_tvalid_o && m.m_tready_i;
    waiting_ = m.m_tvalid_o && !m.m_tready_i;
    held_ = now;
    if (fire) beats_.push_back(now);
    return fire;
  }

  std::vector<Beat>& beats() { return beats_; }
  const std::string& violation() const { return violation_; }

 private:
  bool chance(double p) { return p > 0 && std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::mt19937 rng_;
  double busy_;
  std::vector<Beat> beats_;
  Beat held_;
  bool waiting_ = false;
  std::string violation_;
};

// The beats of one well-formed frame from a left/right gray pair (row-major,
// width x height bytes each).
inline std::vector<Beat> frameBeats(const uint8_t* left, const uint8_t* right, int width, int height,
                                    size_t leftStride, size_t rightStride) {
  std::vector<Beat> beats;
  beats.reserve(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      beats.push_back(Beat{uint16_t(left[y * leftStride + x] | right[y * rightStride + x] << 8), x == 0 && y == 0,
                           x == width - 1});
  return beats;
}

// Checks the framing of `count` output beats from `first`: tuser on the first
// beat only, tlast exactly at every line end. Returns "" or the problem.
inline std::string checkFraming(const std::vector<Beat>& beats, size_t first, int width, int height) {
  const size_t count = size_t(width) * height;
  if (beats.size() < first + count)
    return "only " + std::to_string(beats.size() - first) + " output beats, expected " + std::to_string(count);
  for (size_t i = 0; i < count; ++i) {
    const Beat& b = beats[first + i];
    const int x = int(i % width), y = int(i / width);
    if (b.user != (i == 0) || b.last != (x == width - 1)) {
      std::ostringstream msg;
      msg << "framing at output (x=" << x << ", y=" << y << "): tuser=" << b.user << " tlast=" << b.last;
      return msg.str();
    }
  }
  return "";
}

}  // namespace sgm::tb
