#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/datasheet-check.sh PAGE EXPECTED: every line of EXPECTED must occur in PAGE
# (fixed strings); one line per missing one, exit 1 if any (make datasheet-ci).
set -u
page=$1 expected=$2
[ -s "$page" ] || { echo "datasheet-ci: FAIL: $page missing or empty"; exit 1; }
missing=0
while IFS= read -r line; do
  [ -z "$line" ] && continue
  grep -qF -- "$line" "$page" || { echo "datasheet-ci: FAIL: $page lacks: $line"; missing=$((missing + 1)); }
done < "$expected"
[ "$missing" -eq 0 ] || exit 1
echo "datasheet-ci: OK ($page has the $(grep -c . "$expected") expected lines of $expected)"
