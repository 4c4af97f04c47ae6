"""Tasks 1 and 3 are done by what the board showed, as their steps' data say (issue 20's
second walk: they never got a tick), and the board checks are kept in the session."""

from __future__ import annotations

import json

import numpy as np
import pytest

from minseg_tui.lab.content.steps import BOARD_CHECKS, step, validate
from minseg_tui.lab.state.session import Session
from minseg_tui.report import markdown
from minseg_tui.report.content import build


def test_what_makes_tasks_1_and_3_done_is_step_data():
    assert step("task1").done_when == ("board_check",)
    assert step("task3").done_when == ("speed_watched",)
    assert validate() == []
    assert set(BOARD_CHECKS) == {"board_check", "revolution", "speed_watched"}


def test_task1_is_done_once_the_board_check_passes_and_it_is_saved(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert s.step_status("task1") == "todo"
        s.record_check("board_check", False, "nothing was counted", 0)
        assert s.step_status("task1") == "started"  # tried, not passed: no tick
        s.record_check("revolution", True, "720 counts for one revolution", 720)
        assert s.step_status("task1") == "started"
        s.record_check("board_check", True, "the count follows the motor", 152)
        assert s.step_status("task1") == "done"
        with pytest.raises(KeyError):
            s.record_check("no such check", True, "")
        folder = s.folder
    with Session.open(folder) as again:
        got = again.board_checks()
        assert got["board_check"]["ok"] and got["board_check"]["counts"] == 152
        assert got["revolution"]["counts"] == 720 and again.step_status("task1") == "done"
    data = json.loads((folder / "session.json").read_text(encoding="utf-8"))
    del data["board_checks"]  # a session from before opens as it was: Task 1 to do
    (folder / "session.json").write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder) as old:
        assert old.board_checks() == {} and old.step_status("task1") == "todo"


def test_task3_is_done_once_the_live_speed_shows_the_wheel_turning(tmp_path):
    t = np.arange(0.0, 3.0, 0.025)
    with Session.create(tmp_path, ["A"]) as s:
        assert s.step_status("task3") == "todo"
        assert not s.watch_speed(t, np.zeros(t.size, dtype=np.int64))  # standing still
        assert not s.watch_speed(t, np.round(100 * t).astype(np.int64))  # 200 counts in 2 s
        assert s.step_status("task3") == "todo"
        # half a revolution long ago, then still: not what the speed shows now
        early = np.where(t < 0.5, np.round(800 * t), 400).astype(np.int64)
        assert not s.watch_speed(t, early)
        assert s.watch_speed(t, np.round(300 * t).astype(np.int64))  # 600 counts in 2 s
        assert s.step_status("task3") == "done"
        assert s.board_checks()["speed_watched"]["counts"] == 600


def test_the_report_says_what_the_board_checks_found(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        md = markdown.render(build(s))
        assert "No board check was made" in md
        s.record_check("board_check", True, "the count follows the motor", 152)
        s.record_check("revolution", False, "360 counts, half of 720", 360)
        md = markdown.render(build(s))
    (row,) = [line for line in md.splitlines() if line.startswith("| board check (F10)")]
    assert "✓ passed (152 counts)" in row and "the count follows the motor" in row
    (row,) = [line for line in md.splitlines() if line.startswith("| one revolution by hand")]
    assert "✗ failed (360 counts)" in row and "half of 720" in row
