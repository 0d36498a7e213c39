# SPDX-License-Identifier: Apache-2.0
# ECP5 synthesis of the loop harness (synth/sgm_path_loop.sv) for `make pnr-loop`
# (synth/pnr.mk): SYNTH_LOOP_D, SYNTH_LOOP_LANES, SYNTH_ECP5_FLAGS, SYNTH_OUT.
yosys -import

proc env_or {name default} {
  if {[info exists ::env($name)] && $::env($name) ne ""} { return $::env($name) }
  return $default
}
set rtl   [env_or SYNTH_RTL rtl]
set d     [env_or SYNTH_LOOP_D 64]
set lanes [env_or SYNTH_LOOP_LANES 1]
set flags [env_or SYNTH_ECP5_FLAGS ""]
set out   [env_or SYNTH_OUT build/pnr/loop-d$d-k$lanes/synth]
set here  [file dirname [info script]]

yosys read_verilog -sv $rtl/sgm_path_pe.sv $rtl/sgm_min_tree.sv $rtl/sgm_delay_ram.sv $rtl/sgm_path_ring.sv $here/sgm_path_loop.sv
yosys chparam -set D $d -set LANES $lanes sgm_path_loop
yosys hierarchy -check -top sgm_path_loop
yosys synth_ecp5 {*}$flags -top sgm_path_loop -json $out/netlist.json
yosys tee -q -o $out/stat.txt stat
