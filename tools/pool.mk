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
