"""Walk 17's defects (/work/coord/WALK17.md), at 80x24 with Pilot on real session folders.

D1: the class view's F8 wrote class.md/html/csv from the rows read when the view opened, so a
group's work done since (in another window) was missing from the files. D2: in a session
opened read-only from the class view, Enter on an answer moved the pick on screen to it,
though the pick was refused and not stored. D4: on Tasks 11-15 at 80x24, once the answers are
typed the plot is above the view, and Alt+→ or F9 changed it there with nothing seen."""

from __future__ import annotations

import csv
import os
from pathlib import Path

import pytest
from textual.widgets import DataTable

from minseg_tui.lab.state.session import Session
from minseg_tui.report.write import write_class
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.panels.results import ResponsePlot, ResultsPanel
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.help import HelpScreen, KeyList
from minseg_tui.ui.screens.lab import LabScreen, StepPane
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from tests.classview.build import group
from tests.seeded import Clock
from tests.ui.conftest import DATE, quiet_app
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    answering,
    burst,
    class_view,
    enter_all,
    goto,
    heard_notifications,
    record_response_run,
    resume,
    settle,
    shown,
    start,
    start_with_a_run,
    typing_box,
)


def _class_app(root: Path) -> LabApp:
    """The app on the device double, with the class report's writer (F8 in the class view)."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: dev, None, write_class)


def _summary_group(root: Path) -> Path:
    """A group that answered the Summary's first question "a system" (option 1)."""
    s = Session.create(root, ["Mira K", "Jonas P"], date="2026-11-28", clock=Clock())
    s.choose("summary.1", [1])
    s.go_to("summary")
    s.close()
    return s.folder


def _row(app: LabApp, key: str) -> FieldRow:
    return next(r for r in app.screen.query(FieldRow) if r.field.key == key)


