# minseg-tui: `make run` and `make test` work on a fresh machine.
# Both create .venv (if needed) and install the package with what it needs.

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
# AVR=0 skips the firmware cross-build (for a laptop without gcc-avr and without root).
AVR    ?= 1

.PHONY: run test lint typecheck pytest snapshot-update firmware firmware-host-test firmware-hex bench clean

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV) || { echo "error: could not create a virtualenv with $(PYTHON) -m venv (Debian: apt-get install python3-venv)"; exit 2; }
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[dev]'
	@touch $(STAMP)

run: $(STAMP)
	$(VENV)/bin/minseg-tui $(ARGS)

lint: $(STAMP)
	$(VENV)/bin/ruff check minseg_tui tests benchmarks
	$(VENV)/bin/ruff format --check minseg_tui tests benchmarks
	$(VENV)/bin/lint-imports
	$(VENV)/bin/mypy

typecheck: $(STAMP)
	$(VENV)/bin/mypy

# The suite in one process by default; PYTEST_WORKERS=2 spreads it over two (pytest-xdist),
# faster on a quiet machine. With a core busy elsewhere, two workers starve the tests that
# run the virtual board in real time (a reply later than the link's 1 s timeout).
PYTEST_WORKERS ?= 0

pytest: $(STAMP)
	$(PY) -m pytest -q -n $(PYTEST_WORKERS) $(PYTEST_ARGS)

# Re-pin the screens after a change meant to alter them; review the SVG diffs before committing.
snapshot-update: $(STAMP)
	$(PY) -m pytest -q tests/ui/test_snapshots.py --snapshot-update

firmware-host-test:
	$(MAKE) -C firmware host-test

# The build of every profile must equal the .hex the package ships (minseg-tui flash writes
# those): a difference fails here with a line per profile and the command that fixes it.
firmware: $(STAMP)
ifeq ($(AVR),0)
	@echo "AVR=0: firmware cross-build for the ATmega2560 not run"
else
	@sh firmware/ensure-toolchain.sh
	$(MAKE) -C firmware all-profiles sim-test-all
	$(PY) -m minseg_tui.device.flashing check firmware/build
endif

# After a change to the firmware: rebuild every profile and ship the new .hex files (commit
# minseg_tui/device/hex/ with the change).
firmware-hex: $(STAMP)
	@sh firmware/ensure-toolchain.sh
	$(MAKE) -C firmware all-profiles
	$(PY) -m minseg_tui.device.flashing refresh firmware/build

test: $(STAMP) lint firmware-host-test firmware pytest

bench: $(STAMP)
	@for b in benchmarks/*.py; do echo "== $$b"; $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache
	-$(MAKE) -C firmware clean
