"""Walk 9's defects (issue 20), each with the keys the tester typed, Pilot at 80x24 on a real
session folder."""

from __future__ import annotations

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, settle, start, stored_text


def _said(app, key: str) -> str:
    row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
    return " ".join(row.message.split())


async def test_a_share_typed_as_a_fraction_is_quoted_as_typed_never_as_the_answer(quiet):
    """D1: on Prep 5 every fraction below 1 got "that reads as 0.63 %: type the percentage,
    63 %": the group's value misquoted and the answer given away. Keys as walked: '0.63'
    Enter, Ctrl+U '0.5' Enter, Ctrl+U '0.9' Enter."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep5")
        said = []
        for typed in ("0.63", "0.5", "0.9"):
            await pilot.press("ctrl+u", *typed, "enter")
            await settle(pilot)
            said.append(_said(app, "prep5.percent"))
        assert "that reads as 0.63 %: did you mean 63 %?" in said[0]
        assert "that reads as 0.5 %: did you mean 50 %?" in said[1]
        assert "that reads as 0.9 %: did you mean 90 %?" in said[2]
        for line in said[1:]:
            assert "63" not in line, line
        assert stored_text(app, "prep5.percent") == "0.9"
