# Thin front end over CMake + CTest. `make help` lists the targets.
BUILD     ?= build
TYPE      ?= Release
NATIVE    ?= ON
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
PROFILE   ?= default
RESULTS   ?=
FUZZ_SECONDS ?= 60
FUZZ_BUILD   ?= build-fuzz
CMAKE_ARGS = -DCMAKE_BUILD_TYPE=$(TYPE) -DCFPO_NATIVE=$(NATIVE)

.PHONY: all build test test-sanitize fuzz bench bench-core replot help clean deps deps-fuzz deps-python deps-bench deps-test python

all: build

# Missing Debian packages, by group (scripts/install-deps.sh: installed
# as root on Debian, only reported anywhere else). Plain `make` asks for
# the core and cgal groups (without CGAL it still builds cfpo and all that
# does not need CGAL, and says what it left out); fuzzing needs no CGAL;
# the Python package and the benchmark need every baseline, so CGAL too.
deps:
	@scripts/install-deps.sh core cgal
deps-fuzz:
	@scripts/install-deps.sh core fuzz
deps-python:
	@scripts/install-deps.sh core cgal python
deps-bench:
	@scripts/install-deps.sh core cgal bench
# Every test: the Python package's (label python) and the benchmark's smoke
# run (label bench) among them.
deps-test:
	@scripts/install-deps.sh core cgal python bench

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_ARGS) >/dev/null

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

test: deps-test build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The Python package in a virtual environment $(BUILD)/venv (pip install
# of this checkout through scikit-build-core; see README.md, "Python").
python: deps-python
	scripts/python-venv.sh $(BUILD)

# Unit tests under AddressSanitizer + UndefinedBehaviorSanitizer. A report
# names the allocation and the free of a block by their two innermost
# frames (malloc_context_size=2; the faulting access keeps its whole
# stack): with the default 30, recording the stacks of CGAL's many small
# allocations took 90% of the Delaunay measures' test (361 s against 18 s).
# ASAN_OPTIONS set by the caller wins.
test-sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCFPO_SANITIZE=ON >/dev/null
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS="$${ASAN_OPTIONS:-malloc_context_size=2}" ctest --output-on-failure -j $(JOBS) -L unit

# libFuzzer harnesses (fuzz/) in their own clang build folder, each run
# FUZZ_SECONDS (default 60), FUZZ_JOBS at a time (default: the cores);
# fails on any crash, sanitizer report or time-out.
fuzz: deps-fuzz
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCFPO_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	cmake --build $(FUZZ_BUILD) -j $(JOBS)
	scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The method comparison and the paper's figures (scripts/bench.py run).
bench: deps-bench build
	python3 scripts/bench.py run $(BUILD) $(PROFILE)

# Redraw figures and summary.md of a results folder (default: the newest).
replot: deps-bench
	python3 scripts/bench.py replot $(RESULTS)

# The core CFPO benchmark: sweep and convergence figures (core.txt).
bench-core: deps-bench build
	python3 scripts/bench.py core $(BUILD) $(PROFILE)

help:
	@echo "Targets:"
	@echo "  make               optimised build into $(BUILD)/ (installs missing Debian packages first, as root;"
	@echo "                     elsewhere only reports them: scripts/install-deps.sh, CFPO_NO_APT=1)"
	@echo "  make test          build, then run every CTest test"
	@echo "  make test-sanitize unit tests in an ASan+UBSan build (build-asan/)"
	@echo "  make fuzz          libFuzzer harnesses, FUZZ_SECONDS each (default 60), FUZZ_JOBS at a time, in $(FUZZ_BUILD)/"
	@echo "  make python        the Python package (import cfpo) in a virtual environment $(BUILD)/venv"
	@echo "  make bench         method comparison and figures (PROFILE=smoke|default|paper|seeds|lowk|density|3d|progressive); results/<date>-<host>/"
	@echo "  make replot        redraw figures and summary.md of RESULTS=results/... (default: newest)"
	@echo "  make bench-core    core CFPO benchmark, sweeps and convergence (PROFILE=smoke|default)"
	@echo "  make deps-GROUP    missing Debian packages of GROUP = fuzz, python, bench (with core; all but fuzz with cgal)"
	@echo "  make clean         remove build folders"
	@echo "Build settings:"
	@echo "  build type   $(TYPE)   (TYPE=Debug|Release|RelWithDebInfo)"
	@echo "  C flags      -O3 -DNDEBUG -Wall -Wextra -Werror -ffp-contract=off -fopenmp"
	@echo "  -march       $(if $(filter ON,$(NATIVE)),native (NATIVE=OFF for portable x86-64),generic (NATIVE=ON for -march=native))"
	@echo "  compiler     $$(cc --version 2>/dev/null | head -n 1)"

clean:
	rm -rf $(BUILD) build-asan $(FUZZ_BUILD)
