// SPDX-License-Identifier: Apache-2.0
// AXI4-Lite master bus-functional model with seeded random delays on all five
// channels, for a verilated model with AXI4-Lite slave ports named s_axil_*
// (sgm_axi). One request at a time: AW and W each wait a random number of
// cycles before VALID (independently, so either may come first), AR likewise;
// BREADY and RREADY are low on random cycles. A transfer ends when its
// response is seen (VALID high), not when it is accepted: on random responses
// the master then holds READY low for a few more cycles, so that the next
// request (AW and W, or AR) is presented and held while the previous response
// of its kind still waits, and a slave that takes a second write (read) before
// its first response is accepted is caught by the checker. While a VALID is
// low its payload is random, so a slave that looks at it unasked gets garbage.
// Every cycle goes through an AxilChecker (one transaction in flight per kind,
// as the slave promises).
//
// Call drive() before the model evaluates its inputs and sample() after (both
// before the clock edge). write() and read() run one blocking transaction,
// clocking the simulation with the step function given at construction;
// finish() accepts the responses still waiting and returns the checker's verdict.
// randomStrobes() draws byte strobes for writes from the model's seeded generator.
#pragma once

#include "axil_checker.hpp"
#include "sgm/params.hpp"  // sgm::Error

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

namespace sgm::tb {

struct AxilDelays {
  int maxRequestDelay = 3;    // AW, W, AR: 0 .. this many idle cycles before VALID
  double readyStall = 0.3;    // B, R: READY low with this probability per cycle
  double responseHold = 0.5;  // B, R: with this probability a response seen with READY low
  int maxResponseHold = 6;    // keeps READY low for 1 .. this many more cycles
};

struct AxilResponse {
  uint32_t data = 0;  // reads
  uint32_t resp = 0;  // 0 OKAY, 2 SLVERR
};

constexpr uint32_t kAxilOkay = 0, kAxilSlvErr = 2;

template <class Model>
class AxilMaster {
 public:
  // step(): one clock cycle of the whole simulation (which calls drive and sample).
  AxilMaster(Model& model, uint32_t seed, AxilDelays delays, std::function<void()> step)
      : model_(model), rng_(seed), delays_(delays), step_(std::move(step)) {}

  AxilResponse write(uint32_t addr, uint32_t data, uint32_t strb = 0xF) { return transfer(true, addr, data, strb); }
  AxilResponse read(uint32_t addr) { return transfer(false, addr, 0, 0); }

  // Byte strobes 0x0 .. 0xF, uniformly.
  uint32_t randomStrobes() { return random() & 0xF; }

  void drive() {
    Model& m = model_;
    const bool w = active_ && isWrite_, r = active_ && !isWrite_;
    m.s_axil_awvalid_i = w && !awDone_ && awDelay_ == 0;
    m.s_axil_awaddr_i = m.s_axil_awvalid_i ? addr_ : random();
    m.s_axil_awprot_i = 0;
    m.s_axil_wvalid_i = w && !wDone_ && wDelay_ == 0;
    m.s_axil_wdata_i = m.s_axil_wvalid_i ? data_ : random();
    m.s_axil_wstrb_i = m.s_axil_wvalid_i ? strb_ : random() & 0xF;
    m.s_axil_bready_i = bHold_ == 0 && !stall();
    m.s_axil_arvalid_i = r && !arDone_ && arDelay_ == 0;
    m.s_axil_araddr_i = m.s_axil_arvalid_i ? addr_ : random();
    m.s_axil_arprot_i = 0;
    m.s_axil_rready_i = rHold_ == 0 && !stall();
    if (awDelay_) --awDelay_;
    if (wDelay_) --wDelay_;
    if (arDelay_) --arDelay_;
    if (bHold_) --bHold_;
    if (rHold_) --rHold_;
  }

