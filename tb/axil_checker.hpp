// SPDX-License-Identifier: Apache-2.0
// AXI4-Lite protocol checker, fed cycle by cycle (before the clock edge) with
// what the bus carries. Rules:
//   handshake:  on each of the five channels (AW, W, AR from the master, B, R
//               from the slave), once VALID is high it stays high, and the
//               payload stays unchanged, until the cycle with READY;
//   responses:  no BVALID without a write whose address and data were both
//               taken in an earlier cycle and not answered yet, no RVALID
//               without such a read (no response without a request); at the
//               end, one response per request (finish());
//   in flight:  at most maxOutstanding writes and maxOutstanding reads at a
//               time (1 by default: the slave's promise): no AW (W) handshake
//               while that many write addresses (data) wait for their B
//               handshake, no AR handshake while that many reads wait for
//               their R handshake (a response accepted in the same cycle
//               still counts: its request is free from the next cycle on).
// The first broken rule is kept, naming the cycle, the channel and the rule.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

namespace sgm::tb {

// One cycle of the bus.
struct AxilWires {
  bool awvalid = false, awready = false;
  uint32_t awaddr = 0;
  bool wvalid = false, wready = false;
  uint32_t wdata = 0, wstrb = 0;
  bool bvalid = false, bready = false;
  uint32_t bresp = 0;
  bool arvalid = false, arready = false;
  uint32_t araddr = 0;
  bool rvalid = false, rready = false;
  uint32_t rdata = 0, rresp = 0;
};

// The AXI4-Lite slave ports (s_axil_*) of a verilated model.
template <class Model>
AxilWires axilWires(const Model& m) {
  AxilWires w;
  w.awvalid = m.s_axil_awvalid_i, w.awready = m.s_axil_awready_o, w.awaddr = m.s_axil_awaddr_i;
  w.wvalid = m.s_axil_wvalid_i, w.wready = m.s_axil_wready_o, w.wdata = m.s_axil_wdata_i, w.wstrb = m.s_axil_wstrb_i;
  w.bvalid = m.s_axil_bvalid_o, w.bready = m.s_axil_bready_i, w.bresp = m.s_axil_bresp_o;
  w.arvalid = m.s_axil_arvalid_i, w.arready = m.s_axil_arready_o, w.araddr = m.s_axil_araddr_i;
  w.rvalid = m.s_axil_rvalid_o, w.rready = m.s_axil_rready_i, w.rdata = m.s_axil_rdata_o, w.rresp = m.s_axil_rresp_o;
  return w;
}

class AxilChecker {
 public:
  explicit AxilChecker(uint64_t maxOutstanding = 1) : maxOutstanding_(maxOutstanding) {}

  // One cycle; returns the first violation so far ("" when none).
  const std::string& observe(uint64_t cycle, const AxilWires& w) {
    cycle_ = cycle;
    // Responses first, against the requests of earlier cycles.
    if (w.bvalid && responsesB_ >= writesTaken()) fail("B", "BVALID without an outstanding write");
    if (w.rvalid && responsesR_ >= reads_) fail("R", "RVALID without an outstanding read");
    if (w.awvalid && w.awready && addresses_ >= responsesB_ + maxOutstanding_)
      fail("AW", "write address taken while the write response before it still waits (too many writes in flight)");
    if (w.wvalid && w.wready && data_ >= responsesB_ + maxOutstanding_)
      fail("W", "write data taken while the write response before it still waits (too many writes in flight)");
    if (w.arvalid && w.arready && reads_ >= responsesR_ + maxOutstanding_)
      fail("AR", "read address taken while the read response before it still waits (too many reads in flight)");
    aw_.observe(*this, "AW", w.awvalid, w.awready, {w.awaddr, 0, 0});
    wd_.observe(*this, "W", w.wvalid, w.wready, {w.wdata, w.wstrb, 0});
    b_.observe(*this, "B", w.bvalid, w.bready, {w.bresp, 0, 0});
    ar_.observe(*this, "AR", w.arvalid, w.arready, {w.araddr, 0, 0});
    r_.observe(*this, "R", w.rvalid, w.rready, {w.rdata, w.rresp, 0});
    addresses_ += w.awvalid && w.awready;
    data_ += w.wvalid && w.wready;
    responsesB_ += w.bvalid && w.bready;
    reads_ += w.arvalid && w.arready;
    responsesR_ += w.rvalid && w.rready;
    return violation_;
  }

  // "" or the first broken rule, including requests left without a response.
  std::string finish() {
    if (violation_.empty() && (responsesB_ != writesTaken() || addresses_ != data_ || responsesR_ != reads_)) {
      std::ostringstream text;
      text << "end: " << addresses_ << " write addresses, " << data_ << " write data, " << responsesB_
           << " write responses, " << reads_ << " reads, " << responsesR_ << " read responses";
      violation_ = text.str();
    }
    return violation_;
  }

  const std::string& violation() const { return violation_; }
  uint64_t writes() const { return responsesB_; }
  uint64_t reads() const { return responsesR_; }

 private:
  struct Payload {
    uint32_t a, b, c;
    bool operator==(const Payload& o) const { return a == o.a && b == o.b && c == o.c; }
  };
  // VALID held until READY with a stable payload, on one channel.
  struct Channel {
    bool waiting = false;
    Payload held{0, 0, 0};
    void observe(AxilChecker& c, const char* name, bool valid, bool ready, const Payload& now) {
      if (waiting && !valid)
        c.fail(name, "VALID dropped before its handshake");
      else if (waiting && !(now == held))
        c.fail(name, "payload changed while VALID was high and READY low");
      waiting = valid && !ready;
      held = now;
    }
  };

  uint64_t writesTaken() const { return addresses_ < data_ ? addresses_ : data_; }
  void fail(const char* channel, const char* rule) {
    if (!violation_.empty()) return;
    std::ostringstream text;
    text << "cycle " << cycle_ << ", " << channel << ": " << rule;
    violation_ = text.str();
  }

  Channel aw_, wd_, b_, ar_, r_;
  uint64_t maxOutstanding_;
  uint64_t addresses_ = 0, data_ = 0, responsesB_ = 0, reads_ = 0, responsesR_ = 0;
  uint64_t cycle_ = 0;
  std::string violation_;
};

}  // namespace sgm::tb
