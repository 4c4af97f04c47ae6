"""Walk 15's defects (issue 20), each as the walk met it, at 80x24 with Pilot on real session
folders (/work/coord/WALK15.md)."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable, OptionList, ProgressBar

from minseg_tui.device.link import LinkEvent
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.panels.square_wave import SquareWavePanel
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.prose import Prose
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.helpers import (
    TABLE,
    burst,
    class_view,
    enter_all,
    goto,
    quit_asked_mid_run,
    record_response_run,
    settle,
    shown,
    start,
    start_run_on,
    taken,
)


def _two_sessions(root: Path) -> None:
    """Two groups' sessions under ``root``, each closed (no lock): the start screen lists
    both."""
    for names in (["Lea P", "Tom R"], ["Mia K", "Omar S"]):
        Session.create(root, names, date="2026-11-28").close()


async def test_down_enter_in_one_burst_resumes_the_session_the_cursor_went_to(tmp_path):
    """D1: the start screen's list of saved sessions focused, its first row highlighted,
    'Down Enter' in one burst (tmux send-keys Down Enter): the first row's session opened,
    writable, not the second's that Down had moved to. Textual runs the list's Down binding
    only once its key has bubbled up to the app's queue, behind the Enter that the app runs
    at once (a priority binding). Now Enter opens the row the cursor is on after the keys
    typed before it."""
    root = tmp_path / "sessions"
    _two_sessions(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        listed = app.screen.query_one("#sessions", OptionList)
        listed.focus()
        await settle(pilot, lambda: app.focused is listed and listed.highlighted == 0)
        second = listed.get_option_at_index(1).id
        await burst(pilot, "down", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        assert app.session is not None
        with app.session as s:
            assert str(s.folder) == second
            assert not s.readonly


async def test_down_enter_in_one_burst_opens_the_group_the_cursor_went_to(tmp_path):
    """D1 in the class view: F12, the cursor on row 1, 'Down Enter' in one burst opened row
    1's session (read-only), not row 2's where the cursor stood."""
    root = tmp_path / "sessions"
    folders = [
        group(root, ["Lea P", "Tom R"], seed=1, run=False),
        group(root, ["Mia K", "Omar S"], seed=2, run=False),
    ]
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        table = screen.query_one(DataTable)
        await settle(pilot, lambda: app.focused is table and table.cursor_row == 0)
        second = screen.groups[1].folder
        assert second in folders
        await burst(pilot, "down", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        assert app.session is not None
        with app.session as s:
            assert s.folder == second and s.readonly


async def test_the_quit_question_of_a_run_that_ends_while_it_is_up_says_it_ended(quiet):
    """D2: Task 10, F5, Ctrl+Q during the recording ("Run steps-1 is being recorded (…
    samples so far). Quitting stops it before its plan ends."), and the run's plan ended
    while the question was up: the run was kept complete, and the dialog still said it was
    being recorded and offered to stop it. Now the question says the run has ended, what was
    kept, and offers to keep working or quit; Quit quits, the run not marked as cut."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task10")
        seq = await quit_asked_mid_run(pilot, dev)
        asking = app.screen
        recording = app.recording.name
        dev.feed(square_wave_stream(seq + 80, (seq + 81) * 25_000, 10.0))
        dev.feed_event(LinkEvent("square_wave_done", "square wave done", 0.0))
        await taken(pilot, seq + 480)
        await settle(pilot, lambda: app.recording is None)
        assert app.screen is asking
        words = str(asking.query_one("#problem", Prose).render()) + " ".join(
            text for _, text in asking.choices
        )
        assert "being recorded" not in words and "Stop the run" not in words
        assert "The run ended while this was asked" in words and recording in words
        assert [key for key, _ in asking.choices] == ["keep", "quit_now"]
        with app.session as s:
            (run,) = [r for r in s.runs if r.name == recording]
            assert not run.interrupted
        folder = s.folder
        await pilot.press("down", "enter")
        await settle(pilot, lambda: not app.is_running)
    kept = Session.open(folder, readonly=True)
    (run,) = [r for r in kept.runs if r.name == recording]
    assert not run.interrupted and run.samples >= 480


async def test_task10_shows_no_progress_bar_at_0_percent_beside_a_run_recorded_before(quiet):
    """D7: a session resumed with its step run recorded (steps-1, complete, in use): Task 10
    showed its progress bar at '0%' under the runs' line, as if nothing had been recorded.
    Now no bar shows until a run waits or records here; F5 brings it."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task10")
        panel = app.screen.query_one(SquareWavePanel)
        bar = panel.query_one(ProgressBar)
        assert not bar.display and bar.region.height == 0
        await start_run_on(pilot, dev)
        await settle(pilot, lambda: bar.display)
        await settle(pilot, lambda: bar.region.height > 0)
