# SPDX-License-Identifier: Apache-2.0
# `make regress`: constrained-random regression of the verilated sgm_top against
# the golden model (tests/rtl/regress_main.cpp; included by the main Makefile).
#
#   make regress [REGRESS_SEED=S] [REGRESS_FRAMES=500] [REGRESS_MAX_HEIGHT=40]
#                [REGRESS_D=16 REGRESS_MAX_WIDTH=128 REGRESS_LANES=1]
#        random cases of master seed S (default: from the clock, printed) until
#        REGRESS_FRAMES good frames are checked; a failing case prints its replay
#        command, e.g.  build/bin/sgm-regress-d16-w128 --seed S --case K
#   make regress REGRESS_SEED=S REGRESS_CASE=K    replays case K of seed S
#   make regress-ci                               the fixed seeded slices CI runs
#                                                 (one lane, and 2 lanes)
#
# $(call regress_build,BINARY,D,MAX_WIDTH,EXTRA-VERILATOR-FLAGS) adds the rule of
# one regression binary (its own -Mdir under build/verilator/), e.g. a --coverage
# variant in another directory.

REGRESS_D          ?= 16
REGRESS_MAX_WIDTH  ?= 128
REGRESS_LANES      ?= 1
REGRESS_FRAMES     ?= 500
REGRESS_MAX_HEIGHT ?= 40
REGRESS_SEED       ?=
REGRESS_CASE       ?=
REGRESS_CI_SEED    ?= 1
REGRESS_CI_FRAMES  ?= 300
REGRESS_VFLAGS     ?= -O3 --x-assign unique --x-initial unique
REGRESS_BIN         = $(BIN)/sgm-regress-d$(REGRESS_D)-w$(REGRESS_MAX_WIDTH)$(if $(filter-out 1,$(REGRESS_LANES)),-k$(REGRESS_LANES))
REGRESS_CI_BIN     := $(BIN)/sgm-regress-d16-w128
REGRESS_CI_K2_BIN  := $(BIN)/sgm-regress-d16-w128-k2
REGRESS_ARGS        = --max-height $(REGRESS_MAX_HEIGHT) $(if $(REGRESS_SEED),--seed $(REGRESS_SEED)) \
                      $(if $(REGRESS_CASE),--case $(REGRESS_CASE),--frames $(REGRESS_FRAMES))

define regress_build
$(1): tests/rtl/regress_main.cpp $(RTL_SRC) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating sgm_top (D=$(2), MAX_WIDTH=$(3)) for $$@ (log: $(BUILD)/verilator-$$(notdir $$@).log)"
	@$(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) $(REGRESS_VFLAGS) $(4) -y rtl --top-module sgm_top \
	  -GD=$(2) -GMAX_WIDTH=$(3) -Mdir $(BUILD)/verilator/$$(notdir $$@) -o $$(abspath $$@) \
	  rtl/sgm_top.sv $(abspath tests/rtl/regress_main.cpp) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS)" -LDFLAGS "$(OPENCV_LIBS) -pthread" > $(BUILD)/verilator-$$(notdir $$@).log || \
	  { tail -30 $(BUILD)/verilator-$$(notdir $$@).log; exit 1; }
endef

$(eval $(call regress_build,$(REGRESS_BIN),$(REGRESS_D),$(REGRESS_MAX_WIDTH),-GLANES=$(REGRESS_LANES)))
ifneq ($(REGRESS_CI_BIN),$(REGRESS_BIN))
$(eval $(call regress_build,$(REGRESS_CI_BIN),16,128,))
endif
ifneq ($(REGRESS_CI_K2_BIN),$(REGRESS_BIN))
$(eval $(call regress_build,$(REGRESS_CI_K2_BIN),16,128,-GLANES=2))
endif

.PHONY: regress regress-ci
TEST_EXTRA += regress-ci

regress: $(REGRESS_BIN)
	$(REGRESS_BIN) $(REGRESS_ARGS)

# CI: a fixed seed, --quiet (failing cases and the summary only), one XML report per build
# counted by the closing "N passed" line (one test per case).
regress-ci: $(REGRESS_CI_BIN) $(REGRESS_CI_K2_BIN)
	@mkdir -p $(RESULTS)
	$(REGRESS_CI_BIN) --seed $(REGRESS_CI_SEED) --frames $(REGRESS_CI_FRAMES) --max-height $(REGRESS_MAX_HEIGHT) \
	  --quiet --xml $(RESULTS)/regress-ci.xml
	$(REGRESS_CI_K2_BIN) --seed $(REGRESS_CI_SEED) --frames $(REGRESS_CI_FRAMES) --max-height $(REGRESS_MAX_HEIGHT) \
	  --quiet --xml $(RESULTS)/regress-ci-k2.xml
