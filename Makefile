# The README's two commands: `make demo` and `make test`. Both install dependencies first.
PRESET ?= release
JOBS ?= $(shell nproc)
DEMO_CHART ?= examples/chemical_plant/chemical_plant.st
# The paper's checks: every step reachable and re-enterable, T1 safe, T2's valves overlap.
DEMO_ARGS ?= --checks reachable,dead-transitions,reentry --ctl 'AG !(V1 & V3)' --ctl 'AG !(V2 & V4)'

.PHONY: deps build demo test test-asan clean

deps:
	@bash scripts/install-deps.sh

build: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS)

# Only what the demo runs: the sfcv target (not the tests, benchmarks and header checks of
# `make build`), one translation unit per library (the demo preset), so that a fresh clone
# shows its first verdict in about two minutes on 2 cores.
DEMO_PRESET ?= demo
demo: deps
	@cmake --preset $(DEMO_PRESET) >/dev/null
	@cmake --build --preset $(DEMO_PRESET) -j $(JOBS) --target sfcv
	@if [ -f "$(DEMO_CHART)" ]; then \
	  ./build/$(DEMO_PRESET)/sfcv check $(DEMO_CHART) $(DEMO_ARGS); status=$$?; \
	  echo "(sfcv exit code: $$status)"; \
	else \
	  echo "demo: the example chart $(DEMO_CHART) does not exist yet"; \
	  ./build/$(DEMO_PRESET)/sfcv --help; \
	fi

test: build
	@cd build/$(PRESET) && ctest --output-on-failure -j $(JOBS)

# The sanitizer build's tests (AddressSanitizer + UndefinedBehaviorSanitizer).
test-asan:
	@$(MAKE) --no-print-directory test PRESET=asan

clean:
	rm -rf build
