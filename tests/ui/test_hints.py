"""An entry's hint is read in full: in the empty box where it fits, else on the line under
the box while the box is empty (an Input's placeholder is one line, cut at the box's edge)."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.steps import step
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import goto, settle, start

HINT = next(f.hint for f in step("task4").fields if f.key == "u_ss@2.5")


def _row(app) -> FieldRow:
    return app.screen.query_one(f"#{field_id('u_ss@2.5')}", FieldRow)


async def test_a_hint_too_long_for_the_box_at_80_columns_is_under_it_in_full(quiet):
    """Seen in the walk: 'multimeter on V=, between M1A and M1B' read 'multimeter on V=,
    between M1A an' in Task 4's boxes at 80 columns."""
    assert len(HINT) > 34  # wider than the box at 80 columns with the list of steps
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        row = _row(app)
        hint = row.query_one(".field-hint", Prose)
        assert hint.display and hint.text == HINT and row.input.placeholder == ""
        row.input.focus()
        await pilot.press(*"2,05")
        await settle(pilot)
        assert not hint.display  # the box holds a value: the hint has done its job


@pytest.mark.parametrize("size", [(120, 40)])
async def test_a_hint_that_fits_stays_in_the_box(quiet, size):
    app = quiet()
    async with app.run_test(size=size) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        row = _row(app)
        assert row.input.placeholder == HINT
        assert not row.query_one(".field-hint", Prose).display
