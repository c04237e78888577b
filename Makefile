# The two commands of the README:
#   make test   install what is missing, configure, build, run the whole suite
#   make demo   same set-up, then run the main job
# Other targets: build, test-sanitize (ASan+UBSan build running the CI part;
# test-sanitize-all: the whole suite),
# bench (Google Benchmark programs, kept out of `make test`), lint, format,
# synth (Yosys cell count of the card RTL).
BUILD ?= build
# ccache (used when present) sees paths relative to the repository, so the
# mutant trees (tests/mutants/run_mutants.py) hit the main build's entries.
export CCACHE_BASEDIR ?= $(CURDIR)
export CCACHE_NOHASHDIR ?= 1
BUILD_SAN ?= build-asan
BUILD_BENCH ?= build-bench
JOBS ?= $(shell nproc)
CMAKE_GEN := $(shell command -v ninja >/dev/null 2>&1 && echo "-G Ninja")

.PHONY: all deps configure build test demo test-sanitize bench lint format clean \
	campaign-smoke campaign-full

all: build

deps:
	@bash scripts/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# The default scenario through the whole co-simulation (sensors -> card RTL ->
# EMIF -> C6416 running the firmware), 12 periods, into out/demo/ (docs/cli.md);
# prints the summary. Builds the stereosim program only (make test builds the
# tests and the traced cards too). Exit 1 is the budget verdict "over budget" (a result,
# shown in the summary); 2 and up are errors.
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target stereosim
	@rc=0; $(BUILD)/stereosim run --scenario default --out out/demo --summary || rc=$$?; \
		if [ $$rc -eq 1 ]; then echo "demo: the default scenario is over budget (docs/budget.md): a result, not a failure"; \
		elif [ $$rc -ne 0 ]; then exit $$rc; fi

# The fault campaigns (docs/fault-contract.md): every fault kind over its
# parameters and seeds, each run checked against the contract; non-zero exit
# on any violation. smoke runs in CI; full is run before a release.
CAMPAIGN_JOBS ?= $(JOBS)
campaign-smoke: build
	$(BUILD)/stereosim faults --campaign smoke --jobs $(CAMPAIGN_JOBS) --out out/campaign-smoke

campaign-full: build
	$(BUILD)/stereosim faults --campaign full --jobs $(CAMPAIGN_JOBS) --out out/campaign-full $(CAMPAIGN_ARGS)

# The CI's sanitizer pass: every layer but the system and cli ones, plus one
# short system scenario; it builds only those layers' programs (tests_<layer>,
# tests/CMakeLists.txt), not the traced cards or the stereosim application.
# The two largest host object-size runs, the larger box cases and the
# 320 px key's traffic (100 s under ASan) are left to the whole-suite pass,
# which is run before an issue is resolved: make test-sanitize-all.
SAN_LABELS ?= dsp|scene|model|rtl|firmware
SAN_TARGETS ?= tests_dsp tests_scene tests_model tests_rtl tests_firmware system_test_data_integrity_sc
SAN_EXCLUDE ?= CardCounters\.|KeyTraffic\.|BoxOnReturn\.|ObjectSize\.DetectedAndTrackedWithinTheBounds/(240|320)px|BoxOnMotion\.StaysOnTheObject/(pass(80|125|160|320)|throw(60px_1|60px_10|90|100|2[0-9]0px)|heldout|open_|spin(80|140)|spin40px_1pxpf_(0_5|1|2)rps|spin40px_1pxpf_3rps_(x|y)|approach1[1-3]0px_6pxpf|recede1[234][05]px_([68]|12)pxpf|recede100px_3pxpf|recede80px_2pxpf|circle(_back90px_3pxpf_1rps_y_kodim19|80px_3pxpf_2rps_x_venus|100px_1pxpf))
SAN_SYSTEM ?= ^system\.data_integrity\.
SAN_ENV := ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp
.PHONY: test-sanitize-all sanitize-configure
sanitize-configure: deps
	cmake -S . -B $(BUILD_SAN) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Debug -DSTEREOSIM_SANITIZE=ON

