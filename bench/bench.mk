# SPDX-License-Identifier: Apache-2.0
# `make bench [DATA=...]`: accuracy and speed of the core, the golden model and
# OpenCV StereoSGBM on the same pairs, in one run (included by the main Makefile).
#
#   1. verilates sgm_top (D, BENCH_MAX_WIDTH) as sgm-sim, once per Verilator
#      option set in BENCH_VARIANTS (fast / threads2 / checked);
#   2. runs the fast build on every Middlebury scene under DATA and on Aloe, and
#      on one frame of each video format (the paper's Table II sizes and 1080p);
#      sgm-sim compares every output pixel with the golden model as it goes;
#   3. runs every variant on Cones for the simulation speed, BENCH_REPEATS
#      interleaved rounds (one run of each variant per round), so that the
#      report gives each variant's median and spread;
#   4. with the scene pool (POOL, tools/pool.mk): the verilated core at D = 128
#      (`make eval-pool-rtl`, MAX_WIDTH = 1280) on BENCH_POOL_SCENES, one Middlebury
#      and one KITTI pair (1242 px wide) by default, every pixel checked;
#   5. sgm-bench report: OpenCV (MODE_SGBM, MODE_HH, MODE_SGBM_3WAY), golden vs
#      OpenCV timing, the pool summary (BENCH_POOL=1: `make eval-pool`'s means, golden
#      model and OpenCV on every pool scene), and build/bench/report.{md,json}, accuracy.png.
#
# Builds take a few minutes per variant (D = 64); the runs about two minutes.
# Timing figures are only meaningful on an otherwise idle machine.

BENCH_DIR       := $(BUILD)/bench
BENCH_MAX_WIDTH ?= 1920
BENCH_MAX_HEIGHT ?= 1088

BENCH_REPEATS   ?= 3
BENCH_VARIANTS  ?= fast threads2 checked
BENCH_FLAGS_fast     = $(SIM_VFLAGS)
BENCH_FLAGS_threads2 = $(SIM_VFLAGS) --threads 2
BENCH_FLAGS_checked  = --x-assign unique --x-initial unique
# The build: make sim's (SIM_CORE, scripts/build.mk) at BENCH_MAX_WIDTH x BENCH_MAX_HEIGHT.
# The `fast` variant is the `make sim` build itself (same options, same binary name,
# sgm-sim-<tag>); the others are sgm-sim-<tag>-<variant>. build/bench/meta.txt records the build.
BENCH_CORE       = $(SIM_CORE) MAX_WIDTH=$(BENCH_MAX_WIDTH) MAX_HEIGHT=$(BENCH_MAX_HEIGHT)
BENCH_SIM        = $(BIN)/sgm-sim-$(call core_tag,$(BENCH_CORE))$(if $(filter-out fast,$(1)),-$(1))
SIM_BIN_SUFFIXES += $(filter-out fast,$(BENCH_VARIANTS))
BENCH_SCENES    ?= cones teddy sawtooth venus
BENCH_ALOE      ?= 1
BENCH_FRAMES    ?= 450x375 640x480 1280x720 1920x1080
BENCH_POOL      ?= 1
BENCH_POOL_SCENES ?= $(POOL_RTL_SCENES)
# `make bench-ci`: the smoke slice CI runs (one scene, one frame size, one build
# shared with `make sim-ci`, one round).
BENCH_CI_VARS   := BENCH_SCENES=cones BENCH_ALOE=0 BENCH_FRAMES=450x375 BENCH_VARIANTS=fast BENCH_REPEATS=1 \
                   BENCH_MAX_WIDTH=512 BENCH_MAX_HEIGHT=1024 D=64 BENCH_POOL=0 BENCH_POOL_SCENES=
TEST_EXTRA      += bench-ci
BENCH_TOOL      := $(BIN)/sgm-bench
ALOE_DIR        := /usr/share/doc/opencv-doc/examples/data

.PHONY: bench bench-ci bench-help

bench-help:
	@echo "make bench [DATA=dir] [D=64] [BENCH_MAX_WIDTH=1920] [BENCH_VARIANTS='fast threads2 checked'] [BENCH_REPEATS=3]"
	@echo "           [BENCH_SCENES='cones teddy sawtooth venus'] [BENCH_ALOE=1] [BENCH_FRAMES='450x375 640x480 1280x720 1920x1080']"
	@echo "           [POOL=dir] [BENCH_POOL=1] [BENCH_POOL_SCENES='$(POOL_RTL_SCENES)']"
	@echo "make bench-ci   the CI smoke: $(BENCH_CI_VARS)"

$(BENCH_TOOL): bench/sgm_bench.cpp $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(OPENCV_CFLAGS) -o $@ $^ $(LDLIBS)

