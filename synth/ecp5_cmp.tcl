# SPDX-License-Identifier: Apache-2.0
# The ECP5 flow's comparison map (sourced by synth/ecp5.tcl and by
# tests/synth/ecp5_cmp_chain_check.tcl, so both run the same selection).
#
# ecp5_cmp_prepare: the steps in front of the map, where synth_ecp5's own
# cmp2lut would sit: processes, one flat module, widths reduced.
#
# ecp5_cmp_map cmp_lut chain_files: comparisons of at most cmp_lut bits in the
# current design become LUT logic (synth/ecp5_cmp_lut.v), except those from the
# source files named in chain_files (space-separated, e.g. sgm_path_ring.sv)
# and from every module instantiated inside them: they stay carry chains. A
# flattened cell's src attribute names each instance on its way down, so
# `a:src=*<file>*` finds them. cmp_lut = 0: nothing is mapped.
set ecp5_cmp_map_file [file join [file dirname [info script]] ecp5_cmp_lut.v]

proc ecp5_cmp_map {cmp_lut chain_files} {
  if {$cmp_lut <= 0} return
  set sel {*}
  foreach f $chain_files { lappend sel a:src=*$f* %d }
  yosys techmap -D SGM_CMP_LUT_MAX=$cmp_lut -map $::ecp5_cmp_map_file {*}$sel
}

proc ecp5_cmp_prepare {} {
  foreach step {proc flatten opt_expr opt_clean wreduce opt_clean} { yosys $step }
}
