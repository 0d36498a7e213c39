# SPDX-License-Identifier: Apache-2.0
# What the AXI4-Lite wrapper adds on xc7: synth_xilinx of sgm_axi with sgm_top
# read as a black box (read_verilog -lib), so the netlist holds the register
# file, the AXI4-Lite slave and the stream gating only. Run by `make synth-axi`
# (synth/axi.mk). Environment: SYNTH_RTL, SYNTH_D, SYNTH_MAX_WIDTH,
# SYNTH_MAX_HEIGHT, SYNTH_OUT (as synth/common.tcl). Writes $SYNTH_OUT/stat.txt.
yosys -import

proc env_or {name default} {
  if {[info exists ::env($name)] && $::env($name) ne ""} { return $::env($name) }
  return $default
}

set rtl [env_or SYNTH_RTL rtl]
set out [env_or SYNTH_OUT build/synth/axi]

yosys read_verilog -sv $rtl/sgm_axil_slave.sv $rtl/sgm_axi.sv
yosys read_verilog -sv -lib $rtl/sgm_top.sv
yosys hierarchy -check -top sgm_axi -chparam D [env_or SYNTH_D 16] \
  -chparam MAX_WIDTH [env_or SYNTH_MAX_WIDTH 128] -chparam MAX_HEIGHT [env_or SYNTH_MAX_HEIGHT 64]
yosys synth_xilinx -family xc7 -top sgm_axi -flatten -noiopad -noclkbuf
yosys tee -q -o $out/stat.txt stat
