#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `make param-checks` (tests/params.mk): every parameter check of rtl/ (and tb/tops/) fires,
# and the legal configurations elaborate.
#
#   tests/params/cases.txt  one case a line: TOOLS | TOP | NAME=VALUE ... | EXPECT
#     TOOLS   v: verilator --lint-only -Wall only; vy: Yosys 0.23 elaboration too
#             (read_verilog -sv, chparam, hierarchy -check)
#     EXPECT  ok: the set must elaborate; else a substring of the check's message, which
#             must name one of the parameters set: elaboration must fail and print it on a
#             Verilator USERERROR line / a Yosys ERROR line. (Yosys 0.23 prints an
#             $error's format string without the arguments: "D = %0d", so the substrings
#             stop before the value.)
#             fail: elaboration must fail, with any message (a value that breaks the
#             module's own localparams before its checks run, e.g. LANES = 0 divides by 0).
#   The Makefile's rtl_test fixtures are legal sets too: each is linted with its -G
#   parameters and -D defines; those of sgm_top / sgm_axi (whole-core lints of several
#   seconds each) only with PARAM_CHECKS_ALL=1 (cases.txt has legal whole-core sets).
#
# Usage: tests/params/param_checks.sh [CASES]   (JOBS=2 cases at once; VERILATOR, YOSYS)
# Exit 1 with one line per failing case ("param-checks: FAIL ..."), 0 when every case passes.
set -u
cd "$(dirname "$0")/../.."
CASES=${1:-tests/params/cases.txt}
JOBS=${JOBS:-2}
VERILATOR=${VERILATOR:-verilator}
YOSYS=${YOSYS:-yosys}
export VERILATOR YOSYS

# One case: TOOL (v / y), TOP, DEFINES, PARAMS, EXPECT; prints PASS or FAIL and a description.
run_one() {
  local tool=$1 top=$2 defs=$3 params=$4 expect=$5 file out rc p
  file=rtl/$top.sv; [ -f "$file" ] || file=tb/tops/$top.sv
  local desc="$tool $top [$params${defs:+ $defs}] expect '$expect'"
  if [ "$tool" = v ]; then
    local g=() d=()
    for p in $params; do g+=("-G$p"); done
    for p in $defs; do d+=("-D$p"); done
    out=$($VERILATOR --lint-only -Wall rtl/lint.vlt -Irtl -Itb/tops "${d[@]}" --top-module "$top" "$file" "${g[@]}" 2>&1); rc=$?
  else
    local set="" rd=""
    for p in $params; do set+=" -set ${p%%=*} ${p#*=}"; done
    for p in $defs; do rd+=" -D$p"; done
    out=$($YOSYS -q -p "read_verilog -sv -Irtl$rd rtl/*.sv tb/tops/*.sv; ${set:+chparam$set $top;} hierarchy -check -top $top" 2>&1); rc=$?
  fi
  if [ "$expect" = fail ]; then
    if [ $rc -ne 0 ]; then echo "PASS $desc"; else echo "FAIL $desc: an illegal set elaborates"; fi
  elif [ "$expect" = ok ]; then
    if [ $rc -eq 0 ]; then echo "PASS $desc"
    else echo "FAIL $desc: a legal set does not elaborate: $(grep -m1 -E '%Error|%Warning|ERROR' <<<"$out")"; fi
  else
    local tag='USERERROR'; [ "$tool" = y ] && tag='ERROR:'
    if [ $rc -eq 0 ]; then echo "FAIL $desc: an illegal set elaborates"
    elif ! grep -F "$tag" <<<"$out" | grep -qF -- "$expect"; then
      echo "FAIL $desc: elaboration fails without the message: $(grep -m1 -E '%Error|%Warning|ERROR' <<<"$out")"
    else echo "PASS $desc"; fi
  fi
}
export -f run_one

jobs_file=$(mktemp); trap 'rm -f "$jobs_file"' EXIT
bad=0
# The cases file.
n=0
while IFS= read -r line; do
  n=$((n + 1))
  line=${line%%#*}; [ -n "${line//[[:space:]]/}" ] || continue
  IFS='|' read -r tools top params expect <<<"$line"
  tools=$(echo $tools); top=$(echo $top); params=$(echo $params); expect=$(echo $expect)
  if [ -z "$top" ] || [ -z "$expect" ]; then
    echo "param-checks: FAIL $CASES:$n: malformed line"; bad=1; continue
  fi
  if [ "$expect" != ok ] && [ "$expect" != fail ]; then
    named=0
    for p in $params; do case "$expect" in *"${p%%=*}"*) named=1 ;; esac; done
    if [ $named -eq 0 ]; then
      echo "param-checks: FAIL $CASES:$n: '$expect' names none of the parameters set ($params)"; bad=1; continue
    fi
  fi
  case "$tools" in v | vy | y) ;; *) echo "param-checks: FAIL $CASES:$n: tools '$tools' (v, y or vy)"; bad=1; continue ;; esac
  for t in $(grep -o . <<<"$tools"); do printf '%s|%s||%s|%s\n' "$t" "$top" "$params" "$expect" >> "$jobs_file"; done
done < "$CASES"

# The Makefile's rtl_test fixtures: $(eval $(call rtl_test,NAME,TOP,OPTIONS[,TEST])).
fixtures=0
while IFS= read -r line; do
  args=$(sed 's/)*$//' <<<"${line#*rtl_test,}")
  top=$(cut -d, -f2 <<<"$args"); opts=$(cut -d, -f3 <<<"$args")
  params="" defs="" skip=0 prev=""
  for o in $opts; do
    if [ "$prev" = --top-module ]; then top=$o
    elif [ "$prev" != -CFLAGS ]; then
      case "$o" in -G*) params+=" ${o#-G}" ;; -D*) defs+=" ${o#-D}" ;; esac
    fi
    prev=$o
  done
  case "$top" in sgm_top | sgm_axi) [ "${PARAM_CHECKS_ALL:-0}" = 1 ] || continue ;; esac
  printf 'v|%s|%s|%s|ok\n' "$top" "${defs# }" "${params# }" >> "$jobs_file"
  fixtures=$((fixtures + 1))
done < <(grep -E '^\$\(eval \$\(call rtl_test,' Makefile)

total=$(wc -l < "$jobs_file")
start=$(date +%s)
results=$(tr '\n' '\0' < "$jobs_file" | xargs -0 -P "$JOBS" -I{} bash -c 'IFS="|" read -r a b c d e <<<"$1"; run_one "$a" "$b" "$c" "$d" "$e"' _ {})
fails=$(grep -c '^FAIL' <<<"$results")
grep '^FAIL' <<<"$results" | sed 's/^/param-checks: /'
echo "param-checks: $((total - fails)) of $total cases pass ($fixtures Makefile fixtures among them), $(( $(date +%s) - start )) s"
[ "$fails" -eq 0 ] && [ $bad -eq 0 ]
