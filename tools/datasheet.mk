# SPDX-License-Identifier: Apache-2.0
# `make datasheet [DATASHEET=docs/datasheet.md] [DATASHEET_BUILD=build]`: the datasheet,
# and the summary section of README.md (DATASHEET_README), from the measured JSON reports
# only (sgm-eval datasheet, tools/datasheet.cpp):
# $(DATASHEET_BUILD)/synth/**/summary.json, pnr/summary.json, bench/report.json,
# eval/report.json, eval/pool.json; an absent report gives "not measured: run `make X`".
# `make datasheet-ci`: the generator on the hand-made reports of tests/data/datasheet/
# (the real formats), the page checked for figures taken from each of them, and a copy of
# README.md given its summary section (it must keep the section's markers).
DATASHEET       ?= docs/datasheet.md
DATASHEET_BUILD ?= $(BUILD)
DATASHEET_README ?= README.md
DATASHEET_CI    := tests/data/datasheet

.PHONY: datasheet datasheet-ci

datasheet: $(BIN)/sgm-eval
	$(BIN)/sgm-eval datasheet --build $(DATASHEET_BUILD) --out $(DATASHEET) --readme $(DATASHEET_README)

datasheet-ci: $(BIN)/sgm-eval
	@mkdir -p $(BUILD)/datasheet-ci && cp $(DATASHEET_README) $(BUILD)/datasheet-ci/README.md
	@$(BIN)/sgm-eval datasheet --build $(DATASHEET_CI) --out $(BUILD)/datasheet-ci/datasheet.md \
	  --readme $(BUILD)/datasheet-ci/README.md
	@scripts/datasheet-check.sh $(BUILD)/datasheet-ci/datasheet.md $(DATASHEET_CI)/expected.txt

TEST_EXTRA += datasheet-ci
