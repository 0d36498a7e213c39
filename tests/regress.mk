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
# $(call regress_build,BINARY,CORE,EXTRA-VERILATOR-FLAGS) adds the rule of one regression
# binary of the build CORE (a spec of scripts/build.mk, e.g. "D=16 MAX_WIDTH=128 LANES=2";
# every parameter passed, the rest at sgm_top's defaults) with its own -Mdir under
# build/verilator/ holding its meta.txt, e.g. a --coverage variant in another directory.
# The binaries are named sgm-regress-<tag> (REGRESS_MAX_HEIGHT is the frames' height at run
# time, not the build's MAX_HEIGHT).

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
REGRESS_CORE        = D=$(REGRESS_D) MAX_WIDTH=$(REGRESS_MAX_WIDTH) LANES=$(REGRESS_LANES)
REGRESS_CI_CORE    := D=16 MAX_WIDTH=128 DEPTH=1 MIN_DISPARITY=1 RECTIFY=1 RECTIFY_ROWS=16 RECTIFY_GRID_LOG2=3 CONFIDENCE=1
REGRESS_CI_K2_CORE := D=16 MAX_WIDTH=128 LANES=2
REGRESS_BIN         = $(BIN)/sgm-regress-$(call core_tag,$(REGRESS_CORE))
REGRESS_CI_BIN     := $(BIN)/sgm-regress-$(call core_tag,$(REGRESS_CI_CORE))
REGRESS_CI_K2_BIN  := $(BIN)/sgm-regress-$(call core_tag,$(REGRESS_CI_K2_CORE))
REGRESS_ARGS        = --max-height $(REGRESS_MAX_HEIGHT) $(if $(REGRESS_SEED),--seed $(REGRESS_SEED)) \
                      $(if $(REGRESS_CASE),--case $(REGRESS_CASE),--frames $(REGRESS_FRAMES))

define regress_build
$(1): tests/rtl/regress_main.cpp $(RTL_SRC) $(RTL_INC) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating sgm_top ($(call core_tag,$(2))) for $$@ (log: $(BUILD)/verilator-$$(notdir $$@).log)"
	@$(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) $(REGRESS_VFLAGS) $(3) -y rtl --top-module sgm_top \
	  $(call core_gflags,$(2)) -Mdir $(BUILD)/verilator/$$(notdir $$@) -o $$(abspath $$@) \
	  rtl/sgm_top.sv $(abspath tests/rtl/regress_main.cpp) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS)" -LDFLAGS "$(OPENCV_LIBS) -pthread" > $(BUILD)/verilator-$$(notdir $$@).log || \
	  { tail -30 $(BUILD)/verilator-$$(notdir $$@).log; exit 1; }
	@$(call core_meta_write,$(2),$(BUILD)/verilator/$$(notdir $$@)/meta.txt)
endef

$(eval $(call regress_build,$(REGRESS_BIN),$(REGRESS_CORE),))
ifneq ($(REGRESS_CI_BIN),$(REGRESS_BIN))
$(eval $(call regress_build,$(REGRESS_CI_BIN),$(REGRESS_CI_CORE),))
endif
ifneq ($(REGRESS_CI_K2_BIN),$(REGRESS_BIN))
$(eval $(call regress_build,$(REGRESS_CI_K2_BIN),$(REGRESS_CI_K2_CORE),))
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
