# SPDX-License-Identifier: Apache-2.0
# FuseSoC: sgm.core (top level) describes the core for FuseSoC users; these
# targets run its three targets with this repository as the cores root, work
# directories under build/fusesoc/. Included by the main Makefile; CI runs
# fusesoc-lint (TEST_EXTRA).
#
#   make fusesoc-lint    Verilator -Wall lint of sgm_axi (D=16, MAX_WIDTH=128, 9x9, 2 lanes, without
#                        the uniqueness ratio and the AD term: the generate branches the default lint misses)
#   make fusesoc-sim     Icarus, the file-driven testbench on make icarus's files, checked
#   make fusesoc-synth   Yosys synth_xilinx (xc7) of sgm_axi, D=16, MAX_WIDTH=128

# scripts/deps.mk sets FUSESOC to the full path of the pinned PyPI install.
FUSESOC     ?= fusesoc
FUSESOC_DIR := $(BUILD)/fusesoc
FUSESOC_RUN  = cd $(FUSESOC_DIR) && $(FUSESOC) --cores-root $(CURDIR) run --build-root $(abspath $(FUSESOC_DIR))/$(1) --target $(1) ::sgm:1.0.0

.PHONY: fusesoc-lint fusesoc-sim fusesoc-synth
TEST_EXTRA += fusesoc-lint

fusesoc-lint: | check-pip-tools
	@mkdir -p $(FUSESOC_DIR)
	@$(call FUSESOC_RUN,lint) > $(abspath $(FUSESOC_DIR))/lint.log 2>&1 || { tail -30 $(abspath $(FUSESOC_DIR))/lint.log; exit 1; }
	@echo "fusesoc-lint: sgm.core lint target (Verilator -Wall, sgm_axi) clean"

fusesoc-sim: $(BIN)/sgm-icarus-frames | check-pip-tools
	@mkdir -p $(FUSESOC_DIR)/sim-files
	@$(BIN)/sgm-icarus-frames write $(FUSESOC_DIR)/sim-files
	@$(call FUSESOC_RUN,sim) --cfg=$(abspath $(FUSESOC_DIR))/sim-files/cfg.txt \
	  --in=$(abspath $(FUSESOC_DIR))/sim-files/in.txt --out=$(abspath $(FUSESOC_DIR))/sim-files/out.txt \
	  > $(abspath $(FUSESOC_DIR))/sim.log 2>&1 || { tail -30 $(abspath $(FUSESOC_DIR))/sim.log; exit 1; }
	@$(BIN)/sgm-icarus-frames check $(FUSESOC_DIR)/sim-files

fusesoc-synth: | check-pip-tools
	@mkdir -p $(FUSESOC_DIR)
	@$(call FUSESOC_RUN,synth) > $(abspath $(FUSESOC_DIR))/synth.log 2>&1 || { tail -30 $(abspath $(FUSESOC_DIR))/synth.log; exit 1; }
	@echo "fusesoc-synth: done, netlist and log under $(FUSESOC_DIR)/synth/"
