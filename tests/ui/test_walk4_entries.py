"""Issue 20, walk 4's defects in the entries, each through the real TUI (Pilot) at 80x24:
a refused formula stayed selected, so the missing ')' typed next replaced it; its refusal
said "write products with *" for an unclosed parenthesis."""

from __future__ import annotations

import re

from textual.widgets import DataTable

from minseg_tui.quantities import format_number
from minseg_tui.ui.panels.live import Readout
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import TABLE, enter_all, goto, settle, start, type_in


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


async def test_a_current_that_falls_as_the_voltage_rises_is_warned_beside_its_row(quiet):
    """Walk 4: on Task 5 the readings went in one row off (37.2 mA in the 3.5 V row, 33.5 mA
    in the 4.5 V row) without a word. The row of the higher voltage now says so, names both
    rows and values, and the warning goes once the reading is put right; the table of Tasks
    6-9 lists it among its warnings while it stands."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        await type_in(pilot, "i_ss@2.5", "29,8")
        await type_in(pilot, "i_ss@3.5", "37,2 mA")
        high = await type_in(pilot, "i_ss@4.5", "33,5")
        said = (
            "! i_ss falls from 37.2 mA at 3.5 V to 33.5 mA at 4.5 V, while i_ss should rise a little "
            "with the speed: check that each reading is in its row."
        )
        assert said in high.message and high.has_class("warned"), high.message
        await settle(pilot)
        shown = high.query_one(".field-msg").region  # the whole warning in view: above the
        assert shown.bottom <= app.screen.query_one(Readout).region.y  # lines docked under it
        assert "falls" not in _row(app, "i_ss@3.5").message
        await goto(pilot, "table")
        warnings = app.screen.query_one("#warnings")
        assert said in str(warnings.render()).replace("\n", " ")
        await goto(pilot, "task5")
        await type_in(pilot, "i_ss@3.5", "33,5")  # put right in the other row
        high = _row(app, "i_ss@4.5")
        assert "falls" not in high.message and not high.has_class("warned"), high.message


def _worked(text: str) -> tuple[float, str]:
    """The F7 line 'name = formula = (numbers) = result unit ...' worked out again from the
    numbers it shows, and the result as it shows it."""
    worked = text.split(" = ")[2]
    result, unit = text.split(" = ")[3].split()[:2]
    expr = re.sub(r"\s*(N m/A|V|Ω|A|rad/s)(?=[\s)]|$)", "", worked).replace("×", "*")
    value = float(eval(expr, {"__builtins__": {}}))  # only numbers and + - * / ( ) left
    return value * 1e3 if unit == "mN" else value, result


async def test_f7_shows_inputs_whose_arithmetic_gives_the_result_shown(quiet):
    """Walk 4: F7 on a k_v cell showed omega_ss = 3.82 rad/s (the capture's 3.8247 rounded),
    and (2.05 - 5.3 x 0.0298) / 3.82 is 0.4953, not the 0.4948 shown. Every number on the
    line now has the digits its result needs: worked out again from the text, each k_v and
    f cell's formula gives the result it prints, to its printed digits."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(
            app,
            {
                **TABLE,
                "omega_ss@2.5": "3.8247",
                "i_ss@2.5": "29,8 mA",
                "omega_ss@3.5": "5.80613",
                "omega_ss@4.5": "7.7871",
            },
        )
        await goto(pilot, "table")
        table = app.screen.query_one("#table", DataTable)
        table.focus()
        checked = 0
        for row in range(3):
            for column in (4, 5):
                table.move_cursor(row=row, column=column)
                await pilot.press("f7")
                await settle(pilot)
                text = str(app.screen.query_one("#formula").render()).replace("\n", " ")
                value, shown = _worked(text)
                assert format_number(value, len(shown.replace(".", "").lstrip("0"))) == shown, text
                checked += 1
        assert checked == 6
