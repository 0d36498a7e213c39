# SPDX-License-Identifier: Apache-2.0
# `make synth`: Yosys resource and timing reports of sgm_top against the
# paper's Table III (included by the main Makefile; synth/README.md explains
# the flow, the outputs and the figures).
#
#   make synth [D=64] [MAX_WIDTH=1280] [CENSUS=9x5|9x9] [LANES=1] [UNIQUENESS=1] [AD_TERM=1] [RIGHT_BLOCK=64]
#              [MAX_HEIGHT=1024] [EDGE_RESET=1]
#                                        xc7, xc6s, generic and iCE40 synthesis of
#                                        that configuration (CENSUS=9x9: the paper's
#                                        census window, sgm_top's CENSUS_H = 9), the
#                                        routed iCE40 loop harness, build/synth/summary.{json,md}
#   make synth-ci                        D=16, MAX_WIDTH=128: xc7 and the routed iCE40 loop
#                                        harness (ICE40_LOOP_D=16), then checks the summary
#                                        and that the path buffers are block RAM
#   make synth-xc7 | synth-xc6s | synth-generic | synth-ice40 | synth-ice40-loop
#                                        one target (then make synth-summary)
#   make synth-flat                      xc7 of the whole core flattened in one run
#                                        (cross-stage optimisation, slow for D = 64)
#   make synth-levers [D=64]             what the two build-time levers cost: sgm_wta with
#                                        UNIQUENESS 1 and 0, sgm_cost_volume (one lane) with
#                                        AD_TERM 1 and 0, each alone, synth_ecp5 -abc9
#                                        -> build/synth/levers-d<D>/summary.md
#   make synth-right-path [D=64]         what the fifth path costs: sgm_right_path alone,
#                                        SYNTH_RIGHT_PATH="64x1 32x6" (block x lanes)
#                                        -> build/synth/right-path-d<D>/summary.md
#
# UNIQUENESS=0 / AD_TERM=0 build the core without the uniqueness ratio / the AD term
# (sgm_top's build parameters, docs/rtl.md "Build parameters"); the default 1 builds them.
# The knobs are `make sim`'s, with the same defaults (scripts/build.mk); the build is
# SYNTH_CORE, passed whole to Yosys (every sgm_top parameter, chparam in synth/common.tcl),
# its results in build/synth/<tag>/<target>/ (the tag of scripts/build.mk, e.g. d64-w1280)
# with every parameter in meta.txt.
#
# Yosys and nextpnr run one at a time (flock on build/synth/.lock, also under
# make -j), each under `timeout $(SYNTH_TIMEOUT)`. The results depend on rtl/*.sv and
# synth/*.tcl; after changing an option here, `make synth-clean` (or delete the
# target directory) to rerun.

SYNTH_TARGETS     ?= xc7 xc6s generic ice40
SYNTH_TIMEOUT     ?= 10800
SYNTH_CI_D        ?= 16
SYNTH_CI_MAX_WIDTH ?= 128
# CI runs the small configuration (see the main Makefile's TEST_EXTRA).
TEST_EXTRA += synth-ci
# Loop harness on iCE40: D, device, package, nextpnr target frequency (MHz).
ICE40_LOOP_D      ?= 16
ICE40_DEVICE      ?= hx8k
ICE40_PACKAGE     ?= ct256
ICE40_FREQ        ?= 100
ICE40_SEED        ?= 1

SYNTH_DIR    := $(BUILD)/synth
comma := ,
SYNTH_CORE    = $(CORE)
synth_get     = $(call core_get,$(SYNTH_CORE),$(1))
SYNTH_CENSUS  = 9x$(call synth_get,CENSUS_H)
SYNTH_CFG     = $(call core_tag,$(SYNTH_CORE))
SYNTH_OUT     = $(SYNTH_DIR)/$(SYNTH_CFG)
# The configuration synth-ci builds and checks.
SYNTH_CI_CORE = $(SYNTH_CORE) D=$(SYNTH_CI_D) MAX_WIDTH=$(SYNTH_CI_MAX_WIDTH)
SYNTH_LOOP    = $(SYNTH_DIR)/ice40-loop-d$(ICE40_LOOP_D)
SYNTH_LOCK    = $(SYNTH_DIR)/.lock
SYNTH_SUMMARY = $(BIN)/synth-summary
SYNTH_COMMON := $(RTL_SRC) $(RTL_INC) synth/common.tcl

.PHONY: synth synth-ci synth-summary synth-help synth-clean synth-flat \
        synth-xc7 synth-xc6s synth-generic synth-ice40 synth-ice40-loop

