# The README's quick-start commands.  CMake does the real work; this file
# installs what is missing, configures and builds.
BUILD ?= build
CMAKE_FLAGS ?=
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
OUT ?= out

.PHONY: all run test bench deps test-deps build compile clean

all: build

# Packages needed to build; the tests need a few more (deps/test*.txt).
deps:
	@scripts/install-deps.sh build

test-deps:
	@scripts/install-deps.sh build test
	@scripts/install-npm-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

compile: $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

build: deps
	@$(MAKE) --no-print-directory compile

# Renders the demo gallery to $(OUT)/index.html.
run: build
	$(BUILD)/tools/cg/cg demo -o $(OUT)

# Builds and runs every test.  CMake is configured again after the test
# packages are installed, so that the checks against the peers they bring
# (GEOS, OSMesa, Embree, ...) are built even when `make run` configured the
# build before they were there.
test: test-deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	@$(MAKE) --no-print-directory compile
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# Builds and runs the benchmarks against the peer libraries; rewrites bench/RESULTS.md.
# BENCHES=bench_fill (or several names) reruns only those, keeping the others' last rows.
BENCHES ?=
bench:
	@scripts/install-deps.sh build bench
	@scripts/install-npm-deps.sh
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)
	bench/run.sh $(BUILD) $(BENCHES)

clean:
	rm -rf $(BUILD) $(OUT)
