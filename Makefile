# trapdem: the two Quick-start commands (make demo, make test) and the benchmarks.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build test test-slow demo study bench bench-peers clean

all: build

deps:
	@bash scripts/install-deps

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > $(BUILD).cmake.log 2>&1 || (cat $(BUILD).cmake.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Every fast test (analytic cases, properties, regressions); slow validations are labelled "slow".
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

test-slow: build
	@cd $(BUILD) && ctest --output-on-failure -L slow

demo: build
	@bash scripts/demo.sh $(BUILD)

# The paper's Table 2 at the demo's scale (~25 min on 2 cores): trapdem-out/paper-table2-demo/report/index.html
study: build
	@$(BUILD)/apps/trapdem study studies/paper-table2.toml --quiet

bench: build
	@bash bench/run-bench.sh $(BUILD)

bench-peers: build
	@bash scripts/install-deps --peers
	@bash bench/run-peers.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD).cmake.log
