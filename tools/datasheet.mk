# SPDX-License-Identifier: Apache-2.0
# `make datasheet [DATASHEET=docs/datasheet.md] [DATASHEET_BUILD=build]`: the datasheet
# from the measured JSON reports only (sgm-eval datasheet, tools/datasheet.cpp):
# $(DATASHEET_BUILD)/synth/**/summary.json, pnr/summary.json, bench/report.json,
# eval/report.json, eval/pool.json; an absent report gives "not measured: run `make X`".
# `make datasheet-ci`: the generator on the hand-made reports of tests/data/datasheet/
# (the real formats), the page checked for figures taken from each of them.
DATASHEET       ?= docs/datasheet.md
DATASHEET_BUILD ?= $(BUILD)
DATASHEET_CI    := tests/data/datasheet

.PHONY: datasheet datasheet-ci

datasheet: $(BIN)/sgm-eval
	$(BIN)/sgm-eval datasheet --build $(DATASHEET_BUILD) --out $(DATASHEET)

datasheet-ci: $(BIN)/sgm-eval
	@$(BIN)/sgm-eval datasheet --build $(DATASHEET_CI) --out $(BUILD)/datasheet-ci/datasheet.md
	@scripts/datasheet-check.sh $(BUILD)/datasheet-ci/datasheet.md $(DATASHEET_CI)/expected.txt

TEST_EXTRA += datasheet-ci
