"""Walk 7, D5: a step opened again (PgDn, PgUp) showed its first entry's box empty although
it held the stored value. The box scrolled its text out of view while it had no width yet
(its text selected as the step opened), drew that at its new size, and scrolled it back on
the Resize message without drawing again: the terminal kept the empty line (Pilot, every
frame painted as in a terminal)."""

from __future__ import annotations

import pytest
from textual.strip import Strip

from minseg_tui.ui.widgets.fields import EntryBox, FieldRow, field_id
from tests.ui.helpers import goto, settle, start, type_in


@pytest.mark.slow  # every frame painted: the empty line is a painted one
async def test_a_step_opened_again_never_draws_its_first_box_empty(quiet, monkeypatch):
    drawn: list[str] = []  # every first line the boxes drew after the step opened again
    render_line = EntryBox.render_line

    def drawing(self: EntryBox, y: int) -> Strip:
        strip = render_line(self, y)
        if y == 0 and self.value == "5,3":
            drawn.append(strip.text)
        return strip

    monkeypatch.setattr(EntryBox, "render_line", drawing)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await type_in(pilot, "R", "5,3")
        await pilot.press("pagedown")
        await settle(pilot)
        drawn.clear()
        await pilot.press("pageup")
        await settle(pilot)
        box = app.screen.query_one(f"#{field_id('R')}", FieldRow).input
        assert box.value == "5,3"
    # the box is 30-odd cells wide: '5,3' fits, and every line drawn of it shows it
    assert drawn, "the box of R was not drawn"
    assert all("5,3" in line for line in drawn), drawn
