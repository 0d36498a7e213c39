# SPDX-License-Identifier: Apache-2.0
# Common part of the synth/*.tcl scripts (run as `yosys -c synth/<target>.tcl`).
#
# Reads the RTL, sets the top's parameters with chparam, elaborates, runs
# `check` and saves the elaborated design as "elab". The pipeline stages (the
# module instances of sgm_top, docs/rtl.md) are then synthesized one at a time
# as their own top (everything inside a stage flattened), which gives the
# per-module breakdown and keeps Yosys' optimisation loops per stage: `opt`
# iterates over the whole design until nothing changes, and constant bits
# travelling down the long register chains of sgm_lr_check make that loop
# iterate ~D times. sgm_top itself holds no logic, only the stage instances.
#
# Environment (set by synth/synth.mk):
#   SYNTH_RTL        directory of the *.sv sources (default rtl)
#   SYNTH_D          disparities D (16, 32, 64, 128)
#   SYNTH_MAX_WIDTH  MAX_WIDTH
#   SYNTH_MAX_HEIGHT MAX_HEIGHT (default 1024, the RTL default)
#   SYNTH_CENSUS_H   CENSUS_H, census window height (5, the default, or 9: the paper's 9x9)
#   SYNTH_LANES      LANES, row lanes of the schedule (1, the default: the raster)
#   SYNTH_UNIQUENESS UNIQUENESS, the uniqueness ratio built (1, the default) or not (0)
#   SYNTH_AD_TERM    AD_TERM, the AD term built (1, the default) or not (0)
#   SYNTH_RIGHT_BLOCK RIGHT_BLOCK, the fifth path's block (0, the default: not built)
#   SYNTH_EDGE_RESET EDGE_RESET, the path restart at strong edges built (1) or not (0);
#   SYNTH_DEPTH      DEPTH, the depth output built (1) or not (0; empty: sgm_top's default);
#   SYNTH_MIN_DISPARITY MIN_DISPARITY, the minimum disparity built (1) or not (0; empty: the default);
#   SYNTH_RECTIFY, SYNTH_RECTIFY_ROWS, SYNTH_RECTIFY_GRID_LOG2 the rectification (RECTIFY 1 or 0, its
#                    line buffer rows and mesh step; empty: the default);
#   SYNTH_CONFIDENCE CONFIDENCE, the confidence built (1) or not (0; empty: the default);
#   SYNTH_MIN_WIDTH  MIN_WIDTH, the narrowest frame accepted (0: the build's least; empty: the default);
#                    empty (the default): sgm_top's own default
#   SYNTH_OUT        output directory of this target (created by make)
#   SYNTH_DEFINES    Verilog macros to define, space-separated (the ECP5 flow:
#                    SGM_DELAY_CHAIN, rtl/sgm_delay_ram.sv, and SGM_ECP5_GLOBAL,
#                    rtl/sgm_global_buf.sv; none by default)
#
# Files written into SYNTH_OUT by this part:
#   check.txt      `check` of the elaborated design
#   hierarchy.txt  `stat -top sgm_top` of the elaborated design (instance counts)
yosys -import

proc env_or {name default} {
  if {[info exists ::env($name)] && $::env($name) ne ""} { return $::env($name) }
  return $default
}

set rtl        [env_or SYNTH_RTL rtl]
set d          [env_or SYNTH_D 64]
set max_width  [env_or SYNTH_MAX_WIDTH 1280]
set max_height [env_or SYNTH_MAX_HEIGHT 1024]
set census_h   [env_or SYNTH_CENSUS_H 5]
set lanes      [env_or SYNTH_LANES 1]
set uniqueness [env_or SYNTH_UNIQUENESS 1]
set ad_term    [env_or SYNTH_AD_TERM 1]
set right_block [env_or SYNTH_RIGHT_BLOCK 0]
set edge_reset [env_or SYNTH_EDGE_RESET ""]
set depth      [env_or SYNTH_DEPTH ""]
set min_disparity [env_or SYNTH_MIN_DISPARITY ""]
set rectify    [env_or SYNTH_RECTIFY ""]
set rectify_rows [env_or SYNTH_RECTIFY_ROWS ""]
set rectify_grid [env_or SYNTH_RECTIFY_GRID_LOG2 ""]
set confidence [env_or SYNTH_CONFIDENCE ""]
set min_width  [env_or SYNTH_MIN_WIDTH ""]
set out        [env_or SYNTH_OUT build/synth]
set defines    [env_or SYNTH_DEFINES ""]

