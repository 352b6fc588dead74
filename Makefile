# Quick start (as root on Debian 12):  make run   |   make test
# Missing Debian packages are installed first (list: deps/debian-packages.txt).
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
PACKAGES := $(shell grep -v '^\s*\#' deps/debian-packages.txt)
EXAMPLE ?= examples/rubber_sphere.k
ABUT := $(BUILD_DIR)/apps/abut/abut

.PHONY: all setup build run test bench clean sanitize

all: build

setup:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

build: setup
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_ARGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	$(ABUT) run $(EXAMPLE)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) --timeout 900

bench: build
	$(BUILD_DIR)/bench/abut_bench

sanitize:
	$(MAKE) test BUILD_DIR=build-asan BUILD_TYPE=Debug CMAKE_ARGS="-DABUT_SANITIZE=ON"

clean:
	rm -rf $(BUILD_DIR)
