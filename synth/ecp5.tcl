# SPDX-License-Identifier: Apache-2.0
# ECP5 synthesis of the whole sgm_top for place and route (`make pnr`,
# synth/pnr.mk). Each pipeline stage is synthesized as its own top with
# synth_ecp5 (flattened inside; see common.tcl for why one stage at a time),
# saved, and the mapped stages are then put back under the elaborated
# sgm_top in place of their RTL modules, so that one hierarchical netlist of
# the whole core goes to nextpnr-ecp5 (which flattens it). sgm_top holds only
# the stage instances, so no logic is left unmapped. Writes into $SYNTH_OUT:
#   <name>.stat.txt   `stat` of each mapped stage, <name>.seconds its run time
#   netlist.json      the whole core (write_json), input of nextpnr-ecp5
#   top.stat.txt      `stat -top sgm_top` of that netlist (cell totals)
source [file join [file dirname [info script]] common.tcl]

# SYNTH_ECP5_FLAGS: extra synth_ecp5 options (synth/pnr.mk, PNR_SYNTH_FLAGS).
set synth_flags [env_or SYNTH_ECP5_FLAGS ""]
# SYNTH_ECP5_CMP_LUT: comparisons of at most this many bits as LUT logic
# (synth/ecp5_cmp_lut.v); empty or 0: every comparison to synth_ecp5's carry chains.
set cmp_lut [env_or SYNTH_ECP5_CMP_LUT 0]
# SYNTH_ECP5_CMP_CHAIN: source files (space-separated names, e.g. sgm_path_ring.sv)
# whose comparisons stay carry chains whatever SYNTH_ECP5_CMP_LUT says (ecp5_cmp.tcl).
set cmp_chain [env_or SYNTH_ECP5_CMP_CHAIN ""]
source [file join [file dirname [info script]] ecp5_cmp.tcl]

set stages {}
foreach_stage {
  if {$cmp_lut > 0} {
    # synth_ecp5 up to its coarse step, the comparisons mapped after the
    # first width reduction (as synth_ecp5's own cmp2lut step sits), then the rest.
    yosys synth_ecp5 {*}$synth_flags -top $mod -run begin:coarse
    ecp5_cmp_prepare
    ecp5_cmp_map $cmp_lut $cmp_chain
    yosys synth_ecp5 {*}$synth_flags -top $mod -run coarse:
  } else {
    yosys synth_ecp5 {*}$synth_flags -top $mod
  }
  yosys tee -q -o $out/$name.stat.txt stat
  yosys design -save stage_$name
  lappend stages [list $mod $name]
}

# Back to the elaborated design: replace each stage module by its mapped copy.
yosys design -load elab
yosys hierarchy -top sgm_top
foreach s $stages {
  lassign $s mod name
  yosys delete $mod
  yosys design -copy-from stage_$name $mod
}
# The ECP5 primitives as black boxes, as synth_ecp5 reads them.
yosys read_verilog -lib -specify +/ecp5/cells_sim.v +/ecp5/cells_bb.v
yosys hierarchy -check -top sgm_top
yosys tee -q -o $out/top.stat.txt stat -top sgm_top
# As synth_ecp5 ends: the primitives stay as black boxes (their port directions).
yosys blackbox =A:whitebox
# Ports that carry nothing get no pins (IOs a package may not have): min_width_o, a constant
# of the build, and without the rectification (sgm_top RECTIFY = 0) its mesh port.
yosys delete -port sgm_top/w:min_width_o
if {$rectify eq "" || $rectify == 0} {
  yosys delete -port sgm_top/w:mesh_* sgm_top/w:rect_row_miss_o
}
yosys write_json $out/netlist.json
