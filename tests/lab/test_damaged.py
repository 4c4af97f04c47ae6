"""Damaged session files: the whole file is checked against one schema; a damaged session is
listed as damaged with the reason, opened read-only where possible, never written over, and
one bad session never hides the others."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.lab.saving.store import SessionDamaged, list_sessions
from minseg_tui.lab.state.session import Session


def _good_session(root):
    """A closed session with entries, a capture and a run; its folder."""
    s = Session.create(root, ["Ada"], date="2026-11-22")
    s.enter("R", "5.2")
    s.enter("R", "5.2 kg")  # a refused attempt kept beside the accepted value
    s.enter("u_ss@2.5", "2.05")
    t = np.arange(100) * 0.025
    s.capture_omega(2.5, t, 3.8 + 0.01 * np.sin(t))
    rec = s.start_run("free", ts=0.025)
    for k in range(20):
        rec.append(k, 25000 * k, 3 * k, 2000)
    s.finish_run(rec)
    s.close()
    return s.folder


def _set(data, path, value):
    node = data
    *head, last = path
    for p in head:
        node = node[p]
    node[last] = value


_CHOICE_AS_NUMBER = {"text": "b", "ok": True, "value": 1.0}
_CHOICE_BEYOND = {"text": "b", "ok": True, "value": [1, 40]}

WRONG = {
    "history is a number": (("entries", "R", "history"), 5, "entries.R.history"),
    "refused holds a number": (("entries", "R", "refused"), [1], "entries.R.refused"),
    "warnings is a number": (("entries", "R", "warnings"), 7, "entries.R.warnings"),
    "value is text": (("entries", "R", "value"), "5.2", "entries.R.value"),
    "text is a number": (("entries", "R", "text"), 5, "entries.R.text"),
    "a capture is a number": (("captures", "omega_ss@2.5"), 3, "captures.omega_ss@2.5"),
    "a run's ts is text": (("runs", 0, "ts"), "abc", "runs[0].ts"),
    "a run's ts is null": (("runs", 0, "ts"), None, "runs[0].ts"),
    "a run's plan is text": (("runs", 0, "plan"), "fast", "runs[0].plan"),
    "a run's samples is text": (("runs", 0, "samples"), "20", "runs[0].samples"),
    "a run's file leaves the folder": (("runs", 0, "file"), "../../x.csv", "runs[0].file"),
    "members is text": (("members",), "Ada", "members"),
    "selected_run is a number": (("selected_run",), 5, "selected_run"),
    "a value is NaN": (("entries", "R", "value"), float("nan"), "entries.R.value"),
    # issue 18: a long whole number was an OverflowError that kept the TUI from starting
    "a value of 401 digits": (("entries", "R", "value"), 10**400, "entries.R.value"),
    "a capture of 401 digits": (("captures", "omega_ss@2.5", "omega_ss"), -(10**400), "captures"),
    "a run's samples beyond any count": (("runs", 0, "samples"), 2**64, "runs[0].samples"),
    # one verdict: what the listing calls sound, report and the TUI read as sound
    "a quantity's value is a list": (("entries", "R", "value"), [1, 2], "entries.R.value"),
    "a choice's value is a number": (("entries", "summary.1"), _CHOICE_AS_NUMBER, "summary.1"),
    "a choice beyond its options": (("entries", "summary.1"), _CHOICE_BEYOND, "summary.1"),
    "an unknown step": (("current_step",), "task99", "current_step"),
}


@pytest.mark.parametrize("case", list(WRONG))
def test_a_wrong_type_anywhere_is_damage(tmp_path, capsys, case):
    path_in_file, value, where = WRONG[case]
    root = tmp_path / "sessions"
    folder = _good_session(root)
    other = Session.create(root, ["Bo"], date="2026-11-23")
    other.close()
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    _set(data, path_in_file, value)
    path.write_text(json.dumps(data), encoding="utf-8")
    content = path.read_bytes()

    with pytest.raises(SessionDamaged) as info:
        Session.open(folder)
    msg = str(info.value)
    assert where in msg and "left untouched" in msg and "\n" not in msg
    assert not (folder / "lock").exists()

    listed = {s.path: s for s in list_sessions(root)}
    assert where in listed[folder].damaged
    assert listed[other.folder].damaged is None  # one bad session hides no other

    assert main(["report", str(folder)]) == 2
    err = capsys.readouterr().err
    assert where in err and err.count("\n") == 1

    # read-only, what can be read is there, and says what is not
    with Session.open(folder, readonly=True) as ro:
        assert ro.damaged and where in ro.damaged
        assert ro.members in (("Ada",), ())
        ro.results()
        ro.table()
        ro.model_check()
    assert path.read_bytes() == content  # never written over


def test_a_number_too_long_to_read_is_damage_and_hides_nothing(tmp_path, capsys):
    """5000 digits: Python refuses to read it (ValueError), which stopped the TUI and report."""
    root = tmp_path / "sessions"
    folder = _good_session(root)
    other = Session.create(root, ["Bo"], date="2026-11-23")
    other.close()
    path = folder / "session.json"
    path.write_text(
        path.read_text(encoding="utf-8").replace(
            '"schema": 1,', '"schema": 1, "x": ' + "9" * 5000 + ","
        ),
        encoding="utf-8",
    )
    with pytest.raises(SessionDamaged, match="number too long"):
        Session.open(folder)
    listed = {s.path: s for s in list_sessions(root)}
    assert "number too long" in listed[folder].damaged
    assert listed[other.folder].damaged is None
    assert main(["report", str(folder)]) == 2
    err = capsys.readouterr().err
    assert "number too long" in err and err.count("\n") == 1


def test_nested_brackets_do_not_hide_the_other_sessions(tmp_path):
    root = tmp_path / "sessions"
    good = Session.create(root, ["Ada"])
    good.close()
    deep = root / "deep"
    deep.mkdir()
    (deep / "session.json").write_text("[" * 100_000 + "]" * 100_000)
    listed = {s.path.name: s for s in list_sessions(root)}
    assert "nested too deeply" in listed["deep"].damaged
    assert listed[good.folder.name].damaged is None
    with pytest.raises(SessionDamaged, match="nested too deeply"):
        Session.open(deep)


def test_an_unreadable_session_is_listed_not_raised(tmp_path):
    root = tmp_path / "sessions"
    good = Session.create(root, ["Ada"])
    good.close()
    (root / "not-a-session.json").mkdir()  # a folder without a session.json: not listed
    (root / "odd").mkdir()
    (root / "odd" / "session.json").mkdir()  # a folder where the file should be
    listed = {s.path.name: s for s in list_sessions(root)}
    assert listed[good.folder.name].damaged is None
    assert "cannot be read" in listed["odd"].damaged
    assert "not-a-session.json" not in listed


@pytest.mark.parametrize(
    "header",
    [
        '# {"ts": "abc", "kind": "steps"}',
        '# {"plan": 5}',
        "# [1, 2]",
        "# {not json",
        '# {"ts": -1}',
        "# " + "[" * 50_000,
    ],
    ids=["ts-text", "plan-number", "a-list", "not-json", "ts-negative", "deep-brackets"],
)
def test_a_damaged_partial_header_never_keeps_a_session_shut(tmp_path, header):
    s = Session.create(tmp_path, ["A"])
    rec = s.start_run("steps", ts=0.025, flush_interval=0.0)
    for k in range(10):
        rec.append(k, 1000 + 25000 * k, 3 * k, 2500)
    rec.close()
    s.close()
    lines = rec.path.read_text().splitlines()
    rec.path.write_text("\n".join([header, *lines[1:]]) + "\n")
    with Session.open(s.folder) as again:  # the run is rebuilt from its samples
        (info,) = again.runs
        assert info.interrupted and info.samples == 10 and info.ts == pytest.approx(0.025)
        assert any("header" in n for n in again.recovery_notes)
        assert list(again.load_run(info.name).extra["count"]) == [3 * k for k in range(10)]


def test_a_session_file_that_is_a_fifo_is_listed_not_waited_on(tmp_path):
    """A FIFO where session.json should be: opening it would wait for a writer for ever, and
    the start screen's list with it."""
    root = tmp_path / "sessions"
    good = Session.create(root, ["Ada"])
    good.close()
    (root / "pipe").mkdir()
    os.mkfifo(root / "pipe" / "session.json")
    listed = {s.path.name: s for s in list_sessions(root)}
    assert "not a regular file" in listed["pipe"].damaged
    assert listed[good.folder.name].damaged is None
    with pytest.raises(SessionDamaged, match="not a regular file"):
        Session.open(root / "pipe")