test-sanitize: sanitize-configure
	cmake --build $(BUILD_SAN) -j $(JOBS) --target $(SAN_TARGETS)
	cd $(BUILD_SAN) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -L '$(SAN_LABELS)' \
		-E '$(SAN_EXCLUDE)' $(CTEST_ARGS)
	cd $(BUILD_SAN) && $(SAN_ENV) ctest --output-on-failure -R '$(SAN_SYSTEM)' $(CTEST_ARGS)

test-sanitize-all: sanitize-configure
	cmake --build $(BUILD_SAN) -j $(JOBS)
	cd $(BUILD_SAN) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

bench: deps
	cmake -S . -B $(BUILD_BENCH) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release -DSTEREOSIM_BENCH=ON
	cmake --build $(BUILD_BENCH) -j $(JOBS)
	@for b in $(BUILD_BENCH)/bench/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

# The card's synthesizable RTL (rtl/*.v).
lint: deps
	@for f in $$(find rtl -maxdepth 1 -name '*.v' | sort); do \
		verilator --lint-only -Wall -Irtl $$f || exit 1; done; echo "lint: rtl clean"

# Generic synthesis of the card with Yosys (docs/card.md "Synthesis"): cells
# by type, flip-flops and memory bits of card_top, the FIFOs kept as memories;
# summary printed and written to $(BUILD_SYNTH)/summary.txt with Yosys' log.
BUILD_SYNTH ?= build-synth
SYNTH_FIFO_AW ?= 17
.PHONY: synth
synth: deps
	@bash scripts/synth-card $(BUILD_SYNTH) $(SYNTH_FIFO_AW)


format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD) $(BUILD_SAN) $(BUILD_BENCH) $(BUILD_COVERAGE) build-coverage-full

# Line and toggle coverage of the card RTL by the rtl tests (verilator
# --coverage-line --coverage-toggle in a separate build directory, so normal
# builds stay fast); prints the line coverage and fails below 90%.
BUILD_COV ?= build-coverage-rtl
.PHONY: coverage-rtl
coverage-rtl: deps
	cmake -S . -B $(BUILD_COV) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEREOSIM_RTL_COVERAGE=ON
	cmake --build $(BUILD_COV) -j $(JOBS) --target rtl_tests
	rm -rf $(BUILD_COV)/coverage-rtl
	cd $(BUILD_COV) && ctest --output-on-failure -j $(JOBS) -L rtl
	bash rtl/coverage_report.sh $(BUILD_COV)/coverage-rtl 90

# What a fault campaign exercised (docs/fault-contract.md "Coverage"): a
# coverage build ($(BUILD_COVERAGE): gcov of dsp/, the card verilated with
# line, toggle and functional coverage, every run writing its own), the rtl
# tests and then the campaign COVERAGE_CAMPAIGN (smoke or full) run there,
# and scripts/coverage-report: the firmware's branches and the card's lines
# each reached or listed with its reason (tests/coverage/unreached.txt), per
# module figures, lcov pages, the fault space and the safety classes. Fails
# on a contract break or an unexplained hole.
BUILD_COVERAGE ?= build-coverage
COVERAGE_CAMPAIGN ?= smoke
COVERAGE_TOGGLE ?= ON
.PHONY: coverage coverage-full
coverage: deps
	cmake -S . -B $(BUILD_COVERAGE) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
		-DSTEREOSIM_COVERAGE=ON -DSTEREOSIM_COVERAGE_TOGGLE=$(COVERAGE_TOGGLE)
	cmake --build $(BUILD_COVERAGE) -j $(JOBS) --target stereosim rtl_tests
	rm -rf $(BUILD_COVERAGE)/coverage $(BUILD_COVERAGE)/coverage-rtl
	cd $(BUILD_COVERAGE) && ctest -L rtl -j $(JOBS) --output-on-failure
	find $(BUILD_COVERAGE) -name '*.gcda' -delete
	@rc=0; $(BUILD_COVERAGE)/stereosim faults --campaign $(COVERAGE_CAMPAIGN) \
		--jobs $(CAMPAIGN_JOBS) --out $(BUILD_COVERAGE)/campaign-$(COVERAGE_CAMPAIGN) || rc=$$?; \
	python3 scripts/coverage-report $(BUILD_COVERAGE) \
		$(BUILD_COVERAGE)/campaign-$(COVERAGE_CAMPAIGN) || rc=$$((rc ? rc : 1)); exit $$rc

