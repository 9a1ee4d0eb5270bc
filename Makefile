# Set-up and everyday commands. `make run` and `make test` both work first on
# a fresh Debian 12 machine as root: they install what is missing, then build.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
DATASET ?= $(if $(CLIPS_DATASET),$(CLIPS_DATASET),../shared/dataset)
# ccache (when installed) shares objects between checkouts beside this one.
export CCACHE_BASEDIR ?= $(abspath $(CURDIR)/..)

.PHONY: all deps configure build test run bench clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

run: build
	@bash scripts/main-job.sh $(BUILD_DIR) "$(DATASET)"

bench: build
	@$(BUILD_DIR)/clips_bench --benchmark_min_time=0.2
	@bash scripts/bench-report.sh $(BUILD_DIR) "$(DATASET)"
	@CLIPS_DATASET="$(DATASET)" python3 bench/python_session_bench.py $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR)
