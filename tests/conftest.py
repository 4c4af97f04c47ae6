"""Tests that read ../shared/data carry the ``shared_data`` mark. Where that folder is absent
they are not run and the session ends with one line saying so; with CI=true they fail."""

import atexit
import gc
import hashlib
import os
import pickle
import shutil
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import minseg_tui.lab.state.results as lab_results
from minseg_tui.model.check import CheckResult
from minseg_tui.model.identify import Identification
from tests.shared_data import absent_reason, required
from tests.ui.textual_internals import parse_stylesheets_once

GC_THRESHOLDS = (50_000, 20, 20)
"""The cyclic garbage collector's thresholds in a test process (Python's are 700, 10, 10). A
UI test makes and drops many small objects (Textual's styles, messages, segments): at 700 the
collector ran some 50 times a test and took 16 % of tests/ui/test_flow.py's CPU. Garbage
is still collected, in fewer and larger rounds; a test that needs it gone calls
``gc.collect()`` itself (tests/test_lock.py).

Measured at stop 38 (gc.callbacks, the collecting thread's CPU; test_flow, test_walk7_answers,
test_step_keys and test_snapshots, 57 tests): the collector still takes about 11 % of their
CPU, and that is the freeing of the apps the tests drop (a pass of about 100 ms frees some
40,000 objects), not the walk of live ones. Neither a gen-0 threshold of 200,000 (2.3 s of
2.7) nor ``gc.freeze()`` after the first test's end cuts it; a ``gc.collect()`` after every
test costs 2 s more, and no collector at all saves those 2.7 s for 2.3 times the memory."""


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "shared_data: reads ../shared/data (real motor logs)")
    gc.set_threshold(*GC_THRESHOLDS)
    _own_port_locks()


def _own_port_locks() -> None:
    """Each test process (each pytest-xdist worker, and the programs its tests start) keeps
    the lock files of the ports it opens in a folder of its own (``XDG_RUNTIME_DIR``, which
    :func:`minseg_tui.device.port.lock_path` reads). A port's lock is named after its path,
    and the pseudo-terminals the tests open as boards are numbered by the system: a lock on
    /dev/pts/0 still held on one worker made a new board of the other worker, given
    /dev/pts/0 again, 'in use by minseg-tui (pid N)' (once, in a full run with one core busy
    at stop 39). Within one worker the locks work as on a lab PC, and the tests of them see
    them."""
    folder = tempfile.mkdtemp(prefix="minseg-tui-locks-")
    os.environ["XDG_RUNTIME_DIR"] = folder
    atexit.register(shutil.rmtree, folder, ignore_errors=True)


def pytest_collection_finish(session: pytest.Session) -> None:
    """What exists once the tests are collected (the modules, their functions and
    parameters: most of the objects of a test process) is left out of every later
    collection, which then walks only what the tests themselves make."""
    gc.collect()
    gc.freeze()


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The ``slow`` tests first (in their order; the rest keep theirs): under pytest-xdist
    each starts on a worker at once instead of ending the run on one worker alone."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)


def pytest_runtest_setup(item: pytest.Item) -> None:
    if item.get_closest_marker("shared_data") is None:
        return
    reason = absent_reason()
    if reason is None:
        return
    if required():
        pytest.fail(f"CI=true and {reason.removeprefix('not run: ')}", pytrace=False)
    pytest.skip(reason)


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    # counted from the reports, which also come back from pytest-xdist's workers
    not_run = [
        r
        for r in terminalreporter.stats.get("skipped", [])
        if "is not beside this clone" in str(getattr(r, "longrepr", ""))
    ]
    if not_run:
        terminalreporter.write_line(
            f"{len(not_run)} tests that read ../shared/data were not run: "
            "it is not beside this clone (CI always has it)"
        )


_checked: dict[bytes, CheckResult] = {}
_checked_lock = threading.Lock()
_check = lab_results.check
_checked_dir: list[Path] = []
"""The folder (one per test process, under pytest's temporary files) where a check computed
in a process the test process forked (the class view's pool: classread.build) is kept for
the test process and its later forks; set by :func:`model_check_once_per_log`."""


def _key(t: object, u: object, omega: object, *rest: object) -> bytes:
    """The inputs of one model check, as bytes: the three columns' exact values and the rest."""
    h = hashlib.sha256()
    for col in (t, u, omega):
        a = np.ascontiguousarray(np.asarray(col, dtype=float))
        h.update(repr(a.shape).encode())
        h.update(a.tobytes())
    h.update(repr(rest).encode())
    return h.digest()


