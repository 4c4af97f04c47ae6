"""Defects a new student met walking the lab at 80x24 (issue 20's second walk), each as the
TUI shows it: the run list after an interrupted run, Task 1 and Task 3 done, a second
session of the same names."""

from __future__ import annotations

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.classview import judge, read_group
from minseg_tui.report import markdown
from minseg_tui.report.content import build
from minseg_tui.ui.panels.square_wave import SquareWavePanel
from minseg_tui.ui.screens.boardcheck import BoardCheckScreen
from minseg_tui.ui.screens.lab import StepCommands
from minseg_tui.ui.screens.start import StartScreen
from tests.ui.conftest import board_url, quiet_app, real_app
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    Heard,
    enter_all,
    goto,
    nav_mark,
    record_response_run,
    settle,
    shown,
    start,
)


def _interrupted(session: Session, ended_by: str) -> str:
    """A 25 ms step run interrupted after 80 samples (``ended_by`` says by what); its name."""
    plan = dict(step("task10").plans)["manual"]
    rec = session.start_run("steps", plan)
    for k in range(80):
        rec.append(k, k * 25_000, 3 * k, 4500 if k >= 20 else 0)
    info = session.finish_run(rec, stopped_early=True, ended_by=ended_by)
    assert info is not None
    return info.name


async def test_the_run_list_keeps_the_run_in_use_after_an_interrupted_run(quiet):
    """steps-1 complete, steps-2 quit: Task 10 listed only steps-2 although Tasks 11-15 use
    steps-1. Now every run is listed, the one in use marked, the interrupted one labelled."""
    app = quiet(QuietDevice(seed=1))
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            used = record_response_run(s, seed=5)
            quit_run = _interrupted(s, "quit")
            cable_run = _interrupted(s, "cable")
            assert s.response_run().name == used
        await goto(pilot, "task10", focus=None)
        panel = app.screen.query_one(SquareWavePanel)

        def status() -> str:
            return str(app.screen.query_one("#run-status").render())

        await settle(pilot, lambda: used in status())
        said = status()
        assert f"▸ {used}" in said and "in use for Tasks 11-15" in said
        assert f"{quit_run} (80 samples, interrupted: quit)" in said
        assert f"{cable_run} (80 samples, interrupted: board lost (cable pulled?))" in said
        readings = str(app.screen.query_one("#t-readings").render())
        assert f"▸ {used}" in readings and quit_run in readings and cable_run in readings
        # the plot shows the run in use, not the newest interrupted one (walk 5, 2e6b9df)
        assert [v.name for v in panel.view or () if v.plotted] == [used]
        texts = [t for t, _, _ in StepCommands(app.screen).entries()]
        assert f"Use run {quit_run} (quit) for Tasks 11-15" in texts
        assert f"Use run {used} for Tasks 11-15" in texts
        # the group picks the interrupted run on purpose: it is the one marked
        app.screen.use_run(quit_run)
        await settle(pilot, lambda: f"▸ {quit_run}" in status())
        assert f"▸ {used}" not in status()


async def test_task1_and_task3_get_their_tick_and_the_board_check_reaches_the_report(tmp_path):
    """On the virtual MinSeg: F10 on Task 1 passes and Task 1 is ticked; on Task 3, F3 sets a
    voltage, the wheel turns under the live speed and Task 3 is ticked. The report says what
    the board check found. Both stayed unticked however much was done."""
    app = real_app(tmp_path / "sessions", board_url(seed=2))
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        await goto(pilot, "task1")
        assert nav_mark(app, "task1") == " " and nav_mark(app, "task3") == " "
        await pilot.press("f10")
        await heard.until(
            pilot,
            lambda: (
                isinstance(app.screen, BoardCheckScreen) and bool(app.screen.query("#check-text"))
            ),
        )
        assert app.screen.ok
        await pilot.press("enter")
        await settle(pilot, lambda: not isinstance(app.screen, BoardCheckScreen))
        assert nav_mark(app, "task1") == "✓"
        await goto(pilot, "task3")
        await pilot.press("f3")  # 2.5 V: the wheel turns, the live speed shows it
        await heard.until(pilot, lambda: nav_mark(app, "task3") == "✓")
        await pilot.press("f2")
        with app.session as s:
            checks = s.board_checks()
            md = markdown.render(build(s))
    assert checks["board_check"]["ok"] and checks["speed_watched"]["ok"]
    assert "## Set-up: the board checks" in md
    (row,) = [line for line in md.splitlines() if line.startswith("| board check (F10)")]
    assert "✓ passed" in row and "the count follows" in row


def _msg(app) -> str:
    return str(app.screen.query_one("#start-msg").render())


async def test_the_same_names_again_offer_the_existing_session(tmp_path):
    """'Ada, Bo' a second time made a second, empty session silently. Now the start screen
    says a session of these names exists, and Enter again resumes it."""
    root = tmp_path / "sessions"
    with Session.create(root, ["Ada", "Bo"], date="2026-11-26") as old:
        old.enter("R", "5.2")
        old.go_to("task4")
        folder = old.folder
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await pilot.press(*"bo,  ada")  # the same group, typed otherwise
        await pilot.press("enter")
        await settle(pilot, lambda: "exists" in _msg(app))
        assert isinstance(app.screen, StartScreen) and app.session is None
        said = _msg(app)
        assert "A session of Ada, Bo exists (2026-11-26, at Task 4" in said
        assert "Enter resumes it" in said and "Ctrl+N" in said
        await pilot.press("enter")
        await settle(pilot, lambda: shown(app))
        with app.session as s:
            assert s.folder == folder and s.value("R") == 5.2
    assert len(list_sessions(root)) == 1


async def test_a_second_session_of_the_same_names_on_purpose_is_told_apart(tmp_path):
    root = tmp_path / "sessions"
    Session.create(root, ["Ada", "Bo"], date="2026-11-26").close()
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await pilot.press(*"Ada, Bo", "enter")
        await settle(pilot, lambda: "exists" in _msg(app))
        await pilot.press("ctrl+n")  # a new one, on purpose
        await settle(pilot, lambda: shown(app))
        with app.session as s:
            new_id = s.id
    ids = sorted(i.id for i in list_sessions(root))
    assert len(ids) == 2 and new_id in ids
    view = judge([read_group(root / i) for i in ids])
    for g in view.groups:
        (other,) = [i for i in ids if i != g.id]
        assert any(f"another session of the same names: {other}" in f for f in g.flags)
