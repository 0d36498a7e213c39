# SPDX-License-Identifier: Apache-2.0
# The area of the two build-time levers (sgm_top UNIQUENESS, AD_TERM): one module alone,
# synth_ecp5 -abc9 (Yosys 0.23), its `stat` into SYNTH_OUT/stat.txt. Run as
# `yosys -c synth/levers.tcl` by `make synth-levers` (synth/synth.mk), once per module and
# lever value:
#   SYNTH_LEVER_TOP  sgm_wta (lever UNIQUENESS), sgm_cost_volume (lever AD_TERM) or
#                    sgm_right_path (lever RIGHT_BLOCK, `make synth-right-path`)
#   SYNTH_LEVER      0 or 1 (the lever's value); the block B for sgm_right_path
#   SYNTH_LANES      row lanes K of sgm_right_path (default 1)
#   SYNTH_D          disparities D (default 64); the cost volume is built with one lane
#   SYNTH_OUT        output directory
yosys -import

proc env_or {name default} {
  if {[info exists ::env($name)] && $::env($name) ne ""} { return $::env($name) }
  return $default
}

set top   [env_or SYNTH_LEVER_TOP sgm_wta]
set lever [env_or SYNTH_LEVER 1]
set d     [env_or SYNTH_D 64]
set out   [env_or SYNTH_OUT build/synth/levers]

yosys read_verilog -sv {*}[lsort [glob rtl/*.sv]]
if {$top eq "sgm_wta"} {
  yosys chparam -set D $d -set UNIQUENESS $lever sgm_wta
} elseif {$top eq "sgm_cost_volume"} {
  yosys chparam -set D $d -set LANES 1 -set AD_TERM $lever sgm_cost_volume
} elseif {$top eq "sgm_right_path"} {
  # The fifth path (lever RIGHT_BLOCK = B): its module alone, K = SYNTH_LANES row lanes, the
  # side bundle of sgm_top at MAX_WIDTH 1280 (2 XW + 2 RW + 42 = 80 bits), L5_LAG as in sgm_top.
  set lanes [env_or SYNTH_LANES 1]
  yosys chparam -set D $d -set BLOCK $lever -set XW 11 -set LANES $lanes -set SIDE_W 80 \
    -set L5_LAG [expr {$lanes + 1}] sgm_right_path
} else {
  error "SYNTH_LEVER_TOP=$top: expected sgm_wta, sgm_cost_volume or sgm_right_path"
}
yosys synth_ecp5 -abc9 -top $top
yosys tee -o $out/stat.txt stat
