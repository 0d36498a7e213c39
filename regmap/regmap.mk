# SPDX-License-Identifier: Apache-2.0
# The register map, described once in regmap/sgm_regmap.def, and its generated copies:
#   make regmap         writes sw/include/sgm_regs.h, rtl/sgm_regmap.svh, rtl/sgm_cfg.svh (the
#                       frame configuration word), tb/sgm_cfg_fields.hpp (its table for the
#                       testbenches) and the generated sections of docs/registers.md from the
#                       description
#   make regmap-check   fails when any of them differs from what the description gives
#                       (run by `make lint`, so by `make test`)
REGMAP_GEN   := $(BIN)/sgm-regmap-gen
REGMAP_DEF   := regmap/sgm_regmap.def
REGMAP_CHECK := $(BUILD)/regmap
REGMAP_OUT   := sw/include/sgm_regs.h rtl/sgm_regmap.svh rtl/sgm_cfg.svh tb/sgm_cfg_fields.hpp docs/registers.md

.PHONY: regmap regmap-check

$(REGMAP_GEN): regmap/regmap_gen.cpp $(REGMAP_DEF) regmap/regmap.mk
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O1 -Wall -Wextra -Werror -Iregmap -o $@ regmap/regmap_gen.cpp

regmap: $(REGMAP_GEN)
	$(REGMAP_GEN) --header sw/include/sgm_regs.h --svh rtl/sgm_regmap.svh --cfg-svh rtl/sgm_cfg.svh \
	  --tb tb/sgm_cfg_fields.hpp --doc docs/registers.md docs/registers.md

regmap-check: $(REGMAP_GEN)
	@mkdir -p $(REGMAP_CHECK)
	@$(REGMAP_GEN) --header $(REGMAP_CHECK)/sgm_regs.h --svh $(REGMAP_CHECK)/sgm_regmap.svh \
	  --cfg-svh $(REGMAP_CHECK)/sgm_cfg.svh --tb $(REGMAP_CHECK)/sgm_cfg_fields.hpp \
	  --doc docs/registers.md $(REGMAP_CHECK)/registers.md
	@bad=0; for f in $(REGMAP_OUT); do \
	  if ! cmp -s $$f $(REGMAP_CHECK)/$$(basename $$f); then \
	    echo "regmap-check: $$f differs from $(REGMAP_DEF) (first difference below; run 'make regmap' after changing the description, never the copy)"; \
	    diff $(REGMAP_CHECK)/$$(basename $$f) $$f | head -4; bad=1; fi; \
	done; [ $$bad = 0 ] && echo "regmap-check: $(notdir $(REGMAP_OUT)) match $(REGMAP_DEF)"
