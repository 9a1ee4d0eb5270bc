# Set-up and everyday commands. `make run` and `make test` both work first on
# a fresh Debian 12 machine as root: they install what is missing, then build.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
DATASET ?= $(if $(CLIPS_DATASET),$(CLIPS_DATASET),../shared/dataset)
# ccache (when installed) shares objects between checkouts beside this one.
export CCACHE_BASEDIR ?= $(abspath $(CURDIR)/..)

# libFuzzer targets (clang-14) build into their own folder; see README "Fuzzing".
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 2
# `make test` also builds the fuzz targets for its short smoke run when
# clang-14 is installed; FUZZ_SMOKE=0 leaves them out.
FUZZ_SMOKE ?= 1

.PHONY: all deps configure build test run bench clean fuzz-build fuzz

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@if [ "$(FUZZ_SMOKE)" != 0 ] && command -v clang++-14 >/dev/null; then $(MAKE) --no-print-directory fuzz-build; fi
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

run: build
	@bash scripts/main-job.sh $(BUILD_DIR) "$(DATASET)"

bench: build
	@$(BUILD_DIR)/clips_bench --benchmark_min_time=0.2
	@bash scripts/bench-report.sh $(BUILD_DIR) "$(DATASET)"

fuzz-build: deps
	@cmake -S . -B $(FUZZ_DIR) -DCLIPS_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(FUZZ_DIR) --target fuzz_targets -j $(FUZZ_JOBS)

fuzz: fuzz-build
	@bash fuzz/run.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR)
