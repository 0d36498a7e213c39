#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the TEST_EXTRA targets of `make test` in two streams so that both cores of a CI machine
# work: the BESIDE targets (single-threaded EDA runs: yosys, nextpnr) one after another in the
# background, the other targets one after another in the foreground. Each target's output goes
# to LOGDIR/TARGET.log and is printed whole when the target ends, followed by
# "time: TARGET N s"; the two streams never interleave their lines. Both streams always run to
# their end (no orphaned job); the exit status is non-zero when any target failed, and the
# failed targets are named on the last line.
#
# usage: test-extra.sh MAKE LOGDIR "BESIDE TARGETS" "OTHER TARGETS"
set -uo pipefail
make=${1:?usage: test-extra.sh MAKE LOGDIR BESIDE OTHERS}
logdir=${2:?usage: test-extra.sh MAKE LOGDIR BESIDE OTHERS}
beside=${3-}
others=${4-}
mkdir -p "$logdir"
rm -f "$logdir"/*.log "$logdir"/failed
lock="$logdir/.print"

# run_stream TARGET...: stops at the first failure of its stream (later targets may need it).
run_stream() {
  local t s rc
  for t in "$@"; do
    s=$(date +%s)
    $make --no-print-directory "$t" > "$logdir/$t.log" 2>&1
    rc=$?
    echo "time: $t $(( $(date +%s) - s )) s" >> "$logdir/$t.log"
    flock "$lock" cat "$logdir/$t.log"
    if [ "$rc" -ne 0 ]; then
      flock "$lock" sh -c "echo $t >> '$logdir/failed'"
      return 1
    fi
  done
}

# shellcheck disable=SC2086  # the target lists are word lists
run_stream $beside &
bg=$!
# shellcheck disable=SC2086
run_stream $others
wait "$bg"

if [ -s "$logdir/failed" ]; then
  echo "make test: FAILED: $(tr '\n' ' ' < "$logdir/failed")(logs: $logdir/)"
  exit 1
fi
