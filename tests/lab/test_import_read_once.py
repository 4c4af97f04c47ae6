"""After an import the model check parsed the log again, and its view a third time (the u of
the close-up): stop 38's "left". The import's read is held as the copy reads, so the check
and its view parse nothing; a copy changed on disk since is read again; and what is held is
what the copy reads (the same check as a session opened afresh computes)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from minseg_tui.lab.saving import runs
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.model.plant import Plant, PlantParams


def _log(path, seconds: float = 6.0) -> None:
    """The seeded plant on Task 10's square wave at 25 ms, with an older import's line."""
    plant = Plant(PlantParams(), seed=3)
    rows = ["# imported_from: /bench/older.csv", "t,u,omega,count"]
    last = 0
    for k in range(int(seconds / 0.025)):
        u = 4.5 if (k // 60) % 2 == 0 else 0.0
        plant.set_command(u)
        plant.advance(0.025)
        c = plant.count
        omega = (c - last) * 2 * np.pi / 720 / 0.025
        last = c
        rows.append(f"{k * 0.025:.3f},{u:.2f},{omega:.6f},{c}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


@pytest.fixture
def parses(monkeypatch):
    """The paths the run logs were parsed from, in order (read_run_log as runs.py calls it)."""
    got: list[str] = []
    real = runs.read_run_log

    def counted(path, *args, **kwargs):
        got.append(str(path))
        return real(path, *args, **kwargs)

    monkeypatch.setattr(runs, "read_run_log", counted)
    return got


def test_the_check_after_an_import_parses_nothing_again(tmp_path, parses):
    src = tmp_path / "log.csv"
    _log(src)
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        assert parses == [str(src)]  # the import's own read
        view = views.check(s.snapshot())
        assert view.problem == "" and view.cause is not None
        log = s.load_run(info.name)
        assert parses == [str(src)]  # neither the check, its view nor a load parsed it
        assert log.metadata["imported_from"] == str(src)
        assert log.metadata["earlier_imported_from"] == "/bench/older.csv"
        copy = s.folder / info.file
        fresh = runs.read_run_log(copy)  # what the copy reads, parsed
        assert fresh.metadata == log.metadata and fresh.source == log.source
        assert np.array_equal(fresh.lines, log.lines)
        for name in fresh.columns:
            assert np.array_equal(fresh.column(name), log.column(name))
        folder = s.folder
    with Session.open(folder) as again:  # the same check from the file, parsed afresh
        _same(views.check(again.snapshot()), view)


def _same(a: object, b: object) -> None:
    """Two check views field by field (their arrays value by value)."""
    for f in dataclasses.fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            assert np.array_equal(x, y), f.name
        else:
            assert x == y, f.name


def test_a_copy_changed_on_disk_is_read_again(tmp_path, parses):
    src = tmp_path / "log.csv"
    _log(src)
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        copy = s.folder / info.file
        text = copy.read_text(encoding="utf-8")
        copy.write_text(text.replace("# imported_from:", "# note: x\n# imported_from:", 1))
        log = s.load_run(info.name)
        assert parses == [str(src), str(copy)]
        assert log.metadata["note"] == "x" and log.line_of(0) == fresh_line(copy)


def fresh_line(path) -> int | None:
    return runs.read_run_log(path).line_of(0)
