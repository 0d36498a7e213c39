# SPDX-License-Identifier: Apache-2.0
# `make mutate`: mutation testing of rtl/ (tests/mutate/mutate.sh; included by the main Makefile).
#
#   make mutate [MUTATE_ONLY=id,id]   every mutation of tests/mutate/mutations.txt (or the listed
#                                      ids) on a scratch copy of the tree -> build/mutate/report.{md,json}
#   make mutate-ci                     the fixed cheap slice CI runs; fails unless each is killed
#
# Long (one Verilator build per test tried per mutation): not part of `make test`, except
# mutate-ci. When a module changes, its mutations in tests/mutate/mutations.txt change in
# the same commit (a text that no longer matches stops the run).

MUTATE_LIST   ?= tests/mutate/mutations.txt
MUTATE_ONLY   ?=
MUTATE_CI_IDS := ctrl-height-max,p2-entry-max,wta-tie,axi-error-w1c-race,ctrl-out-tuser-row,deal-skew,delay-ram-wrap
MUTATE_DEPS   := $(GOLDEN_LIB) $(EVAL_OBJ)

.PHONY: mutate mutate-ci
TEST_EXTRA += mutate-ci

mutate: $(MUTATE_DEPS)
	DATA="$(DATA)" JOBS=$(JOBS) tests/mutate/mutate.sh $(if $(MUTATE_ONLY),--only $(MUTATE_ONLY)) $(MUTATE_LIST)

mutate-ci: $(MUTATE_DEPS)
	DATA="$(DATA)" JOBS=$(JOBS) tests/mutate/mutate.sh --require-kill --only $(MUTATE_CI_IDS) \
	  --out $(BUILD)/mutate-ci $(MUTATE_LIST)
