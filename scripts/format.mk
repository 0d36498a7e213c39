# SPDX-License-Identifier: Apache-2.0
# `make format`: clang-format (the style of .clang-format) applied in place to every
# C++ file git tracks. `make format-check`: scripts/format-check.sh, one line per
# file that is not formatted, non-zero exit if any (not part of `make test` yet).
CLANG_FORMAT ?= clang-format

.PHONY: format format-check

format:
	@git ls-files -z -- '*.cpp' '*.hpp' '*.h' '*.cc' | xargs -0 -r $(CLANG_FORMAT) --style=file -i
	@echo "format: $$(git ls-files -- '*.cpp' '*.hpp' '*.h' '*.cc' | wc -l) C++ files formatted with $(CLANG_FORMAT)"

format-check:
	@scripts/format-check.sh $(CLANG_FORMAT)
