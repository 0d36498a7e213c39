# SPDX-License-Identifier: Apache-2.0
# Xilinx synthesis of the whole of sgm_top in one run, flattened (optimisation
# across stage boundaries; exact totals and the longest path across stages).
# Slow for large D: Yosys' opt loop then iterates over the whole design
# (see common.tcl). Writes sgm_top.{memories,stat,ramcells,ltp}.txt into
# $SYNTH_OUT, the files synth/xilinx.tcl writes per stage.
source [file join [file dirname [info script]] common.tcl]

set family [env_or SYNTH_FAMILY xc7]
set opts [list -family $family -top sgm_top -flatten -noiopad -noclkbuf]
set name sgm_top
set t0 [clock milliseconds]
yosys synth_xilinx {*}$opts -run begin:map_memory
yosys tee -q -o $out/$name.memories.txt dump {t:$mem_v2}
yosys synth_xilinx {*}$opts -run map_memory:
yosys tee -q -o $out/$name.stat.txt stat
write_cells $out/$name.ramcells.txt $ram_types(xilinx)
yosys tee -q -o $out/$name.ltp.txt ltp {*}[ltp_sel xilinx]
set f [open $out/$name.seconds w]
puts $f [format %.1f [expr {([clock milliseconds] - $t0) / 1000.0}]]
close $f
