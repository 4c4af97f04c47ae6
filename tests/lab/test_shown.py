"""Issue 20, item 1 and the report's "shown to the group": the session records, the moment it
happens, when each computed value of Tasks 11-15 was first on the group's screen (and by what:
Tasks 11-15 after the answer, a lab assistant's reveal, the lab's policy, the model check) and
the lab's policy in force (at opening, and each change). Real session folders and files."""

from __future__ import annotations

import json
import shutil
from datetime import UTC, datetime
from pathlib import Path

from minseg_tui.lab.state import shown as lab_shown
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as views
from minseg_tui.report.write import write_report
from tests.lab.test_compare import _lab

OLD = Path(__file__).parent / "old_sessions" / "schema1"


def _file(folder: Path) -> dict:
    return json.loads((folder / "session.json").read_text(encoding="utf-8"))


def test_the_model_check_opened_before_answering_is_recorded_on_disk_at_once(tmp_path):
    """The report said "after the group answered" of T once T was typed, though the model
    check, which writes the fitted T and K, may have been on the screen before."""
    with _lab(tmp_path) as s:
        modified = _file(s.folder)["modified"]
        check = views.check(s.snapshot())  # as the lab screen builds it, in a worker
        assert check.shows == {"own.K", "own.T", "own.model"}
        assert sorted(views.note_drawn(s, check)) == ["own.K", "own.T", "own.model"]
        on_disk = _file(s.folder)  # saved at once: a crash now keeps it
        assert on_disk["shown"]["own.T"]["by"] == lab_shown.MODEL_CHECK
        assert on_disk["shown"]["own.T"]["answer"] is None
        assert on_disk["modified"] == modified  # a record, not a change of the group's
        s.enter("own.T", "57 ms")
        assert views.note_drawn(s, views.results(s.snapshot(), "task12")) == []
        # the first showing stays the one recorded: T was revealed before the answer
        assert s.shown()["own.T"] == lab_shown.Shown(
            on_disk["shown"]["own.T"]["at"], lab_shown.MODEL_CHECK, None
        )
    with Session.open(s.folder) as again:
        assert again.shown()["own.T"].by == lab_shown.MODEL_CHECK


def test_results_drawn_after_the_answer_record_the_answer_then(tmp_path):
    with _lab(tmp_path) as s:
        view = views.results(s.snapshot(), "task12")
        assert "own.T" not in view.shows  # hidden: nothing to record
        assert views.note_drawn(s, view) == []
        s.enter("own.T", "57 ms")
        view = views.results(s.snapshot(), "task12")
        assert views.note_drawn(s, view) == ["own.T"]
        assert s.shown()["own.T"].by == lab_shown.AFTER_ANSWER
        assert s.shown()["own.T"].answer == "57 ms"
        assert views.note_drawn(s, view) == []  # the first time only
        s.enter("own.T", "56 ms")
        assert s.shown()["own.T"].answer == "57 ms"


def test_a_reveal_is_recorded_as_a_showing_before_the_answer(tmp_path):
    with _lab(tmp_path) as s:
        assert s.reveal("task13") == ["own.J"]
        got = _file(s.folder)["shown"]["own.J"]
        assert (got["by"], got["answer"]) == (lab_shown.REVEAL, None)


def test_the_lab_policy_shows_values_at_once_and_is_recorded(tmp_path):
    (tmp_path / "lab.toml").write_text("answers_first = false\n", encoding="utf-8")
    with _lab(tmp_path) as s:
        (first,) = s.policies()
        assert (first.answers_first, first.file) == (False, True)
        views.note_drawn(s, views.results(s.snapshot(), "task11"))
        assert {k: v.by for k, v in s.shown().items()} == dict.fromkeys(
            ("own.omega_step", "own.K", "own.T", "own.J", "own.model", "own.omega_5"),
            lab_shown.POLICY,
        )


def test_a_change_of_the_policy_while_the_session_is_open_is_recorded(tmp_path):
    with _lab(tmp_path) as s:
        (first,) = s.policies()
        assert first.answers_first and not first.file
        assert s.note_policy().answers_first
        assert len(s.policies()) == 1  # unchanged: nothing new
        (tmp_path / "lab.toml").write_text("answers_first = false\n", encoding="utf-8")
        views.note_drawn(s, views.results(s.snapshot(), "task11"))  # the next view drawn
        assert [p.answers_first for p in s.policies()] == [True, False]
        assert [p["answers_first"] for p in _file(s.folder)["policy"]] == [True, False]


def test_a_read_only_session_and_a_snapshot_record_nothing(tmp_path):
    with _lab(tmp_path) as s:
        s.enter("own.T", "57 ms")
        snap = s.snapshot()
        assert views.note_drawn(snap, views.results(snap, "task12")) == []
        folder = s.folder
    before = (folder / "session.json").read_bytes()
    with Session.open(folder, readonly=True) as ro:
        assert views.note_drawn(ro, views.results(ro, "task12")) == []
    assert (folder / "session.json").read_bytes() == before


def _later() -> datetime:
    """A clock years after the old session was written."""
    return datetime(2030, 1, 2, 3, 4, 5, tzinfo=UTC)


def test_an_old_session_records_from_its_first_opening_on(tmp_path):
    folder = tmp_path / "schema1"
    shutil.copytree(OLD, folder)
    with Session.open(folder, readonly=True) as ro:
        assert ro.shown_since is None and ro.policies() == [] and ro.shown() == {}
    with Session.open(folder, clock=_later) as s:
        assert s.shown_since == "2030-01-02T03:04:05+00:00" > s.created
        (p,) = s.policies()
        assert p.at == s.shown_since
    data = _file(folder)
    assert data["shown_since"] == "2030-01-02T03:04:05+00:00" and data["shown"] == {}


def test_task10_showing_its_T_readings_is_recorded_once_they_are_shown(tmp_path):
    with _lab(tmp_path) as s:
        runs = views.runs(s.snapshot())
        assert runs and all(v.T_hidden for v in runs)
        assert views.note_drawn(s, runs) == []  # T hidden: nothing shown
        s.enter("own.T", "57 ms")
        runs = views.runs(s.snapshot())
        assert any(v.T_ls is not None for v in runs)
        assert views.note_drawn(s, runs) == ["own.T"]
        assert (s.shown()["own.T"].by, s.shown()["own.T"].answer) == ("answer", "57 ms")


def test_a_broken_record_of_what_was_shown_is_named_and_left_out(tmp_path):
    with _lab(tmp_path) as s:
        folder = s.folder
    data = _file(folder)
    data["shown"] = {"own.T": {"at": 5, "by": "answer"}}
    data["policy"] = "answers first"
    (folder / "session.json").write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder, readonly=True) as ro:
        assert ro.damaged is not None
        assert "shown.own.T.at: expected text" in ro.damaged and "(and 1 more)" in ro.damaged
        assert ro.shown() == {} and ro.policies() == []
    # the report claims neither "not shown" nor an older program of it
    md = write_report_of(folder)
    (row,) = [ln for ln in md.splitlines() if ln.startswith("| T (Task 12)")]
    assert row.endswith(f"| {own_first.DAMAGED} |"), row
    assert "is not known: the session file is damaged" in md


def write_report_of(folder: Path) -> str:
    with Session.open(folder, readonly=True) as ro:
        return write_report(ro).markdown.read_text(encoding="utf-8")
