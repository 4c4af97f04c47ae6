"""Issue 20, walk 4's defects in the entries, each through the real TUI (Pilot) at 80x24:
a refused formula stayed selected, so the missing ')' typed next replaced it; its refusal
said "write products with *" for an unclosed parenthesis."""

from __future__ import annotations

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, settle, start, type_in


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _at_end_unselected(row: FieldRow) -> bool:
    box = row.input
    return box.selection.is_empty and box.cursor_position == len(box.value)


async def test_the_missing_parenthesis_typed_after_a_refusal_completes_the_formula(quiet):
    """Walk 4: '(u_ss - R i_ss' Enter was refused and left selected; ')/omega_ss' typed next
    replaced it. Now the refusal names the unclosed '(' and the text stays, the cursor at
    its end, nothing selected: the rest typed goes on after it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep11")
        row = await type_in(pilot, "prep11.k_v", "(u_ss - R i_ss")
        assert row.has_class("refused")
        assert "a '(' is not closed" in row.message and "products" not in row.message
        assert row.input.value == "(u_ss - R i_ss" and _at_end_unselected(row)
        await pilot.press(*")/omega_ss", "enter")
        await settle(pilot)
        assert not row.has_class("refused"), row.message
        with app.session as s:
            entry = s.entry("prep11.k_v")
        assert entry is not None and entry.text == "(u_ss - R i_ss)/omega_ss"


async def test_one_backspace_after_a_refusal_deletes_one_character_and_escape_withdraws(quiet):
    """Issue 20: one Backspace after a refusal deleted the whole text. Now it deletes the
    last character; Escape still takes the refused text back to the answer in effect."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep10")
        await type_in(pilot, "prep10.gain", "2*pi/720")
        row = await type_in(pilot, "prep10.gain", "2*pi/7200)")
        assert row.has_class("refused") and "has no '(' left to close" in row.message
        assert _at_end_unselected(row)
        await pilot.press("backspace")
        await settle(pilot)
        assert row.input.value == "2*pi/7200"
        await pilot.press("backspace", "enter")
        await settle(pilot)
        assert not row.has_class("refused") and row.input.value == "2*pi/720"
        row = await type_in(pilot, "prep10.gain", "2*pi/")
        assert row.has_class("refused") and "'/' at the end" in row.message
        await pilot.press("escape")
        await settle(pilot)
        assert row.input.value == "2*pi/720" and not row.has_class("refused")
        with app.session as s:
            entry = s.entry("prep10.gain")
        assert entry is not None and entry.text == "2*pi/720" and entry.refused is None
