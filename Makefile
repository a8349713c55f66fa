# mpmcut — the two commands a newcomer needs: `make run` and `make test`.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build run test test-sanitize fuzz bench clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Runs the built-in default case into runs/default (replaced on every `make run`).
run: build
	./$(BUILD_DIR)/mpmcut run --out runs/default --force

# Tests run side by side (ctest -j); OpenMP threads that wait passively leave the cores to the
# other tests instead of spinning on them.
test: build
	cd $(BUILD_DIR) && OMP_WAIT_POLICY=PASSIVE ctest --output-on-failure -j $(JOBS) --timeout 900

# AddressSanitizer + UndefinedBehaviorSanitizer build of everything, then the whole test suite
# (docs/reliability.md). SANITIZE_CTEST_ARGS narrows it, e.g. SANITIZE_CTEST_ARGS="-L reliability".
SANITIZE_DIR ?= build-sanitize
SANITIZE_CTEST_ARGS ?=
test-sanitize: deps
	@cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMPMCUT_SANITIZE=ON -DMPMCUT_BENCH=OFF $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) --timeout 1800 $(SANITIZE_CTEST_ARGS)

# libFuzzer on the case-file parser (fuzz/): clang with its fuzzer runtime (installed here, not by
# `make deps`), seeds from cases/*.toml, FUZZ_SECONDS of fuzzing. Crashes land in $(FUZZ_DIR)/.
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
fuzz: deps
	@for p in clang-14 libclang-rt-14-dev libomp-14-dev; do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; done; \
	  if [ -n "$$missing" ]; then echo "fuzz: installing$$missing"; SUDO=""; [ "$$(id -u)" -ne 0 ] && SUDO=sudo; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; fi
	@cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
	  -DMPMCUT_FUZZ=ON -DMPMCUT_TESTS=OFF -DMPMCUT_BENCH=OFF >/dev/null
	@cmake --build $(FUZZ_DIR) -j $(JOBS) --target fuzz_scene_parser
	@mkdir -p $(FUZZ_DIR)/corpus
	./$(FUZZ_DIR)/fuzz/fuzz_scene_parser -max_total_time=$(FUZZ_SECONDS) -timeout=10 -dict=fuzz/toml.dict \
	  -artifact_prefix=$(FUZZ_DIR)/ $(FUZZ_DIR)/corpus cases

bench: build
	./$(BUILD_DIR)/mpmcut bench

clean:
	rm -rf $(BUILD_DIR)