  void sample(uint64_t cycle) {
    const Model& m = model_;
    checker_.observe(cycle, axilWires(m));
    if (bWaiting_ && (m.s_axil_awvalid_i || m.s_axil_wvalid_i)) ++writeCyclesBehindResponse_;
    if (rWaiting_ && m.s_axil_arvalid_i) ++readCyclesBehindResponse_;
    const bool writeWasTaken = awDone_ && wDone_, readWasTaken = arDone_;
    if (m.s_axil_awvalid_i && m.s_axil_awready_o) awDone_ = true;
    if (m.s_axil_wvalid_i && m.s_axil_wready_o) wDone_ = true;
    if (m.s_axil_arvalid_i && m.s_axil_arready_o) arDone_ = true;
    if (!writeWasTaken && awDone_ && wDone_) writeTaken_ = cycle;
    if (!readWasTaken && arDone_) readTaken_ = cycle;
    // A response seen for the first time ends its transfer; one that was already
    // seen is the previous transfer's, still waiting for READY.
    if (m.s_axil_bvalid_o && !bWaiting_ && active_ && isWrite_) {
      response_.resp = m.s_axil_bresp_o, active_ = false, bWaiting_ = true;
      if (!m.s_axil_bready_i && hold()) bHold_ = holdCycles();
    }
    if (m.s_axil_rvalid_o && !rWaiting_ && active_ && !isWrite_) {
      response_ = {uint32_t(m.s_axil_rdata_o), uint32_t(m.s_axil_rresp_o)}, active_ = false, rWaiting_ = true;
      if (!m.s_axil_rready_i && hold()) rHold_ = holdCycles();
    }
    if (m.s_axil_bvalid_o && m.s_axil_bready_i) bWaiting_ = false;
    if (m.s_axil_rvalid_o && m.s_axil_rready_i) rWaiting_ = false;
  }

  // Clocks until the responses still waiting are accepted, then returns the
  // checker's verdict on the whole run ("" when no rule was broken).
  std::string finish() {
    for (long i = 0; (bWaiting_ || rWaiting_) && checker_.violation().empty(); ++i) {
      if (i > kTimeoutCycles) return "a response still waiting after " + std::to_string(kTimeoutCycles) + " cycles";
      step_();
    }
    return checker_.finish();
  }

  AxilChecker& checker() { return checker_; }
  // The cycle in which the last write (both AW and W) / the last read was taken.
  uint64_t lastWriteTaken() const { return writeTaken_; }
  uint64_t lastReadTaken() const { return readTaken_; }
  // Cycles in which a write (AW or W) / a read (AR) was presented while the previous
  // response of its kind still waited: how often the one-in-flight rule was tried.
  uint64_t writeCyclesBehindResponse() const { return writeCyclesBehindResponse_; }
  uint64_t readCyclesBehindResponse() const { return readCyclesBehindResponse_; }

 private:
  static constexpr long kTimeoutCycles = 1000;

  AxilResponse transfer(bool isWrite, uint32_t addr, uint32_t data, uint32_t strb) {
    active_ = true, isWrite_ = isWrite, addr_ = addr, data_ = data, strb_ = strb;
    awDone_ = wDone_ = arDone_ = false;
    awDelay_ = delay(), wDelay_ = delay(), arDelay_ = delay();
    response_ = {};
    for (long i = 0; active_; ++i) {
      if (i > kTimeoutCycles)
        throw Error(std::string("AXI4-Lite ") + (isWrite ? "write" : "read") + " of 0x" + hex(addr) +
                    " not answered in " + std::to_string(kTimeoutCycles) + " cycles");
      step_();
      if (!checker_.violation().empty()) throw Error("AXI4-Lite protocol: " + checker_.violation());
    }
    return response_;
  }

  static std::string hex(uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "%x", v);
    return text;
  }
  int delay() { return std::uniform_int_distribution<int>(0, delays_.maxRequestDelay)(rng_); }
  bool stall() { return std::uniform_real_distribution<double>(0, 1)(rng_) < delays_.readyStall; }
  bool hold() { return std::uniform_real_distribution<double>(0, 1)(rng_) < delays_.responseHold; }
  int holdCycles() { return std::uniform_int_distribution<int>(1, std::max(1, delays_.maxResponseHold))(rng_); }
  uint32_t random() { return uint32_t(rng_()); }

  Model& model_;
  std::mt19937 rng_;
  AxilDelays delays_;
  std::function<void()> step_;
  AxilChecker checker_;
  bool active_ = false, isWrite_ = false, awDone_ = false, wDone_ = false, arDone_ = false;
  bool bWaiting_ = false, rWaiting_ = false;  // a response seen, its READY not yet given
  int awDelay_ = 0, wDelay_ = 0, arDelay_ = 0, bHold_ = 0, rHold_ = 0;
  uint32_t addr_ = 0, data_ = 0, strb_ = 0;
  AxilResponse response_;
  uint64_t writeTaken_ = 0, readTaken_ = 0;
  uint64_t writeCyclesBehindResponse_ = 0, readCyclesBehindResponse_ = 0;
};

}  // namespace sgm::tb
