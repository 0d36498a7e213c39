# SPDX-License-Identifier: Apache-2.0
# `make synth-axi [D=16 MAX_WIDTH=128 SYNTH_AXI_MAX_HEIGHT=64]`: the xc7 cells the
# AXI4-Lite wrapper (sgm_axi + sgm_axil_slave) adds around sgm_top, which is
# a black box here (synth/xilinx_axi.tcl). Prints one line; the full `stat` is
# in build/synth/axi-d<D>-w<MAX_WIDTH>/stat.txt. Included by the main Makefile.
SYNTH_AXI_MAX_HEIGHT ?= 64

.PHONY: synth-axi
synth-axi: | check-tools
	@out=$(BUILD)/synth/axi-d$(D)-w$(MAX_WIDTH); rm -rf $$out && mkdir -p $$out; \
	 SYNTH_RTL=rtl SYNTH_D=$(D) SYNTH_MAX_WIDTH=$(MAX_WIDTH) SYNTH_MAX_HEIGHT=$(SYNTH_AXI_MAX_HEIGHT) SYNTH_OUT=$$out \
	   timeout 600 yosys -q -l $$out/yosys.log -c synth/xilinx_axi.tcl > $$out/yosys.out 2>&1 || \
	   { echo "synth-axi: Yosys failed, see $$out/yosys.log"; exit 1; }; \
	 awk '/LUT[1-6] /{l+=$$2} /FD[RSCP]E /{f+=$$2} /CARRY4 /{c+=$$2} / INV /{i+=$$2} \
	   END{printf "synth-axi: xc7, the wrapper alone (D=$(D), MAX_WIDTH=$(MAX_WIDTH)): %d LUT1..6, %d FF, %d CARRY4, %d INV\n",l,f,c,i}' $$out/stat.txt