# The full campaign's coverage, without the card's toggle coverage (7.6 times
# slower a run with it; the smoke campaign and the rtl tests give toggles).
coverage-full:
	$(MAKE) coverage COVERAGE_CAMPAIGN=full BUILD_COVERAGE=build-coverage-full COVERAGE_TOGGLE=OFF

# Mutation qualification of the fault campaign (docs/mutants.md): every
# firmware mutant (tests/mutants/firmware/*.patch) and RTL mutant
# (tests/mutants/rtl/generate) is built in its own tree under build-mutants/
# and must be killed: firmware first by the tests that killed it last time
# (tests/mutants/firmware-killers.tsv), then ctest -L dsp or the campaign
# (MUTANTS_ARGS=--whole: the campaign first, every test), RTL by ctest -L rtl
# or the campaign. Reports in build-mutants/results*/mutants.txt.
# MUTANT_JOBS mutants at a time (empty: the runner's default, 1).
MUTANT_JOBS ?=
MUTANTS_ARGS ?=
# mutants-ci: a fixed slice the smoke campaign kills (--whole: the campaign
# first, whatever the record of known killers says), three firmware mutants
# of different kinds (the left frame processed twice: pair identity; the
# watchdog re-arming a healthy card every period: rule 11 over the clean soak
# row; an overflow re-arm counted towards the give-up: rule 4 over the row of
# a sensor dead from the overflow re-arm) and one RTL mutant: MUTANTS_CI_RTL
# (the card counting every failed check since ENABLE: rule 11 over the
# intermittent soak row), or if empty the first id the generator makes with
# seed MUTANTS_CI_RTL_SEED.
MUTANTS_CI_FIRMWARE ?= fw-15-left-frame-twice,fw-24-watchdog-progress-saved-first,fw-32-overflow-rearm-counts-as-failure
MUTANTS_CI_RTL ?= rt-01-oe-failures-never-cleared
MUTANTS_CI_RTL_SEED ?= 1
MUTANTS_CI_RTL_DIR ?= build-mutants/rtl-ci
.PHONY: mutants mutants-ci
mutants: build
	python3 tests/mutants/run_mutants.py $(if $(MUTANT_JOBS),--jobs $(MUTANT_JOBS)) $(MUTANTS_ARGS)

mutants-ci: build
	@rtl="$(MUTANTS_CI_RTL)"; kind=firmware; rtl_args=""; \
	if [ -x tests/mutants/rtl/generate ]; then \
		tests/mutants/rtl/generate $(MUTANTS_CI_RTL_DIR) --seed $(MUTANTS_CI_RTL_SEED) || exit 2; \
		[ -n "$$rtl" ] || rtl=$$(awk -F'\t' 'NR == 2 { print $$1 }' $(MUTANTS_CI_RTL_DIR)/rtl-mutants.tsv); \
		kind=all; rtl_args="--rtl-dir $(MUTANTS_CI_RTL_DIR)"; \
	else \
		echo "mutants-ci: tests/mutants/rtl/generate does not exist yet: firmware mutants only"; rtl=""; \
	fi; \
	set -x; python3 tests/mutants/run_mutants.py --kind $$kind $$rtl_args --no-baseline --whole \
		--only $(MUTANTS_CI_FIRMWARE)$${rtl:+,$$rtl} --out build-mutants/results-ci \
		$(if $(MUTANT_JOBS),--jobs $(MUTANT_JOBS)) $(MUTANTS_ARGS)
