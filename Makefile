# SGM stereo core: golden model, evaluator, RTL simulation, synthesis, tests.
# `make help` lists the targets.

SHELL      := /bin/bash
BUILD      := build
BIN        := $(BUILD)/bin
OBJ        := $(BUILD)/obj
DATA       ?= $(abspath ../shared/data/middlebury)
JOBS       ?= 2

CXX        ?= g++
ARCH       ?= x86-64-v3
CXXFLAGS   ?= -O3 -march=$(ARCH) -g
override CXXFLAGS += -std=c++17 -Wall -Wextra -pthread -Igolden -Itools
OPENCV_CFLAGS = $(shell pkg-config --cflags opencv4 2>/dev/null)
OPENCV_LIBS   = $(shell pkg-config --libs opencv4 2>/dev/null)
LDLIBS     += $(OPENCV_LIBS) -pthread

GOLDEN_SRC := $(wildcard golden/sgm/*.cpp)
GOLDEN_OBJ := $(patsubst %.cpp,$(OBJ)/%.o,$(GOLDEN_SRC))
GOLDEN_LIB := $(BUILD)/lib/libsgmgolden.a
GOLDEN_HDR := $(wildcard golden/sgm/*.hpp)
RTL_SRC    := $(wildcard rtl/*.sv)
TB_HDR     := $(wildcard tb/*.hpp)

# tools/*.cpp except the CLI mains form the evaluation library (scenes, error
# figures, OpenCV reference, reports) shared by sgm-eval, the tests and the harness.
EVAL_SRC   := $(filter-out tools/sgm_eval.cpp,$(wildcard tools/*.cpp))
EVAL_OBJ   := $(patsubst %.cpp,$(OBJ)/%.o,$(EVAL_SRC))
TEST_SRC   := $(wildcard tests/*.cpp)
TEST_OBJ   := $(patsubst %.cpp,$(OBJ)/%.o,$(TEST_SRC))

.PHONY: all help deps check-tools golden eval bench-golden test unit-test rtl-tests sim synth lint clean
.DEFAULT_GOAL := all

all: golden

help:
	@echo "make deps          install the Debian packages the project needs (root, idempotent)"
	@echo "make golden        build build/bin/sgm-golden and build/bin/sgm-eval"
	@echo "make sim           the verilated core on Aloe (or LEFT= RIGHT= [GT=] [OUT=]) vs the golden model"
	@echo "                   options: D=64 MAX_WIDTH=1280 STALL=0.3 FRAMES=2 SEED=1 TRACE=1"
	@echo "make lint          verilator --lint-only -Wall on every RTL module"
	@echo "make rtl-tests     every verilated GoogleTest fixture (modules and the whole core)"
	@echo "make eval          Table I and full-pipeline accuracy on DATA=$(DATA) -> build/eval/"
	@echo "make bench-golden  golden model vs OpenCV StereoSGBM time on one frame, same run"
	@echo "make bench         accuracy (RTL, golden, OpenCV x3, paper) and speed in one run -> build/bench/"
	@echo "make synth         Yosys area/timing reports (D=64 MAX_WIDTH=1280) -> build/synth/; make synth-help"
	@echo "make pnr           ECP5 place and route of the whole core (D=64 MAX_WIDTH=1024, LFE5U-85F) -> build/pnr/; make pnr-help"
	@echo "make regress       constrained-random regression of the core (seeded, replayable)"
	@echo "make fuzz          seeded random-corruption fuzzing of image loading and argument parsing"
	@echo "make coverage      line and toggle coverage of rtl/ -> build/coverage/"
	@echo "make test          everything CI runs (lint, unit tests, RTL fixtures, synth-ci, regress-ci, fuzz-ci)"
	@echo "make clean         remove build/"

# ---------------------------------------------------------------- dependencies
include scripts/deps.mk
# Fragments add their own targets; each appends the targets CI must run to
# TEST_EXTRA (run by `make test` after the GoogleTest binaries).
TEST_EXTRA :=
# `make synth` and its reports (synth/synth.mk, when present).
-include synth/synth.mk
# `make pnr`, `make pnr-ci`: place and route on ECP5 (synth/pnr.mk).
-include synth/pnr.mk

# ---------------------------------------------------------------- golden model
$(OBJ)/%.o: %.cpp $(GOLDEN_HDR) $(wildcard tools/*.hpp tests/*.hpp) | check-tools
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(OPENCV_CFLAGS) -c $< -o $@

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
#          [STALL=0.0] [SEED=1] [FRAMES=1] [TRACE=1]
OUT       ?= $(BUILD)/sim
D         ?= 64
MAX_WIDTH ?= 1280
MAX_HEIGHT ?= 1024
SIM_BIN    = $(BIN)/sgm-sim-d$(D)-w$(MAX_WIDTH)$(if $(filter-out 1024,$(MAX_HEIGHT)),-h$(MAX_HEIGHT))$(if $(filter 1,$(TRACE)),-trace)
SIM_ARGS   = --out $(OUT) --d $(D) $(if $(LEFT),--left $(LEFT)) $(if $(RIGHT),--right $(RIGHT)) \
             $(if $(GT),--gt $(GT)) $(if $(GT_SCALE),--gt-scale $(GT_SCALE)) $(if $(STALL),--stall $(STALL)) \
             $(if $(SEED),--seed $(SEED)) $(if $(FRAMES),--frames $(FRAMES))
SIM_VFLAGS = -O3 --x-assign fast --x-initial fast

$(BIN)/sgm-sim-d%: tb/sim_main.cpp $(RTL_SRC) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating sgm_top (D=$(D), MAX_WIDTH=$(MAX_WIDTH)) for $@"
	@$(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) $(SIM_VFLAGS) $(VL_TRACE) -y rtl --top-module sgm_top \
	  -GD=$(D) -GMAX_WIDTH=$(MAX_WIDTH) -GMAX_HEIGHT=$(MAX_HEIGHT) -Mdir $(BUILD)/verilator/$(notdir $@) -o $(abspath $@) \
	  rtl/sgm_top.sv $(abspath tb/sim_main.cpp) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS) -DSGM_D=$(D) -DSGM_MAX_WIDTH=$(MAX_WIDTH) -DSGM_MAX_HEIGHT=$(MAX_HEIGHT)" -LDFLAGS "$(OPENCV_LIBS) -pthread" \
	  > $(BUILD)/verilator-$(notdir $@).log || { tail -30 $(BUILD)/verilator-$(notdir $@).log; exit 1; }

sim: $(SIM_BIN)
	TRACE=$(TRACE) $(SIM_BIN) $(SIM_ARGS)

eval: golden
	$(BIN)/sgm-eval table --data "$(DATA)" --out $(BUILD)/eval

bench-golden: golden
	$(BIN)/sgm-eval bench --data "$(DATA)" --out $(BUILD)/eval

# ---------------------------------------------------------------- RTL
RTL_TOPS   := $(wildcard tb/tops/*.sv)
RTL_MODULES = $(basename $(notdir $(RTL_SRC)))
VERILATOR  := verilator
VLT        := rtl/lint.vlt
VL_CFLAGS   = -std=c++17 -O2 -march=$(ARCH) -I$(abspath golden) -I$(abspath tools) -I$(abspath tb) $(OPENCV_CFLAGS)
VL_LDFLAGS  = -lgtest -lgtest_main $(OPENCV_LIBS) -pthread
# TRACE=1 builds the verilated models with FST tracing (then run with TRACE=1 to write build/trace/*.fst).
VL_TRACE    = $(if $(filter 1,$(TRACE)),--trace-fst)

# $(call rtl_test,NAME,TOP,VERILATOR-OPTIONS): build/bin/rtl-NAME runs tests/rtl/test_TOP.cpp
# against the verilated TOP (an rtl/ module or a tb/tops/ wrapper) built with the options
# (parameters as -GNAME=VALUE).
define rtl_test
RTL_TEST_BINS += $(BIN)/rtl-$(1)
$(BIN)/rtl-$(1): tests/rtl/test_$(2).cpp $(RTL_SRC) $(RTL_TOPS) $(TB_HDR) $(EVAL_OBJ) $(GOLDEN_LIB) | check-tools
	@mkdir -p $(BIN) $(BUILD)/verilator
	@echo "verilating $(2) for $$@ (log: $(BUILD)/verilator-$(1).log)"
	@$(VERILATOR) --cc --exe --build -j $(JOBS) -Wall $(VLT) --x-assign unique --x-initial unique $(VL_TRACE) \
	  -y rtl -y tb/tops --top-module $(2) $(3) -Mdir $(BUILD)/verilator/$(1) -o $(abspath $(BIN))/rtl-$(1) \
	  $(wildcard rtl/$(2).sv tb/tops/$(2).sv) $(abspath tests/rtl/test_$(2).cpp) $(abspath $(EVAL_OBJ)) $(abspath $(GOLDEN_LIB)) \
	  -CFLAGS "$(VL_CFLAGS)" -LDFLAGS "$(VL_LDFLAGS)" > $(BUILD)/verilator-$(1).log || \
	  { tail -30 $(BUILD)/verilator-$(1).log; exit 1; }
endef

$(eval $(call rtl_test,p2-lut,sgm_p2_lut,))
$(eval $(call rtl_test,stream-ctrl,tb_stream_ctrl,))
$(eval $(call rtl_test,hole-fill,sgm_hole_fill,))
$(eval $(call rtl_test,hole-fill-d64,sgm_hole_fill,-GDW=10 -GMAX_WIDTH=512))
$(eval $(call rtl_test,edge-snap,sgm_edge_snap,))
$(eval $(call rtl_test,edge-snap-d64,sgm_edge_snap,-GDW=10 -GMAX_WIDTH=512))
$(eval $(call rtl_test,median5x5,sgm_median5x5,))
$(eval $(call rtl_test,median5x5-d64,sgm_median5x5,-GDW=10 -GMAX_WIDTH=512))
$(eval $(call rtl_test,top-d16,sgm_top,-GD=16 -GMAX_WIDTH=128 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,top-d64,sgm_top,-GD=64 -GMAX_WIDTH=512 -CFLAGS -DSGM_D=64))
$(eval $(call rtl_test,top-d32,sgm_top,-GD=32 -GMAX_WIDTH=128 -CFLAGS -DSGM_D=32))
$(eval $(call rtl_test,top-d128,sgm_top,-GD=128 -GMAX_WIDTH=256 -CFLAGS -DSGM_D=128))
$(eval $(call rtl_test,path-engine-d16,sgm_path_engine,-GD=16 -GMAX_WIDTH=128 -GXW=8 -GYW=8 -CFLAGS -DSGM_D=16))
$(eval $(call rtl_test,path-engine-d64,sgm_path_engine,-GD=64 -GMAX_WIDTH=512 -GXW=10 -GYW=10 -CFLAGS -DSGM_D=64 -CFLAGS -DSGM_YW=10))
$(eval $(call rtl_test,wta-d16,sgm_wta,-GD=16))
$(eval $(call rtl_test,wta-d64,sgm_wta,-GD=64))
$(eval $(call rtl_test,lr-check-d16,sgm_lr_check,-GD=16 -GMAX_WIDTH=128))
$(eval $(call rtl_test,lr-check-d64,sgm_lr_check,-GD=64 -GMAX_WIDTH=128))
$(eval $(call rtl_test,census-unit,sgm_census_unit,-GMAX_WIDTH=128 -GCW=8 -GRW=8))
# tests/rtl/test_sgm_cost_volume.cpp drives the wrapper tb_cost_front (two census units + the volume): the later --top-module wins.
$(eval $(call rtl_test,cost-volume-d16,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=16 -GMAX_WIDTH=128 -GCW=8 -GRW=8))
$(eval $(call rtl_test,cost-volume-d64,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=64 -GMAX_WIDTH=512 -GCW=10 -GRW=9))

RESULTS := $(BUILD)/test-results

rtl-tests: $(RTL_TEST_BINS)
	@mkdir -p $(RESULTS)
	@for t in $(RTL_TEST_BINS); do echo "== $$t"; \
	  SGM_DATA="$(DATA)" $$t --gtest_output=xml:$(RESULTS)/$$(basename $$t).xml || exit 1; done

# verilator --lint-only -Wall on every module; waivers live in rtl/lint.vlt.
lint: | check-tools
	@for m in $(RTL_MODULES); do \
	  $(VERILATOR) --lint-only -Wall $(VLT) -Irtl --top-module $$m rtl/$$m.sv || exit 1; \
	done; echo "lint: $(words $(RTL_MODULES)) modules clean"

# ---------------------------------------------------------------- tests
$(BIN)/unit-tests: $(TEST_OBJ) $(EVAL_OBJ) $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ -lgtest -lgtest_main $(LDLIBS)

unit-test: $(BIN)/unit-tests golden
	@mkdir -p $(RESULTS)
	SGM_DATA="$(DATA)" SGM_BIN="$(abspath $(BIN))" $(BIN)/unit-tests --gtest_output=xml:$(RESULTS)/unit-tests.xml

# `make regress` (constrained-random regression), `make fuzz` (bad input), `make coverage`,
# `make bench`: included here, after every variable and the rtl_test macro are defined.
-include tests/regress.mk tests/fuzz.mk tests/coverage.mk bench/bench.mk

# One closing line over every GoogleTest binary of this run.
test: lint unit-test rtl-tests
	@for t in $(TEST_EXTRA); do $(MAKE) --no-print-directory $$t || exit 1; done
	@scripts/test-summary.sh $(RESULTS)

clean:
	rm -rf $(BUILD)
