"""Issue 20, walk 2: an answer is not lost to a stray key (defect 1), a new value after a
refusal (defect 4; since walk 4 the refused text is kept to be mended, and Ctrl+U clears
it), and R stands as the group typed it (defect 11). Each through the real TUI (Pilot)."""

from __future__ import annotations

from textual.widgets import DataTable

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    heard_notifications,
    settle,
    start,
    type_in,
    typing_box,
)


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _stored(app, key: str):
    with app.session as s:
        return s.entry(key)


async def _on_task2(pilot) -> None:
    """A new session, on Task 2 (R)."""
    await start(pilot)
    await goto(pilot, "task2")


async def _back_on_task2_with_r(pilot) -> None:
    """R typed as 5,3 on Task 2, then Task 1 and back: the revisited step, landed in R."""
    await _on_task2(pilot)
    await type_in(pilot, "R", "5,3")
    await goto(pilot, "task1")
    await goto(pilot, "task2")


async def test_escape_brings_back_the_answer_a_stray_key_replaced(quiet):
    """Walk 2, defect 1: the revisited step lands with its answer selected; a stray key
    replaced it, and Escape did not bring it back."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _back_on_task2_with_r(pilot)
        history = len(_stored(app, "R").history)
        await pilot.press("7")
        await settle(pilot)
        assert _row(app, "R").input.value == "7"
        await pilot.press("escape")
        await settle(pilot)
        assert _row(app, "R").input.value == "5,3"
        await pilot.press("pagedown")
        await settle(pilot)
        entry = _stored(app, "R")
        assert entry.text == "5,3" and len(entry.history) == history  # nothing stored


async def test_a_stray_key_stored_by_pgdn_is_said_and_ctrl_z_brings_the_answer_back(quiet):
    """Walk 2, defect 1: one stray key, then PgDn, stored the key in place of R without a
    word, and Ctrl+Z did nothing."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _back_on_task2_with_r(pilot)
        said = heard_notifications(app)
        await pilot.press("7", "pagedown")
        await settle(pilot)
        assert _stored(app, "R").text == "7"  # kept, as anything left in a field is
        assert any("'5,3'" in s and "Ctrl+Z" in s for s in said), said
        await goto(pilot, "task2")
        await pilot.press("ctrl+z")
        await settle(pilot)
        assert _stored(app, "R").text == "5,3"
        assert _row(app, "R").input.value == "5,3"
        assert typing_box(app) is _row(app, "R").input


async def test_after_a_refusal_ctrl_u_clears_the_box_for_a_new_value(quiet):
    """Walk 2, defect 4 asked that a value typed after a refusal replace the refused text
    (it was left selected); walk 4 tripped on that: the ')' typed to mend a formula replaced
    it. Issue 20 settles it: the refused text stays, the cursor at its end, and keys edit it
    (Backspace one character); Ctrl+U clears the box for a new value, Escape takes it back."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_task2(pilot)
        row = await type_in(pilot, "R", "5.3 V")
        assert row.has_class("refused")
        await pilot.press("ctrl+u", *"5,3", "enter")
        await settle(pilot)
        assert _stored(app, "R").text == "5,3" and not row.has_class("refused")
        row = await type_in(pilot, "R", "5.3 V")
        assert row.has_class("refused")
        await pilot.press("left", "backspace")
        await settle(pilot)
        assert row.input.value == "5.3V"


async def test_r_typed_with_a_decimal_comma_shows_its_own_digits_in_the_formula(quiet):
    """Walk 2, defect 11: R typed as 5,3 was shown as 5.30 Ω in the table's formula."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_task2(pilot)
        await type_in(pilot, "R", "5,3")
        enter_all(app, {k: v for k, v in TABLE.items() if k != "R"})
        await goto(pilot, "table")
        table = app.screen.query_one("#table", DataTable)
        table.focus()
        table.move_cursor(row=0, column=4)
        await pilot.press("f7")
        await settle(pilot)
        text = str(app.screen.query_one("#formula").render())
        assert "- 5.3 Ω ×" in text and "5.30" not in text
