"""Walk 15's defects (issue 20), each as the walk met it, at 80x24 with Pilot on real session
folders (/work/coord/WALK15.md)."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable, OptionList

from minseg_tui.lab.state.session import Session
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.helpers import burst, settle, shown


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
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        await pilot.press("f12")
        await settle(pilot, lambda: isinstance(app.screen, ClassScreen) and app.screen.done)
        screen = app.screen
        assert isinstance(screen, ClassScreen)
        table = screen.query_one(DataTable)
        await settle(pilot, lambda: app.focused is table and table.cursor_row == 0)
        second = screen.groups[1].folder
        assert second in folders
        await burst(pilot, "down", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        assert app.session is not None
        with app.session as s:
            assert s.folder == second and s.readonly
