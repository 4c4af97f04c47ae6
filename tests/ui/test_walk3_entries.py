"""Issue 20, walk 3's defects 5, 6, 7 and 9 (units and entries): the list of steps marks a
step whose field holds a refused text, Enter leaves the cursor at the end of an accepted
value, Escape, Ctrl+Z and Ctrl+Y say and do what they bring back, and the palette and the
preparations' marks. Each through the real TUI (Pilot), judged by what the screen shows and
what the session stores."""

from __future__ import annotations

from textual.widgets import OptionList

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, settle, start, type_in


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _mark(app, step_id: str) -> str:
    nav = app.screen.query_one("#nav", OptionList)
    return str(nav.get_option(step_id).prompt)[0]


async def test_a_refused_text_takes_the_tick_away_until_corrected_or_escaped(quiet):
    """Walk 3, defect 5: R accepted, then '5.3 V' refused over it: the list of steps still
    showed Task 2's ✓ (the mark of the answer still in effect)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await type_in(pilot, "R", "5,3")
        assert _mark(app, "task2") == "✓"
        row = await type_in(pilot, "R", "5.3 V")
        assert row.has_class("refused")
        assert _mark(app, "task2") == "?"
        await pilot.press("escape")
        await settle(pilot)
        assert _mark(app, "task2") == "✓"
        assert row.input.value == "5,3" and row.message == "" and not row.has_class("refused")
        with app.session as s:
            entry = s.entry("R")
            assert entry is not None and entry.text == "5,3" and entry.refused is None
        await type_in(pilot, "R", "5.3 V")
        assert _mark(app, "task2") == "?"
        await type_in(pilot, "R", "5,2")
        assert _mark(app, "task2") == "✓"


async def test_a_refused_first_answer_is_marked_and_escape_empties_the_field(quiet):
    """Nothing accepted yet: the refused text is the step's only entry; Escape takes it back
    and the step is as it was, unmarked."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "five")
        assert _mark(app, "task2") == "?"
        await pilot.press("escape")
        await settle(pilot)
        assert _mark(app, "task2") == " " and row.input.value == "" and row.message == ""
        with app.session as s:
            assert s.entry("R") is None


async def test_after_enter_a_digit_typed_goes_on_after_the_accepted_value(quiet):
    """Walk 3, defect 6: '2*pi/72' Enter, then '0' to make it 2*pi/720, replaced the value
    with '0' (the text stayed selected after Enter). A refused text still stays selected: the
    next value replaces it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep10")
        row = await type_in(pilot, "prep10.gain", "2*pi/72")
        assert not row.has_class("refused") and _mark(app, "prep10") == "✗"
        await pilot.press("0", "enter")
        await settle(pilot)
        assert row.input.value == "2*pi/720" and _mark(app, "prep10") == "✓"
        with app.session as s:
            assert s.entry("prep10.gain").text == "2*pi/720"  # type: ignore[union-attr]
        row = await type_in(pilot, "prep10.gain", "2*pi/")
        assert row.has_class("refused")
        await pilot.press(*"2*pi/720", "enter")
        await settle(pilot)
        assert row.input.value == "2*pi/720" and not row.has_class("refused")
