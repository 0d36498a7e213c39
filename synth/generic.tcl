# SPDX-License-Identifier: Apache-2.0
# Technology-independent synthesis of sgm_top, one pipeline stage at a time
# (see common.tcl): Yosys `synth -flatten` up to its `fine` label, then the
# fine steps except memory_map, so that every inferred memory stays one $mem_v2
# cell (mapping the path buffers to flip-flops would be meaningless and slow)
# and the rest becomes Yosys' internal gate cells ($_AND_, $_MUX_, $_DFF_*, ...).
# Per stage <name> it writes into $SYNTH_OUT:
#   <name>.memories.txt  the inferred memories ($mem_v2 cells)
#   <name>.stat.txt      `stat` of the gate-level netlist (memories as $mem_v2)
#   <name>.ltp.txt       longest path of gates between flip-flops / memories
source [file join [file dirname [info script]] common.tcl]

foreach_stage {
  yosys synth -top $mod -flatten -run begin:fine
  yosys tee -q -o $out/$name.memories.txt dump {t:$mem_v2}
  yosys opt -fast -full
  yosys opt -full
  yosys techmap
  yosys opt -fast
  yosys abc -fast
  yosys opt -fast
  yosys tee -q -o $out/$name.stat.txt stat
  yosys tee -q -o $out/$name.ltp.txt ltp {*}[ltp_sel generic]
}
