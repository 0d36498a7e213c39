# SPDX-License-Identifier: Apache-2.0
# One definition of a core build (sgm_top's build parameters), included first by the
# Makefile. Every flow that builds the whole core (make sim, synth, pnr, regress, bench,
# coverage) names its binary or output directory with core_tag, passes the parameters
# with core_gflags (Verilator) or core_env (synth/common.tcl, which applies them with
# chparam) and records them with core_meta, all from one spec.
#
# A spec is a list of NAME=VALUE words over CORE_PARAMS, e.g. "D=16 MAX_WIDTH=128 LANES=2".
# A parameter the spec leaves out (or gives empty) has sgm_top's default (CORE_DEFAULTS,
# equal to the parameter defaults of rtl/sgm_top.sv: `make build-defaults-check`); when a
# name appears twice the last word wins, so "$(SIM_CORE) MAX_WIDTH=512" is SIM_CORE at 512.
#
# The tag names a build by every parameter that differs from sgm_top's default, in a fixed
# order; D and MAX_WIDTH always:
#
#   d<D>-w<MAX_WIDTH>[-h<MAX_HEIGHT>][-c9x<CENSUS_H>][-k<LANES>][-u<UNIQUENESS>][-ad<AD_TERM>][-rb<RIGHT_BLOCK>][-er<EDGE_RESET>][-z<DEPTH>][-dm<MIN_DISPARITY>]
#   [-rect<RECTIFY>][-rr<RECTIFY_ROWS>][-rg<RECTIFY_GRID_LOG2>][-cf<CONFIDENCE>][-mw<MIN_WIDTH>]
#
#   d64-w1280                 sgm_top's defaults (H 1024, 9x5 census, one lane, both levers,
#                             the fifth path in blocks of 64, the path restart built, no
#                             depth output or minimum disparity)
#   d64-w1024-k6-rb0-er0-mw128  the `make pnr` core (six lanes, four paths, no restart, frames from 128 columns)
#   d16-w128-u0-ad0-rb0-er0   the lean build
#
# One build has one tag whichever flow makes it: build/bin/sgm-sim-<tag>[-trace|-<variant>],
# build/bin/sgm-regress-<tag>, build/bin/cov-regress-<tag>, build/synth/<tag>/<target>/,
# build/pnr/<tag>/<device>-<speed>/. Each records its parameters, NAME=VALUE in lower case
# with the tag (tag=..., d=..., max_width=..., ...), in a meta.txt: the synth and pnr run
# directories', the Verilator directory of a binary (build/verilator/<binary>/meta.txt),
# and the output directories of make sim (OUT), make bench (build/bench) and make coverage
# (build/coverage, the regression build's).
#
#   $(call core_get,SPEC,NAME)    NAME's value in SPEC, else its default
#   $(call core_tag,SPEC)         the tag
#   $(call core_gflags,SPEC)      -GD=.. -GMAX_WIDTH=.. ... every parameter (Verilator)
#   $(call core_chparam,SPEC)     -set D .. -set MAX_WIDTH .. ... every parameter (Yosys chparam)
#   $(call core_env,SPEC,PREFIX)  PREFIX<NAME>=VALUE for every parameter (SYNTH_ for synth/common.tcl)
#   $(call core_meta,SPEC)        shell commands echoing the meta.txt lines (tag and every parameter)
#   $(call core_meta_write,SPEC,FILE)  a shell command writing them to FILE
#   $(call core_spec_of,PREFIX)   the spec of the variables PREFIX<NAME> that are set
#                                 (PNR_ -> PNR_D, PNR_MAX_WIDTH, ...; empty -> D, MAX_WIDTH, ...)

CORE_PARAMS   := D MAX_WIDTH MAX_HEIGHT CENSUS_H LANES UNIQUENESS AD_TERM RIGHT_BLOCK EDGE_RESET DEPTH MIN_DISPARITY \
                 RECTIFY RECTIFY_ROWS RECTIFY_GRID_LOG2 CONFIDENCE MIN_WIDTH
CORE_DEFAULTS := D=64 MAX_WIDTH=1280 MAX_HEIGHT=1024 CENSUS_H=5 LANES=1 UNIQUENESS=1 AD_TERM=1 RIGHT_BLOCK=64 EDGE_RESET=1 DEPTH=0 \
                 MIN_DISPARITY=0 RECTIFY=0 RECTIFY_ROWS=32 RECTIFY_GRID_LOG2=4 CONFIDENCE=0 MIN_WIDTH=0
# The tag's letters (D and MAX_WIDTH always named; CENSUS_H as the window, c9x9).
CORE_TAG_D := d
CORE_TAG_MAX_WIDTH := w
CORE_TAG_MAX_HEIGHT := h
CORE_TAG_CENSUS_H := c9x
CORE_TAG_LANES := k
CORE_TAG_UNIQUENESS := u
CORE_TAG_AD_TERM := ad
CORE_TAG_RIGHT_BLOCK := rb
CORE_TAG_EDGE_RESET := er
CORE_TAG_DEPTH := z
CORE_TAG_MIN_DISPARITY := dm
CORE_TAG_RECTIFY := rect
CORE_TAG_RECTIFY_ROWS := rr
CORE_TAG_RECTIFY_GRID_LOG2 := rg
CORE_TAG_CONFIDENCE := cf
CORE_TAG_MIN_WIDTH := mw

