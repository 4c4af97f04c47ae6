"""A run's file changed after it was written (s38 attack, left by stop 37): the report said a
row deleted by hand, the class view and the lab's Tasks 11-15 said nothing, and an edit that
kept the number of rows was seen by none. Now each run records the SHA-256 of its file as
written (session.json, ``runs[].sha256``), and one rule (runs.changed_file, through
Session.run_changed) gives the one line the three say; a session of an older program, which
kept no checksum, still opens and says its runs cannot be checked.

Real session folders (tests/classview/build.py: the seeded plant's recorded run), the real
report CLI, the class view's row and the lab's view of Task 12."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.classview import read_group
from tests.classview.build import group


@pytest.fixture(autouse=True)
def _own_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))


def _said_by_all(folder: Path) -> tuple[list[str], list[str], list[str], str]:
    """What the class row (flags, notes), Task 12 and the report say of the runs' files."""
    row = read_group(folder)
    with Session.open(folder, readonly=True) as s:
        lab = [p for p in views.results(s, "task12").problems if "its file runs/" in p]
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8")
    return list(row.flags), list(row.notes), lab, report


def _one_value_changed(path: Path) -> None:
    """omega of one data row changed by 5 rad/s: as many rows as before."""
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    k = next(i for i, line in enumerate(lines) if line[:1].isdigit()) + 40
    parts = lines[k].split(",")
    parts[2] = f"{float(parts[2]) + 5.0:.9g}"
    lines[k] = ",".join(parts)
    path.write_text("".join(lines), encoding="utf-8")


def test_a_recorded_run_keeps_the_checksum_of_its_file(tmp_path):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    (run,) = json.loads((folder / "session.json").read_text(encoding="utf-8"))["runs"]
    data = (folder / run["file"]).read_bytes()
    assert run["sha256"] == hashlib.sha256(data).hexdigest()
    flags, notes, lab, report = _said_by_all(folder)
    assert not [f for f in flags if "runs/" in f] and not notes and not lab
    assert "its file runs/" not in report


def test_an_edit_that_keeps_the_rows_is_said_by_all_three(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    _one_value_changed(folder / "runs" / "steps-1.csv")
    flags, notes, lab, report = _said_by_all(folder)
    line = (
        "run steps-1: its file runs/steps-1.csv was changed after the recording (edited by "
        "hand?): it holds the 500 samples recorded, but not the bytes written; what is "
        "computed from it uses the file as it is now"
    )
    assert line in flags  # counted: the class view's '!'
    assert lab == [line]
    assert "R" + line[1:] + "." in report


def test_a_row_deleted_is_said_by_all_three(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    path = folder / "runs" / "steps-1.csv"
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    del lines[30]
    path.write_text("".join(lines), encoding="utf-8")
    flags, _, lab, report = _said_by_all(folder)
    line = (
        "run steps-1: its file runs/steps-1.csv was changed after the recording (edited by "
        "hand?): it holds 499 samples where 500 were recorded; what is computed from it uses "
        "the file as it is now"
    )
    assert line in flags and lab == [line] and "R" + line[1:] + "." in report


def _older(folder: Path) -> None:
    """session.json as an older program wrote it: no checksum of its runs."""
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    for r in data["runs"]:
        del r["sha256"]
    path.write_text(json.dumps(data), encoding="utf-8")


def test_an_older_session_opens_and_says_its_run_cannot_be_checked(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    _older(folder)
    _one_value_changed(folder / "runs" / "steps-1.csv")  # cannot be seen without a checksum
    flags, notes, lab, report = _said_by_all(folder)
    line = (
        "run steps-1: its file runs/steps-1.csv cannot be checked for edits by hand (an older "
        "minseg-tui wrote it and kept no checksum of it)"
    )
    assert notes == [line] and not [f for f in flags if "runs/" in f]  # a note, not counted
    assert lab == [line] and "R" + line[1:] + "." in report
    with Session.open(folder) as s:  # opens for work, and keeps no checksum it never had
        s.enter("R", "5.3")
    (run,) = json.loads((folder / "session.json").read_text(encoding="utf-8"))["runs"]
    assert "sha256" not in run


def test_an_older_session_with_a_row_deleted_is_said_edited(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    _older(folder)
    path = folder / "runs" / "steps-1.csv"
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    del lines[30]
    path.write_text("".join(lines), encoding="utf-8")
    flags, _, lab, _ = _said_by_all(folder)
    assert any("holds 499 samples where 500 were recorded" in f for f in flags)
    assert lab and "holds 499 samples where 500 were recorded" in lab[0]


def test_an_imported_log_keeps_the_checksum_of_its_copy(tmp_path):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    with Session.open(folder) as s:
        info = s.import_run(folder / "runs" / "steps-1.csv")
        assert info.sha256 == hashlib.sha256((folder / info.file).read_bytes()).hexdigest()
        assert s.run_changed(info.name) is None
        _one_value_changed(folder / info.file)
        changed = s.run_changed(info.name)
        assert changed is not None and changed.edited
