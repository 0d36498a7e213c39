# Debian packages the project needs, the `deps` target that installs them and
# the `check-tools` guard every build target depends on.

DEB_PACKAGES := build-essential pkg-config verilator yosys libopencv-dev libgtest-dev googletest \
                nextpnr-ice40 fpga-icestorm opencv-doc

# One probe per package: a file it installs.
TOOL_PROBES := /usr/bin/g++ /usr/bin/pkg-config /usr/bin/verilator /usr/bin/yosys \
               /usr/include/opencv4/opencv2/core.hpp /usr/include/gtest/gtest.h \
               /usr/bin/nextpnr-ice40 /usr/bin/icepack \
               /usr/share/doc/opencv-doc/examples/data/aloeL.jpg
MISSING_TOOLS = $(strip $(foreach f,$(TOOL_PROBES),$(if $(wildcard $(f)),,$(f))))

.PHONY: deps check-tools
deps:
	@if [ -z "$(MISSING_TOOLS)" ]; then echo "deps: all packages present"; \
	elif [ "$$(id -u)" = 0 ]; then \
	  echo "deps: installing $(DEB_PACKAGES)"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $(DEB_PACKAGES) >/dev/null; \
	else \
	  echo "deps: missing $(MISSING_TOOLS)"; \
	  echo "deps: run: sudo apt-get update && sudo apt-get install -y $(DEB_PACKAGES)"; exit 1; \
	fi

check-tools:
	@if [ -n "$(MISSING_TOOLS)" ]; then \
	  if [ "$$(id -u)" = 0 ]; then $(MAKE) --no-print-directory deps; \
	  else echo "missing: $(MISSING_TOOLS)"; \
	       echo "run 'make deps' as root, or: sudo apt-get install -y $(DEB_PACKAGES)"; exit 1; fi; \
	fi
