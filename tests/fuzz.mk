# SPDX-License-Identifier: Apache-2.0
# Bad input to the tools (included by the Makefile after its variables).
#
#   make fuzz [FUZZ_SEED=S] [FUZZ_ITERS=N] [FUZZ_TOOL_RUNS=K]
#       seeded random-corruption fuzzing (tests/fuzz/fuzz_main.cpp): N mutated image files
#       through the image loading, N random argument vectors through the parser, K runs of
#       each binary (sgm-golden, sgm-eval, sgm-sim D=16 MAX_WIDTH=128). Random seed unless
#       FUZZ_SEED is given; the seed is printed, and a failure prints the line that replays it.
#   make fuzz-ci
#       what CI runs (TEST_EXTRA): the sgm-sim bad-input GoogleTests, then a bounded fuzz
#       slice with a fixed seed (FUZZ_CI_SEED, FUZZ_CI_ITERS, FUZZ_CI_TOOL_RUNS).

FUZZ_ITERS        ?= 20000
FUZZ_TOOL_RUNS    ?= 100
FUZZ_CI_SEED      ?= 1
FUZZ_CI_ITERS     ?= 3000
FUZZ_CI_TOOL_RUNS ?= 20
FUZZ_CORE         := D=16 MAX_WIDTH=128
FUZZ_SIM          := sgm-sim-$(call core_tag,$(FUZZ_CORE))

.PHONY: fuzz fuzz-ci

# The small simulator build the bad-input tests run (tests/fuzz/test_sim_cli.cpp names it):
# D = 16, MAX_WIDTH = 128, sgm_top's defaults otherwise (scripts/build.mk), whatever the
# command line says.
$(BIN)/$(FUZZ_SIM): override SIM_CORE = $(FUZZ_CORE)

$(BIN)/sgm-fuzz: $(OBJ)/tests/fuzz/fuzz_main.o $(EVAL_OBJ) $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDLIBS)

$(BIN)/sim-cli-tests: $(OBJ)/tests/fuzz/test_sim_cli.o
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ -lgtest -lgtest_main $(LDLIBS)

fuzz: $(BIN)/sgm-fuzz golden $(BIN)/$(FUZZ_SIM)
	$(BIN)/sgm-fuzz $(if $(FUZZ_SEED),--seed $(FUZZ_SEED)) --iters $(FUZZ_ITERS) --tool-runs $(FUZZ_TOOL_RUNS) \
	  --bin $(BIN) --sim $(FUZZ_SIM)

fuzz-ci: $(BIN)/sgm-fuzz $(BIN)/sim-cli-tests golden $(BIN)/$(FUZZ_SIM)
	@mkdir -p $(RESULTS)
	SGM_BIN="$(abspath $(BIN))" $(BIN)/sim-cli-tests --gtest_output=xml:$(RESULTS)/sim-cli-tests.xml
	$(BIN)/sgm-fuzz --seed $(FUZZ_CI_SEED) --iters $(FUZZ_CI_ITERS) --tool-runs $(FUZZ_CI_TOOL_RUNS) \
	  --bin $(BIN) --sim $(FUZZ_SIM)

TEST_EXTRA += fuzz-ci