# One sgm-sim build per variant, through the main Makefile's sgm-sim rule.
define bench_variant
$(call BENCH_SIM,$(1)): $(RTL_SRC) $(RTL_INC) sim/sgm_sim.cpp $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@$$(MAKE) --no-print-directory BENCH_INNER=1 MAX_WIDTH=$(BENCH_MAX_WIDTH) MAX_HEIGHT=$(BENCH_MAX_HEIGHT) SIM_VFLAGS="$(BENCH_FLAGS_$(1))" $$@
endef
# (BENCH_INNER: the inner make builds with the pattern rule, not this one.)
ifndef BENCH_INNER
$(foreach v,$(BENCH_VARIANTS),$(eval $(call bench_variant,$(v))))
endif

bench: $(BENCH_TOOL) $(foreach v,$(BENCH_VARIANTS),$(call BENCH_SIM,$(v))) | check-tools
	@test -d "$(DATA)" || { echo "bench: DATA=$(DATA) not found: point DATA at the Middlebury scenes (README, 'Data')"; exit 1; }
	@rm -rf $(BENCH_DIR) && mkdir -p $(BENCH_DIR)/rtl $(BENCH_DIR)/formats $(BENCH_DIR)/simspeed
	@echo $(BENCH_MAX_WIDTH) > $(BENCH_DIR)/max_width.txt
	@$(call core_meta_write,$(BENCH_CORE),$(BENCH_DIR)/meta.txt)
	@set -e; sim=$(call BENCH_SIM,fast); \
	 for s in $(BENCH_SCENES); do \
	   if [ -f "$(DATA)/$$s/left.png" ]; then \
	     echo "bench: RTL on $$s"; \
	     $$sim --left "$(DATA)/$$s/left.png" --right "$(DATA)/$$s/right.png" --gt "$(DATA)/$$s/gt.png" \
	       --out $(BENCH_DIR)/rtl/$$s > $(BENCH_DIR)/rtl/$$s.log || { cat $(BENCH_DIR)/rtl/$$s.log; exit 1; }; \
	   fi; \
	 done; \
	 if [ "$(BENCH_ALOE)" = 1 ]; then echo "bench: RTL on aloe"; \
	   $$sim --out $(BENCH_DIR)/rtl/aloe > $(BENCH_DIR)/rtl/aloe.log || { cat $(BENCH_DIR)/rtl/aloe.log; exit 1; }; fi; \
	 $(BENCH_TOOL) formats --source $(ALOE_DIR)/aloeL.jpg --out $(BENCH_DIR)/formats/images; \
	 for f in $(BENCH_FRAMES); do \
	   echo "bench: RTL on a $$f frame"; \
	   $$sim --left $(BENCH_DIR)/formats/images/$${f}_left.png --right $(BENCH_DIR)/formats/images/$${f}_right.png \
	     --out $(BENCH_DIR)/formats/$$f > $(BENCH_DIR)/formats/$$f.log || { cat $(BENCH_DIR)/formats/$$f.log; exit 1; }; \
	 done
	@set -e; if [ -n "$(strip $(BENCH_POOL_SCENES))" ] && [ -d "$(POOL)" ]; then \
	   $(MAKE) --no-print-directory eval-pool-rtl POOL="$(POOL)" POOL_RTL_SCENES="$(BENCH_POOL_SCENES)" \
	     POOL_RTL_OUT=$(abspath $(BENCH_DIR))/pool-rtl; \
	 else echo "bench: the core on pool scenes skipped (POOL=$(POOL) not a directory, or BENCH_POOL_SCENES empty)"; fi
	@set -e; src="$(DATA)/cones"; [ -f "$$src/left.png" ] && args="--left $$src/left.png --right $$src/right.png" || args=""; \
	 for r in $$(seq 1 $(BENCH_REPEATS)); do for vb in $(foreach v,$(BENCH_VARIANTS),$(v)=$(call BENCH_SIM,$(v))); do \
	   v=$${vb%%=*}; echo "bench: simulation speed, $$v build, cones, round $$r of $(BENCH_REPEATS)"; \
	   run=$(BENCH_DIR)/simspeed/$$v/run$$r; mkdir -p $$run; \
	   $${vb#*=} $$args --out $$run > $$run.log || { cat $$run.log; exit 1; }; \
	 done; done
	@$(foreach v,$(BENCH_VARIANTS),echo '$(strip $(BENCH_FLAGS_$(v)))' > $(BENCH_DIR)/simspeed/$(v)/flags.txt;)
	@pool=""; if [ "$(BENCH_POOL)" = 1 ]; then \
	   if [ -d "$(POOL)" ]; then pool="--pool $(POOL)"; else echo "bench: the pool summary skipped: POOL=$(POOL) is not a directory"; fi; \
	 fi; \
	 $(BENCH_TOOL) report --data "$(DATA)" --bench $(BENCH_DIR) --repeats $(BENCH_REPEATS) $$pool

bench-ci:
	@$(MAKE) --no-print-directory $(BENCH_CI_VARS) bench
