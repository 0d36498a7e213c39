# SPDX-License-Identifier: Apache-2.0
# Xilinx synthesis of sgm_top, one pipeline stage at a time (see common.tcl):
# synth_xilinx -family $SYNTH_FAMILY (xc7 or xc6s) -flatten, no I/O buffers and
# no clock buffer (the core is an IP block, not a chip). Per stage <name> it
# writes into $SYNTH_OUT:
#   <name>.memories.txt  the inferred memories ($mem_v2 cells) before mapping
#   <name>.stat.txt      `stat` of the mapped netlist
#   <name>.ramcells.txt  the RAM primitives (block and distributed): "TYPE module/cell"
#   <name>.ltp.txt       longest path of LUT / carry / wide-mux cells between
#                        sequential cells (FFs, RAMs, SRLs, DSPs)
#   <name>.seconds       run time
source [file join [file dirname [info script]] common.tcl]

set family [env_or SYNTH_FAMILY xc7]

foreach_stage {
  set opts [list -family $family -top $mod -flatten -noiopad -noclkbuf]
  yosys synth_xilinx {*}$opts -run begin:map_memory
  yosys tee -q -o $out/$name.memories.txt dump {t:$mem_v2}
  yosys synth_xilinx {*}$opts -run map_memory:
  yosys tee -q -o $out/$name.stat.txt stat
  write_cells $out/$name.ramcells.txt $ram_types(xilinx)
  yosys tee -q -o $out/$name.ltp.txt ltp {*}[ltp_sel xilinx]
}
