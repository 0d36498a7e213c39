# SPDX-License-Identifier: Apache-2.0
# `make ecp5-cmp-check`: synth/ecp5_cmp.tcl's carry-chain exception. After
# the flow's own steps (proc, flatten, width reduction), ecp5_cmp_map with
# cmp_chain_inner.sv named keeps the 6 comparisons of its two instances and
# maps the 2 of the top; with no file named it maps all 8; and the result
# equals the design before the map.
yosys -import
source synth/ecp5_cmp.tcl

proc load_case {} {
  design -reset
  read_verilog -sv tests/synth/cmp_chain_inner.sv tests/synth/cmp_chain_case.sv
  hierarchy -top cmp_chain_case
  ecp5_cmp_prepare
}

load_case
select -assert-count 8 t:\$lt t:\$le t:\$gt t:\$ge
design -save gold

ecp5_cmp_map 12 {cmp_chain_inner.sv}
select -assert-count 6 t:\$lt t:\$le t:\$gt t:\$ge
select -assert-count 6 t:\$lt t:\$le %u t:\$gt %u t:\$ge %u a:src=*cmp_chain_inner.sv* %i
opt
yosys rename cmp_chain_case gate
design -save gate

design -reset
design -copy-from gold -as gold cmp_chain_case
design -copy-from gate -as gate gate
equiv_make gold gate equiv
equiv_simple -undef
equiv_status -assert

load_case
ecp5_cmp_map 12 {}
select -assert-count 0 t:\$lt t:\$le t:\$gt t:\$ge

load_case
ecp5_cmp_map 0 {cmp_chain_inner.sv}
select -assert-count 8 t:\$lt t:\$le t:\$gt t:\$ge
