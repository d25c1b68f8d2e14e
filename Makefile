# The two entry points of the README: `make run` and `make test`. Both install what is missing.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
PYTHON := /usr/bin/python3

.PHONY: deps configure build run test test-all bench clean

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: the Hertz benchmark (p = 8, force control to F/2), and the Lamé cylinder.
run: build
	@$(BUILD_DIR)/hpcontact run examples/hertz/p8.yaml --out results/hertz-p8
	@$(PYTHON) scripts/plot_pressure.py results/hertz-p8
	@$(PYTHON) scripts/study_table.py examples/hertz/table-5-1.yaml --hpcontact $(BUILD_DIR)/hpcontact --out results/table-5-1
	@$(BUILD_DIR)/hpcontact run examples/lame/thick-cylinder.yaml --out results/lame
	@echo "results: results/hertz-p8/ (summary.json, pressure.png, pressure.csv, contact.csv, solution.vtu), results/table-5-1/ (table.md, table.csv, pressure.png: the seed's Table 5.1 rows), results/lame/ (summary.json, solution.vtu); open the .vtu files in ParaView"

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE slow

test-all: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	@bash bench/run.sh

clean:
	rm -rf $(BUILD_DIR) results
