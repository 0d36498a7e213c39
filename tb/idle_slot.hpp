// SPDX-License-Identifier: Apache-2.0
// One enabled slot of a verilated model with an en_i input, after a random run
// of idle cycles (en_i = 0): each cycle before the slot is idle with
// probability `idle`. The inputs set before the call are the slot's.
#pragma once

#include <random>

namespace sgm::tb {

template <class Top, class Rng>
void slotAfterIdle(Top& top, Rng& rng, double idle) {
  while (std::uniform_real_distribution<double>(0, 1)(rng) < idle) {
    top->en_i = 0;
    top.tick();
  }
  top->en_i = 1;
  top.tick();
}

}  // namespace sgm::tb
