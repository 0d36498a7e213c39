# SPDX-License-Identifier: Apache-2.0
# iCE40 synthesis of the loop harness synth/sgm_path_loop.sv (the 0 degree path
# recursion of sgm_path_engine) for nextpnr-ice40.
#
# Environment (set by synth/synth.mk): SYNTH_RTL (rtl), SYNTH_LOOP_D (D),
# SYNTH_OUT. Writes into SYNTH_OUT: netlist.json (for nextpnr), stat.txt,
# ltp.txt.
yosys -import

proc env_or {name default} {
  if {[info exists ::env($name)] && $::env($name) ne ""} { return $::env($name) }
  return $default
}
set rtl [env_or SYNTH_RTL rtl]
set d   [env_or SYNTH_LOOP_D 16]
set out [env_or SYNTH_OUT build/synth/ice40-loop-d$d]
set here [file dirname [info script]]

yosys read_verilog -sv $rtl/sgm_path_pe.sv $rtl/sgm_min_tree.sv $rtl/sgm_delay_ram.sv $rtl/sgm_path_ring.sv $here/sgm_path_loop.sv
yosys chparam -set D $d sgm_path_loop
yosys hierarchy -check -top sgm_path_loop
yosys synth_ice40 -top sgm_path_loop -json $out/netlist.json
yosys tee -q -o $out/stat.txt stat
yosys tee -q -o $out/ltp.txt ltp t:SB_DFF* t:SB_RAM* %u %n
