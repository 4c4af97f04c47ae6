"""F7 from the entries of Tasks 6-9 shows the formula of the table's cell that has the keys,
with that cell and the formula's line on the screen (issue 20, walk 14's D3: at 80x24,
'Ctrl+P task 6 Enter F7' on a session whose k_v, k_a and f were typed and judged wrote the
first cell's formula on a line under the step's heading, the table and its cursor above the
screen). The manual's Task 7, 8 and 9 are the same step: 'task 7', 'task 8' and 'task 9'
in the palette go there too ('task 8' matched no command)."""

from __future__ import annotations

import pytest
from textual.command import CommandList, CommandPalette
from textual.widgets import DataTable

from minseg_tui.ui.screens.lab import LabScreen, StepPane
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import TABLE, burst, enter_all, in_step_view, settle, shown, start

OWN = {"own.k_v": "5.3", "own.k_a": "5.3", "own.f": "5.3"}
"""The group's k_v, k_a and f as walk 14's session had them (each judged wrong, its
comparison and verdict four rows tall under the table)."""


@pytest.mark.parametrize("search", ["task 6", "task 7", "task 8", "task 9"])
@pytest.mark.parametrize("one_burst", [True, False], ids=["one-burst", "looked-at"])
async def test_f7_after_the_palette_shows_the_focused_cell_and_its_formula(
    quiet, search, one_burst
):
    """'Ctrl+P task N Enter F7' at 80x24, from Task 2, with the table filled and the group's
    k_v, k_a and f judged: Tasks 6-9 shown, the keys in the table, its cursor's cell (the
    first) and the formula's line in view below the heading, the line giving that cell's
    formula."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE | OWN)
        if one_burst:
            await burst(pilot, "ctrl+p", *search, "enter", "f7")
        else:
            await pilot.press("ctrl+p")
            await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
            await pilot.press(*search)
            await settle(pilot, lambda: bool(app.screen.query_one(CommandList).option_count))
            await burst(pilot, "enter")
            await settle(pilot, lambda: shown(app, "table"))
            await burst(pilot, "f7")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen) and shown(app, "table")
        pane = app.screen.query(StepPane).last()
        table = app.screen.query_one("#table", DataTable)
        line = app.screen.query_one("#formula", Prose)
        panel = app.screen.panel
        assert app.focused is table
        assert panel is not None and panel.view is not None
        r, c = table.cursor_coordinate
        cell = panel.view.rows[r][c]
        assert str(line.render()) == (cell.formula or f"{cell.text}: measured, no formula")
        assert in_step_view(pane, line), (pane.scroll_y, pane.heading_rows, line.region)
        assert in_step_view(pane, table), (pane.scroll_y, pane.heading_rows, table.region)