synth-help:
	@echo "make synth [D=64 MAX_WIDTH=1280] [CENSUS=9x9]  xc7 / xc6s / generic / iCE40 synthesis + routed iCE40 loop -> build/synth/summary.{json,md}"
	@echo "make synth-ci                     D=$(SYNTH_CI_D) MAX_WIDTH=$(SYNTH_CI_MAX_WIDTH), xc7 + the routed iCE40 loop harness; fails unless the path buffers are block RAM"
	@echo "make synth-xc7 | synth-xc6s | synth-generic | synth-ice40 | synth-ice40-loop [ICE40_LOOP_D=16]"
	@echo "make synth-flat                   xc7, whole core flattened in one Yosys run (slow for D = 64)"
	@echo "make synth-summary                rebuild summary.{json,md} from what build/synth holds"

synth: $(foreach t,$(SYNTH_TARGETS),$(SYNTH_OUT)/$(t)/done) $(SYNTH_LOOP)/done $(SYNTH_SUMMARY) | check-tools
	@$(SYNTH_SUMMARY) $(SYNTH_DIR)
	@awk '/^## D = $(call synth_get,D), MAX_WIDTH = $(call synth_get,MAX_WIDTH), census $(SYNTH_CENSUS)$(if $(filter 0,$(call synth_get,UNIQUENESS)),$(comma) UNIQUENESS = 0)$(if $(filter 0,$(call synth_get,AD_TERM)),$(comma) AD_TERM = 0)$(if $(filter-out 0,$(call synth_get,RIGHT_BLOCK)),$(comma) RIGHT_BLOCK = $(call synth_get,RIGHT_BLOCK)) /{f=1} f && /^\*\*Path buffers/{exit} f' $(SYNTH_DIR)/summary.md

synth-ci: $(SYNTH_SUMMARY) | check-tools
	@$(MAKE) --no-print-directory D=$(SYNTH_CI_D) MAX_WIDTH=$(SYNTH_CI_MAX_WIDTH) synth-xc7
	@$(MAKE) --no-print-directory synth-ice40-loop
	@$(SYNTH_SUMMARY) $(SYNTH_DIR) --check $(call core_tag,$(SYNTH_CI_CORE))/xc7 --check ice40-loop-d$(ICE40_LOOP_D)
	@test -s $(SYNTH_DIR)/summary.json && test -s $(SYNTH_DIR)/summary.md || \
	  { echo "synth-ci: FAIL: $(SYNTH_DIR)/summary.json or summary.md missing or empty"; exit 1; }
	@echo "synth-ci: OK ($(SYNTH_DIR)/summary.json, $(SYNTH_DIR)/summary.md)"

synth-summary: $(SYNTH_SUMMARY) | check-tools
	@$(SYNTH_SUMMARY) $(SYNTH_DIR)

synth-xc7:        $(SYNTH_OUT)/xc7/done
synth-xc6s:       $(SYNTH_OUT)/xc6s/done
synth-generic:    $(SYNTH_OUT)/generic/done
synth-ice40:      $(SYNTH_OUT)/ice40/done
synth-ice40-loop: $(SYNTH_LOOP)/done
synth-flat:       $(SYNTH_OUT)/xc7-flat/done

synth-clean:
	rm -rf $(SYNTH_DIR)

$(SYNTH_SUMMARY): synth/synth_summary.cpp $(REPORT_SRC) $(REPORT_HDR) | check-tools
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Igolden -Itools -o $@ synth/synth_summary.cpp $(REPORT_SRC)

# $(call synth_yosys,TARGET,SCRIPT,ENV): run SCRIPT for TARGET into $(@D), with the
# configuration in the environment, then write $(@D)/meta.txt and the stamp.
define synth_yosys
	@rm -rf $(@D) && mkdir -p $(@D)
	@echo "synth: $(1), $(SYNTH_CORE) (log: $(@D)/yosys.log)"
	@start=$$(date +%s); \
	 commit=$$(git log -1 --format=%h -- rtl 2>/dev/null)$$(git status --porcelain -- rtl 2>/dev/null | grep -q . && echo -dirty); \
	 SYNTH_RTL=rtl $(call core_env,$(SYNTH_CORE),SYNTH_) SYNTH_OUT=$(@D) $(3) \
	   flock $(SYNTH_LOCK) timeout $(SYNTH_TIMEOUT) yosys -q -l $(@D)/yosys.log -c $(2) > $(@D)/yosys.out 2>&1; rc=$$?; \
	 if [ $$rc != 0 ]; then \
	   if [ $$rc = 124 ]; then echo "synth: $(1): Yosys timed out after $(SYNTH_TIMEOUT) s (SYNTH_TIMEOUT)"; \
	   else echo "synth: $(1): Yosys failed (exit $$rc):"; grep -E '^ERROR' $(@D)/yosys.log | tail -5; fi; exit 1; fi; \
	 { echo "target=$(1)"; $(call core_meta,$(SYNTH_CORE)) echo "census=$(SYNTH_CENSUS)"; $(if $(SYNTH_REF),echo "ref=$(SYNTH_REF)";) \
	   echo "yosys=$$(yosys -V)"; echo "rtl_commit=$$commit"; \
	   echo "date=$$(date -u +%Y-%m-%dT%H:%M:%SZ)"; echo "seconds=$$(( $$(date +%s) - start ))"; } > $(@D)/meta.txt; \
	 echo "synth: $(1) done in $$(( $$(date +%s) - start )) s"
	@touch $@