# SGM_ECP5_GLOBAL: sgm_global_buf instantiates the ECP5 DCCA, a primitive the
# elaboration needs to know (as synth_ecp5 reads it: a black box).
if {"SGM_ECP5_GLOBAL" in $defines} { yosys read_verilog -lib +/ecp5/cells_bb.v }
yosys read_verilog -sv {*}[lmap m $defines {string cat -D $m}] {*}[lsort [glob $rtl/*.sv]]
yosys chparam -set D $d -set MAX_WIDTH $max_width -set MAX_HEIGHT $max_height -set CENSUS_H $census_h -set LANES $lanes \
  -set UNIQUENESS $uniqueness -set AD_TERM $ad_term -set RIGHT_BLOCK $right_block sgm_top
if {$edge_reset ne ""} { yosys chparam -set EDGE_RESET $edge_reset sgm_top }
if {$depth ne ""} { yosys chparam -set DEPTH $depth sgm_top }
if {$min_disparity ne ""} { yosys chparam -set MIN_DISPARITY $min_disparity sgm_top }
if {$rectify ne ""} { yosys chparam -set RECTIFY $rectify sgm_top }
if {$rectify_rows ne ""} { yosys chparam -set RECTIFY_ROWS $rectify_rows sgm_top }
if {$rectify_grid ne ""} { yosys chparam -set RECTIFY_GRID_LOG2 $rectify_grid sgm_top }
if {$confidence ne ""} { yosys chparam -set CONFIDENCE $confidence sgm_top }
if {$min_width ne ""} { yosys chparam -set MIN_WIDTH $min_width sgm_top }
yosys hierarchy -check -top sgm_top
yosys proc
yosys tee -o $out/check.txt check
yosys tee -q -o $out/hierarchy.txt stat -top sgm_top
yosys design -save elab

# The stage modules ($paramod$<hash>\sgm_<name>): the direct children of sgm_top in
# the "design hierarchy" section of hierarchy.txt (indented by 5 spaces).
proc stage_modules {} {
  set f [open $::out/hierarchy.txt r]
  set mods {}
  set in_hier 0
  foreach line [split [read $f] "\n"] {
    if {[string match "=== design hierarchy ===*" $line]} { set in_hier 1; continue }
    if {$in_hier && [string match "*Number of wires*" $line]} break
    if {$in_hier && [regexp {^     (\S+)\s+[0-9]+$} $line -> mod]} { lappend mods $mod }
  }
  close $f
  return [lsort -unique $mods]
}

# sgm_<name> of a stage module: $paramod$<hash>\sgm_<name>, or with one parameter
# $paramod\sgm_<name>\NAME=value (sgm_depth's DW), or sgm_<name> itself.
proc stage_name {mod} {
  if {[regexp {\\(sgm_[A-Za-z0-9_]+)} $mod -> name]} { return $name }
  return $mod
}

# Run BODY once per stage with the variables mod (module name) and name (its
# sgm_<name>, with _2, _3, .. for a second, third parametrisation of one module:
# RIGHT_BLOCK puts a second sgm_delay beside the top's) set and only that stage
# (and what it instantiates) loaded. The seconds each stage took go to
# $out/<name>.seconds.
proc foreach_stage {body} {
  set used {}
  foreach mod [stage_modules] {
    set name [stage_name $mod]
    set base $name
    for {set n 2} {$name in $used} {incr n} { set name "${base}_$n" }
    lappend used $name
    set t0 [clock milliseconds]
    yosys design -load elab
    yosys hierarchy -top $mod
    uplevel 1 [list set mod $mod]
    uplevel 1 [list set name $name]
    uplevel 1 $body
    set f [open $::out/$name.seconds w]
    puts $f [format %.1f [expr {([clock milliseconds] - $t0) / 1000.0}]]
    close $f
  }
}

# Write into FILE one line "TYPE module/cell" per cell of each of TYPES (the
# RAM primitives, so that the summary can tell which memory went where).
proc write_cells {file types} {
  set lines {}
  foreach t $types {
    yosys tee -q -o $::out/.cells.tmp select -list t:$t
    set f [open $::out/.cells.tmp r]
    foreach line [split [read $f] "\n"] {
      set line [string trim $line]
      if {$line ne ""} { lappend lines "$t $line" }
    }
    close $f
  }
  file delete $::out/.cells.tmp
  set f [open $file w]
  foreach line $lines { puts $f $line }
  close $f
}

# RAM primitives per technology (block RAM first, then distributed RAM).
set ram_types(xilinx) {RAMB36E1 RAMB18E1 RAMB36E2 RAMB18E2 RAMB16BWER RAMB8BWER
  RAM16X1S RAM16X1D RAM32X1S RAM32X1D RAM64X1S RAM64X1D RAM128X1S RAM128X1D RAM256X1S RAM256X1D
  RAM512X1S RAM32M RAM64M RAM32M16 RAM64M8 RAM32X16DR8 RAM64X8SW}
set ram_types(ice40) {SB_RAM40_4K SB_SPRAM256KA}

# Sequential primitives that end a combinational path, per technology, as a
# selection (ltp counts the cells between them: LUTs, carry cells, wide muxes).
proc ltp_sel {tech} {
  switch $tech {
    xilinx  { return [list t:FD* t:LD* t:RAM* t:SRL* t:DSP* t:BUFG* %u %u %u %u %u %n] }
    ice40   { return [list t:SB_DFF* t:SB_RAM* t:SB_MAC16 t:SB_SPRAM* %u %u %u %n] }
    generic { return [list t:\$_DFF* t:\$_SDFF* t:\$_DFFE* t:\$_SDFFE* t:\$_SDFFCE* t:\$_ALDFF* t:\$_DLATCH* t:\$mem* %u %u %u %u %u %u %u %n] }
  }
}
