"""Issue 20, left by stop 34 (s34-fix's crowding rule): a single notice taller than the room
on either side of the entry with the keys and the row judged last still covered one of them
at 80x24 (the crowding rule only takes the oldest of two away). Now the step scrolls those
rows out from under it when it can, and else the notice is made wider, so fewer rows, and
the step scrolls if it must; the notice says all it said."""

from __future__ import annotations

import pytest
from textual.geometry import Region

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, lab_screen, settle, start

LONG = "a notice long enough to wrap over several lines of a half screen: " * 4


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _toasts(app) -> list[tuple[str, Region]]:
    return [(str(t.render()), t.region) for t in app.screen.query("Toast")]


@pytest.mark.parametrize("scroll", [2, 4])
async def test_one_tall_notice_leaves_the_entries_in_sight(quiet, scroll):
    """Task 5, '30,1' then Enter: the 2.5 V reading judged, the keys on the 3.5 V row; the
    step scrolled by 2 or by 4 rows, as it is left then by one timing or another. A notice
    nine rows tall at half the screen's width covered the judged row (at the top, scrolled
    by 2) or the 3.5 V entry (at the bottom, scrolled by 4)."""
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        await pilot.press(*"30,1")
        await pilot.pause()
        await pilot.press("enter")
        await settle(pilot)
        pane = lab_screen(app).pane
        pane.scroll_to(y=scroll, animate=False, immediate=True)
        await settle(pilot)
        judged, keyed = _row(app, "i_ss@2.5"), _row(app, "i_ss@3.5")
        assert judged.message == "read as 30.1 mA" and pane.current is keyed
        app.notify(LONG, title="one kind", timeout=600)
        await settle(pilot)
        (text, notice), *more = _toasts(app)
        assert not more
        assert " ".join(text.split()) == " ".join(("one kind " + LONG).split())  # all of it
        for row in (judged, keyed):
            assert row.region.height > 0
            assert not notice.overlaps(row.region), (notice, row.field.key, row.region)
            # and the row is not under the lines docked at the step's bottom either
            assert row.region.bottom <= app.screen.query_one(".readout").region.y
