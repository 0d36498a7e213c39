# SPDX-License-Identifier: Apache-2.0
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
# The regression (tests/regress.mk) built the same way, D = 16: cov-regress-<tag> (scripts/build.mk);
# build/coverage/meta.txt records its build.
COV_REGRESS_CORE   := D=16 MAX_WIDTH=128
COV_REGRESS_BIN    := $(BIN)/cov-regress-$(call core_tag,$(COV_REGRESS_CORE))
COV_REGRESS_ARGS    = --seed $(COV_REGRESS_SEED) --frames $(COV_REGRESS_FRAMES) --max-height 40 --quiet
$(eval $(call regress_build,$(COV_REGRESS_BIN),$(COV_REGRESS_CORE),$(COV_VFLAGS)))

# The coverage variants: the fixtures of COV_FIXTURES built again, with the same
# top and options as their `make rtl-tests` builds (the rtl_test macro records
# them) plus the coverage flags. They are kept out of RTL_TEST_BINS so that
# `make rtl-tests` does not run them.
COV_FIXTURES   := p2-lut stream-ctrl hole-fill median5x5 edge-snap census-unit cost-volume-d16 \
                  path-ring-d16 path-ring-d16-k12 path-engine-d16 wta-d16 lr-check-d16 top-d16 axi-d16 \
                  path-engine-d16-k2 cost-lanes-d16-k3 lr-lanes-d16-k3 lane-deal-k3 top-d16-k2
COV_SAVED_BINS := $(RTL_TEST_BINS)
RTL_TEST_BINS  :=
$(foreach f,$(COV_FIXTURES),$(eval $(call rtl_test,cov-$(f),$(FIXTURE_TOP_$(f)),$(FIXTURE_FLAGS_$(f)) $(COV_VFLAGS),$(FIXTURE_TEST_$(f)))))
COV_TEST_BINS  := $(RTL_TEST_BINS)
$(BIN)/rtl-cov-axi-d16: sw/sgm_driver.cpp $(wildcard sw/include/*.h*)
RTL_TEST_BINS  := $(COV_SAVED_BINS)

# CI: the same flow (coverage build, run, merge, annotate, summary) on the
# regression alone, 40 frames: one coverage build of the whole core instead of
# thirteen (`make test` runs the fixtures in their plain builds).
COV_CI_REGRESS_FRAMES ?= 40
TEST_EXTRA += coverage-ci

.PHONY: coverage coverage-ci coverage-help

coverage-help:
	@echo "make coverage [COV_REGRESS_FRAMES=120 COV_REGRESS_SEED=1]   line + toggle coverage of rtl/ -> build/coverage/"

$(COV_SUMMARY): tests/coverage/coverage_summary.cpp | check-tools
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -o $@ $<

coverage: $(COV_TEST_BINS) $(COV_SUMMARY) $(COV_REGRESS_BIN) | check-tools
	@rm -rf $(COV_DIR) && mkdir -p $(COV_DIR)/data $(COV_DIR)/results
	@$(call core_meta_write,$(COV_REGRESS_CORE),$(COV_DIR)/meta.txt)
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

coverage-ci:
	@$(MAKE) --no-print-directory coverage COV_FIXTURES= COV_REGRESS_FRAMES=$(COV_CI_REGRESS_FRAMES)