async def test_a_pick_refused_in_a_read_only_session_leaves_the_groups_answer_shown(tmp_path):
    """D2: F12, Enter on the group, its Summary, 'Up Enter' on Q1: the list showed 'a model'
    picked (● moved off 'a system') under "✗ this session is open read-only …: not stored".
    The pick is refused and the list shows the group's answer again; Space does the same;
    nothing is written."""
    root = tmp_path / "sessions"
    folder = _summary_group(root)
    before = (folder / "session.json").read_bytes()
    app = _class_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        await settle(pilot, lambda: app.focused is screen.query_one(DataTable))
        await burst(pilot, "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        await goto(pilot, "summary")  # the keys on Q2, the first question not answered
        row = _row(app, "summary.1")
        assert row.answers is not None and row.answers.chosen == (1,)
        await burst(pilot, "shift+tab")
        await settle(pilot, lambda: answering(app) is row.answers)
        await burst(pilot, "up", "enter")
        await settle(pilot)
        assert "read-only" in row.message
        assert row.answers.chosen == (1,), "the refused pick is shown as the group's answer"
        await burst(pilot, "up", "up", "space")  # on "a model"
        await settle(pilot)
        assert row.answers.chosen == (1,)
    assert (folder / "session.json").read_bytes() == before


def _class_csv(root: Path) -> dict[str, dict[str, str]]:
    """class.csv under ``root``: each group's row by its folder's name."""
    with (root / "class.csv").open(newline="", encoding="utf-8") as f:
        return {r["id"]: r for r in csv.DictReader(f)}


def _cell(screen: ClassScreen, row: int, column: str) -> str:
    table = screen.query_one(DataTable)
    return str(
        table.get_cell_at((row, [c.key.value for c in table.columns.values()].index(column)))
    )


def _retype_R(folder: Path, text: str) -> None:
    """The group, in its own program, corrects R (the class view is open elsewhere)."""
    s = Session.open(folder)
    s.enter("R", text)
    s.close()


async def test_f8_in_the_class_view_writes_what_the_sessions_hold_when_it_is_pressed(tmp_path):
    """D1: the class view opened, then a group (in another window) corrected R from 3.5 to
    5.3 Ω; F8 wrote class.csv with R 3.5 and the k_v computed from it (the rows read when the
    view opened), while `minseg-tui class` said 5.3. F8 now reads the sessions again: the
    files and the table hold 5.3 and the k_v from it."""
    root = tmp_path / "sessions"
    mira = group(root, ["Mira K", "Jonas P"], seed=1, R="3,5 ohms", run=False)
    group(root, ["Ada L", "Alan T"], seed=2, run=False)
    app = _class_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        row = next(k for k, g in enumerate(screen.groups) if g.folder == mira)
        assert _cell(screen, row, "R") == "3.5"
        k_v_before = _cell(screen, row, "k_v")
        _retype_R(mira, "5,3 ohms")
        await burst(pilot, "f8")
        await settle(pilot, lambda: (root / "class.csv").exists())
        written = _class_csv(root)[mira.name]
        assert written["R (Ω)"] == "5.3"
        await settle(pilot, lambda: _cell(screen, row, "R") == "5.3")
        assert _cell(screen, row, "k_v") != k_v_before
        assert float(written["k_v (V s/rad)"]) == pytest.approx(
            float(_cell(screen, row, "k_v")), rel=1e-3
        )


async def test_the_class_view_reads_the_sessions_again_when_a_group_opened_from_it_closes(
    tmp_path,
):
    """D1: Escape from a group opened read-only showed the class view as it was read at F12,
    though another group had corrected its R meanwhile; the rows are read again, the cursor
    on the group opened."""
    root = tmp_path / "sessions"
    mira = group(root, ["Mira K", "Jonas P"], seed=1, R="3,5 ohms", run=False)
    group(root, ["Ada L", "Alan T"], seed=2, run=False)
    app = _class_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        row = next(k for k, g in enumerate(screen.groups) if g.folder == mira)
        other = 1 - row
        table = screen.query_one(DataTable)
        await settle(pilot, lambda: app.focused is table)
        await burst(pilot, *(["down"] if other > table.cursor_row else ["up"]), "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        _retype_R(mira, "5,3 ohms")
        await burst(pilot, "escape")
        await settle(pilot, lambda: app.screen is screen)
        await settle(pilot, lambda: _cell(screen, row, "R") == "5.3")
        assert table.cursor_row == other
    assert not list(root.rglob("lock"))


def _in_view(pane: StepPane, widget) -> bool:
    """``widget`` lies whole in the part of the pane on screen (screen coordinates)."""
    return widget.region.height > 0 and pane.scrollable_content_region.contains_region(
        widget.region
    )


@pytest.mark.parametrize("key", ["alt+right", "f9"])
async def test_a_rise_key_brings_the_plot_it_changes_into_view(quiet, key):
    """D4: Task 11 at 80x24, both answers typed, the keys on 'your K': the plot lies above
    the view. Alt+→ zoomed to rise 2 there and F9 too, and the screen did not change. The
    plot now comes into view, showing the rise the key chose; the keys stay on 'your K'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        pane = app.screen.query(StepPane).last()
        await burst(pilot, *"7,8", "enter", *"1,93", "enter")
        k_row = app.screen.query_one(f"#{field_id('own.K')}", FieldRow)
        await settle(pilot, lambda: typing_box(app) is k_row.input)
        await settle(pilot)
        plot = app.screen.query_one(ResponsePlot)
        panel = app.screen.query_one(ResultsPanel)
        assert not _in_view(pane, plot), "the walk's state: the plot above the view"
        before = panel.zoom
        await burst(pilot, key)
        await settle(pilot, lambda: panel.zoom != before)
        await settle(pilot)
        assert _in_view(pane, plot), (pane.scroll_y, plot.region)
        assert typing_box(app) is k_row.input


async def test_a_character_typed_after_the_plot_came_into_view_brings_the_entry_back(quiet):
    """D4, the other half: the plot brought into view by Alt+→ pushes 'your K' (entered,
    its comparison under it) below the screen; a character typed then goes into 'your K'
    (the keys stayed there) and the entry comes back into view: the group sees what it
    types."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        pane = app.screen.query(StepPane).last()
        await burst(pilot, *"7,8", "enter", *"1,9", "enter")
        k_row = app.screen.query_one(f"#{field_id('own.K')}", FieldRow)
        await settle(pilot, lambda: typing_box(app) is k_row.input)
        panel = app.screen.query_one(ResultsPanel)
        await burst(pilot, "alt+right")
        await settle(pilot, lambda: panel.zoom == 1)
        await settle(pilot)
        assert not _in_view(pane, k_row.input), "the walk's state: the entry below the view"
        await burst(pilot, "3")  # goes on after the K entered: "1,93"
        await settle(pilot)
        assert k_row.input.value == "1,93"
        assert _in_view(pane, k_row.input), (pane.scroll_y, k_row.input.region)


async def test_a_group_opened_read_only_says_when_it_was_saved_and_that_the_group_has_it_open(
    tmp_path,
):
    """D3: a group opened from the class view while it still worked in another window was
    shown as saved then, with nothing saying so: the lab assistant read its Summary as empty
    though the group answered it a minute later. The notice now says when the session was
    saved and that the group has it open (the other program's pid), so what it does next
    shows when it is opened again; a session nobody holds says only when it was saved."""
    root = tmp_path / "sessions"
    held = group(root, ["Mira K", "Jonas P"], seed=1, run=False)
    group(root, ["Ada L", "Alan T"], seed=2, run=False)
    working = Session.open(held)  # the group's own program, in another window
    try:
        app = _class_app(root)
        async with app.run_test(size=(80, 24)) as pilot:
            screen = await class_view(pilot)
            table = screen.query_one(DataTable)
            await settle(pilot, lambda: app.focused is table)
            heard = heard_notifications(app)
            for folder in (held, next(g.folder for g in screen.groups if g.folder != held)):
                row = next(k for k, g in enumerate(screen.groups) if g.folder == folder)
                moves = row - table.cursor_row
                await burst(pilot, *(["down"] * moves if moves > 0 else ["up"] * -moves))
                await burst(pilot, "enter")
                await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
                said = next(n for n in heard if "opened read-only" in n)
                with app.session as s:
                    saved = s.modified[11:19]
                assert f"as saved at {s.modified[:10]} {saved} UTC" in said
                open_elsewhere = f"has it open in another minseg-tui (pid {os.getpid()})"
                assert (open_elsewhere in said) == (folder == held), said
                await burst(pilot, "escape")
                await settle(pilot, lambda: app.screen is screen)
                heard.clear()
    finally:
        working.close()


def _help_text(app: LabApp) -> str:
    """What F1's screen says, its paragraphs and its list of keys, as plain text."""
    screen = app.screen
    assert isinstance(screen, HelpScreen)
    paras = [str(w.render()) for w in screen.query(".para")]
    return "\n".join([*paras, screen.query_one(KeyList).text])


async def test_f1_says_what_to_do_on_the_screen_it_is_pressed_on(quiet):
    """D7: F1 was the same on every screen. On the start screen it began "The left column
    lists the lab's steps" (there is none there) and said Ctrl+Q quits with "the session
    already saved" (there is no session yet); on a step it said nothing of that step. It now
    begins with what to do where it is pressed."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        await burst(pilot, "f1")
        await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
        said = _help_text(app)
        assert said.startswith("Now: type the group's names and press Enter"), said
        assert "left column" not in said
        assert "already saved" not in said
        await burst(pilot, "escape")
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        await start(pilot)
        await goto(pilot, "task12")
        await burst(pilot, "f1")
        await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
        said = _help_text(app)
        assert said.startswith("Now: Task 12: the time constant T. What to do stands"), said
        assert "The left column lists the lab's steps" in said
        assert "quit (the session is already saved)" in said


async def test_the_formula_line_follows_the_tables_cursor(quiet):
    """D8: Tasks 6-9, F7 ("u = 2.5 V: the voltage requested on the board"), then → five
    times to the f cell: the line still explained u = 2.5 V until F7 was pressed again. It
    now gives the formula of the cell the cursor is on; F7 there says the same."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        line = app.screen.query_one("#formula", Prose)
        await burst(pilot, "f7")
        await settle(pilot, lambda: str(line.text).startswith("u = 2.5 V"))
        await burst(pilot, *["right"] * 5)
        await settle(pilot)
        moved = str(line.text)
        assert moved.startswith("f = k_a i_ss / omega_ss"), moved
        await burst(pilot, "f7")
        await settle(pilot)
        assert str(line.text) == moved


async def test_a_j_turned_wrong_by_a_corrected_r_says_so_under_it(tmp_path):
    """D5: a group gave J from its own T with R misread as 3.5 Ω (✓), then corrected R to
    5.3 Ω three steps later: Task 13 turned ✗ "+55 % from … computed your way", nothing
    saying that R changed after J was given. The verdict under J now says it."""
    root = tmp_path / "sessions"
    s = Session.create(root, ["Mira K", "Jonas P"], date=DATE, clock=Clock())
    for key, text in TABLE.items():
        s.enter(key, text)
    s.enter("R", "3,5 ohms")
    record_response_run(s)
    s.enter("own.T", "50 ms")
    computed = next(c for c in s.comparisons("task13") if c.key == "own.J").computed
    assert isinstance(computed, float)
    s.enter("own.J", f"{computed:.4g}")
    assert next(c for c in s.comparisons("task13") if c.key == "own.J").right
    s.enter("R", "5,3 ohm")
    s.go_to("task13")
    s.close()
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        await settle(pilot, lambda: shown(app, "task13"))
        row = _row(app, "own.J")
        await settle(pilot, lambda: "wrong" in row.message)
        assert "R was changed from '3,5 ohms' to '5,3 ohm' after you gave it" in row.message
