# minseg-tui: `make run` and `make test` work on a fresh machine.
# Both create .venv (if needed) and install the package with what it needs.

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
# AVR=0 skips the firmware cross-build (for a laptop without gcc-avr and without root).
AVR    ?= 1

# Python may cache the bytecode of the package and the tests (__pycache__/, ignored by git):
# with PYTHONDONTWRITEBYTECODE set, every pytest worker and every command a test starts
# compiled them from source again.
unexport PYTHONDONTWRITEBYTECODE

.PHONY: run test test-stages lint typecheck pytest snapshot-update firmware firmware-sim \
	firmware-host-binary firmware-host-test firmware-hex bench clean test-times

# The virtualenv's own pip (Python 3.11's: 23.x) installs the package as it is (an editable
# install from pyproject.toml needs pip 21.3): it is upgraded first only when older. The
# upgrade on every clean clone cost a round trip to the index and a reinstall of pip (23.6 s
# wall, 1.7 s CPU on the shared machine at load 20) before pytest could start.
$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV) || { echo "error: could not create a virtualenv with $(PYTHON) -m venv (Debian: apt-get install python3-venv)"; exit 2; }
	@$(PY) -c 'import pip, sys; sys.exit(tuple(map(int, pip.__version__.split(".")[:2])) < (21, 3))' \
		|| $(PY) -m pip install -q --disable-pip-version-check --upgrade pip
	$(PY) -m pip install -q --disable-pip-version-check -e '.[dev]'
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

# pytest over two processes (pytest-xdist); PYTEST_WORKERS=0 runs it in one. The tests that
# run the virtual board in real time wait for what they hear, and the link takes a reply for
# missing only once its reader has looked after the timeout: a busy machine makes them
# slower, not red.
# --dist loadgroup hands out tests one by one as -n does, except that the tests of an
# xdist_group run on one worker (tests/firmware: its fixture builds the sanitized binary once).
# The tests' temporary files (pytest's tmp_path: the sessions they save, the logs they write)
# go to a RAM file system where there is one (/dev/shm; TEST_TMPDIR= keeps TMPDIR as it is):
# every save of a session is a real atomic write with its fsyncs, and on a disk each fsync
# waited some 4 ms (tests/ui/test_flow.py and tests/lab/test_session.py: 841 fsyncs and 394
# renames, 4.1 s of waiting on /tmp, 0.05 s on /dev/shm).
PYTEST_WORKERS ?= 2
TEST_TMPDIR ?= $(shell test -d /dev/shm -a -w /dev/shm && echo /dev/shm)

pytest: $(STAMP) firmware-host-binary
	$(if $(TEST_TMPDIR),TMPDIR=$(TEST_TMPDIR) )$(PY) -m pytest -q -n $(PYTEST_WORKERS) --dist loadgroup $(PYTEST_ARGS)

# Where pytest's time goes: pytest as `make test` runs it (PYTEST_ARGS too) with tests/timing.py,
# which prints per worker the time it sat idle at the end, per folder the wall and CPU seconds,
# and the tests that used the most CPU. On a shared machine compare CPU seconds: a test's wall
# time there is mostly waiting for a core.
test-times:
	@$(MAKE) --no-print-directory pytest PYTEST_ARGS="-p tests.timing $(PYTEST_ARGS)"

# Re-pin the screens after a change meant to alter them; review the SVG diffs before committing.
snapshot-update: $(STAMP)
	$(PY) -m pytest -q tests/ui/test_snapshots.py --snapshot-update

firmware-host-test:
	$(MAKE) -C firmware host-test

# The build of every profile must equal the .hex the package ships (minseg-tui flash writes
# those): a difference fails here with a line per profile and the command that fixes it.
# The builds and the simavr runs need no virtualenv (firmware-sim): make test runs them while
# the virtualenv is made, only the comparison with the shipped files waits for it.
firmware: firmware-sim $(STAMP)
ifneq ($(AVR),0)
	$(PY) -m minseg_tui.device.flashing check firmware/build
endif

firmware-sim:
ifeq ($(AVR),0)
	@echo "AVR=0: firmware cross-build for the ATmega2560 not run"
else
	@sh firmware/ensure-toolchain.sh
	$(MAKE) -C firmware all-profiles
	$(MAKE) -C firmware sim-test-all
endif

# The sanitized binary of the firmware's host tests, which tests/firmware runs through `make
# -C firmware host-test` (make builds it only when it is missing or older than a source):
# make test builds it while the virtualenv is made, and pytest's fixture finds it made. A
# failed build is left to that fixture to report (leading -), as it does without this step.
firmware-host-binary:
	-@$(MAKE) --no-print-directory -s -C firmware build/host/test_core

# After a change to the firmware: rebuild every profile and ship the new .hex files (commit
# minseg_tui/device/hex/ with the change).
firmware-hex: $(STAMP)
	@sh firmware/ensure-toolchain.sh
	$(MAKE) -C firmware all-profiles
	$(PY) -m minseg_tui.device.flashing refresh firmware/build

# The stages side by side (make -j, each stage's output printed whole when it ends): pytest
# (the longest, so it starts first), lint, the firmware's AVR builds and simavr runs
# (themselves in parallel as job slots free up). The firmware's host tests run inside
# pytest (tests/firmware runs `make -C firmware host-test` and checks its result): as a stage
# of their own beside it, a clean clone compiled the sanitized test binary twice at once.
# On a clean clone the virtualenv comes first for pytest and lint; the firmware's builds, its
# simavr runs and the host test binary need none and run meanwhile (pip spends about half of
# its time waiting on files and the index).
TEST_JOBS ?= 4

test:
	@$(MAKE) --no-print-directory -j$(TEST_JOBS) -O test-stages

test-stages: pytest lint firmware

bench: $(STAMP)
	@for b in benchmarks/*.py; do echo "== $$b"; $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache
	-$(MAKE) -C firmware clean
