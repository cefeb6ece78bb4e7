# trapdem: the two Quick-start commands (make demo, make test) and the benchmarks.
BUILD ?= build
ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
# make install: the program goes to $(PREFIX)/bin, the presets to $(PREFIX)/share/trapdem/presets,
# the Python package to $(PREFIX)/lib/python3/dist-packages/trapdem.
PREFIX ?= /usr/local
# ccache, where installed, shares compiled objects between build folders (build, build-asan).
LAUNCHER := $(if $(shell command -v ccache),-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

.PHONY: all deps configure build test test-slow test-asan fuzz demo study bench bench-peers install clean

all: build

deps:
	@bash scripts/install-deps

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(LAUNCHER) $(CMAKE_FLAGS) > $(BUILD).cmake.log 2>&1 || (cat $(BUILD).cmake.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Every fast test (analytic cases, properties, regressions); slow validations are labelled "slow".
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

# The slow validations (tests/<module>/slow: the whole photograph sequence, a demo-scale run), one
# at a time: each uses every core.
test-slow: build
	@cd $(BUILD) && ctest --output-on-failure -L slow

# The fast suite again, every library and test built with AddressSanitizer and
# UndefinedBehaviorSanitizer in its own folder; any finding fails the test that met it. -O1 (what
# AddressSanitizer's authors advise) and line tables only (-g1: enough for the file:line of a
# report) compile much faster than -O2 -g with the instrumentation.
test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
	  -DTRAPDEM_SANITIZE="address;undefined" \
	  -DTRAPDEM_BUILD_BENCH=OFF $(LAUNCHER) $(CMAKE_FLAGS) > $(ASAN_BUILD).cmake.log 2>&1 || (cat $(ASAN_BUILD).cmake.log; exit 1)
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 ctest --output-on-failure -j $(JOBS) -LE slow

# libFuzzer over every reader of user input (tests/fuzz), FUZZ_SECONDS each, one after another,
# built with clang and AddressSanitizer + UndefinedBehaviorSanitizer in its own folder. Findings:
# $(FUZZ_BUILD)/findings, logs: $(FUZZ_BUILD)/logs.
fuzz: deps
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
	  -DCMAKE_CXX_COMPILER=clang++-14 -DTRAPDEM_FUZZ=ON -DTRAPDEM_SANITIZE="address;undefined;fuzzer-no-link" \
	  -DTRAPDEM_BUILD_TESTS=OFF -DTRAPDEM_BUILD_BENCH=OFF -DTRAPDEM_MPI=OFF $(LAUNCHER) $(CMAKE_FLAGS) \
	  > $(FUZZ_BUILD).cmake.log 2>&1 || (cat $(FUZZ_BUILD).cmake.log; exit 1)
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz
	@FUZZ_SECONDS=$(FUZZ_SECONDS) bash tests/fuzz/run-fuzz.sh $(FUZZ_BUILD)

demo: build
	@bash scripts/demo.sh $(BUILD)

# The paper's Table 2 at the demo's scale (~25 min on 2 cores): trapdem-out/paper-table2-demo/report/index.html
study: build
	@$(BUILD)/apps/trapdem study studies/paper-table2.toml --quiet

# The MPI cases (2 ranks x 1 thread against 1 rank x 2 threads) run where the build has MPI.
bench: build
	@bash bench/run-bench.sh $(BUILD)
	@if [ -x $(BUILD)/bench/mpi_standard ]; then NO_PEERS=1 bash bench/run-mpi.sh $(BUILD); fi
	@if command -v lmp > /dev/null; then bash bench/run-clumps.sh $(BUILD); fi  # the clump bed beside LAMMPS rigid/small

# The peers on 1 and 2 ranks, trapdem on 1 and 2 threads, then trapdem on 2 ranks against the
# peers' 2-rank results of this same run.
bench-peers: build
	@bash scripts/install-deps --peers
	@bash bench/run-peers.sh $(BUILD)
	@if [ -x $(BUILD)/bench/mpi_standard ]; then NO_PEERS=1 PEERS_THIS_RUN=1 bash bench/run-mpi.sh $(BUILD); fi

install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD) $(BUILD).cmake.log $(ASAN_BUILD) $(ASAN_BUILD).cmake.log $(FUZZ_BUILD) $(FUZZ_BUILD).cmake.log