endef

$(SYNTH_OUT)/xc7/done: $(SYNTH_COMMON) synth/xilinx.tcl | check-tools
	$(call synth_yosys,xc7,synth/xilinx.tcl,SYNTH_FAMILY=xc7)

$(SYNTH_OUT)/xc6s/done: $(SYNTH_COMMON) synth/xilinx.tcl | check-tools
	$(call synth_yosys,xc6s,synth/xilinx.tcl,SYNTH_FAMILY=xc6s)

$(SYNTH_OUT)/generic/done: $(SYNTH_COMMON) synth/generic.tcl | check-tools
	$(call synth_yosys,generic,synth/generic.tcl,)

$(SYNTH_OUT)/ice40/done: $(SYNTH_COMMON) synth/ice40.tcl | check-tools
	$(call synth_yosys,ice40,synth/ice40.tcl,)

$(SYNTH_OUT)/xc7-flat/done: $(SYNTH_COMMON) synth/xilinx_flat.tcl | check-tools
	$(call synth_yosys,xc7-flat,synth/xilinx_flat.tcl,SYNTH_FAMILY=xc7)

# The loop harness: synth_ice40, nextpnr-ice40 (placed and routed, timing
# report), icetime on the routed design as a second opinion.
$(SYNTH_LOOP)/done: synth/sgm_path_loop.sv synth/ice40_loop.tcl rtl/sgm_path_pe.sv rtl/sgm_min_tree.sv rtl/sgm_delay_ram.sv rtl/sgm_path_ring.sv | check-tools
	@rm -rf $(@D) && mkdir -p $(@D)
	@echo "synth: iCE40 loop harness, D=$(ICE40_LOOP_D), $(ICE40_DEVICE) (logs: $(@D)/)"
	@start=$$(date +%s); \
	 SYNTH_RTL=rtl SYNTH_LOOP_D=$(ICE40_LOOP_D) SYNTH_OUT=$(@D) \
	   flock $(SYNTH_LOCK) timeout $(SYNTH_TIMEOUT) yosys -q -l $(@D)/yosys.log -c synth/ice40_loop.tcl > $(@D)/yosys.out 2>&1 || \
	   { echo "synth: loop harness: Yosys failed, see $(@D)/yosys.log"; exit 1; }; \
	 flock $(SYNTH_LOCK) timeout $(SYNTH_TIMEOUT) nextpnr-ice40 --$(ICE40_DEVICE) --package $(ICE40_PACKAGE) \
	   --json $(@D)/netlist.json --pcf-allow-unconstrained --freq $(ICE40_FREQ) --timing-allow-fail \
	   --seed $(ICE40_SEED) --threads 1 --report $(@D)/report.json --asc $(@D)/loop.asc -l $(@D)/nextpnr.log \
	   > /dev/null 2>&1 || \
	   { echo "synth: loop harness: nextpnr-ice40 failed:"; grep -E '^ERROR' $(@D)/nextpnr.log | tail -3; exit 1; }; \
	 icetime -d $(ICE40_DEVICE) -P $(ICE40_PACKAGE) -t $(@D)/loop.asc > $(@D)/icetime.txt 2>&1 || \
	   { echo "synth: loop harness: icetime failed, see $(@D)/icetime.txt"; exit 1; }; \
	 { echo "target=ice40-loop"; echo "d=$(ICE40_LOOP_D)"; echo "device=$(ICE40_DEVICE)-$(ICE40_PACKAGE)"; \
	   echo "freq_mhz=$(ICE40_FREQ)"; echo "yosys=$$(yosys -V)"; \
	   echo "date=$$(date -u +%Y-%m-%dT%H:%M:%SZ)"; echo "seconds=$$(( $$(date +%s) - start ))"; } > $(@D)/meta.txt; \
	 echo "synth: loop harness: $$(grep -o 'Max frequency.*' $(@D)/nextpnr.log | tail -1) ($$(( $$(date +%s) - start )) s)"
	@touch $@

