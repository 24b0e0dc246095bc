# Two-command set-up: `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
ifeq ($(CI),true)
  CMAKE_FLAGS += -DRIS_WARNINGS_AS_ERRORS=ON
endif

.PHONY: deps configure build demo test bench format format-check clean sanitize fuzz

deps:
	./scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The demo needs the tool alone: its target and what it links, not the
# test suite (a first image in minutes on two cores, not half an hour).
demo: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target ris
	./scripts/demo.sh $(BUILD_DIR)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD_DIR)/ris bench

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

format-check:
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.h')

# AddressSanitizer + UndefinedBehaviorSanitizer over the whole test suite, in
# its own build folder (docs/testing.md); -O1 with line tables only, which
# halves the compile time of -O2 -g and keeps file:line in the reports. The
# Python module is left out: an ASan library cannot be loaded into an
# uninstrumented python3. Warnings are not errors here (CI's CMAKE_FLAGS are
# not passed): `make test` enforces them, and GCC's flow warnings change
# with the instrumentation.
SANITIZE_DIR ?= build-sanitize
# Without MPI (its tests then skip): OpenMPI's own process-lifetime
# allocations would flood LeakSanitizer, and the MPI split is plain message
# passing around the same code the single-process tests cover.
# The resident-memory bound of the streamed run is left out: ASan's shadow
# memory and quarantine are what it would measure.
SANITIZE_CTEST_ARGS ?= -E StreamMemory
sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DRIS_SANITIZE=ON \
	  -DRIS_BUILD_PYTHON=OFF -DRIS_BUILD_BENCH=OFF -DRIS_WITH_MPI=OFF
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) $(SANITIZE_CTEST_ARGS)

# The libFuzzer harnesses (fuzz/), built with clang, each run for
# FUZZ_SECONDS on a working copy of its corpus; findings (crash-*, oom-*,
# timeout-*) land in $(FUZZ_DIR)/findings/<harness>/ (docs/testing.md).
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DRIS_FUZZ=ON -DRIS_BUILD_TESTS=OFF -DRIS_BUILD_BENCH=OFF -DRIS_BUILD_PYTHON=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS)
	./scripts/fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_HARNESSES)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR)
