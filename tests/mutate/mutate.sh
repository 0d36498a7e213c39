#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Mutation runner of rtl/ (`make mutate`, `make mutate-ci`; tests/mutate/mutate.mk).
#
#   tests/mutate/mutate.sh [--only id,id] [--check] [--require-kill] [--out DIR] [--tree DIR] LIST
#
# LIST holds one mutation per line (blank lines and # comments skipped):
#   id @@ rtl/file.sv @@ exact text @@ replacement @@ bug class [@@ equivalent: reason]
# (a file may be an included rtl/*.svh: its tests are those of the modules that include it)
# The exact text must occur exactly once in the file (else the run stops: the RTL
# changed and the list must follow it in the same commit). Each mutation is applied
# to a scratch copy of the tree (--tree, default build/mutate/tree; rtl/ is never
# touched), and the tests that contain the mutated module run there, cheapest first: the
# formal tasks whose .sby reads the module's file (tests/formal/*.sby, `make formal
# FORMAL_ONLY=task`, seconds each; a task that fails or leaves a cover unreached kills, one
# whose model does not elaborate makes the mutant invalid), then the verilated test binaries
# whose top instantiates the module, rebuilt (unit fixtures, then the whole core at
# D = 16 (and its lean build), the D = 16 regression slice, the whole core at D = 32 and
# D = 64, the AXI4-Lite wrapper and its lean build), up to the
# first one that fails: that test kills the mutation. A mutation no test fails
# survived. Lines marked equivalent are reported with their reason and not run. A mutant
# that does not build (a lint warning of Verilator -Wall, a syntax error) is "invalid",
# not killed: no test saw it; the list must plant a bug that compiles.
# Before its first use, every test runs once on the unmutated tree (the
# build/bin/ binaries of this checkout): a test that fails there would kill anything.
# --check only validates the list (every text found exactly once).
# MUTATE_TESTS=name,name (environment) restricts the tests tried to those listed (e.g. the
# builds that have a mutated option: MUTATE_TESTS=rtl-top-d16-rb8,formal-stream_ctrl_prove),
# for a quick run of a few mutations; `make mutate` tries every test.
#
# Writes DIR/report.md and DIR/report.json (default DIR build/mutate): mutations,
# killed, survived, equivalent, invalid, kill_ratio and one row per mutation (id, file,
# line, class, status, killed_by, seconds, note). Exit 0, or 1 when --require-kill and a
# mutation survived or was invalid, 2 on a bad list or a failing baseline.
set -uo pipefail
shopt -u patsub_replacement 2>/dev/null || true  # bash 5.2: keep "&" literal in replacements

die() { echo "mutate: $*" >&2; exit 2; }

only="" check_only=0 require_kill=0 out=build/mutate tree="" list=""
while (($#)); do
  case "$1" in
    --only) only="$2"; shift 2 ;;
    --require-kill) require_kill=1; shift ;;
    --check) check_only=1; shift ;;
    --out) out="$2"; shift 2 ;;
    --tree) tree="$2"; shift 2 ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d'; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) list="$1"; shift ;;
  esac
done
[[ -n "$list" && -f "$list" ]] || die "no mutation list (usage: mutate.sh [--only id,id] LIST)"
[[ -f rtl/sgm_top.sv && -f Makefile ]] || die "run from the repository root"
tree="${tree:-$out/tree}"
MAKE_CMD=(make --no-print-directory JOBS="${JOBS:-1}")
# Mutant models are compiled at MUTATE_OPT (default -O1; passed down to the verilated
# makefiles): most of a mutation's time is that compile, the D = 16 tests run in seconds.
MUTANT_OPT="${MUTATE_OPT:--O1}"
MUTANT_MAKE=("${MAKE_CMD[@]}" OPT_FAST="$MUTANT_OPT" OPT_SLOW="$MUTANT_OPT" OPT_GLOBAL="$MUTANT_OPT")
DATA="${DATA:-$(cd .. && pwd)/shared/data/middlebury}"
TEST_TIMEOUT="${MUTATE_TIMEOUT:-1200}"

