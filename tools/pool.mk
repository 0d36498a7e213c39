# SPDX-License-Identifier: Apache-2.0
# `make eval-pool`: the golden model and OpenCV StereoSGBM on every scene of the pool
# (POOL, layout of ../shared/data/pool/README.md), each at its meta.txt ndisp ->
# build/eval/pool.md, pool.json, pool.png. POOL_SCENES=a,b keeps those scenes;
# POOL_FLAGS passes pipeline options (and --half A|B, --opencv off) to sgm-eval pool.
# eval-pool-ci is the CI smoke: one Middlebury 2001 scene and one KITTI scene.
POOL        ?= $(abspath ../shared/data/pool)
POOL_SCENES ?=
POOL_FLAGS  ?=
POOL_CI_SCENES := map,kitti2012_000070

.PHONY: eval-pool eval-pool-ci

eval-pool: golden
	@if [ -d "$(POOL)" ]; then \
	   $(BIN)/sgm-eval pool --pool "$(POOL)" --out $(BUILD)/eval $(if $(POOL_SCENES),--scenes $(POOL_SCENES)) $(POOL_FLAGS); \
	 else echo "eval-pool: skipped: POOL=$(POOL) is not a directory (README, 'Data')"; fi

eval-pool-ci: golden
	@if [ -d "$(POOL)/map" ] && [ -d "$(POOL)/kitti2012_000070" ]; then \
	   $(BIN)/sgm-eval pool --pool "$(POOL)" --out $(BUILD)/eval-pool-ci --scenes $(POOL_CI_SCENES); \
	 else echo "eval-pool-ci: skipped: POOL=$(POOL) has no map and kitti2012_000070 scenes (README, 'Data')"; fi

TEST_EXTRA += eval-pool-ci

# `make eval-confidence`: how well the confidence map ranks the errors on the pool (sgm-eval
# confidence: the error of the most confident 10 .. 100 % of the pixels per scene) ->
# build/eval/confidence.md, confidence.json, confidence.png; POOL_SCENES, POOL_FLAGS as above.
# eval-confidence-ci: the two scenes of eval-pool-ci.
.PHONY: eval-confidence eval-confidence-ci
eval-confidence: golden
	@if [ -d "$(POOL)" ]; then 	   $(BIN)/sgm-eval confidence --pool "$(POOL)" --out $(BUILD)/eval $(if $(POOL_SCENES),--scenes $(POOL_SCENES)) $(POOL_FLAGS); 	 else echo "eval-confidence: skipped: POOL=$(POOL) is not a directory (README, 'Data')"; fi

eval-confidence-ci: golden
	@if [ -d "$(POOL)/map" ] && [ -d "$(POOL)/kitti2012_000070" ]; then 	   $(BIN)/sgm-eval confidence --pool "$(POOL)" --out $(BUILD)/eval-confidence-ci --scenes $(POOL_CI_SCENES); 	 else echo "eval-confidence-ci: skipped: POOL=$(POOL) has no map and kitti2012_000070 scenes (README, 'Data')"; fi

TEST_EXTRA += eval-confidence-ci

# `make eval-pool-rtl`: the verilated core (D = 128, MAX_WIDTH = 1280, the `make sim` build)
# on pool scenes at full size, one Middlebury and one KITTI pair (1242 px wide) by default;
# sgm-sim compares every output pixel with the golden model and exits non-zero on the first
# mismatch. Heavy: one whole-core Verilator build at D = 128 (not part of `make test`).
POOL_RTL_SCENES ?= aloe kitti2015_000045
POOL_RTL_CORE   := D=128 MAX_WIDTH=1280
POOL_RTL_SIM    := $(BIN)/sgm-sim-$(call core_tag,$(POOL_RTL_CORE))
POOL_RTL_OUT    ?= $(BUILD)/eval-pool-rtl

.PHONY: eval-pool-rtl
eval-pool-rtl:
	@if [ -d "$(POOL)" ]; then \
	   $(MAKE) --no-print-directory SIM_CORE="$(POOL_RTL_CORE)" TRACE= $(POOL_RTL_SIM) && \
	   for s in $(POOL_RTL_SCENES); do \
	     echo "eval-pool-rtl: the core on $$s (D = 128)"; \
	     $(POOL_RTL_SIM) --left "$(POOL)/$$s/left.png" --right "$(POOL)/$$s/right.png" --gt "$(POOL)/$$s/gt.png" \
	       --d 128 --out $(POOL_RTL_OUT)/$$s || exit 1; \
	   done; \
	 else echo "eval-pool-rtl: skipped: POOL=$(POOL) is not a directory (README, 'Data')"; fi