core_empty      :=
core_space      := $(core_empty) $(core_empty)
core_word_value = $(lastword $(patsubst $(2)=%,%,$(filter $(2)=%,$(1))))
core_default    = $(call core_word_value,$(CORE_DEFAULTS),$(1))
core_get        = $(or $(call core_word_value,$(1),$(2)),$(call core_default,$(2)))
core_check      = $(foreach w,$(1),$(if $(filter $(addsuffix =%,$(CORE_PARAMS)),$(w)),,$(error core build: $(w) is not NAME=VALUE of $(CORE_PARAMS))))
core_tag_part   = $(if $(filter-out $(call core_default,$(2)),$(call core_get,$(1),$(2))),-$(CORE_TAG_$(2))$(call core_get,$(1),$(2)))
core_tag        = $(strip $(call core_check,$(1)))d$(call core_get,$(1),D)-w$(call core_get,$(1),MAX_WIDTH)$(subst $(core_space),,$(foreach p,$(wordlist 3,$(words $(CORE_PARAMS)),$(CORE_PARAMS)),$(call core_tag_part,$(1),$(p))))
core_gflags     = $(foreach p,$(CORE_PARAMS),-G$(p)=$(call core_get,$(1),$(p)))
core_chparam    = $(foreach p,$(CORE_PARAMS),-set $(p) $(call core_get,$(1),$(p)))
core_env        = $(foreach p,$(CORE_PARAMS),$(2)$(p)=$(call core_get,$(1),$(p)))
core_lc         = $(subst A,a,$(subst B,b,$(subst C,c,$(subst D,d,$(subst E,e,$(subst F,f,$(subst G,g,$(subst H,h,$(subst I,i,$(subst J,j,$(subst K,k,$(subst L,l,$(subst M,m,$(subst N,n,$(subst O,o,$(subst P,p,$(subst Q,q,$(subst R,r,$(subst S,s,$(subst T,t,$(subst U,u,$(subst V,v,$(subst W,w,$(subst X,x,$(subst Y,y,$(subst Z,z,$(1)))))))))))))))))))))))))))
core_meta       = echo "tag=$(call core_tag,$(1))"; $(foreach p,$(CORE_PARAMS),echo "$(call core_lc,$(p))=$(call core_get,$(1),$(p))";)
core_meta_write = { $(call core_meta,$(1)) } > $(2)
core_spec_of    = $(strip $(foreach p,$(CORE_PARAMS),$(if $(strip $($(1)$(p))),$(p)=$(strip $($(1)$(p))))))

# The knobs of `make sim` and `make synth` (D=, MAX_WIDTH=, CENSUS=9x5|9x9, ...), set here
# so that every fragment sees them: sgm_top's defaults, except that PRESET=paper and
# PRESET=four-path build no fifth path (RIGHT_BLOCK=0) and PRESET=paper the 9x9 census.
D           ?= $(call core_default,D)
MAX_WIDTH   ?= $(call core_default,MAX_WIDTH)
MAX_HEIGHT  ?= $(call core_default,MAX_HEIGHT)
LANES       ?= $(call core_default,LANES)
UNIQUENESS  ?= $(call core_default,UNIQUENESS)
AD_TERM     ?= $(call core_default,AD_TERM)
RIGHT_BLOCK ?= $(if $(filter paper four-path,$(PRESET)),0,$(call core_default,RIGHT_BLOCK))
EDGE_RESET  ?= $(call core_default,EDGE_RESET)
DEPTH       ?= $(call core_default,DEPTH)
MIN_DISPARITY ?= $(call core_default,MIN_DISPARITY)
# CALIB=DIR (make sim: a raw pair and its calibration) builds the rectification.
RECTIFY     ?= $(if $(CALIB),1,$(call core_default,RECTIFY))
RECTIFY_ROWS ?= $(call core_default,RECTIFY_ROWS)
RECTIFY_GRID_LOG2 ?= $(call core_default,RECTIFY_GRID_LOG2)
# CALIB=DIR also builds the confidence (make sim writes the confidence picture).
CONFIDENCE  ?= $(if $(CALIB),1,$(call core_default,CONFIDENCE))
MIN_WIDTH   ?= $(call core_default,MIN_WIDTH)
CENSUS      ?= $(if $(filter paper,$(PRESET)),9x9,9x5)
CENSUS_H     = $(if $(filter 9x9,$(CENSUS)),9,$(if $(filter 9x5,$(CENSUS)),5,$(error CENSUS=$(CENSUS): expected 9x5 or 9x9)))
# The build those knobs name (make sim, make synth; make bench at its own MAX_WIDTH).
CORE         = $(call core_spec_of,)

# sgm_top's parameter defaults against CORE_DEFAULTS (cheap: no tool runs).
.PHONY: build-defaults-check
build-defaults-check:
	@for kv in $(CORE_DEFAULTS); do n=$${kv%%=*}; v=$${kv#*=}; \
	   rtl=$$(sed -nE "s/^[[:space:]]*parameter[[:space:]]+int[[:space:]]+$$n[[:space:]][^=]*=[[:space:]]*([0-9]+).*/\1/p" rtl/sgm_top.sv | head -1); \
	   [ "$$rtl" = "$$v" ] || { echo "build-defaults-check: $$n: scripts/build.mk says $$v, rtl/sgm_top.sv says '$$rtl'"; exit 1; }; \
	 done; \
	 for n in $(CORE_PARAMS); do grep -q "^  $$n:$$" sgm.core || { echo "build-defaults-check: sgm.core declares no parameter $$n (scripts/build.mk CORE_PARAMS)"; exit 1; }; done; \
	 echo "build-defaults-check: OK (CORE_DEFAULTS = sgm_top's parameter defaults; sgm.core declares each)"
