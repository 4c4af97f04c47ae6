"""Screen defects found by a new student's walk of the lab in tmux at 80x24: notes typed on
the model check, the footer of Tasks 11-15, the applied voltage in the zoomed rise, an entry
Tab moves to under the readout of Tasks 4-5. Each through the real TUI (Pilot)."""

from __future__ import annotations

import pytest
from textual.geometry import Region
from textual.widgets import Input

from minseg_tui.ui.panels.results import ResponsePlot
from minseg_tui.ui.screens.boardcheck import BoardCheckScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from minseg_tui.ui.widgets.plots import Canvas
from tests.ui.helpers import goto, settle, start_with_a_run, typing_box


async def test_tab_on_the_model_check_reaches_the_notes_before_the_log_to_load(quiet):
    """The first text box Tab reached on the model check was 'load a step log': the notes a
    group typed there were taken for a file's path."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        for _ in range(10):
            await pilot.press("tab")
            await settle(pilot)
            if isinstance(app.focused, Input) or typing_box(app) is not None:
                break  # a text box (the form's current row, or the log's path)
        notes = app.screen.query_one("#" + field_id("model_check.notes"), FieldRow)
        assert typing_box(app) is notes.input
        await pilot.press(*"slower")
        await settle(pilot)
        assert notes.input.value == "slower"
        assert app.screen.query_one("#import-path", Input).value == ""


async def test_typing_on_the_model_checks_fold_goes_into_its_notes(quiet):
    """Letters typed while the details' fold had the focus went nowhere."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await pilot.press("tab")  # the fold's title
        await settle(pilot)
        await pilot.press(*"ok")
        await settle(pilot)
        notes = app.screen.query_one("#" + field_id("model_check.notes"), FieldRow)
        assert notes.input.value == "ok"
        assert app.screen.query_one("#import-path", Input).value == ""


def _footer_keys(app) -> list[tuple[str, Region]]:
    """The keys the footer shows ('f9 Zoom') and where, the palette's last."""
    footer = app.screen.query_one(KeyFooter)
    keys = [k for k in footer.query(KeyLabel) if k.display]
    keys.sort(key=lambda k: k.has_class("-palette"))
    return [(f"{k.key_display} {k.description}".strip(), k.region) for k in keys]


def _whole(app) -> list[str]:
    """The footer's keys, each asserted shown whole: inside the screen, none over another
    (the palette's key docked at the right)."""
    keys = _footer_keys(app)
    width = app.screen.size.width
    for (name, region), (after, nxt) in zip(keys, keys[1:], strict=False):
        assert region.right <= nxt.x, f"{name!r} runs into {after!r}"
    assert all(0 <= r.x and r.right <= width for _, r in keys)
    return [name for name, _ in keys]


@pytest.mark.parametrize("step_id", ["task11", "task12", "task13", "task14", "task15"])
async def test_the_footer_of_tasks_11_to_15_shows_every_key_whole_at_80x24(quiet, step_id):
    """It showed 'alt+→ Step  ^' before the palette's key (Ctrl+R Reveal cut), and with the
    plot focused its own keys pushed F8, F9, Alt+→ and Ctrl+R off the line."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, step_id)
        await settle(pilot)
        shown = _whole(app)
        for key in ("f1 Help", "f2 STOP", "f8 Export", "f9 Zoom", "alt+→ Rise", "^r Reveal"):
            assert key in shown, shown
        app.screen.query_one(ResponsePlot).focus()
        await settle(pilot)
        assert _whole(app) == shown


async def test_the_footer_is_whole_again_after_the_board_checks_dialog(quiet):
    """Closing the board check's dialog (F10) on Task 12 at 80x24 left a stray '^' in the
    footer, before the palette's key."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        app.push_screen(BoardCheckScreen(True, "The wheel turns and the count follows."))
        await settle(pilot, lambda: isinstance(app.screen, BoardCheckScreen))
        await pilot.press("enter")
        await settle(pilot, lambda: not isinstance(app.screen, BoardCheckScreen))
        assert "^r Reveal" in _whole(app)


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
@pytest.mark.parametrize("step_id", ["task11", "task12"])
async def test_the_zoomed_rise_shows_the_applied_voltage_on_its_own_axis(quiet, size, step_id):
    """At 80x24 u_A's level after the edge (4.02 V) fell on the row of the dashed 63 % line
    and was drawn under it: only the edge's two dots were seen, and no axis said volts. Now
    u_A has the right axis, labelled, and its level a row that the other lines leave free."""
    app = quiet()
    async with app.run_test(size=size) as pilot:
        await start_with_a_run(pilot, step_id)
        canvas = app.screen.query_one(ResponsePlot).query_one(Canvas)
        lines = str(canvas.render()).split("\n")
        top = next(k for k, ln in enumerate(lines) if "┌" in ln)
        bottom = next(k for k, ln in enumerate(lines) if "└" in ln)
        first = lines[top].index("┌") + 1
        last = lines[top].index("┐", first)
        edge = first + round((last - first) * -canvas.xlim[0] / (canvas.xlim[1] - canvas.xlim[0]))
        after = last - edge - 1
        level = max(lines[top + 1 : bottom], key=lambda ln: ln[edge + 1 : last].count("•"))
        assert level[edge + 1 : last].count("•") >= 0.8 * after, "\n".join(lines)
        assert "u_A [V]" in lines[bottom + 2]  # the right axis' label, beside omega's
        assert any(ln[last + 1 :].strip() for ln in lines[top:bottom])  # its ticks


@pytest.mark.parametrize("step_id", ["task4", "task5"])
async def test_tab_never_leaves_the_focused_entry_under_the_readout(quiet, step_id):
    """On Task 4 at 80x24 Tab moved to u_ss at 2.5 V and left its box under the lines kept
    at the bottom of the step (steady state, requested voltage, multimeter), as it did the
    last two entries: the group typed into a box they could not see."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "prep1")
        await goto(pilot, step_id)
        readout = app.screen.query_one(".readout")
        boxes = [r.input for r in app.screen.query(FieldRow)]
        seen = 0
        for _ in range(2 * len(boxes)):
            await pilot.press("tab")
            await settle(pilot)
            box = typing_box(app)
            if box in boxes:
                seen += 1
                # the readout's lines change with the live samples (a line wraps, "waiting
                # for samples" goes): the box must come out from under them each time
                await settle(pilot, lambda b=box: not b.region.overlaps(readout.region))
                assert app.screen.can_view_entire(box)
        assert seen >= len(boxes)


async def test_the_board_checks_dialog_stands_in_the_middle_of_the_screen(quiet):
    """F10's dialog stood in the top left corner, over the status line, where the help and
    the quit dialogs stand in the middle."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        app.push_screen(BoardCheckScreen(True, "The wheel turns and the count follows."))
        await settle(pilot, lambda: isinstance(app.screen, BoardCheckScreen))
        box = app.screen.query_one("#board-check").region
        assert abs(box.x - (80 - box.right)) <= 1 and abs(box.y - (24 - box.bottom)) <= 1
