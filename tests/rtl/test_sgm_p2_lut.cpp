// SPDX-License-Identifier: Apache-2.0
// sgm_p2_lut against the golden P2 table (docs/algorithm.md section 4).
#include "Vsgm_p2_lut.h"
#include "verilated_top.hpp"

#include "sgm/aggregate.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using Top = sgm::tb::VerilatedTop<Vsgm_p2_lut>;

// Fills the table for (p1, p2) in a P2 mode and checks all 256 entries through the 4 ports.
void checkTable(Top& top, int p1, int p2, sgm::P2Mode mode = sgm::P2Mode::kKnee) {
  top->start_i = 1;
  top->p1_i = p1;
  top->p2_i = p2;
  top->mode_i = mode == sgm::P2Mode::kPaper;
  top.tick();
  top->start_i = 0;
  int cycles = 0;
  while (!top->ready_o) {
    top.tick();
    ASSERT_LT(++cycles, 2 * 256 + 8) << "table fill did not finish (P1=" << p1 << ", P2'=" << p2 << ")";
  }
  const sgm::P2Table expected = sgm::makeP2Table(p1, p2, mode);
  for (int base = 0; base < 256; base += 4) {
    top->en_i = 1;
    top->idx_i = uint32_t(base) | uint32_t(base + 1) << 8 | uint32_t(base + 2) << 16 | uint32_t(base + 3) << 24;
    top.tick();
    top->en_i = 0;
    for (int p = 0; p < 4; ++p)
      ASSERT_EQ(int((top->p2r_o >> (8 * p)) & 0xff), expected[base + p])
          << "P1=" << p1 << " P2'=" << p2 << " mode " << sgm::p2ModeName(mode) << " |dI|=" << base + p << " (port " << p
          << ")";
  }
}

TEST(SgmP2Lut, HandPickedPenalties) {
  Top top("sgm_p2_lut");
  top.reset();
  top->en_i = 0;
  for (auto [p1, p2] : {std::pair{20, 200}, {7, 100}, {0, 0}, {0, 255}, {255, 255}, {40, 255}, {1, 1}, {3, 254}})
    for (const sgm::P2Mode mode : {sgm::P2Mode::kKnee, sgm::P2Mode::kPaper}) checkTable(top, p1, p2, mode);
}

TEST(SgmP2Lut, RandomPenalties) {
  Top top("sgm_p2_lut_random");
  top.reset();
  top->en_i = 0;
  std::mt19937 rng(12345);
  for (int i = 0; i < 40; ++i) {
    const int p2 = int(rng() % 256), p1 = int(rng() % (p2 + 1));
    checkTable(top, p1, p2, i % 2 ? sgm::P2Mode::kPaper : sgm::P2Mode::kKnee);
  }
}

TEST(SgmP2Lut, LookupsHoldWhileDisabled) {
  Top top("sgm_p2_lut_hold");
  top.reset();
  checkTable(top, 20, 200);
  const auto held = top->p2r_o;
  top->en_i = 0;
  top->idx_i = 0x01020304;
  top.tick();
  EXPECT_EQ(top->p2r_o, held);
}

}  // namespace