def _session_with_partial(tmp_path):
    s = Session.create(tmp_path, ["A"])
    s.close()
    return s.folder


def test_a_partial_that_is_a_fifo_does_not_keep_the_session_shut(tmp_path):
    folder = _session_with_partial(tmp_path)
    os.mkfifo(folder / "runs" / "steps-1.partial")
    with Session.open(folder) as again:  # returns instead of waiting for a writer
        assert again.runs == []
        assert any(
            "steps-1.partial" in n and "not a regular file" in n for n in again.recovery_notes
        )


def test_a_partial_with_numbers_no_board_sends_keeps_the_sound_rows(tmp_path):
    folder = _session_with_partial(tmp_path)
    rows = [f"{k},{1000 + 25000 * k},{3 * k},2500" for k in range(10)]
    rows[4] = "4,101000,99999999999999999999999,2500"  # beyond int64: OverflowError before
    rows[5] = "5,99999999999,15,2500"  # t_us beyond uint32
    header = '# {"kind": "steps", "ts": 0.025}\nseq,t_us,count,u_mV'
    (folder / "runs" / "steps-1.partial").write_text("\n".join([header, *rows]) + "\n")
    with Session.open(folder) as again:
        (info,) = again.runs
        assert info.samples == 8
        assert list(again.load_run(info.name).extra["count"]) == [
            3 * k for k in range(10) if k not in (4, 5)
        ]


def test_a_partial_whose_name_is_no_run_name_is_left_and_the_file_stays_sound(tmp_path):
    """``..partial`` would become a run named '.', which the schema refuses: the session
    file the program wrote itself would then open as damaged."""
    folder = _session_with_partial(tmp_path)
    rows = [f"{k},{1000 + 25000 * k},{3 * k},2500" for k in range(10)]
    (folder / "runs" / "..partial").write_text("\n".join(["# {}", *rows]) + "\n")
    with Session.open(folder) as again:
        assert again.runs == []
        assert any("..partial" in n for n in again.recovery_notes)
    with Session.open(folder) as third:  # still sound
        assert third.runs == []
    assert (folder / "runs" / "..partial").exists()  # left as it was