# What the two build-time levers cost (synth/levers.tcl): each module alone at D, one lane,
# plain synth_ecp5 -abc9, with the lever built and not; the table in summary.md (docs/notes/synthesis-log.md,
# "The build-time levers").
SYNTH_LEVERS_DIR = $(SYNTH_DIR)/levers-d$(D)
.PHONY: synth-levers
synth-levers: synth/levers.tcl $(RTL_SRC) | check-tools
	@mkdir -p $(SYNTH_LEVERS_DIR)
	@for top in sgm_wta sgm_cost_volume; do for lever in 1 0; do o=$(SYNTH_LEVERS_DIR)/$$top-$$lever; mkdir -p $$o; \
	   echo "synth-levers: $$top, lever $$lever, D=$(D) (log: $$o/yosys.log)"; \
	   SYNTH_LEVER_TOP=$$top SYNTH_LEVER=$$lever SYNTH_D=$(D) SYNTH_OUT=$$o \
	     flock $(SYNTH_LOCK) timeout $(SYNTH_TIMEOUT) yosys -q -l $$o/yosys.log -c synth/levers.tcl > $$o/yosys.out 2>&1 || \
	     { echo "synth-levers: Yosys failed ($$o/yosys.log)"; exit 1; }; done; done
	@{ echo "| module (D = $(D), one lane) | lever | LUT4 | CCU2C | PFUMX | L6MUX21 | TRELLIS_FF |"; \
	   echo "| --- | --- | --- | --- | --- | --- | --- |"; \
	   for top in sgm_wta sgm_cost_volume; do for lever in 1 0; do f=$(SYNTH_LEVERS_DIR)/$$top-$$lever/stat.txt; \
	     name=$$([ $$top = sgm_wta ] && echo UNIQUENESS || echo AD_TERM); \
	     printf '| %s | %s=%s |' $$top $$name $$lever; \
	     for c in LUT4 CCU2C PFUMX L6MUX21 TRELLIS_FF; do printf ' %s |' "$$(awk -v c=$$c '$$1 == c { n = $$2 } END { print n + 0 }' $$f)"; done; \
	     echo; done; done; } > $(SYNTH_LEVERS_DIR)/summary.md
	@cat $(SYNTH_LEVERS_DIR)/summary.md

# What the fifth path costs (synth/levers.tcl): sgm_right_path alone at D, plain synth_ecp5
# -abc9, for each block x lanes of SYNTH_RIGHT_PATH; the table in summary.md (docs/notes/synthesis-log.md,
# "The fifth path").
SYNTH_RIGHT_PATH ?= 64x1 32x6
SYNTH_RP_DIR = $(SYNTH_DIR)/right-path-d$(D)
.PHONY: synth-right-path
synth-right-path: synth/levers.tcl $(RTL_SRC) | check-tools
	@mkdir -p $(SYNTH_RP_DIR)
	@for c in $(SYNTH_RIGHT_PATH); do b=$${c%x*}; k=$${c#*x}; o=$(SYNTH_RP_DIR)/b$$b-k$$k; mkdir -p $$o; \
	   echo "synth-right-path: B=$$b, LANES=$$k, D=$(D) (log: $$o/yosys.log)"; \
	   SYNTH_LEVER_TOP=sgm_right_path SYNTH_LEVER=$$b SYNTH_LANES=$$k SYNTH_D=$(D) SYNTH_OUT=$$o \
	     flock $(SYNTH_LOCK) timeout $(SYNTH_TIMEOUT) yosys -q -l $$o/yosys.log -c synth/levers.tcl > $$o/yosys.out 2>&1 || \
	     { echo "synth-right-path: Yosys failed ($$o/yosys.log)"; exit 1; }; done
	@{ echo "| sgm_right_path (D = $(D)) | LUT4 | CCU2C | PFUMX | L6MUX21 | TRELLIS_FF | DP16KD | DPR16X4 |"; \
	   echo "| --- | --- | --- | --- | --- | --- | --- | --- |"; \
	   for c in $(SYNTH_RIGHT_PATH); do b=$${c%x*}; k=$${c#*x}; f=$(SYNTH_RP_DIR)/b$$b-k$$k/stat.txt; \
	     printf '| B = %s, %s lane(s) |' $$b $$k; \
	     for cell in LUT4 CCU2C PFUMX L6MUX21 TRELLIS_FF DP16KD DPR16X4; do printf ' %s |' "$$(awk -v c=$$cell '$$1 == c { n = $$2 } END { print n + 0 }' $$f)"; done; \
	     echo; done; } > $(SYNTH_RP_DIR)/summary.md
	@cat $(SYNTH_RP_DIR)/summary.md
