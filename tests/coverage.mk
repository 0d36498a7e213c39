# `make coverage`: line and toggle coverage of rtl/ (included by the main Makefile).
#
# Builds the verilated GoogleTest fixtures (every module family and the whole
# core at D = 16) and the constrained-random regression with
# `verilator --coverage-line --coverage-toggle`, runs them (each model instance
# writes a data file into build/coverage/data/), merges the data and writes
#   build/coverage/summary.md    per-file table and every uncovered line point
#   build/coverage/summary.json  the same figures for scripts
#   build/coverage/coverage.info lcov (genhtml can render it)
#   build/coverage/annotated/    the sources annotated by verilator_coverage
# Unreachable line points are listed with their reason in tests/coverage/waivers.txt.

COV_DIR      := $(BUILD)/coverage
COV_VFLAGS   := --coverage-line --coverage-toggle
COV_SUMMARY  := $(BIN)/coverage-summary
COV_REGRESS_FRAMES ?= 120
COV_REGRESS_SEED   ?= 1
# The regression (tests/regress.mk) built the same way, D = 16.
COV_REGRESS_BIN    := $(BIN)/cov-regress-d16-w128
COV_REGRESS_ARGS    = --seed $(COV_REGRESS_SEED) --frames $(COV_REGRESS_FRAMES) --max-height 40 --quiet
$(eval $(call regress_build,$(COV_REGRESS_BIN),16,128,$(COV_VFLAGS)))

# The coverage variants reuse the rtl_test macro under other names; they are
# kept out of RTL_TEST_BINS so that `make rtl-tests` does not run them.
COV_SAVED_BINS := $(RTL_TEST_BINS)
RTL_TEST_BINS  :=
$(eval $(call rtl_test,cov-p2-lut,sgm_p2_lut,$(COV_VFLAGS)))
$(eval $(call rtl_test,cov-stream-ctrl,tb_stream_ctrl,$(COV_VFLAGS)))
$(eval $(call rtl_test,cov-hole-fill,sgm_hole_fill,$(COV_VFLAGS)))
$(eval $(call rtl_test,cov-median5x5,sgm_median5x5,$(COV_VFLAGS)))
$(eval $(call rtl_test,cov-edge-snap,sgm_edge_snap,$(COV_VFLAGS)))
$(eval $(call rtl_test,cov-census-unit,sgm_census_unit,-GMAX_WIDTH=128 -GCW=8 -GRW=8 $(COV_VFLAGS)))
$(eval $(call rtl_test,cov-cost-volume-d16,sgm_cost_volume,--top-module tb_cost_front tb/tops/tb_cost_front.sv -GD=16 -GMAX_WIDTH=128 -GCW=8 -GRW=8 $(COV_VFLAGS)))
$(eval $(call rtl_test,cov-path-engine-d16,sgm_path_engine,-GD=16 -GMAX_WIDTH=128 -GXW=8 -GYW=8 -CFLAGS -DSGM_D=16 $(COV_VFLAGS)))
$(eval $(call rtl_test,cov-wta-d16,sgm_wta,-GD=16 $(COV_VFLAGS)))
$(eval $(call rtl_test,cov-lr-check-d16,sgm_lr_check,-GD=16 -GMAX_WIDTH=128 $(COV_VFLAGS)))
$(eval $(call rtl_test,cov-top-d16,sgm_top,-GD=16 -GMAX_WIDTH=128 -GMAX_HEIGHT=64 -CFLAGS -DSGM_D=16 $(COV_VFLAGS)))
COV_TEST_BINS  := $(RTL_TEST_BINS)
RTL_TEST_BINS  := $(COV_SAVED_BINS)

.PHONY: coverage coverage-help

coverage-help:
	@echo "make coverage [COV_REGRESS_FRAMES=120 COV_REGRESS_SEED=1]   line + toggle coverage of rtl/ -> build/coverage/"

$(COV_SUMMARY): tests/coverage/coverage_summary.cpp | check-tools
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -o $@ $<

coverage: $(COV_TEST_BINS) $(COV_SUMMARY) $(COV_REGRESS_BIN) | check-tools
	@rm -rf $(COV_DIR) && mkdir -p $(COV_DIR)/data $(COV_DIR)/results
	@set -e; for t in $(COV_TEST_BINS); do echo "== $$t"; \
	  SGM_COVERAGE_DIR=$(COV_DIR)/data SGM_DATA="$(DATA)" $$t --gtest_brief=1 \
	    --gtest_output=xml:$(COV_DIR)/results/$$(basename $$t).xml > $(COV_DIR)/results/$$(basename $$t).log \
	    || { tail -30 $(COV_DIR)/results/$$(basename $$t).log; exit 1; }; done
	@if [ -n "$(COV_REGRESS_BIN)" ]; then echo "== $(COV_REGRESS_BIN) (regression, $(COV_REGRESS_FRAMES) frames, seed $(COV_REGRESS_SEED))"; \
	  SGM_COVERAGE_DIR=$(COV_DIR)/data $(COV_REGRESS_BIN) $(COV_REGRESS_ARGS) > $(COV_DIR)/results/regress.log \
	    || { tail -30 $(COV_DIR)/results/regress.log; exit 1; }; fi
	@verilator_coverage --write $(COV_DIR)/merged.dat $(COV_DIR)/data/*.dat
	@verilator_coverage --write-info $(COV_DIR)/coverage.info $(COV_DIR)/merged.dat
	@verilator_coverage --annotate $(COV_DIR)/annotated --annotate-min 1 $(COV_DIR)/merged.dat > /dev/null
	@$(COV_SUMMARY) --out $(COV_DIR) --waivers tests/coverage/waivers.txt $(COV_DIR)/merged.dat
