# The two commands of the README: `make demo` and `make test`. Each does all set-up.
BUILD      ?= build
ASAN_BUILD ?= build-asan
BENCH_BUILD?= build-bench
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
JOBS       ?= $(shell nproc)
CTEST_ARGS ?=

.PHONY: all deps build test test-release test-sanitize demo bench fuzz jet-study clean

all: build

deps:
	@scripts/install-deps

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# Release build with every label, then the sanitizer build (the unit, MPI and fuzz tests;
# the validation cases, which run the same code at a larger size, and the long runs
# labelled slow stay in the Release pass only). Both are portable builds: the 1-D and
# MD vector kernels hold every vector path in any build (CMakeLists.txt), and both passes
# run their tests on each path this machine has (fused_path_test, eam_one_type_test).
test: test-release test-sanitize

test-release: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# clang-14 builds it (line tables only: a report still names file and line), with the
# fuzz targets beside the tests, so that the fuzz smoke needs no tree of its own.
test-sanitize:
	@scripts/install-deps --fuzz
	@CC=clang-14 CXX=clang++-14 cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" \
	  -DMPMX_SANITIZE=ON -DMPMX_NATIVE=OFF -DMPMX_BUILD_BENCH=OFF "-DMPMX_SKIP_TEST_LABELS=slow;crosscheck;validation" >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -LE 'slow|crosscheck|validation' $(CTEST_ARGS)

# The demo needs the program only, not the tests; it says how long the build and the
# runs took.
demo: deps
	@start=$$(date +%s); \
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null && \
	cmake --build $(BUILD) -j $(JOBS) --target mpmx && built=$$(date +%s) && \
	scripts/demo $(BUILD)/mpmx && end=$$(date +%s) && \
	echo "make demo: the program built in $$((built - start)) s, the demo ran in $$((end - built)) s"

# -march=native for the code outside the vector kernels; the 1-D and MD kernels pick
# their path at run time whatever the build, and their benches time each path this
# machine has.
# The copper-jet study (Table 7.1, docs/jet.md): make jet-study SCALE=s0p1 (or tiny, s0p05, s0p2, s0p5, full).
SCALE ?= s0p1
jet-study: build
	scripts/jet-study --scale $(SCALE) --build $(BUILD)

bench: deps
	@cmake -S . -B $(BENCH_BUILD) -DCMAKE_BUILD_TYPE=Release -DMPMX_NATIVE=ON >/dev/null
	@cmake --build $(BENCH_BUILD) -j $(JOBS)
	@scripts/bench $(BENCH_BUILD)

# Every libFuzzer target (tests/fuzz) for FUZZ_SECONDS each, from its corpus in
# tests/fuzz/corpus/; clang-14 builds them in FUZZ_BUILD (MPMX_FUZZ=ON). FUZZ_GROW=1
# merges what the run found, minimised, back into the corpus.
fuzz:
	@scripts/install-deps --fuzz
	@scripts/fuzz $(FUZZ_BUILD) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(BENCH_BUILD) $(FUZZ_BUILD)
