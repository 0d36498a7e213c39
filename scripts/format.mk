# SPDX-License-Identifier: Apache-2.0
# `make format`: clang-format (the style of .clang-format) applied in place to every
# C++ file of scripts/cxx-files.sh (git-tracked, not generated). `make format-check`:
# scripts/format-check.sh, one line per file that is not formatted, non-zero exit if
# any (run by `make lint`).
CLANG_FORMAT ?= clang-format

.PHONY: format format-check

format:
	@scripts/cxx-files.sh | xargs -0 -r $(CLANG_FORMAT) --style=file -i
	@echo "format: $$(scripts/cxx-files.sh | tr -cd '\0' | wc -c) C++ files formatted with $(CLANG_FORMAT)"

format-check:
	@scripts/format-check.sh $(CLANG_FORMAT)
