"""Session creation under a race: real processes create sessions of one group on one day in
one sessions folder at the same instant. Every creation succeeds; a name another process
took first is passed over for the next free one (``-2``, ``-3``, ...), never an error."""

from __future__ import annotations

import json
import multiprocessing as mp
from pathlib import Path

WORKERS = 6
EACH = 20


def _worker(root: str, start, results) -> None:
    from minseg_tui.errors import MinsegError
    from minseg_tui.lab.state.session import Session

    start.wait()
    out = []
    for _ in range(EACH):
        try:
            s = Session.create(Path(root), ["Ada", "Bo"], date="2026-11-26")
            out.append(s.folder.name)
            s.close()
        except MinsegError as exc:
            out.append(f"failed: {exc}")
        except Exception as exc:  # anything else is a failure the test reports
            out.append(f"error: {exc!r}")
    results.put(out)


def test_simultaneous_creations_all_get_a_free_name(tmp_path):
    ctx = mp.get_context("spawn")
    start, results = ctx.Barrier(WORKERS), ctx.Queue()
    procs = [
        ctx.Process(target=_worker, args=(str(tmp_path), start, results), daemon=True)
        for _ in range(WORKERS)
    ]
    for p in procs:
        p.start()
    names = [n for _ in procs for n in results.get(timeout=120)]
    for p in procs:
        p.join(30)
    failed = [n for n in names if n.startswith(("failed", "error"))]
    assert failed == []
    assert len(set(names)) == WORKERS * EACH
    base = "2026-11-26-ada-bo"
    assert set(names) == {base} | {f"{base}-{k}" for k in range(2, WORKERS * EACH + 1)}
    for name in names:  # each folder holds its own session, named for its folder
        data = json.loads((tmp_path / name / "session.json").read_text())
        assert data["id"] == name
