#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sums the GoogleTest XML reports in DIR into one line: "N passed, N failed, N skipped".
set -euo pipefail
dir=${1:?usage: test-summary.sh DIR}
tests=0 failures=0 errors=0 skipped=0
for f in "$dir"/*.xml; do
  line=$(grep -m1 '<testsuites ' "$f")
  get() { sed -n "s/.* $1=\"\([0-9]*\)\".*/\1/p" <<<"$line"; }
  tests=$((tests + $(get tests))); failures=$((failures + $(get failures)))
  errors=$((errors + $(get errors))); skipped=$((skipped + $(get disabled) + $(grep -c 'result="skipped"' "$f" || true)))
done
failed=$((failures + errors))
echo "$((tests - failed - skipped)) passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
