# The two entry points of the README: `make run` and `make test`. Both install what is missing.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
PYTHON := /usr/bin/python3

.PHONY: deps configure build program run test test-all test-sanitize fuzz bench bench-slurm bench-examples install deb clean

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Only the command line (what `make run` needs): no tests, benchmarks, fuzz replays or Python module.
program: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target hpcontact_app

# The main job: the Hertz benchmark (p = 8, force control to F/2), and the Lamé cylinder.
run: program
	@$(BUILD_DIR)/hpcontact run examples/hertz/p8.yaml --out results/hertz-p8
	@$(PYTHON) scripts/plot_pressure.py results/hertz-p8
	@$(PYTHON) scripts/plot_field.py results/hertz-p8/solution.vtu --xlim 0 4 --ylim -0.5 3 --out results/hertz-p8/von_mises.png
	@$(PYTHON) scripts/study_table.py examples/hertz/table-5-1.yaml --hpcontact $(BUILD_DIR)/hpcontact --out results/table-5-1 --jobs $(JOBS)
	@$(BUILD_DIR)/hpcontact run examples/lame/thick-cylinder.yaml --out results/lame
	@echo "results: results/hertz-p8/ (report.html, summary.json, pressure.png, von_mises.png, pressure.csv, contact.csv, solution.vtu, contact.vtu), results/table-5-1/ (report.html, table.md, study.csv, pressure.png: the dissertation's Table 5.1 rows), results/lame/ (report.html, summary.json, solution.vtu); open report.html in a browser, the .vtu files in ParaView"

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE slow

test-all: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The fast C++ tests (unit, verification, fuzz replays; the Slurm study test) built with
# AddressSanitizer and UBSan (gcc); the Python module is left out (an instrumented extension
# needs an instrumented interpreter or a preloaded libasan), and so are the tests that load it
# (docs) or link an uninstrumented consumer against the instrumented library (install).
test-sanitize: deps
	@cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHPC_BUILD_BENCH=OFF \
	  "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
	  > /dev/null
	@cmake --build build-sanitize -j $(JOBS)
	@cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) -LE "slow|cli|python|docs|install"

# libFuzzer targets (clang) of the problem and Gmsh readers, FUZZ_SECONDS each (default 60);
# inputs that fail are kept in fuzz/regressions/ and replayed by `make test`.
FUZZ_SECONDS ?= 60
fuzz:
	@bash scripts/install-deps.sh fuzz
	@cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	  -DHPC_FUZZ=ON -DHPC_BUILD_TESTS=OFF -DHPC_BUILD_BENCH=OFF \
	  "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
	  > /dev/null
	@cmake --build build-fuzz -j $(JOBS)
	@bash fuzz/run.sh build-fuzz $(FUZZ_SECONDS)

bench: build
	@bash bench/run.sh

# The 24-row study locally (--jobs 2) and as a Slurm job array on a private one-node cluster:
# BENCHMARKS.md's section "Studies: local processes and a Slurm job array" (about 2 minutes).
bench-slurm: build
	@$(PYTHON) bench/study_executors.py --hpcontact $(BUILD_DIR)/hpcontact

# Every example's Newton iterations and time (a section of BENCHMARKS.md); BEFORE=path/to/an/older/hpcontact
# measures it beside this build.
bench-examples: program
	@$(PYTHON) bench/examples.py --hpcontact $(BUILD_DIR)/hpcontact $(if $(BEFORE),--before $(BEFORE))

# Installs the program, library, CMake package, Python module, scripts and docs under PREFIX.
PREFIX ?= /usr/local
install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX)

# A Debian package of the installed tree (prefix /usr): build/hpcontact_<version>_<arch>.deb.
deb: build
	@cd $(BUILD_DIR) && cpack -G DEB

clean:
	rm -rf $(BUILD_DIR) build-sanitize build-fuzz results
