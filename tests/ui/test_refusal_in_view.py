"""Issue 20, walk 5, item 11 (not reproduced): on Task 4 at 80x24 a refusal's line ended up
under the readout docked at the bottom of the step, likely after something grew once the
refusal had been scrolled into view. What was tried, pinned here: the refusal under the
last entry of Task 4 (the one nearest the readout) stays whole above the readout while the
readout grows line by line (its steady-state lines wrap as the live speed changes) and
while a text refused in a row above lands there (the rows above grow). Pilot, a real
session folder, the device double."""

from __future__ import annotations

from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import burst, enter_all, goto, settle, start


async def test_a_refusal_stays_above_the_readout_when_the_step_grows(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        row = app.screen.query_one(f"#{field_id('u_ss@4.5')}", FieldRow)
        row.input.focus()
        await settle(pilot)
        await burst(pilot, *"3,1x", "enter")
        await settle(pilot)
        msg = row.query_one(".field-msg")
        readout = app.screen.query_one(".readout")
        assert "is not a unit this field takes" in row.message
        assert msg.region.height >= 2 and msg.region.bottom <= readout.region.y
        for lines in (3, 4, 5):  # the readout grows
            app.screen.query_one("#steady", Prose).update("\n".join(["steady"] * lines))
            await settle(pilot)
            assert msg.region.bottom <= readout.region.y, (lines, msg.region, readout.region)
        enter_all(app, {"omega_ss@2.5": "3,1 x", "u_ss@3.5": "3,04 y"})  # rows above grow
        screen = app.screen
        assert isinstance(screen, LabScreen)
        screen._changed()
        await settle(pilot)
        assert msg.region.bottom <= readout.region.y and msg.region.y > 0
