# SPDX-License-Identifier: Apache-2.0
# The reference builds: the configurations the datasheet gives routed or synthesized figures
# for, each named once here (included by the Makefile after scripts/build.mk). A reference
# build is a core build (a spec of scripts/build.mk, so its directories carry the same tag in
# every flow) on one target:
#
#   REF_<name>_CORE     the core's build parameters (NAME=VALUE over CORE_PARAMS)
#   REF_<name>_TARGET   ecp5 (Yosys synth_ecp5 + nextpnr-ecp5: `make pnr-ref`, `make synth-ref`)
#                       or xc7 (Yosys synth_xilinx, an estimate before place and route:
#                       `make synth-ref`; there is no open router for 7-series)
#   REF_<name>_DEVICE   ECP5: nextpnr's device (45k, 85k); REF_<name>_PACKAGE, _SPEED
#   REF_<name>_FREQ     the clock target of nextpnr (MHz)
#   REF_<name>_NEXTPNR  nextpnr options beyond synth/pnr.mk's defaults
#   REF_<name>_ABOUT    one line for `make refs`: what the build is for (its parameters are
#                       printed from REF_<name>_CORE, not repeated here)
#
# Every reference build is also a whole-core test build of `make rtl-tests` (rtl-ref-<name>,
# the same spec: its D, lanes, width and features, bit-exact against the golden model on
# frames up to its MAX_WIDTH), so that what is routed is what is tested.
#
# Why each build is what it is (the measurements: docs/notes/synthesis-log.md, the entry
# "reference builds"; the conclusions: synth/README.md, "Reference builds"):
# - hd64: the D = 64 core on the largest ECP5. Four paths: the default feature set's fifth
#   path does not fit beside it (LUT positions and block RAM). Six lanes: one lane slot per
#   unit of the 0 degree recursion at D = 64. MAX_WIDTH: the widest whose block RAM fits.
#   MIN_WIDTH 128: frames from 128 columns, so that the LR check's lag is at most 13 rows, not
#   16, and its memories and the edge snap's gray rows hold 16 rows, not 32.
# - fhd32: 1080p frames at D = 32 on the largest ECP5. Three lanes (two units of the recursion
#   per lane slot: a clock for 1080p30): six lanes' rows in flight do not fit its block RAM
#   at 1920 columns.
# - small: the five paths at D = 16 on a mid-size ECP5, in blocks small enough for its block RAM.
# - fhd128: sgm_top's default features at D = 128, where the block RAM and the logic are.
REF_NAMES := hd64 fhd32 small fhd128

REF_hd64_CORE    := D=64 MAX_WIDTH=1024 LANES=6 RIGHT_BLOCK=0 EDGE_RESET=0 MIN_WIDTH=128
REF_hd64_TARGET  := ecp5
REF_hd64_DEVICE  := 85k
REF_hd64_PACKAGE := CABGA381
REF_hd64_SPEED   := 8
REF_hd64_FREQ    := 125
# HeAP found no placement of the D = 64 six-lane core that routed; the electrostatic
# placer did (synth/pnr.mk, PNR_FULL_FLAGS).
REF_hd64_NEXTPNR := --placer static
REF_hd64_ABOUT   := the D = 64 core on the largest ECP5

REF_fhd32_CORE    := D=32 MAX_WIDTH=1920 LANES=3 RIGHT_BLOCK=0 EDGE_RESET=0
REF_fhd32_TARGET  := ecp5
REF_fhd32_DEVICE  := 85k
REF_fhd32_PACKAGE := CABGA381
REF_fhd32_SPEED   := 8
REF_fhd32_FREQ    := 90
REF_fhd32_NEXTPNR :=
REF_fhd32_ABOUT   := 1080p frames at D = 32 on the largest ECP5

REF_small_CORE    := D=16 MAX_WIDTH=640 LANES=5 RIGHT_BLOCK=16 EDGE_RESET=1
REF_small_TARGET  := ecp5
REF_small_DEVICE  := 45k
REF_small_PACKAGE := CABGA381
REF_small_SPEED   := 8
REF_small_FREQ    := 125
REF_small_NEXTPNR :=
REF_small_ABOUT   := the five paths at D = 16 on a mid-size ECP5

REF_fhd128_CORE   := D=128 MAX_WIDTH=1920 LANES=7
REF_fhd128_TARGET := xc7
REF_fhd128_ABOUT  := sgm_top's default features at D = 128 (Yosys estimate)

REF_TARGETS := ecp5 xc7
ref_check = $(if $(filter $(1),$(REF_NAMES)),,$(error REF=$(1): expected one of $(REF_NAMES) (scripts/refs.mk)))$(if $(filter $(REF_$(1)_TARGET),$(REF_TARGETS)),,$(error REF_$(1)_TARGET=$(REF_$(1)_TARGET): expected one of $(REF_TARGETS)))
# The names of the reference builds on one target.
refs_on = $(foreach r,$(REF_NAMES),$(if $(filter $(1),$(REF_$(r)_TARGET)),$(r)))

# The Verilator options of a reference build's whole-core test (rtl-ref-<name>).
ref_gflags = $(call core_gflags,$(REF_$(1)_CORE)) $(if $(filter ecp5,$(REF_$(1)_TARGET)),-DSGM_DELAY_CHAIN) \
             -CFLAGS -DSGM_D=$(call core_get,$(REF_$(1)_CORE),D)

# docs/integration.md's table of the reference builds against the specs above: each build's row
# names every parameter of its spec as `NAME = VALUE` (cheap: in `make test`, the Makefile's TEST_EXTRA).
REFS_DOC := docs/integration.md
.PHONY: refs-doc-check
refs-doc-check:
	@$(foreach r,$(REF_NAMES),row=$$(grep -E '^\| `$(r)` \|' $(REFS_DOC)) || { echo "refs-doc-check: $(REFS_DOC) has no row for reference build $(r)"; exit 1; }; \
	  for kv in $(REF_$(r)_CORE); do n=$${kv%%=*}; v=$${kv#*=}; \
	    echo "$$row" | grep -qE "(\`|, )$$n = $$v(,|\`)" || { echo "refs-doc-check: $(REFS_DOC), row $(r): no '$$n = $$v' (scripts/refs.mk: $(REF_$(r)_CORE))"; exit 1; }; done;) \
	 echo "refs-doc-check: OK ($(REFS_DOC) names every parameter of the $(words $(REF_NAMES)) reference builds)"

.PHONY: refs refs-tags
# `make refs-tags`: "name tag" per line (tests/mutate/mutate.sh orders fixtures by D and lanes).
refs-tags:
	@$(foreach r,$(REF_NAMES),echo "$(r) $(call core_tag,$(REF_$(r)_CORE))";)
refs:
	@$(foreach r,$(REF_NAMES),echo "$(r): $(REF_$(r)_ABOUT)"; \
	   echo "    $(REF_$(r)_TARGET)$(if $(REF_$(r)_DEVICE), LFE5U-$(subst k,F,$(REF_$(r)_DEVICE))-$(REF_$(r)_SPEED) $(REF_$(r)_PACKAGE) at $(REF_$(r)_FREQ) MHz), build $(call core_tag,$(REF_$(r)_CORE)): $(REF_$(r)_CORE)";)
