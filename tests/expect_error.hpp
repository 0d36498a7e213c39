// SPDX-License-Identifier: Apache-2.0
// Shared test helper: expects an sgm::Error with a one-line message naming the problem.
#pragma once

#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

// Runs f, expects an sgm::Error whose message is one line and contains every needle.
template <typename F>
void expectError(F&& f, std::initializer_list<std::string> needles) {
  try {
    f();
    ADD_FAILURE() << "no sgm::Error thrown";
  } catch (const sgm::Error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "multi-line message: " << msg;
    for (const std::string& n : needles) EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' not in: " << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}
