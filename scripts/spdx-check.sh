#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that every source file of the repository (RTL, C/C++, Tcl, make, shell, Yosys
# scripts, FuseSoC, Verilator configuration) names its licence in an SPDX line within its
# first three lines: "SPDX-License-Identifier: Apache-2.0" (LICENSE at the top).
# Prose (*.md), data (*.txt) and LICENSE itself are not source. Run by `make lint`.
# Usage: scripts/spdx-check.sh [FILE...]   (default: every file git tracks)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then files=("$@"); else mapfile -t files < <(git ls-files --cached --others --exclude-standard); fi
missing=0 checked=0
for f in "${files[@]}"; do
  case "$f" in
    LICENSE | *.md | *.txt | .gitignore | *.png | *.json) continue ;;
  esac
  [ -f "$f" ] || continue
  checked=$((checked + 1))
  if ! head -3 "$f" | grep -q 'SPDX-License-Identifier: Apache-2.0'; then
    echo "spdx-check: $f: no 'SPDX-License-Identifier: Apache-2.0' in its first three lines"
    missing=$((missing + 1))
  fi
done
if [ "$missing" -ne 0 ]; then echo "spdx-check: $missing of $checked source files lack the SPDX line"; exit 1; fi
echo "spdx-check: $checked source files carry the Apache-2.0 SPDX line"
