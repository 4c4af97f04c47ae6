"""Issue 20, left by walk 13: on the Task 4-9 table, "Right Right F7" in ONE burst showed
the formula of the cell the cursor started on. The arrows are the step form's priority
keys; with the table focused the form skipped them and Textual ran the table's binding only
when the key had bubbled back up to the app, after F7, which the app had read meanwhile.
The formula must be that of the cell the keys ended on, whether the keys come in one burst
or one by one."""

from __future__ import annotations

import pytest
from textual.widgets import DataTable

from minseg_tui.ui.panels.table import TablePanel
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import TABLE, burst, enter_all, goto, settle, start

KEYS = ("right", "right", "down", "left", "f7")


@pytest.mark.parametrize("one_burst", [True, False], ids=["one-burst", "key-by-key"])
async def test_f7_gives_the_formula_of_the_cell_the_arrows_ended_on(quiet, one_burst):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        table = app.screen.query_one("#table", DataTable)
        await burst(pilot, "f7")  # the keys to the table, on its first cell
        assert app.focused is table and table.cursor_coordinate == (0, 0)
        start_row, start_col = table.cursor_coordinate
        if one_burst:
            await burst(pilot, *KEYS)
        else:
            for key in KEYS:
                await pilot.press(key)
                await pilot.pause()
        await settle(pilot)
        assert table.cursor_coordinate == (start_row + 1, start_col + 1)
        view = app.screen.query_one(TablePanel).view
        assert view is not None
        cells = [
            view.rows[r][c] for r, c in ((start_row, start_col), (start_row + 1, start_col + 1))
        ]
        left, ended = (c.formula or f"{c.text}: measured, no formula" for c in cells)
        assert left != ended  # the two cells tell apart
        assert str(app.screen.query_one("#formula", Prose).render()) == ended
