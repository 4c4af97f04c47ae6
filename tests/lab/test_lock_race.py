"""The session lock under a race: 8 real processes open the same session at the same instant.

Each trial, 8 worker processes wait at a barrier, then all call ``Session.open`` on one
session folder; each says whether it got the session, and only after all 8 have tried
does the winner close it. Exactly one may win, every time: with no lock file, and with a
stale lock file left by a dead process. (The pid-file lock this replaced let two in, in
about 1 of 30 trials without a stale lock and 1 of 6 with one.)
"""

from __future__ import annotations

import multiprocessing as mp
import subprocess
import sys
from pathlib import Path

import pytest

from minseg_tui.lab.state.session import Session

WORKERS = 8
TRIALS = 300


def _worker(tasks, results, start, tried) -> None:
    from minseg_tui.errors import MinsegError
    from minseg_tui.lab.state.session import Session

    while True:
        folder = tasks.get()
        if folder is None:
            return
        start.wait()
        session = None
        try:
            session = Session.open(Path(folder))
            outcome = "won"
        except MinsegError as exc:
            outcome = f"lost {type(exc).__name__}"
        except Exception as exc:  # anything else is a failure the test reports
            outcome = f"error {exc!r}"
        tried.wait()  # the winner keeps the session until every worker has tried
        if session is not None:
            try:
                session.close()
            except Exception as exc:
                outcome = f"error on close {exc!r}"
        results.put(outcome)


@pytest.fixture(scope="module")
def workers():
    ctx = mp.get_context("spawn")
    tasks = [ctx.Queue() for _ in range(WORKERS)]
    results = ctx.Queue()
    start, tried = ctx.Barrier(WORKERS), ctx.Barrier(WORKERS)
    procs = [
        ctx.Process(target=_worker, args=(q, results, start, tried), daemon=True) for q in tasks
    ]
    for p in procs:
        p.start()

    def trial(folder: Path) -> list[str]:
        for q in tasks:
            q.put(str(folder))
        return sorted(results.get(timeout=60) for _ in range(WORKERS))

    yield trial
    for q in tasks:
        q.put(None)
    for p in procs:
        p.join(10)
        if p.is_alive():
            p.kill()


def _dead_pid() -> str:
    done = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    )
    return done.stdout.strip()


@pytest.mark.parametrize("stale", [False, True], ids=["no-lock-file", "stale-lock-file"])
def test_exactly_one_of_8_simultaneous_openers_gets_the_session(tmp_path, workers, stale):
    s = Session.create(tmp_path, ["A"])
    s.close()
    dead = _dead_pid()
    outcomes: dict[str, int] = {}
    bad = []
    for k in range(TRIALS):
        if stale:
            (s.folder / "lock").write_text(f"{dead}\n")
        got = workers(s.folder)
        for o in got:
            outcomes[o] = outcomes.get(o, 0) + 1
        if got.count("won") != 1 or any(o.startswith("error") for o in got):
            bad.append((k, got))
    print(f"{TRIALS} trials x {WORKERS} processes, stale={stale}: {outcomes}")
    assert not bad, f"{len(bad)} of {TRIALS} trials without exactly one winner: {bad[:3]}"