# ------------------------------------------------------------------ the list
ids=() files=() olds=() news=() classes=() equivs=() lines=()
declare -A seen=()
while IFS= read -r raw || [[ -n "$raw" ]]; do
  [[ -z "${raw// /}" || "$raw" =~ ^[[:space:]]*# ]] && continue
  rest="$raw" fields=()
  while [[ "$rest" == *" @@ "* ]]; do fields+=("${rest%% @@ *}"); rest="${rest#* @@ }"; done
  fields+=("$rest")
  ((${#fields[@]} == 5 || ${#fields[@]} == 6)) || die "$list: bad line (want 5 or 6 fields separated by ' @@ '): $raw"
  id="${fields[0]// /}" file="${fields[1]// /}"
  [[ -z "${seen[$id]:-}" ]] || die "$list: id $id twice"
  seen[$id]=1
  [[ -f "$file" ]] || die "$id: no file $file"
  equiv=""
  if ((${#fields[@]} == 6)); then
    [[ "${fields[5]}" == equivalent:* ]] || die "$id: 6th field must be 'equivalent: reason'"
    equiv="${fields[5]#equivalent: }"
  fi
  old="${fields[2]}"
  count=$(grep -cF -- "$old" "$file")
  ((count == 1)) || die "$id: the text '$old' occurs $count times in $file (needs exactly once; did the RTL change? update $list)"
  [[ "$old" != "${fields[3]}" ]] || die "$id: replacement equals the text"
  ids+=("$id") files+=("$file") olds+=("$old") news+=("${fields[3]}") classes+=("${fields[4]}") equivs+=("$equiv")
  lines+=("$(grep -nF -- "$old" "$file" | cut -d: -f1)")
done < "$list"
((${#ids[@]})) || die "$list: no mutations"
selected=()
if [[ -n "$only" ]]; then
  IFS=, read -ra want <<< "$only"
  for w in "${want[@]}"; do
    found=""
    for i in "${!ids[@]}"; do [[ "${ids[$i]}" == "$w" ]] && found=$i; done
    [[ -n "$found" ]] || die "--only: no mutation $w in $list"
    selected+=("$found")
  done
else
  selected=("${!ids[@]}")
fi

# ------------------------------------------------------------------ tests per module
# Test binaries: every rtl_test fixture of the Makefile (NAME -> make target build/bin/rtl-NAME,
# with the top it verilates) and the regression of regress.mk, tried cheapest first: module
# fixtures before whole-core (sgm_top, sgm_axi) builds, then by D, then by lanes (the
# -d<D> and -k<K> of the name; D = 16 and one lane where the name says none).
declare -A top_of=()
while IFS= read -r l; do
  args="${l#*call rtl_test,}"
  name="${args%%,*}" rest="${args#*,}"
  top="${rest%%,*}"
  [[ "$rest" =~ --top-module[[:space:]]+([a-z_0-9]+) ]] && top="${BASH_REMATCH[1]}"
  top_of["rtl-$name"]="$top"
done < <(grep -E '^\$\(eval \$\(call rtl_test,' Makefile)
regress_test=sgm-regress-d16-w128  # the regression at its defaults (tests/regress.mk, REGRESS_BIN)
top_of[$regress_test]=sgm_top
((${#top_of[@]} > 1)) || die "no rtl_test fixtures found in the Makefile"
# The reference builds' fixtures (rtl-ref-NAME) are named without D and lanes: their tags
# (scripts/refs.mk) give them.
declare -A ref_tag=()
while read -r r tag; do ref_tag["rtl-ref-$r"]="$tag"; done < <(make --no-print-directory -s refs-tags)
test_cost() {  # whole-core D K name
  local t="$1" d=16 k=1 whole=0 n="$1"
  [[ -n "${ref_tag[$t]:-}" ]] && n="-${ref_tag[$t]}"
  [[ "$n" =~ -d([0-9]+) ]] && d=${BASH_REMATCH[1]}
  [[ "$n" =~ -k([0-9]+) ]] && k=${BASH_REMATCH[1]}
  [[ "${top_of[$t]}" == sgm_top || "${top_of[$t]}" == sgm_axi ]] && whole=1
  echo "$whole $d $k $t"
}
order=($(for t in "${!top_of[@]}"; do test_cost "$t"; done | sort -k1,1n -k2,2n -k3,3n -k4,4 | awk '{ print $4 }'))

# Formal tasks (tests/formal/TASK.sby) as tests formal-TASK, tried first: the modules of
# one are the rtl/*.sv files its [files] section reads, its top the `prep -top` module.
declare -A formal_mods=()
formal_tests=()
for f in tests/formal/*.sby; do
  [[ -f "$f" ]] || continue
  t="formal-$(basename "$f" .sby)"
  top_of[$t]=$(awk '$1 == "prep" { for (i = 2; i < NF; i++) if ($i == "-top") print $(i + 1) }' "$f" | head -1)
  formal_mods[$t]=$(sed -n '/^\[files\]/,/^\[/p' "$f" | grep -oE 'rtl/sgm_[a-z0-9_]+\.sv' | sed 's|rtl/||; s|\.sv$||' | tr '\n' ' ')
  [[ -n "${top_of[$t]}" && -n "${formal_mods[$t]// /}" ]] || die "$f: no 'prep -top' line or no rtl/*.sv in [files]"
  formal_tests+=("$t")
done
is_formal() { [[ "$1" == formal-* ]]; }
# Proofs before covers (a proof names the broken property, a cover only its lost trace),
# each the tasks of fewer modules first (the module's own property set).
order=($(for t in "${formal_tests[@]}"; do
           set -- ${formal_mods[$t]}; echo "$([[ $t == *_cover ]] && echo 1 || echo 0) $# $t"
         done | sort -k1,1n -k2,2n -k3,3 | awk '{ print $3 }') "${order[@]}")

# Modules a top instantiates, itself included (instantiation lines: `  sgm_x #(` or `  sgm_x u_name (`).
closure() {
  local m="$1" f sub
  echo "$m"
  f=$(ls rtl/"$m".sv tb/tops/"$m".sv 2>/dev/null | head -1)
  [[ -n "$f" ]] || return 0
  for sub in $(grep -oE '^[[:space:]]*sgm_[a-z0-9_]+[[:space:]]+(#|u_)' "$f" | awk '{print $1}' | sort -u); do
    closure "$sub"
  done
}
declare -A tests_of=()  # module -> tests containing it, cheapest first
for t in "${order[@]}"; do
  if is_formal "$t"; then mods_t=${formal_mods[$t]}; else mods_t=$(closure "${top_of[$t]}" | sort -u); fi
  for m in $mods_t; do tests_of[$m]+="$t "; done
done
# The tests of a mutated file: those of its module, or for an included .svh those of every
# module that includes it, cheapest first.
tests_of_file() {
  local f="$1" m t mods=() out=""
  if [[ "$f" == *.svh ]]; then
    for m in $(grep -lF "\`include \"$(basename "$f")\"" rtl/*.sv tb/tops/*.sv 2>/dev/null); do mods+=("$(basename "$m" .sv)"); done
  else
    mods=("$(basename "$f" .sv)")
  fi
  for t in "${order[@]}"; do
    [[ -z "${MUTATE_TESTS:-}" || ",$MUTATE_TESTS," == *",$t,"* ]] || continue
    for m in "${mods[@]}"; do [[ " ${tests_of[$m]:-} " == *" $t "* ]] && { out+="$t "; break; }; done
  done
  echo "$out"
}

# build_test DIR NAME LOG: builds build/bin/NAME in DIR (a formal task has nothing to build).
build_test() {
  local dir="$1" name="$2" log="$3"
  is_formal "$name" && return 0
  if [[ "$dir" == . ]]; then (nice -n 5 "${MAKE_CMD[@]}" "build/bin/$name") > "$log" 2>&1
  else (cd "$dir" && nice -n 5 "${MUTANT_MAKE[@]}" "build/bin/$name") > "$log" 2>&1; fi
}

run_test() {  # run_test DIR NAME LOG: runs build/bin/NAME (or the formal task) of DIR; returns its status,
  local dir="$1" name="$2" log="$3" st  # 3 when a formal task's model does not elaborate
  if is_formal "$name"; then
    (cd "$dir" && timeout "$TEST_TIMEOUT" nice -n 5 "${MAKE_CMD[@]}" formal FORMAL_ONLY="${name#formal-}") > "$log" 2>&1 && return 0
    st=$(awk '{ print $1; exit }' "$dir/build/formal/${name#formal-}/status" 2>/dev/null)
    [[ "$st" == ERROR ]] && return 3
    return 1
  elif [[ "$name" == sgm-regress-* ]]; then
    (cd "$dir" && timeout "$TEST_TIMEOUT" nice -n 5 "build/bin/$name" --seed 1 --frames 60 --quiet) > "$log" 2>&1
  else
    (cd "$dir" && SGM_DATA="$DATA" timeout "$TEST_TIMEOUT" nice -n 5 "build/bin/$name" --gtest_brief=1) > "$log" 2>&1
  fi
}

# ------------------------------------------------------------------ baseline
for i in "${selected[@]}"; do
  [[ -n "${equivs[$i]}" ]] && continue
  [[ -n "$(tests_of_file "${files[$i]}")" ]] || die "${ids[$i]}: no test binary instantiates the module of ${files[$i]}"
done
((check_only)) && { echo "mutate: $list: ${#ids[@]} mutations, every text found once"; exit 0; }
mkdir -p "$out/logs"
# Each test, before its first use, builds and passes in this checkout (unmutated).
declare -A baseline_done=()
baseline() {
  local t="$1"
  [[ -n "${baseline_done[$t]:-}" ]] && return 0
  echo "mutate: baseline $t (unmutated)"
  build_test . "$t" "$out/logs/baseline-$t.log" || die "baseline build of $t failed ($out/logs/baseline-$t.log)"
  run_test . "$t" "$out/logs/baseline-run-$t.log" || die "baseline: $t fails on the unmutated tree ($out/logs/baseline-run-$t.log)"
  baseline_done[$t]=1
}

# ------------------------------------------------------------------ scratch tree
# A copy of the sources with the checkout's golden/eval objects (mtimes kept, so make
# reuses them); its verilator directories persist between runs.
mkdir -p "$tree/build"
tar -cf - Makefile rtl tb tests golden tools scripts regmap $(ls -d synth bench sw 2>/dev/null) | tar -xf - -C "$tree"
for d in obj lib; do [[ -d build/$d ]] && { rm -rf "$tree/build/$d"; cp -a "build/$d" "$tree/build/"; }; done
# Seed its verilator directories from this checkout's (CI has them from `make rtl-tests`):
# the Verilator runtime and test objects are then reused, only the mutant model recompiles.
mkdir -p "$tree/build/verilator"
declare -A needed=()
for i in "${selected[@]}"; do
  [[ -z "${equivs[$i]}" ]] && for t in $(tests_of_file "${files[$i]}"); do needed[$t]=1; done
done
for t in "${!needed[@]}"; do
  mdir="build/verilator/${t#rtl-}"
  [[ -d "$mdir" && ! -d "$tree/$mdir" ]] && cp -a "$mdir" "$tree/$mdir"
done

# ------------------------------------------------------------------ report
# Written after every mutation, so that an interrupted run leaves its rows so far.
write_report() {
local i sep
n=0 killed=0 survived=0 equivalent=0 invalid=0
for i in "${selected[@]}"; do
  case "${statuses[$i]}" in
    killed) ((n++, killed++)) ;;
    survived) ((n++, survived++)) ;;
    equivalent) ((equivalent++)) ;;
    invalid) ((invalid++)) ;;
  esac
done
ratio=$( ((n)) && awk -v k=$killed -v n=$n 'BEGIN{printf "%.1f", 100*k/n}' || echo 0)
json_str() { local s="${1//\\/\\\\}"; s="${s//\"/\\\"}"; printf '"%s"' "${s//$'\t'/ }"; }
{
  echo "# make mutate"
  echo
  echo "$((killed + survived + equivalent + invalid)) mutations of rtl/: $killed killed, $survived survived, $equivalent equivalent, $invalid invalid (the last two not counted);"
  echo "kill ratio over non-equivalent mutations: $ratio %."
  echo
  echo "| id | file:line | class | status | killed by | s | note |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  for i in "${selected[@]}"; do
    echo "| ${ids[$i]} | ${files[$i]#rtl/}:${lines[$i]} | ${classes[$i]} | ${statuses[$i]} | ${killers[$i]} | ${secs[$i]} | ${notes[$i]//|/\\|} |"
  done
} > "$out/report.md"
{
  printf '{\n  "mutations": %d,\n  "killed": %d,\n  "survived": %d,\n  "equivalent": %d,\n  "invalid": %d,\n  "kill_ratio_percent": %s,\n  "rows": [\n' \
    $((killed + survived + equivalent + invalid)) $killed $survived $equivalent $invalid "$ratio"
  sep=""
  for i in "${selected[@]}"; do
    printf '%s    {"id": %s, "file": %s, "line": %s, "class": %s, "status": %s, "killed_by": %s, "seconds": %s, "note": %s}' \
      "$sep" "$(json_str "${ids[$i]}")" "$(json_str "${files[$i]}")" "${lines[$i]}" "$(json_str "${classes[$i]}")" \
      "$(json_str "${statuses[$i]}")" "$(json_str "${killers[$i]}")" "${secs[$i]}" "$(json_str "${notes[$i]}")"
    sep=$',\n'
  done
  printf '\n  ]\n}\n'
} > "$out/report.json"
}

# ------------------------------------------------------------------ mutations
statuses=() killers=() secs=() notes=()
for i in "${!ids[@]}"; do statuses+=("pending"); killers+=(""); secs+=(0); notes+=(""); done
for i in "${selected[@]}"; do
  id="${ids[$i]}" file="${files[$i]}"
  if [[ -n "${equivs[$i]}" ]]; then
    statuses[$i]=equivalent notes[$i]="${equivs[$i]}"
    echo "mutate: $id ($file:${lines[$i]}) equivalent: ${equivs[$i]}"
    write_report
    continue
  fi
  start=$SECONDS
  content=$(cat "$file"; echo x)
  content="${content%x}"
  mutated="${content/"${olds[$i]}"/"${news[$i]}"}"
  [[ "$mutated" != "$content" ]] || die "$id: replacement did not apply"
  printf '%s' "$mutated" > "$tree/$file"
  status=survived killer=""
  for t in $(tests_of_file "$file"); do
    baseline "$t"
    log="$out/logs/$id-$t.log"
    if ! build_test "$tree" "$t" "$log"; then
      status=invalid killer="" notes[$i]="the mutant does not build for $t (see $log): not a kill; change the mutation"; break
    fi
    run_test "$tree" "$t" "$log.run"
    case $? in
      0) ;;
      3) status=invalid killer="" notes[$i]="the mutant does not elaborate in $t (see $log.run): not a kill; change the mutation"; break ;;
      *) status=killed killer="$t"; break ;;
    esac
  done
  cp -p "$file" "$tree/$file"
  touch "$tree/$file"  # newer than every mutant binary: the next build starts clean
  statuses[$i]=$status killers[$i]="$killer" secs[$i]=$((SECONDS - start))
  echo "mutate: $id ($file:${lines[$i]}, ${classes[$i]}): $status${killer:+ by $killer} in ${secs[$i]} s"
  write_report
done

write_report
echo "mutate: $killed killed, $survived survived, $equivalent equivalent, $invalid invalid; kill ratio $ratio % ($out/report.md)"
if ((require_kill && (survived || invalid))); then
  echo "mutate: FAILED: a mutation survived or did not build" >&2
  exit 1
fi
exit 0