def _kept(key: bytes) -> object:
    """The result kept in :data:`_checked_dir` under ``key`` by a forked process, or None."""
    if not _checked_dir:
        return None
    try:
        return pickle.loads((_checked_dir[0] / key.hex()).read_bytes())
    except FileNotFoundError:
        return None


def _keep(key: bytes, result: object) -> None:
    """Keep ``result`` under ``key`` for the test process (written whole, then renamed)."""
    if not _checked_dir:
        return
    path = _checked_dir[0] / key.hex()
    tmp = path.with_name(f".{path.name}.{os.getpid()}")
    tmp.write_bytes(pickle.dumps(result, protocol=pickle.HIGHEST_PROTOCOL))
    os.replace(tmp, path)


def checked_once(
    t: object,
    u: object,
    omega: object,
    ts: float | None = None,
    cpr: int | None = None,
    omega_over: str | None = None,
) -> CheckResult:
    """The model check as the lab runs it (lab.state.results.check_run), computed once per
    test process for each log: many tests build the same seeded run (tests.seeded, the
    UI's recorded run) and read its check through a session, a report, the class view or a
    screen. The check is deterministic (no clock, no unseeded randomness) and its result a
    frozen record, so the second reading is the first one's result; the check itself is
    tested on its own logs in tests/model, which call it directly.

    The class view computes its rows in processes it forks (classread.build), which begin
    with the test process's checks but whose own end with them: those are kept in a file
    (:data:`_checked_dir`), which the test process and its later forks read, so each of
    test_class_cli's cold readings of the same seeded class does not check its eight
    groups again."""
    key = _key(t, u, omega, ts, cpr, omega_over)
    with _checked_lock:
        hit = _checked.get(key)
    if hit is None:
        got = _kept(key)
        hit = got if isinstance(got, CheckResult) else None
    if hit is not None:
        return hit
    result = _check(t, u, omega, ts=ts, cpr=cpr, omega_over=omega_over)
    with _checked_lock:
        _checked.setdefault(key, result)
    _keep(key, result)
    return result


_identified: dict[bytes, Identification] = {}
_identify = lab_results.identify


def identified_once(*args: object, **kwargs: object) -> Identification:
    """identify() as the lab runs it (lab.state.results: the table's readings, R, the run's
    log), computed once per test process and the processes it forks for each input, as
    :func:`checked_once` does for the check: identify is deterministic and its inputs
    (readings, numbers, a RunLog of arrays) and result are plain records, so equal pickles
    of the inputs are equal inputs. identify itself is tested in tests/model, which call it
    directly."""
    key = hashlib.sha256(
        pickle.dumps((args, sorted(kwargs.items())), protocol=pickle.HIGHEST_PROTOCOL)
    ).digest()
    with _checked_lock:
        hit = _identified.get(key)
    if hit is None:
        got = _kept(b"identify" + key)
        hit = got if isinstance(got, Identification) else None
    if hit is not None:
        return hit
    result = _identify(*args, **kwargs)
    with _checked_lock:
        _identified.setdefault(key, result)
    _keep(b"identify" + key, result)
    return result


@pytest.fixture(autouse=True, scope="session")
def model_check_once_per_log(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """The lab's model check of a run log, and its identify of a table and a log, run once
    per input in a test process and the processes it forks (:func:`checked_once`,
    :func:`identified_once`)."""
    _checked_dir.append(tmp_path_factory.mktemp("checked-once"))
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(lab_results, "check", checked_once)
        mp.setattr(lab_results, "identify", identified_once)
        yield
    _checked_dir.clear()


@pytest.fixture(autouse=True, scope="session")
def stylesheets_parsed_once() -> Iterator[None]:
    """Each CSS source of the apps the tests run (the app's lab.tcss, every widget's default
    CSS) is parsed once per test process for each theme, not again for every App and every
    screen (``textual_internals.parse_stylesheets_once``): an app's start, its start screen and
    a step change made 1.16 million Python calls, 6 % of them parsing CSS it had parsed for
    the test before."""
    with pytest.MonkeyPatch.context() as mp:
        parse_stylesheets_once(mp)
        yield
