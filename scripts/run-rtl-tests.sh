#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# run-rtl-tests.sh JOBS RESULTS LOGS BINARY...: the RTL fixtures of `make rtl-tests`, JOBS at
# a time (each single-threaded). Each writes its GoogleTest XML to RESULTS/<name>.xml and its
# output to LOGS/<name>.log; a finished fixture's output is printed whole (never interleaved
# with another's), with the line "time: run <name> <s> s". The exit status is non-zero when
# any fixture failed; the failed ones are named at the end.
set -uo pipefail
jobs="$1" results="$2" logs="$3"
shift 3
mkdir -p "$results" "$logs"
export results logs
run_one() {
  local t="$1" n rc s
  n=$(basename "$t")
  s=$(date +%s)
  "$t" --gtest_output="xml:$results/$n.xml" > "$logs/$n.log" 2>&1
  rc=$?
  {
    flock 9
    echo "== $t"
    cat "$logs/$n.log"
    echo "time: run $n $(($(date +%s) - s)) s"
    [ $rc = 0 ] || echo "rtl-tests: $n FAILED (exit $rc, $logs/$n.log)"
  } 9> "$logs/.print.lock"
  [ $rc = 0 ] || echo "$n" >> "$logs/.failed"
  return 0
}
export -f run_one
rm -f "$logs/.failed"
printf '%s\n' "$@" | xargs -P "$jobs" -I{} bash -c 'run_one "$1"' _ {}
if [ -s "$logs/.failed" ]; then
  echo "rtl-tests: failed: $(tr '\n' ' ' < "$logs/.failed")"
  exit 1
fi
echo "rtl-tests: $# fixtures passed"
