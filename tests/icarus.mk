# SPDX-License-Identifier: Apache-2.0
# `make icarus`: the RTL in a second simulator. Icarus Verilog (iverilog -g2012)
# compiles rtl/ with the file-driven testbench tb/icarus/tb_sgm_top_files.sv
# (D = 16, MAX_WIDTH = 128); tests/icarus/icarus_frames.cpp writes two small
# synthetic frames and the golden model's output, and checks the simulated
# output pixel by pixel (exit 1 naming the first (x, y), expected, got).
# Included by the main Makefile; CI runs it (TEST_EXTRA).

IVERILOG     ?= iverilog
VVP          ?= vvp
ICARUS_DIR   := $(BUILD)/icarus
ICARUS_STALL ?= 64
ICARUS_SEED  ?= 1
# sgm_top RIGHT_BLOCK of the Icarus build (its default); the frames' defaults follow it.
ICARUS_RIGHT_BLOCK := 64

.PHONY: icarus
TEST_EXTRA += icarus

$(BIN)/sgm-icarus-frames: $(OBJ)/tests/icarus/icarus_frames.o $(EVAL_OBJ) $(GOLDEN_LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDLIBS)

$(OBJ)/tests/icarus/icarus_frames.o: override CXXFLAGS += -Itb -DICARUS_RIGHT_BLOCK=$(ICARUS_RIGHT_BLOCK)
$(OBJ)/tests/icarus/icarus_frames.o: tests/icarus.mk

$(ICARUS_DIR)/tb_sgm_top_files.vvp: tb/icarus/tb_sgm_top_files.sv $(RTL_SRC) $(RTL_INC) tests/icarus.mk | check-tools
	@mkdir -p $(dir $@)
	$(IVERILOG) -g2012 -Wall -Wno-timescale -Wno-sensitivity-entire-array -I rtl -o $@ -s tb_sgm_top_files \
	  -Ptb_sgm_top_files.D=16 -Ptb_sgm_top_files.MAX_WIDTH=128 -Ptb_sgm_top_files.MAX_HEIGHT=64 \
	  -Ptb_sgm_top_files.RIGHT_BLOCK=$(ICARUS_RIGHT_BLOCK) \
	  tb/icarus/tb_sgm_top_files.sv $(RTL_SRC) 2> $(ICARUS_DIR)/iverilog.log || { cat $(ICARUS_DIR)/iverilog.log; exit 1; }

icarus: $(BIN)/sgm-icarus-frames $(ICARUS_DIR)/tb_sgm_top_files.vvp
	@$(BIN)/sgm-icarus-frames write $(ICARUS_DIR)
	@rm -f $(ICARUS_DIR)/out.txt
	$(VVP) -n $(ICARUS_DIR)/tb_sgm_top_files.vvp +cfg=$(ICARUS_DIR)/cfg.txt +in=$(ICARUS_DIR)/in.txt \
	  +out=$(ICARUS_DIR)/out.txt +stall=$(ICARUS_STALL) +seed=$(ICARUS_SEED)
	@$(BIN)/sgm-icarus-frames check $(ICARUS_DIR)
