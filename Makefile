# Set-up and everyday commands. `make run` and `make test` both work first on
# a fresh Debian 12 machine as root: they install what is missing, then build.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
DATASET ?= $(if $(CLIPS_DATASET),$(CLIPS_DATASET),../shared/dataset)
# ccache (when installed) shares objects between checkouts beside this one.
export CCACHE_BASEDIR ?= $(abspath $(CURDIR)/..)

# libFuzzer targets (clang-14) build into their own folder; see docs/testing.md, "Fuzzing".
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 2
# `make test` also builds the fuzz targets for its short smoke run when
# clang-14 is installed; FUZZ_SMOKE=0 leaves them out. `make fuzz-build`
# builds those (fuzz_targets); `make fuzz` builds every target
# (fuzz_targets_all: also serve, which compiles most of the code base).
FUZZ_SMOKE ?= 1
FUZZ_BUILD_TARGET ?= fuzz_targets

.PHONY: all deps configure build cli test run bench bench-scaling clean fuzz-build fuzz test-asan test-tsan deb

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Only the CLI and the libraries it links: what the main job runs. A fresh
# clone's first result should not wait for every test binary and benchmark;
# `make test` (and `make build`) compile the rest in the same folder.
cli: configure
	@cmake --build $(BUILD_DIR) --target clips -j $(JOBS)

test: build
	@if [ "$(FUZZ_SMOKE)" != 0 ] && command -v clang++-14 >/dev/null; then $(MAKE) --no-print-directory fuzz-build; fi
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

run: cli
	@bash scripts/main-job.sh $(BUILD_DIR) "$(DATASET)"

# Scaling curves (docs/scaling/): about 20 min; SCALING_ARGS=--quick for a short run.
bench-scaling: build
	@$(BUILD_DIR)/clips bench --scaling --scaling-plans 3 --point-seconds 45 --out docs/scaling $(SCALING_ARGS)

bench: build
	@$(BUILD_DIR)/clips_bench --benchmark_min_time=0.2
	@bash scripts/bench-report.sh $(BUILD_DIR) "$(DATASET)"
	@CLIPS_DATASET="$(DATASET)" python3 bench/python_session_bench.py $(BUILD_DIR)

fuzz-build: deps
	@cmake -S . -B $(FUZZ_DIR) -DCLIPS_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(FUZZ_DIR) --target $(FUZZ_BUILD_TARGET) -j $(FUZZ_JOBS)

fuzz:
	@$(MAKE) --no-print-directory fuzz-build FUZZ_BUILD_TARGET=fuzz_targets_all
	@bash fuzz/run.sh $(FUZZ_DIR) $(FUZZ_SECONDS)
# Sanitizer builds, each in its own folder (the Release build is untouched):
# ASan + UBSan (any UB aborts the test), and TSan. Both at -O1 -g, built at
# low priority. Left out: tests labelled `slow` and the whole-dataset cases
# below, which take minutes in Release and would take an hour sanitized; the
# normal `make test` runs them. SAN_CTEST_ARGS= (empty) runs everything.
SAN_SLOW_TESTS ?= StripsExport\.SameOptimalCostOnTheDataset|DkgDataset\.AllPlansThreeModalities|Paraphrases\.|VirtualHomeRewordings\.|ListenerQuality\.
SAN_CTEST_ARGS ?= -LE slow -E '$(SAN_SLOW_TESTS)'
export ASAN_OPTIONS ?= detect_leaks=1:check_initialization_order=1:strict_init_order=1
export UBSAN_OPTIONS ?= print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS ?= suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0
export TSAN_OPTIONS ?= second_deadlock_stack=1:suppressions=$(CURDIR)/scripts/tsan.supp

test-asan: deps
	@cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCLIPS_SANITIZER=address >/dev/null
	@nice -n 10 cmake --build build-asan -j $(JOBS)
	@cd build-asan && ctest --output-on-failure -j $(JOBS) $(SAN_CTEST_ARGS)

test-tsan: deps
	@cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=Release -DCLIPS_SANITIZER=thread >/dev/null
	@nice -n 10 cmake --build build-tsan -j $(JOBS)
	@cd build-tsan && ctest --output-on-failure -j $(JOBS) $(SAN_CTEST_ARGS)

# The Debian package (docs/library.md, "Installing"): build-deb/clips-assist_<version>_<arch>.deb.
deb: deps
	@cmake -S . -B build-deb -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DCLIPS_BUILD_TESTS=OFF \
	  -DCLIPS_BUILD_BENCH=OFF -DCLIPS_SOURCE_DATA=OFF -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
	@cmake --build build-deb -j $(JOBS)
	@cd build-deb && cpack -G DEB

clean:
	rm -rf $(BUILD_DIR) build-asan build-tsan build-deb build-pip-*
