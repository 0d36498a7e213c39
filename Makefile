# SPDX-License-Identifier: Apache-2.0
# SGM stereo core: golden model, evaluator, RTL simulation, synthesis, tests.
# `make help` lists the targets.

SHELL      := /bin/bash
BUILD      := build
BIN        := $(BUILD)/bin
OBJ        := $(BUILD)/obj
DATA       ?= $(abspath ../shared/data/middlebury)
JOBS       ?= 2

CXX        ?= g++
# Portable by default: no -march unless the compiler targets x86-64 and this
# machine has the x86-64-v3 features (AVX2, BMI2, FMA), or ARCH= names one
# (ARCH=native, ARCH=armv8.2-a, ...; ARCH= empty for none). Results are
# bit-exact whatever ARCH is (the model is integer); only its speed changes.
CXX_MACHINE := $(shell $(CXX) -dumpmachine 2>/dev/null)
HOST_X86_V3 := $(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && grep -qw bmi2 /proc/cpuinfo && \
                 grep -qw fma /proc/cpuinfo && echo yes)
ARCH       ?= $(if $(and $(filter x86_64-%,$(CXX_MACHINE)),$(HOST_X86_V3)),x86-64-v3)
MARCH      := $(if $(strip $(ARCH)),-march=$(strip $(ARCH)))
CXXFLAGS   ?= -O3 $(MARCH) -g
override CXXFLAGS += -std=c++17 -Wall -Wextra -pthread -Igolden -Itools -Isw/include
OPENCV_CFLAGS = $(shell pkg-config --cflags opencv4 2>/dev/null)
OPENCV_LIBS   = $(shell pkg-config --libs opencv4 2>/dev/null)
LDLIBS     += $(OPENCV_LIBS) -pthread

