"""A frozen snapshot of a session, as the UI's workers get it: it reads as the session did
when it was taken, whatever the session does after, and it changes nothing."""

from __future__ import annotations

import json

import pytest

from minseg_tui.lab.state.session import Session, SessionFrozen
from minseg_tui.lab.views import session as views
from tests.lab.test_session import _fill_table, _record_steps


def test_a_snapshot_reads_as_the_session_did_and_changes_nothing(tmp_path):
    with Session.create(tmp_path, ["A"], date="2026-11-22") as s:
        _fill_table(s)
        s.enter("R", "5.26")
        info, _, _ = _record_steps(s)
        snap = s.snapshot()
        before = (s.folder / "session.json").read_bytes()
        assert snap.frozen and not s.frozen
        assert snap.entries == s.entries and snap.runs == s.runs
        assert snap.results().identification.step.u_ss == pytest.approx(4.05)
        assert views.table(snap) == views.table(s)
        # the session goes on; the snapshot stays as it was taken
        s.enter("u_ss@4.5", "4.2 V")
        s.enter("R", "6.0")
        assert snap.value("R") == pytest.approx(5.26) and s.value("R") == pytest.approx(6.0)
        assert snap.results().identification.step.u_ss == pytest.approx(4.05)
        assert s.results().identification.step.u_ss == pytest.approx(4.2)
        high = snap.load_run(info.name).extra["u_req"] == 4.5
        assert set(snap.load_run(info.name).u[high]) == {4.05}
        assert set(s.load_run(info.name).u[high]) == {4.2}
        # every change is refused before anything is changed
        on_disk = (s.folder / "session.json").read_bytes()
        for change in (
            lambda: snap.enter("R", "7"),
            lambda: snap.go_to("task3"),
            lambda: snap.set_members(["B"]),
            lambda: snap.select_run(info.name),
            lambda: snap.start_run("free", ts=0.025),
            lambda: snap.reveal("task11"),
            lambda: snap.save(),
        ):
            with pytest.raises(SessionFrozen):
                change()
        assert snap.value("R") == pytest.approx(5.26) and snap.current_step == s.current_step
        assert (s.folder / "session.json").read_bytes() == on_disk != before
        assert json.loads(on_disk)["entries"]["R"]["text"] == "6.0"
        snap.close()  # no lock to release: the session keeps its own
        s.enter("R", "6.1")
        assert s.save_problem is None
