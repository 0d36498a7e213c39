# SPDX-License-Identifier: Apache-2.0
# `make raw-scenes [DATA=...] [RAW_SCENES="cones teddy venus sawtooth"] [RAW_GRID=16]`: raw camera
# pairs made from rectified scenes with a known calibration, and the way back (docs/algorithm.md,
# section 13), under RAW_OUT (build/raw-scenes):
#   raw/<scene>/        sgm-eval raw-scene: left.png, right.png (gray), intrinsics.yml, extrinsics.yml
#   mesh/<scene>/       sgm-eval calib-mesh: mesh.bin, mesh.json (mesh error, line-buffer rows, f, B)
#   rectified/<scene>/  sgm-eval rectify: left.png, right.png, and links to the scene's ground truth
#   rawpairs/<scene>/   links to the raw pair, its mesh.bin and the ground truth
# then the golden model's accuracy on the raw pairs, rectified as the core does it (a pixel whose
# left source lies outside the raw image is invalid; sgm-eval run on rawpairs/), beside the
# original ones.
# The scenes are read in place; a scene missing under DATA is skipped with a message.
RAW_OUT    ?= $(BUILD)/raw-scenes
RAW_SCENES ?= cones teddy venus sawtooth
RAW_GRID   ?= 16

.PHONY: raw-scenes
raw-scenes: golden
	@test -d "$(DATA)" || { echo "raw-scenes: no scenes at DATA='$(DATA)' (set DATA=/path/to/middlebury)"; exit 1; }
	@rm -rf $(RAW_OUT) && mkdir -p $(RAW_OUT)/rectified $(RAW_OUT)/rawpairs
	@found=; for s in $(RAW_SCENES); do \
	  d=$(abspath $(DATA))/$$s; \
	  if [ ! -f $$d/left.png ] || [ ! -f $$d/right.png ]; then echo "raw-scenes: $$s: no left.png and right.png under $(DATA), skipped"; continue; fi; \
	  $(BIN)/sgm-eval raw-scene --left $$d/left.png --right $$d/right.png --out $(RAW_OUT)/raw/$$s >/dev/null || exit 1; \
	  echo "raw-scenes: $$s"; \
	  $(BIN)/sgm-eval calib-mesh --calib $(RAW_OUT)/raw/$$s --size-of $$d/left.png --grid $(RAW_GRID) --out $(RAW_OUT)/mesh/$$s | sed -n '2,4p' || exit 1; \
	  $(BIN)/sgm-eval rectify --mesh $(RAW_OUT)/mesh/$$s/mesh.bin --left $(RAW_OUT)/raw/$$s/left.png \
	    --right $(RAW_OUT)/raw/$$s/right.png --out $(RAW_OUT)/rectified/$$s >/dev/null || exit 1; \
	  mkdir -p $(RAW_OUT)/rawpairs/$$s; \
	  for f in left.png right.png; do ln -s $(abspath $(RAW_OUT))/raw/$$s/$$f $(RAW_OUT)/rawpairs/$$s/$$f; done; \
	  ln -s $(abspath $(RAW_OUT))/mesh/$$s/mesh.bin $(RAW_OUT)/rawpairs/$$s/mesh.bin; \
	  for f in gt.png nonocc.png all.png disc.png meta.txt; do [ ! -e $$d/$$f ] || { ln -s $$d/$$f $(RAW_OUT)/rectified/$$s/$$f; \
	    ln -s $$d/$$f $(RAW_OUT)/rawpairs/$$s/$$f; }; done; \
	  found="$$found,$$s"; \
	done; \
	[ -n "$$found" ] || { echo "raw-scenes: none of $(RAW_SCENES) under $(DATA)"; exit 1; }; \
	echo "raw-scenes: the golden model on the raw pairs, rectified as the core does it:"; \
	$(BIN)/sgm-eval run --data $(RAW_OUT)/rawpairs | grep nonocc; \
	echo "raw-scenes: the golden model on the original pairs:"; \
	$(BIN)/sgm-eval run --data $(DATA) --scenes $${found#,} | grep nonocc

# CI: one scene (the smallest of Table I), when DATA has it.
.PHONY: raw-scenes-ci
raw-scenes-ci:
	@if [ -f "$(DATA)/venus/left.png" ]; then $(MAKE) --no-print-directory raw-scenes RAW_SCENES=venus RAW_OUT=$(BUILD)/raw-scenes-ci; \
	 else echo "raw-scenes-ci: skipped: no venus scene under DATA='$(DATA)'"; fi

# CI: the raw venus pair through the core's rectification (make sim CALIB=, a D = 64 build with
# the rectification and the depth output), bit-exact with the golden model or it fails.
.PHONY: sim-calib-ci
sim-calib-ci: raw-scenes-ci
	@if [ -f "$(DATA)/venus/left.png" ]; then \
	  $(MAKE) --no-print-directory sim D=64 MAX_WIDTH=512 MAX_HEIGHT=384 DEPTH=1 OUT=$(BUILD)/sim-calib-ci \
	    LEFT=$(BUILD)/raw-scenes-ci/raw/venus/left.png RIGHT=$(BUILD)/raw-scenes-ci/raw/venus/right.png \
	    CALIB=$(BUILD)/raw-scenes-ci/raw/venus GT=$(DATA)/venus/gt.png \
	    GT_SCALE=$$(sed -n 's/^gt_scale: \([0-9]*\).*/\1/p' $(DATA)/venus/meta.txt) STALL= SEED= FRAMES=; \
	 else echo "sim-calib-ci: skipped: no venus scene under DATA='$(DATA)'"; fi

TEST_EXTRA += sim-calib-ci
