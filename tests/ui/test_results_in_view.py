"""A walk at 80x24: after the group answers in Tasks 11-15, what the answer reveals (the
computed value, the comparison with theirs) was below the screen; the step now scrolls it
into view, keeping the entry in view too."""

from __future__ import annotations

import pytest

from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import settle, start_with_a_run, typing_box


def _visible(pane: StepPane, widget) -> bool:
    """``widget`` lies whole in the part of the pane on screen (screen coordinates)."""
    return widget.region.height > 0 and pane.scrollable_content_region.contains_region(
        widget.region
    )


@pytest.mark.parametrize(
    ("step_id", "key", "typed", "said"),
    [
        ("task12", "own.T", "57 ms", "your T: yours 57 ms"),
        ("task11", "own.omega_step", "7,8", "your omega_ss in the steps: yours 7.8 rad/s"),
        ("task13", "own.J", "0,0013", "your J: yours 0.0013 kg m^2"),
    ],
)
async def test_an_answer_brings_its_comparison_into_view(quiet, step_id, key, typed, said):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, step_id)
        pane = app.screen.query(StepPane).last()
        row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
        assert typing_box(app) is row.input
        await pilot.press(*typed, "enter")
        compare = app.screen.query_one("#compare")
        await settle(pilot, lambda: said in str(compare.render()))
        await settle(pilot)
        assert _visible(pane, compare), (pane.scroll_y, compare.region, pane.region)
        assert _visible(pane, row)