GOLDEN_SRC := $(wildcard golden/sgm/*.cpp)
GOLDEN_OBJ := $(patsubst %.cpp,$(OBJ)/%.o,$(GOLDEN_SRC))
GOLDEN_LIB := $(BUILD)/lib/libsgmgolden.a
GOLDEN_HDR := $(wildcard golden/sgm/*.hpp) sw/include/sgm_mesh_file.hpp sw/include/sgm_driver.hpp sw/include/sgm_regs.h
RTL_SRC    := $(wildcard rtl/*.sv)
RTL_INC    := $(wildcard rtl/*.svh)
TB_HDR     := $(wildcard tb/*.hpp)

# tools/*.cpp except the CLI mains form the evaluation library (scenes, error
# figures, OpenCV reference, reports) shared by sgm-eval, the tests and the harness.
EVAL_SRC   := $(filter-out tools/sgm_eval.cpp,$(wildcard tools/*.cpp))
EVAL_OBJ   := $(patsubst %.cpp,$(OBJ)/%.o,$(EVAL_SRC))
# The report helpers (JSON writer and reader, number formatter, meta.txt reader)
# the summary programs of synth/ link without the rest of the evaluation library.
REPORT_SRC := tools/report_json.cpp tools/report_util.cpp tools/json_read.cpp
REPORT_HDR := tools/report_json.hpp tools/report_util.hpp tools/json_read.hpp tools/video_formats.hpp tools/xc7_parts.hpp
TEST_SRC   := $(wildcard tests/*.cpp)
TEST_OBJ   := $(patsubst %.cpp,$(OBJ)/%.o,$(TEST_SRC))

# One definition of a core build (sgm_top's parameters, their defaults, the tag that names
# a build, its Verilator and Yosys flags, its meta.txt) for every flow (scripts/build.mk).
include scripts/build.mk
include scripts/refs.mk

.PHONY: all help deps check-tools golden eval eval-ci bench-golden test unit-test rtl-tests sim sim-ci synth lint clean
.DEFAULT_GOAL := all

all: golden

help:
	@echo "make deps          install the Debian packages the project needs (root, idempotent)"
	@echo "make golden        build build/bin/sgm-golden and build/bin/sgm-eval"
	@echo "make sim           the verilated core on Aloe (or LEFT= RIGHT= [GT=] [OUT=]) vs the golden model"
	@echo "                   options: D=64 MAX_WIDTH=1280 STALL=0.3 FRAMES=2 SEED=1 TRACE=1"
	@echo "                   PRESET=paper: the paper's system (9x9 census core, unified, P2'/dI, equal weights)"
	@echo "                   CENSUS=9x9|9x5 builds that census window (PRESET=paper implies 9x9)"
	@echo "make lint          SPDX lines, the register map against its description, clang-format, verilator --lint-only -Wall on every RTL module"
	@echo "make rtl-tests     every verilated GoogleTest fixture (modules and the whole core)"
	@echo "make eval          Table I and full-pipeline accuracy on DATA=$(DATA) -> build/eval/"
	@echo "make eval-pool     accuracy on the scene pool POOL=$(POOL) at each scene's ndisp, OpenCV beside -> build/eval/pool.*"
	@echo "make eval-pool-rtl the verilated core (D=128, MAX_WIDTH=1280) bit-exact on pool scenes (POOL_RTL_SCENES)"
	@echo "make bench-golden  golden model vs OpenCV StereoSGBM time on one frame, same run"
	@echo "make bench         accuracy (RTL, golden, OpenCV x3, paper) and speed in one run -> build/bench/"
	@echo "make synth         Yosys area/timing reports (D=64 MAX_WIDTH=1280) -> build/synth/; make synth-help"
	@echo "make icarus        the core in Icarus Verilog: two D=16 frames vs the golden model"
	@echo "make fusesoc-lint  FuseSoC (sgm.core) lint target; fusesoc-sim, fusesoc-synth"
	@echo "make synth-axi     xc7 cells of the AXI4-Lite wrapper (sgm_axi) alone"
	@echo "make pnr           ECP5 place and route of the whole core (D=64 MAX_WIDTH=1024, LFE5U-85F) -> build/pnr/; make pnr-help"
	@echo "make regress       constrained-random regression of the core (seeded, replayable)"
	@echo "make fuzz          seeded random-corruption fuzzing of image loading and argument parsing"
	@echo "make coverage      line and toggle coverage of rtl/ -> build/coverage/"
	@echo "make mutate        plant each bug of tests/mutate/mutations.txt in a copy of rtl/, run the tests -> build/mutate/ (MUTATE_ONLY=id,id)"
	@echo "make datasheet     docs/datasheet.md (DATASHEET=...) and README's summary from the measured JSON reports under build/"
	@echo "make eval-confidence  the error of the most confident pixels on the pool (the confidence map ranks errors)"
	@echo "make raw-scenes    raw camera pairs made from the scenes (known calibration), their rectification meshes and the golden model on the way back"
	@echo "make regmap        sw/include/sgm_regs.h, rtl/sgm_regmap.svh, docs/registers.md from regmap/sgm_regmap.def; make regmap-check"
	@echo "make param-checks  every module's parameter checks fire on an illegal value; the legal sets elaborate"
	@echo "make formal        SymbiYosys proofs and covers: AXI4-Lite slave, sgm_axi registers, stream controller, delay memory, banked memory, lane deal -> build/formal/ (FORMAL_ONLY=task,task)"
	@echo "make format        clang-format every C++ file (.clang-format); make format-check lists the ones that differ"
	@echo "make test          everything CI runs: lint, unit tests, RTL fixtures, then $(TEST_EXTRA)"
	@echo "make clean         remove build/"

# ---------------------------------------------------------------- dependencies
include scripts/deps.mk
# Fragments add their own targets; each appends the targets CI must run to
# TEST_EXTRA (run by `make test` after the GoogleTest binaries).
TEST_EXTRA := build-defaults-check refs-doc-check sim-ci eval-ci
# `make synth` and its reports (synth/synth.mk, when present).
-include synth/synth.mk synth/axi.mk
# `make eval-pool`, `make eval-pool-ci`: accuracy on the scene pool (tools/pool.mk).
-include tools/pool.mk
# `make pnr`, `make pnr-ci`: place and route on ECP5 (synth/pnr.mk).
-include synth/pnr.mk
# `make regmap`, `make regmap-check`: the register map from its one description (regmap/regmap.mk).
include regmap/regmap.mk
# `make datasheet`, `make datasheet-ci`: docs/datasheet.md from the JSON reports (tools/datasheet.mk).
include tools/datasheet.mk
# `make raw-scenes`: raw camera pairs from the rectified scenes, their meshes and the way back (tools/raw_scenes.mk).
include tools/raw_scenes.mk
# `make format`, `make format-check`: clang-format (scripts/format.mk).
include scripts/format.mk

# ---------------------------------------------------------------- golden model
# Each object depends on the headers it includes: the compiler writes them into its .d
# file (-MMD: project headers, not system ones; -MP: a removed header does not stop make).
# An object without its .d file (not built since) is rebuilt: the empty rule makes a missing
# .d a target that is always out of date.
$(OBJ)/%.o: %.cpp $(OBJ)/%.d | check-tools
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(OPENCV_CFLAGS) -MMD -MP -c $< -o $@

$(OBJ)/%.d: ;
.PRECIOUS: $(OBJ)/%.d
-include $(wildcard $(OBJ)/*/*.d $(OBJ)/*/*/*.d $(OBJ)/*/*/*/*.d)

$(GOLDEN_LIB): $(GOLDEN_OBJ)
	@mkdir -p $(dir $@)
	ar rcs $@ $^

$(BIN)/sgm-golden: $(OBJ)/golden/cli/sgm_golden.o $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDLIBS)

$(BIN)/sgm-eval: $(OBJ)/tools/sgm_eval.o $(EVAL_OBJ) $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDLIBS)

golden: $(BIN)/sgm-golden $(BIN)/sgm-eval

# ---------------------------------------------------------------- simulation
# make sim [LEFT=... RIGHT=... [GT=...] [GT_SCALE=...]] [OUT=build/sim] [D=64] [MAX_WIDTH=1280]
#          [STALL=0.0] [SEED=1] [FRAMES=1] [TRACE=1] [PRESET=default|four-path|paper] [CENSUS=9x5|9x9] [LANES=1]
#          [RIGHT_BLOCK=64 [RIGHT_WEIGHT=]] [MAX_HEIGHT=1024] [UNIQUENESS=1] [AD_TERM=1] [EDGE_RESET=1]
#          [DEPTH=0 [OUTPUT=depth FOCAL=F BASELINE=B]] [MIN_DISPARITY=0 [DMIN=N]]
#          [CALIB=DIR [UNIT_MM=U]] [RECTIFY=0 [RECTIFY_ROWS=32] [RECTIFY_GRID_LOG2=4]] [CONFIDENCE=0] [MIN_WIDTH=0]
# CALIB=DIR: LEFT and RIGHT are a raw camera pair and DIR its OpenCV calibration
# (intrinsics.yml, extrinsics.yml); it builds the rectification (RECTIFY=1: a line buffer
# of RECTIFY_ROWS rows, mesh steps of 2^RECTIFY_GRID_LOG2 px) and the confidence, and runs
# sgm-sim --calib DIR (3 frames back to back; the ground truth GT is in the rectified frame).
# CONFIDENCE=1 builds the confidence: the output word's bits 23:16, written as confidence.png
# and confidence_color.png (sgm-sim --output-confidence, on by default in such a build).
# DEPTH=1 builds the depth output; OUTPUT=depth runs it with f = F/256 px and B um (sgm-sim
# --output depth --focal F --baseline B: writes depth16.png and depth_color.png);
# MIN_DISPARITY=1 builds the minimum disparity, DMIN=N runs it (sgm-sim --dmin N).
# The program is sim/sgm_sim.cpp; CENSUS sets the core's census window (-GCENSUS_H),
# PRESET=paper implies CENSUS=9x9 and runs sgm-sim --preset paper. LANES = K row lanes
# (-GLANES, docs/lanes.md; also taken by make synth). RIGHT_BLOCK = B builds the
# fifth path in blocks of B (-GRIGHT_BLOCK; 0: none; default 64, 0 with PRESET=paper or
# four-path); the build runs its defaults (sgm::buildDefaults: with the fifth path ours in
# its blocks, without it the four-path preset); RIGHT_WEIGHT = W5 sets the weight
# (--right-path W5 --right-block B). The knobs and their defaults are scripts/build.mk's;
# the binary is build/bin/sgm-sim-<tag>[-trace] (the tag of scripts/build.mk, e.g.
# sgm-sim-d64-w1280, sgm-sim-d64-w1280-c9x9-rb0 for PRESET=paper), its parameters in
# build/verilator/<binary>/meta.txt and, after a run, in OUT/meta.txt.
OUT       ?= $(BUILD)/sim
RIGHT_WEIGHT ?=
PRESET    ?=
SIM_CORE   = $(CORE)
SIM_BIN    = $(BIN)/sgm-sim-$(call core_tag,$(SIM_CORE))$(if $(filter 1,$(TRACE)),-trace)
# Suffixes a binary name may add to the tag (make bench adds its variants).
SIM_BIN_SUFFIXES := trace
SIM_ARGS   = --out $(OUT) --d $(D) $(if $(PRESET),--preset $(PRESET)) $(if $(filter 9,$(CENSUS_H)),--census 9x9) \
             $(if $(LEFT),--left $(LEFT)) $(if $(RIGHT),--right $(RIGHT)) \
             $(if $(GT),--gt $(GT)) $(if $(GT_SCALE),--gt-scale $(GT_SCALE)) $(if $(STALL),--stall $(STALL)) \
             $(if $(SEED),--seed $(SEED)) $(if $(FRAMES),--frames $(FRAMES)) \
             $(if $(RIGHT_WEIGHT),--right-path $(RIGHT_WEIGHT) --right-block $(RIGHT_BLOCK)) \
             $(if $(OUTPUT),--output $(OUTPUT)) $(if $(FOCAL),--focal $(FOCAL)) $(if $(BASELINE),--baseline $(BASELINE)) \
             $(if $(DMIN),--dmin $(DMIN)) $(if $(CALIB),--calib $(CALIB)) $(if $(UNIT_MM),--unit-mm $(UNIT_MM))
SIM_VFLAGS = -O3 --x-assign fast --x-initial fast

# Any build/bin/sgm-sim-<tag>[-suffix] builds the core of SIM_CORE; the recipe stops unless
# the name is that build's tag (make build/bin/sgm-sim-d16-w128 D=16 MAX_WIDTH=128).
$(BIN)/sgm-sim-d%: sim/sgm_sim.cpp $(RTL_SRC) $(RTL_INC) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@case $(notdir $@) in sgm-sim-$(call core_tag,$(SIM_CORE))$(subst $(core_space),,$(foreach x,$(SIM_BIN_SUFFIXES),|sgm-sim-$(call core_tag,$(SIM_CORE))-$(x)))) ;; \
	   *) echo "$@: not the name of the build asked for (sgm-sim-$(call core_tag,$(SIM_CORE)): $(SIM_CORE))"; exit 1 ;; esac
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating sgm_top ($(call core_gflags,$(SIM_CORE))) for $@"
	@$(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) $(SIM_VFLAGS) $(VL_TRACE) -y rtl --top-module sgm_top \
	  $(call core_gflags,$(SIM_CORE)) -Mdir $(BUILD)/verilator/$(notdir $@) -o $(abspath $@) \
	  rtl/sgm_top.sv $(abspath sim/sgm_sim.cpp) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS) -DSGM_D=$(call core_get,$(SIM_CORE),D) -DSGM_MAX_WIDTH=$(call core_get,$(SIM_CORE),MAX_WIDTH) -DSGM_MAX_HEIGHT=$(call core_get,$(SIM_CORE),MAX_HEIGHT)" \
	  -LDFLAGS "$(OPENCV_LIBS) -pthread" \
	  > $(BUILD)/verilator-$(notdir $@).log || { grep -E -- '-USER(ERROR|FATAL):' $(BUILD)/verilator-$(notdir $@).log || \
	    tail -30 $(BUILD)/verilator-$(notdir $@).log; exit 1; }
	@$(call core_meta_write,$(SIM_CORE),$(BUILD)/verilator/$(notdir $@)/meta.txt)

sim: $(SIM_BIN)
	TRACE=$(TRACE) $(SIM_BIN) $(SIM_ARGS)
	@$(call core_meta_write,$(SIM_CORE),$(OUT)/meta.txt)

# CI smoke of `make sim`: the default scene (Aloe) at D = 64 on a MAX_WIDTH = 512 build,
# the same binary `make bench-ci` runs; sgm-sim exits non-zero unless bit-exact.
sim-ci:
	@$(MAKE) --no-print-directory sim D=64 MAX_WIDTH=512 MAX_HEIGHT=1024 OUT=$(BUILD)/sim-ci STALL= SEED= FRAMES= LEFT= RIGHT=

# make eval [DATA=...] [EVAL_SCENES=cones,teddy]; eval-ci is the CI smoke (one scene).
EVAL_SCENES ?=
eval: golden
	$(BIN)/sgm-eval table --data "$(DATA)" --out $(BUILD)/eval $(if $(EVAL_SCENES),--scenes $(EVAL_SCENES))

eval-ci:
	@if [ -d "$(DATA)/cones" ]; then $(MAKE) --no-print-directory eval EVAL_SCENES=cones; \
	 else echo "eval-ci: skipped: DATA=$(DATA) has no cones scene (README, 'Data')"; fi

bench-golden: golden
	$(BIN)/sgm-eval bench --data "$(DATA)" --out $(BUILD)/eval

# ---------------------------------------------------------------- RTL
RTL_TOPS   := $(wildcard tb/tops/*.sv)
RTL_MODULES = $(basename $(notdir $(RTL_SRC)))
VERILATOR  := verilator
VLT        := rtl/lint.vlt
VL_CFLAGS   = -std=c++17 -O2 $(MARCH) -I$(abspath golden) -I$(abspath tools) -I$(abspath tb) $(OPENCV_CFLAGS)
VL_LDFLAGS  = -lgtest -lgtest_main $(OPENCV_LIBS) -pthread
# TRACE=1 builds the verilated models with FST tracing (then run with TRACE=1 to write build/trace/*.fst).
VL_TRACE    = $(if $(filter 1,$(TRACE)),--trace-fst)

# $(call rtl_test,NAME,TOP,VERILATOR-OPTIONS[,TEST]): build/bin/rtl-NAME runs TEST (default
# tests/rtl/test_TOP.cpp) against the verilated TOP (an rtl/ module or a tb/tops/ wrapper)
# built with the options (parameters as -GNAME=VALUE). Verilator's own make runs -j $(JOBS)
# outside this make's job server (MAKEFLAGS cleared), so `make test` builds two fixtures at once,
# each with its own jobs: the single-threaded Verilator and link steps of one overlap the
# compilation of the other.
define rtl_test
RTL_TEST_BINS += $(BIN)/rtl-$(1)
FIXTURE_TOP_$(1) := $(2)
FIXTURE_FLAGS_$(1) := $(3)
FIXTURE_TEST_$(1) := $(if $(4),$(4),tests/rtl/test_$(2).cpp)
$(BIN)/rtl-$(1): $(if $(4),$(4),tests/rtl/test_$(2).cpp) $(RTL_SRC) $(RTL_INC) $(RTL_TOPS) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating $(2) for $$@ (log: $(BUILD)/verilator-$(1).log)"
	@s=$$$$(date +%s); MAKEFLAGS= $(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) --x-assign unique --x-initial unique $(VL_TRACE) \
	  -y rtl -y tb/tops --top-module $(2) $(3) -Mdir $(BUILD)/verilator/$(1) -o $(abspath $(BIN))/rtl-$(1) \
	  $(wildcard rtl/$(2).sv tb/tops/$(2).sv) $(abspath $(if $(4),$(4),tests/rtl/test_$(2).cpp)) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS)" -LDFLAGS "$(VL_LDFLAGS)" > $(BUILD)/verilator-$(1).log || \
	  { grep -E -- '-USER(ERROR|FATAL):' $(BUILD)/verilator-$(1).log || tail -30 $(BUILD)/verilator-$(1).log; exit 1; }; \
	  echo "time: build rtl-$(1) $$$$(( $$$$(date +%s) - s )) s"
endef

$(eval $(call rtl_test,p2-lut,sgm_p2_lut,))
$(eval $(call rtl_test,stream-ctrl,tb_stream_ctrl,))
$(eval $(call rtl_test,hole-fill,sgm_hole_fill,))
$(eval $(call rtl_test,hole-fill-d64,sgm_hole_fill,-GDW=10 -GMAX_WIDTH=512))
$(eval $(call rtl_test,edge-snap,sgm_edge_snap,))
$(eval $(call rtl_test,edge-snap-d64,sgm_edge_snap,-GDW=10 -GMAX_WIDTH=512))
$(eval $(call rtl_test,median5x5,sgm_median5x5,))
$(eval $(call rtl_test,median5x5-d64,sgm_median5x5,-GDW=10 -GMAX_WIDTH=512))
# sgm_depth (docs/algorithm.md section 10b) at the widest disparity word of the builds (13 bits:
# D = 256, or the minimum disparity).
$(eval $(call rtl_test,depth-dw13,sgm_depth,-GDW=13))
# sgm_rectify (docs/algorithm.md section 13): mesh steps of 8 and 4 px, line buffers of 16 and 8 rows, two and one channels.
$(eval $(call rtl_test,rectify-g8-r16,sgm_rectify,-GMAX_WIDTH=96 -GMAX_HEIGHT=48 -GROWS=16 -GGRID_LOG2=3 -GCHANNELS=2 -GINFO_W=16))
$(eval $(call rtl_test,rectify-g4-r8,sgm_rectify,-GMAX_WIDTH=61 -GMAX_HEIGHT=40 -GROWS=8 -GGRID_LOG2=2 -GINFO_W=3))
# Whole-core builds: small MAX_HEIGHT (384 at D = 64: the tallest Middlebury scene, venus, has
# 383 rows) so that the whole-core test sends frames of MAX_WIDTH x MAX_HEIGHT quickly.
$(eval $(call rtl_test,top-d16,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,top-d64,sgm_top,-GD=64 -GMAX_WIDTH=512 -GMAX_HEIGHT=384 -CFLAGS -DSGM_D=64))
$(eval $(call rtl_test,top-d32,sgm_top,-GD=32 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GRIGHT_BLOCK=0 -CFLAGS -DSGM_D=32))
$(eval $(call rtl_test,top-d128,sgm_top,-GD=128 -GMAX_WIDTH=256 -GMAX_HEIGHT=64 -CFLAGS -DSGM_D=128))
# The paper's 9x9 census window (CENSUS_H = 9): synthetic and malformed frames at D = 16,
# Aloe in the paper preset at D = 64.
$(eval $(call rtl_test,top-d16-9x9,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GCENSUS_H=9 -GRIGHT_BLOCK=0 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,top-d64-9x9,sgm_top,-GD=64 -GMAX_WIDTH=512 -GMAX_HEIGHT=384 -GCENSUS_H=9 -GRIGHT_BLOCK=0 -CFLAGS -DSGM_D=64))
# K row lanes (docs/lanes.md): the whole core at 2 lanes (9x5) and 3 lanes (9x9). The
# 3-lane build has its rotating delays as register chains (SGM_DELAY_CHAIN, the form the ECP5
# flow builds, rtl/sgm_delay_ram.sv); every other build has them in distributed RAM. The
# 2-lane build takes frames from 48 columns (MIN_WIDTH = 48: LR_LAG at most 2 rows, not 4,
# and LR check memories of 4 rows, not 8); its frames of 47 columns are dropped.
$(eval $(call rtl_test,top-d16-k2,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GLANES=2 -GRIGHT_BLOCK=0 -GMIN_WIDTH=48 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,top-d16-k3-9x9,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GLANES=3 -GCENSUS_H=9 -GRIGHT_BLOCK=0 -DSGM_DELAY_CHAIN -CFLAGS -DSGM_D=16))
# The lean build: neither run-time lever that costs area (UNIQUENESS = 0, AD_TERM = 0, docs/rtl.md
# "Build parameters"): bit-exact with the levers off, frames that ask for them dropped.
$(eval $(call rtl_test,top-d16-lean,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GUNIQUENESS=0 -GAD_TERM=0 -GEDGE_RESET=0 -GRIGHT_BLOCK=0 -CFLAGS -DSGM_D=16))
# The fifth path in blocks (sgm_top RIGHT_BLOCK): blocks of 8 at one lane, of 16 at two lanes
# (its defaults run weight 4; the settings, parameter sets and regression vary it); the first
# also has the depth output (DEPTH = 1), both the minimum disparity (MIN_DISPARITY = 1) and the
# rectification (RECTIFY = 1: line buffers of 16 rows and mesh steps of 8 px, 8 rows and 4 px).
$(eval $(call rtl_test,top-d16-rb8,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GRIGHT_BLOCK=8 -GEDGE_RESET=1 -GDEPTH=1 -GMIN_DISPARITY=1 -GRECTIFY=1 -GRECTIFY_ROWS=16 -GRECTIFY_GRID_LOG2=3 -GCONFIDENCE=1 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,top-d16-k2-rb16,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GLANES=2 -GRIGHT_BLOCK=16 -GEDGE_RESET=1 -GMIN_DISPARITY=1 -GRECTIFY=1 -GRECTIFY_ROWS=8 -GRECTIFY_GRID_LOG2=2 -GCONFIDENCE=1 -CFLAGS -DSGM_D=16))
# The reference builds (scripts/refs.mk), each whole (its D, lanes, MAX_WIDTH, features and,
# for the ECP5 ones, the ECP5 flow's register-chain delays): what `make pnr-ref` routes is
# what is tested, with frames up to its MAX_WIDTH.
$(eval $(call rtl_test,ref-hd64,sgm_top,$(call ref_gflags,hd64)))
$(eval $(call rtl_test,ref-fhd32,sgm_top,$(call ref_gflags,fhd32)))
$(eval $(call rtl_test,ref-small,sgm_top,$(call ref_gflags,small)))
$(eval $(call rtl_test,ref-fhd128,sgm_top,$(call ref_gflags,fhd128)))
$(foreach r,$(REF_NAMES),$(if $(FIXTURE_TOP_ref-$(r)),,$(error scripts/refs.mk: reference build $(r) has no rtl-ref-$(r) fixture in the Makefile)))
# A reference build's fixture is rebuilt when scripts/refs.mk (its parameters) changes.
$(foreach r,$(REF_NAMES),$(eval $(BIN)/rtl-ref-$(r): scripts/refs.mk))
# sgm_axi configured through the driver (sw/) over an AXI4-Lite bus model; the lean build reads
# its FEATURES back and has the frames that ask for a missing lever dropped; it takes frames from
# 40 columns (MIN_WIDTH = 40, read back in the MIN_WIDTH register).
$(eval $(call rtl_test,axi-d16,sgm_axi,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -CFLAGS -I$(abspath sw/include) $(abspath sw/sgm_driver.cpp)))
$(eval $(call rtl_test,axi-d16-lean,sgm_axi,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GUNIQUENESS=0 -GAD_TERM=0 -GEDGE_RESET=0 -GRIGHT_BLOCK=0 -GMIN_WIDTH=40 -CFLAGS -I$(abspath sw/include) $(abspath sw/sgm_driver.cpp)))
$(eval $(call rtl_test,axi-d16-rb16,sgm_axi,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -GRIGHT_BLOCK=16 -GEDGE_RESET=1 -GDEPTH=1 -GMIN_DISPARITY=1 -GRECTIFY=1 -GRECTIFY_ROWS=16 -GRECTIFY_GRID_LOG2=3 -GCONFIDENCE=1 -CFLAGS -I$(abspath sw/include) $(abspath sw/sgm_driver.cpp)))
$(BIN)/rtl-axi-d16 $(BIN)/rtl-axi-d16-lean $(BIN)/rtl-axi-d16-rb16: sw/sgm_driver.cpp $(wildcard sw/include/*.h*)
$(eval $(call rtl_test,path-engine-d16,sgm_path_engine,-GD=16 -GMAX_WIDTH=128 -GXW=8 -GYW=8 -GEDGE_RESET=1 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-engine-d64,sgm_path_engine,-GD=64 -GMAX_WIDTH=512 -GXW=10 -GYW=10 -GGRAY_LEAD=0 -GEDGE_RESET=1 -CFLAGS -DSGM_D=64 -CFLAGS -DSGM_YW=10))
# The engine in lane order (docs/lanes.md): K row lanes, SKEW columns apart.
$(eval $(call rtl_test,path-engine-d16-k2,sgm_path_engine,-GD=16 -GMAX_WIDTH=128 -GXW=8 -GYW=8 -GLANES=2 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-engine-d16-k5,sgm_path_engine,-GD=16 -GMAX_WIDTH=128 -GXW=8 -GYW=8 -GLANES=5 -GEDGE_RESET=1 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-engine-d64-k6,sgm_path_engine,-GD=64 -GMAX_WIDTH=512 -GXW=10 -GYW=10 -GLANES=6 -GEDGE_RESET=1 -CFLAGS -DSGM_D=64 -CFLAGS -DSGM_YW=10))
# The fifth path in blocks (sgm_right_path): one lane and lanes, small blocks (narrow
# frames, many blocks per row) and the D = 64 block of 32 at six lanes.
$(eval $(call rtl_test,right-path-d16-b8,sgm_right_path,-GD=16 -GBLOCK=8 -GXW=8 -GSIDE_W=16 -GEDGE_RESET=1 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,right-path-d16-b4-k2,sgm_right_path,-GD=16 -GBLOCK=4 -GXW=8 -GSIDE_W=16 -GLANES=2 -GEDGE_RESET=1 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,right-path-d16-b16-k3,sgm_right_path,-GD=16 -GBLOCK=16 -GXW=8 -GSIDE_W=16 -GLANES=3 -GL5_LAG=11 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,right-path-d64-b32-k6,sgm_right_path,-GD=64 -GBLOCK=32 -GXW=8 -GSIDE_W=16 -GLANES=6 -GL5_LAG=7 -GEDGE_RESET=1 -CFLAGS -DSGM_D=64))
# The 0 degree loop alone at LANES = 1 (the single-lane core) and with 2, 3, 4, 6 row lanes (docs/lanes.md);
# 12 lanes at D = 16 put several registers at one boundary (more lanes than loop units);
# D = 32 pads the tree's 64 leaves (D = 16 and 64 fill theirs).
$(eval $(call rtl_test,path-ring-d16,sgm_path_ring,-GD=16 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-ring-d16-k2,sgm_path_ring,-GD=16 -GLANES=2 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-ring-d16-k3,sgm_path_ring,-GD=16 -GLANES=3 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-ring-d16-k12,sgm_path_ring,-GD=16 -GLANES=12 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-ring-d32-k6,sgm_path_ring,-GD=32 -GLANES=6 -CFLAGS -DSGM_D=32))
$(eval $(call rtl_test,path-ring-d64-k4,sgm_path_ring,-GD=64 -GLANES=4 -CFLAGS -DSGM_D=64))
$(eval $(call rtl_test,path-ring-d64-k6,sgm_path_ring,-GD=64 -GLANES=6 -CFLAGS -DSGM_D=64))
$(eval $(call rtl_test,wta-d16,sgm_wta,-GD=16))
$(eval $(call rtl_test,wta-d64,sgm_wta,-GD=64 -GCONFIDENCE=1))
$(eval $(call rtl_test,wta-d16-lean,sgm_wta,-GD=16 -GUNIQUENESS=0))
$(eval $(call rtl_test,wta-d16-conf,sgm_wta,-GD=16 -GUNIQUENESS=0 -GCONFIDENCE=1))
$(eval $(call rtl_test,lr-check-d16,sgm_lr_check,-GD=16 -GMAX_WIDTH=128))
$(eval $(call rtl_test,lr-check-d64,sgm_lr_check,-GD=64 -GMAX_WIDTH=128))
$(eval $(call rtl_test,lr-check-d16-lean,sgm_lr_check,-GD=16 -GMAX_WIDTH=128 -GUNIQUENESS=0))
# The check with lanes (docs/lanes.md): S and WTA sides in lane order, the read side in raster order.
$(eval $(call rtl_test,lr-lanes-d16-k1,sgm_lr_check,-GD=16 -GMAX_WIDTH=128 -GRW=8 -GLANES=1 -GROW_BANKS=4,tests/rtl/test_sgm_lr_check_lanes.cpp))
$(eval $(call rtl_test,lr-lanes-d16-k3,sgm_lr_check,-GD=16 -GMAX_WIDTH=128 -GRW=8 -GLANES=3 -GROW_BANKS=8,tests/rtl/test_sgm_lr_check_lanes.cpp))
$(eval $(call rtl_test,lr-lanes-d64-k6,sgm_lr_check,-GD=64 -GMAX_WIDTH=256 -GRW=9 -GLANES=6 -GROW_BANKS=16,tests/rtl/test_sgm_lr_check_lanes.cpp))
$(eval $(call rtl_test,census-unit,sgm_census_unit,-GMAX_WIDTH=128 -GCW=8 -GRW=8))
# The census unit in the slot order of K row lanes (tests/rtl/test_sgm_census_unit_lanes.cpp).
$(eval $(call rtl_test,census-lanes-k1,sgm_census_unit,-GMAX_WIDTH=64 -GCW=8 -GRW=8 -GLANES=1,tests/rtl/test_sgm_census_unit_lanes.cpp))
$(eval $(call rtl_test,census-lanes-k2,sgm_census_unit,-GMAX_WIDTH=64 -GCW=8 -GRW=8 -GLANES=2,tests/rtl/test_sgm_census_unit_lanes.cpp))
$(eval $(call rtl_test,census-lanes-k3-9x9,sgm_census_unit,-GMAX_WIDTH=64 -GCW=8 -GRW=8 -GLANES=3 -GCENSUS_H=9,tests/rtl/test_sgm_census_unit_lanes.cpp))
$(eval $(call rtl_test,census-lanes-k6,sgm_census_unit,-GMAX_WIDTH=64 -GCW=8 -GRW=8 -GLANES=6,tests/rtl/test_sgm_census_unit_lanes.cpp))
# tests/rtl/test_sgm_cost_volume.cpp drives the wrapper tb_cost_front (two census units + the volume): the later --top-module wins.
$(eval $(call rtl_test,cost-volume-d16,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=16 -GMAX_WIDTH=128 -GCW=8 -GRW=8))
$(eval $(call rtl_test,cost-volume-d64,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=64 -GMAX_WIDTH=512 -GCW=10 -GRW=9))
$(eval $(call rtl_test,cost-volume-d16-lean,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=16 -GMAX_WIDTH=128 -GCW=8 -GRW=8 -GAD_TERM=0))
# Rows dealt to lanes from the stream controller's raster (docs/lanes.md): LANE_LEAD = max(1, K - 1) and ROWS >= max(2, 2K - 2) rows (a power of two).
$(eval $(call rtl_test,lane-deal-k1,sgm_lane_deal,-GLANES=1 -GLANE_LEAD=1 -GROWS=2))
$(eval $(call rtl_test,lane-deal-k2,sgm_lane_deal,-GLANES=2 -GLANE_LEAD=1 -GROWS=2))
$(eval $(call rtl_test,lane-deal-k3,sgm_lane_deal,-GLANES=3 -GLANE_LEAD=2 -GROWS=4))
$(eval $(call rtl_test,lane-deal-k6,sgm_lane_deal,-GLANES=6 -GLANE_LEAD=5 -GROWS=16))
# The volume in lane order (docs/lanes.md): the right delay line's taps K slots apart.
$(eval $(call rtl_test,cost-lanes-d16-k1,sgm_cost_volume,-GD=16 -GCW=8 -GLANES=1,tests/rtl/test_sgm_cost_volume_lanes.cpp))
$(eval $(call rtl_test,cost-lanes-d16-k3,sgm_cost_volume,-GD=16 -GCW=8 -GLANES=3,tests/rtl/test_sgm_cost_volume_lanes.cpp))
$(eval $(call rtl_test,cost-lanes-d64-k6,sgm_cost_volume,-GD=64 -GCW=8 -GLANES=6,tests/rtl/test_sgm_cost_volume_lanes.cpp))

RESULTS := $(BUILD)/test-results

# The fixtures JOBS at a time (scripts/run-rtl-tests.sh: each one's output printed whole).
rtl-tests: $(RTL_TEST_BINS)
	@SGM_DATA="$(DATA)" scripts/run-rtl-tests.sh $(JOBS) $(RESULTS) $(BUILD)/test-logs/rtl $(RTL_TEST_BINS)

# The SPDX line of every source file (scripts/spdx-check.sh), then verilator --lint-only -Wall
# on every module; waivers live in rtl/lint.vlt.
lint: | check-tools
	@scripts/spdx-check.sh
	@$(MAKE) --no-print-directory regmap-check
	@scripts/format-check.sh $(CLANG_FORMAT)
	@for m in $(RTL_MODULES); do \
	  $(VERILATOR) --lint-only -Wall $(VLT) -Irtl --top-module $$m rtl/$$m.sv || exit 1; \
	done; echo "lint: $(words $(RTL_MODULES)) modules clean"
	@# sgm_top is wiring only: the hierarchical synthesis flows (synth/common.tcl) synthesise
	@# its stage modules and keep none of the top's own logic (nextpnr then meets raw cells).
	@mkdir -p $(BUILD); for g in "" "-set RIGHT_BLOCK 8" "-set LANES 2" "-set LANES 2 -set RIGHT_BLOCK 8" "-set DEPTH 1 -set MIN_DISPARITY 1" \
	  "-set RECTIFY 1 -set RECTIFY_ROWS 16 -set RECTIFY_GRID_LOG2 3 -set CONFIDENCE 1" "-set RECTIFY 1 -set LANES 2" "-set CONFIDENCE 1 -set DEPTH 1"; do \
	  yosys -q -p "read_verilog -sv $(RTL_SRC); chparam -set D 16 -set MAX_WIDTH 128 -set MAX_HEIGHT 64 $$g sgm_top; \
	    hierarchy -top sgm_top; proc; tee -q -o $(BUILD)/lint-top-cells.txt select -list sgm_top/t:\$$* sgm_top/t:\$$paramod* %d" \
	    > /dev/null 2>&1 || { echo "lint: yosys could not elaborate sgm_top ($$g)"; exit 1; }; \
	  if [ -s $(BUILD)/lint-top-cells.txt ]; then echo "lint: sgm_top ($$g) has logic of its own (keep it in a module):"; \
	    cat $(BUILD)/lint-top-cells.txt; exit 1; fi; \
	done; echo "lint: sgm_top is wiring only (8 configurations)"

# ---------------------------------------------------------------- tests
$(BIN)/unit-tests: $(TEST_OBJ) $(EVAL_OBJ) $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ -lgtest -lgtest_main $(LDLIBS)

unit-test: $(BIN)/unit-tests golden
	@mkdir -p $(RESULTS)
	SGM_DATA="$(DATA)" SGM_BIN="$(abspath $(BIN))" $(BIN)/unit-tests --gtest_output=xml:$(RESULTS)/unit-tests.xml

# `make regress` (constrained-random regression), `make fuzz` (bad input), `make coverage`,
# `make bench`: included here, after every variable and the rtl_test macro are defined.
-include tests/regress.mk tests/fuzz.mk tests/coverage.mk bench/bench.mk tests/mutate/mutate.mk
-include tests/icarus.mk tests/fusesoc.mk tests/params.mk tests/formal.mk

# `make test`: lint and every binary of the GoogleTest suites built $(JOBS) at a time, the suites
# run one after another, then TEST_EXTRA in two streams (scripts/test-extra.sh): the targets of
# TEST_BESIDE (single-threaded yosys and nextpnr runs that share no build products with the
# rest) beside the others. One closing line over every GoogleTest binary of this run.
TEST_BESIDE := synth-ci ecp5-cmp-check pnr-ci pnr-ys-ci
test:
	@$(MAKE) --no-print-directory -j$(JOBS) -Otarget lint $(BIN)/unit-tests golden $(RTL_TEST_BINS)
	@$(MAKE) --no-print-directory unit-test rtl-tests
	@scripts/test-extra.sh "$(MAKE)" $(BUILD)/test-logs "$(filter $(TEST_BESIDE),$(TEST_EXTRA))" \
	  "$(filter-out $(TEST_BESIDE),$(TEST_EXTRA))"
	@scripts/test-summary.sh $(RESULTS)

clean:
	rm -rf $(BUILD)
