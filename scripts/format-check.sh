#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The C++ files of scripts/cxx-files.sh (all but the generated ones), checked against .clang-format: prints one line per
# file clang-format would change and exits 1 when there is any; exits 0 when
# every file is formatted. Usage: scripts/format-check.sh [clang-format binary]
# (default: $CLANG_FORMAT, else clang-format). `make format` applies the style.
set -u
cd "$(git rev-parse --show-toplevel)" || exit 2
tool=${1:-${CLANG_FORMAT:-clang-format}}
command -v "$tool" > /dev/null || { echo "format-check: $tool not found (Debian: clang-format)"; exit 2; }
bad=0
total=0
while IFS= read -r -d '' f; do
  total=$((total + 1))
  if ! "$tool" --style=file --dry-run --Werror "$f" > /dev/null 2>&1; then
    n=$("$tool" --style=file --dry-run "$f" 2>&1 | grep -c 'warning:')
    echo "format-check: $f: $n place(s) differ from .clang-format (make format)"
    bad=$((bad + 1))
  fi
done < <(scripts/cxx-files.sh)
if [ "$bad" -ne 0 ]; then
  echo "format-check: $bad of $total C++ files not formatted"
  exit 1
fi
echo "format-check: $total C++ files formatted"
