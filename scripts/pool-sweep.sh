#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Measures golden-model option sets on the scene pool and on the four Table I scenes,
# one line per option set (docs/notes/accuracy-pool.md):
#   options | Middlebury A | B | all | KITTI A | B | all | worst change vs today | cones teddy venus sawtooth
# Usage: scripts/pool-sweep.sh POOL DATA 'OPTIONS' ['OPTIONS' ...]   ('' = the defaults; "today" = the four-path preset, the defaults before issue 15)
# Needs build/bin/sgm-eval (make golden). Golden model only (--opencv off).
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 POOL DATA 'OPTIONS' ['OPTIONS' ...]" >&2; exit 2; }
pool=$1 data=$2
shift 2
eval_bin=build/bin/sgm-eval
[ -x "$eval_bin" ] || { echo "$0: $eval_bin missing (make golden)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mean() { awk -v name="$1" '$0 ~ "^"name" +[0-9]+ scenes" { for (i = 1; i <= NF; ++i) if ($i == "ours") { sub("%", "", $(i+1)); print $(i+1) } }' "$2"; }
printf '| options | Midd. A | Midd. B | Midd. all | KITTI A | KITTI B | KITTI all | worst vs today | Cones | Teddy | Venus | Sawtooth |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|\n'
for options in "$@"; do
  # shellcheck disable=SC2086
  "$eval_bin" pool --pool "$pool" --out "$tmp/pool" --opencv off $options > "$tmp/pool.txt"
  # shellcheck disable=SC2086
  "$eval_bin" pool --pool "$data" --out "$tmp/t1" --opencv off --d 64 $options > /dev/null
  worst=$(awk '/^worst change vs today:/ { printf "%s %+.2f", $5, $6 }' "$tmp/pool.txt")
  scene() { awk -F'|' -v s="$1" '{ gsub(/ /, "", $2) } $2 == s { gsub(/ /, "", $6); print $6 }' "$tmp/t1/pool.md"; }
  printf '| `%s` | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "${options:-(defaults)}" \
    "$(mean 'middlebury A' "$tmp/pool.txt")" "$(mean 'middlebury B' "$tmp/pool.txt")" "$(mean middlebury "$tmp/pool.txt")" \
    "$(mean 'kitti A' "$tmp/pool.txt")" "$(mean 'kitti B' "$tmp/pool.txt")" "$(mean kitti "$tmp/pool.txt")" \
    "${worst:--}" "$(scene cones)" "$(scene teddy)" "$(scene venus)" "$(scene sawtooth)"
done
