"""Walk 15's D6 and D9: a session opened read-only from the class view (/work/coord/WALK15.md),
at 80x24 with Pilot on real session folders.

D6: Escape (or the palette's command) closes that session and shows the class view again,
the cursor on the group opened, so that the next one opens with 'Down Enter'; nothing is
written under the sessions folder. D9: F3 there refuses, as F4 and F5 do."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable

from minseg_tui.lab.content.keys import PALETTE
from minseg_tui.report.write import write_report
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    burst,
    class_view,
    goto,
    heard_notifications,
    settle,
    shown,
    start,
    typing_box,
)


def _files(root: Path) -> dict[str, bytes]:
    """Every file under ``root`` with its bytes (a read-only session changes none)."""
    return {str(p): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def _three_groups(root: Path) -> list[Path]:
    return [
        group(root, ["Lea P", "Tom R"], seed=1, run=False),
        group(root, ["Mia K", "Omar S"], seed=2, run=False),
        group(root, ["Ada L", "Alan T"], seed=3, run=False),
    ]


async def _open_row(pilot, screen: ClassScreen, row: int) -> Path:
    """The cursor to ``row`` of the class view, Enter: that group's session, read-only."""
    app = pilot.app
    table = screen.query_one(DataTable)
    await settle(pilot, lambda: app.focused is table)
    await burst(pilot, *["down"] * (row - table.cursor_row), "enter")
    await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
    assert app.session is not None
    with app.session as s:
        assert s.readonly
        return s.folder


async def test_escape_in_a_session_opened_from_the_class_view_goes_back_to_its_row(tmp_path):
    """D6: F12, Enter on a group, then Escape did nothing (nor did the palette have a way
    back): the instructor restarted the program for each group. Escape now closes the
    session, even from an entry with a refused text in it, and the class view is back, the
    same one, the cursor on the group opened; 'Down Enter' opens the next group. Nothing under
    the sessions folder is written, and no lock is left."""
    root = tmp_path / "sessions"
    _three_groups(root)
    before = _files(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        second = screen.groups[1].folder
        assert await _open_row(pilot, screen, 1) == second
        await goto(pilot, "task2")
        await burst(pilot, *"7,8", "enter")
        assert typing_box(app) is not None  # Escape from an entry
        await burst(pilot, "escape")
        await settle(pilot, lambda: app.screen is screen)
        assert app.session is None
        table = screen.query_one(DataTable)
        assert table.cursor_row == 1
        third = screen.groups[2].folder
        assert await _open_row(pilot, screen, 2) == third
    assert _files(root) == before
    assert not list(root.rglob("lock"))


async def test_the_palette_goes_back_to_the_class_view_from_a_group_opened_there(tmp_path):
    """D6: the palette had no class view ('class' found 'Use the newest complete 25 ms
    run…'). Its 'Back to the class view' closes the session opened from the class view, the
    cursor on that group."""
    root = tmp_path / "sessions"
    _three_groups(root)
    before = _files(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        assert await _open_row(pilot, screen, 2) == screen.groups[2].folder
        await burst(pilot, "ctrl+p", *PALETTE["back_to_class"].lower(), "enter")
        await settle(pilot, lambda: app.screen is screen)
        assert app.session is None
        assert screen.query_one(DataTable).cursor_row == 2
        await burst(pilot, "escape")  # the class view's own Escape: the start screen
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
    assert _files(root) == before
    assert not list(root.rglob("lock"))


async def test_escape_keeps_a_session_opened_from_the_start_screen(tmp_path):
    """Escape closes only a session opened from the class view: in a group's own session it
    is the entries' key (a refused text dropped), and the lab stays; the palette offers no
    way back to a class view that is not there."""
    root = tmp_path / "sessions"
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        lab = app.screen
        await burst(pilot, "escape")
        await settle(pilot)
        assert app.screen is lab and app.session is not None
        titles = [c.title for c in app.get_system_commands(lab)]
        assert PALETTE["back_to_class"] not in titles


async def test_f3_in_a_session_opened_from_the_class_view_refuses_as_f4_does(tmp_path):
    """D9: F12, Enter, Task 4, F3 put 3.5 V on the motor, while F4 there captures nothing.
    F3 now refuses with the read-only line F4 and F5 give, and the motor stays off; F4, the
    motor off, says it is read-only too (not 'set a voltage first' that F3 would refuse)."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12")
    before = _files(root)
    app = quiet_app(root, QuietDevice(seed=2))
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        await _open_row(pilot, screen, 0)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        await settle(pilot, lambda: any("not driven" in m for m in said))
        told = next(m for m in said if "not driven" in m)
        assert "read-only" in told and "to look" in told and "damaged" not in told
        assert app.requested is None and app.motor == "off"
        await burst(pilot, "f4")
        await settle(pilot, lambda: any("not captured" in m for m in said))
        assert not any("set a voltage first" in m for m in said)
        assert app.requested is None and app.motor == "off"
    assert _files(root) == before


async def test_one_burst_opens_a_group_goes_back_and_opens_the_next(tmp_path):
    """D6 as an instructor grading in a hurry types it: 'Down Enter Escape Down Enter' in one
    burst opens the second group, comes back to its row, and opens the third: the keys typed
    after Enter wait until the lab shows the group, and those after Escape go to the class
    view."""
    root = tmp_path / "sessions"
    _three_groups(root)
    before = _files(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        table = screen.query_one(DataTable)
        await settle(pilot, lambda: app.focused is table and table.cursor_row == 0)
        await burst(pilot, "down", "enter", "escape", "down", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        assert app.session is not None
        with app.session as s:
            assert s.folder == screen.groups[2].folder and s.readonly
        assert app.screen_stack[-2] is screen
    assert _files(root) == before
    assert not list(root.rglob("lock"))


async def test_f8_in_a_session_opened_from_the_class_view_writes_nothing_into_it(tmp_path):
    """Found beside D6: F8 in a group's session opened from the class view wrote report.md
    and report.html into the group's folder, though the session is open "to look, not to
    change". F8 there refuses with the read-only line, and the folder stays as it was."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, run=False)
    before = _files(root)
    app = quiet_app(root)
    app._writer = lambda session: write_report(session).paths  # the CLI's writer
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        await _open_row(pilot, screen, 0)
        await burst(pilot, "f8")
        await settle(pilot, lambda: any("no report is written" in m for m in said))
        told = next(m for m in said if "no report is written" in m)
        assert "read-only" in told and "to look" in told
        assert not any(m.startswith("written") for m in said)
    assert _files(root) == before
