# SPDX-License-Identifier: Apache-2.0
# `make param-checks`: every parameter check of rtl/ and tb/tops/ fires with a message
# naming its parameter (Verilator lint; Yosys 0.23 for a subset), and the legal sets
# (tests/params/cases.txt and the Makefile's rtl_test fixtures) elaborate
# (tests/params/param_checks.sh; about a minute on 2 busy cores). PARAM_CHECKS_ALL=1
# also lints the whole-core fixtures. Included by the main Makefile; CI runs it (TEST_EXTRA).

.PHONY: param-checks
TEST_EXTRA += param-checks

param-checks: | check-tools
	@JOBS=$(JOBS) VERILATOR=$(VERILATOR) tests/params/param_checks.sh
