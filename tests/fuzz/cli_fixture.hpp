// SPDX-License-Identifier: Apache-2.0
// GoogleTest fixture for the tools run as child processes: the binaries in
// $SGM_BIN, an input directory and an empty output / working directory. The
// contract of a user error: non-zero exit, exactly one stderr line
// "<tool>: error: ..." naming the problem, nothing on stdout, no output file,
// inputs untouched.
#pragma once

#include "bad_images.hpp"
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <stdlib.h>

namespace sgm::test {

class ToolTest : public testing::Test {
 protected:
  // Skips the test unless $SGM_BIN/binary exists.
  void requireBinary(const std::string& binary, const std::string& howToBuild) {
    const char* bin = std::getenv("SGM_BIN");
    if (!bin || !*bin || !std::filesystem::exists(std::string(bin) + "/" + binary))
      GTEST_SKIP() << "$SGM_BIN/" << binary << " not found (SGM_BIN='" << (bin ? bin : "") << "'); " << howToBuild;
    bin_ = bin;
  }

  void SetUp() override {
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string tmpl = base + "sgm_cli_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    root_ = tmpl;
    in_ = root_ + "/in";
    out_ = root_ + "/out";
    std::filesystem::create_directory(in_);
    std::filesystem::create_directory(out_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!root_.empty()) std::filesystem::remove_all(root_, ec);
  }

  void writeImage(const std::string& name, const cv::Mat& img) {
    ASSERT_TRUE(cv::imwrite(in_ + "/" + name, img));
    inputs_.insert(name);
  }
  void writeRaw(const std::string& name, const std::string& bytes) {
    writeBytes(in_ + "/" + name, bytes);
    inputs_.insert(name);
  }
  std::string in(const std::string& name) const { return in_ + "/" + name; }

  // Runs $SGM_BIN/binary with args in the output directory.
  ChildResult run(const std::string& binary, const std::vector<std::string>& args, double timeoutSeconds = 300) const {
    return runChild(bin_ + "/" + binary, args, out_, root_, timeoutSeconds);
  }

  void expectOneLineError(const ChildResult& r, const std::string& tool, const std::string& needle) {
    EXPECT_EQ(userErrorProblem(r, tool, needle), "");
    EXPECT_TRUE(dirEntries(out_).empty()) << "output files were created";
    EXPECT_EQ(dirEntries(in_), inputs_) << "input directory changed";
  }

  std::string bin_, root_, in_, out_;
  std::set<std::string> inputs_;
};

}  // namespace sgm::test
