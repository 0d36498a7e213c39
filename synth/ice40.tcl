# SPDX-License-Identifier: Apache-2.0
# iCE40 synthesis of sgm_top, one pipeline stage at a time (see common.tcl):
# synth_ice40 (flattened inside each stage). Shows what the whole core needs in
# LUT4s and SB_RAM40_4K against the largest iCE40 (HX8K: 7,680 LCs, 32 RAMs);
# the routed fmax comes from synth/ice40_loop.tcl. Per stage <name> it writes
# into $SYNTH_OUT the same files as synth/xilinx.tcl.
source [file join [file dirname [info script]] common.tcl]

foreach_stage {
  set opts [list -top $mod]
  yosys synth_ice40 {*}$opts -run begin:map_ram
  yosys tee -q -o $out/$name.memories.txt dump {t:$mem_v2}
  yosys synth_ice40 {*}$opts -run map_ram:
  yosys tee -q -o $out/$name.stat.txt stat
  write_cells $out/$name.ramcells.txt $ram_types(ice40)
  yosys tee -q -o $out/$name.ltp.txt ltp {*}[ltp_sel ice40]
}
