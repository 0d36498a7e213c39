// SPDX-License-Identifier: Apache-2.0
// One verilated top with its VerilatedContext: clocking, reset and optional
// FST waveform (TRACE=1 in the environment, file under build/trace/).
#pragma once

#include <verilated.h>
#if VM_TRACE
#include <verilated_fst_c.h>
#endif
#if VM_COVERAGE
#include <verilated_cov.h>
#endif

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

namespace sgm::tb {

template <class Model>
class VerilatedTop {
 public:
  // initialState: how registers and memories start (Verilator's randReset): 2 random
  // (the default: the design must not rely on it), 0 all zeros (an FPGA after
  // configuration), 1 all ones.
  explicit VerilatedTop(const std::string& name, int initialState = 2)
      : name_(name), context_(std::make_unique<VerilatedContext>()) {
    context_->randReset(initialState);
    model_ = std::make_unique<Model>(context_.get(), name.c_str());
#if VM_TRACE
    const char* trace = std::getenv("TRACE");
    if (trace && std::string(trace) == "1") {
      context_->traceEverOn(true);
      trace_ = std::make_unique<VerilatedFstC>();
      model_->trace(trace_.get(), 99);
      std::filesystem::create_directories("build/trace");
      trace_->open(("build/trace/" + name + ".fst").c_str());
    }
#endif
    model_->clk_i = 0;
    model_->eval();
  }
  ~VerilatedTop() {
    model_->final();
#if VM_COVERAGE
    // Coverage builds (make coverage) leave one data file per model instance.
    if (const char* dir = std::getenv("SGM_COVERAGE_DIR")) {
      static int serial = 0;
      std::filesystem::create_directories(dir);
      const std::string file = std::string(dir) + "/" + name_ + "-" + std::to_string(::getpid()) + "-" +
                               std::to_string(serial++) + ".dat";
      context_->coveragep()->write(file.c_str());
    }
#endif
#if VM_TRACE
    if (trace_) trace_->close();
#endif
  }
  VerilatedTop(const VerilatedTop&) = delete;
  VerilatedTop& operator=(const VerilatedTop&) = delete;

  Model* operator->() { return model_.get(); }
  Model& model() { return *model_; }

  // One clock cycle: inputs set before the call are sampled on the rising edge;
  // after the call the registered outputs show the new state.
  void tick() {
    model_->clk_i = 1;
    model_->eval();
    dump();
    model_->clk_i = 0;
    model_->eval();
    dump();
    ++cycles_;
  }

  // Active-low synchronous reset for `cycles` cycles.
  void reset(int cycles = 2) {
    model_->rst_ni = 0;
    for (int i = 0; i < cycles; ++i) tick();
    model_->rst_ni = 1;
  }

  uint64_t cycles() const { return cycles_; }

 private:
  void dump() {
#if VM_TRACE
    context_->timeInc(1);
    if (trace_) trace_->dump(context_->time());
#endif
  }

  std::string name_;
  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<Model> model_;
#if VM_TRACE
  std::unique_ptr<VerilatedFstC> trace_;
#endif
  uint64_t cycles_ = 0;
};

}  // namespace sgm::tb
