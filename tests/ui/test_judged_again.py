"""Under an answer of Tasks 11-15 judged again, a line says so, against which run, on which
run it was given and how to go back to it (issue 20's leftovers, walk 9's D10: T answered
on the run in use, then F5: the new run took over and T turned ✗ with no word of why under
it). Pilot at 80x24, a real session folder, the seeded plant's runs."""

from __future__ import annotations

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import answer_T_on_a_run, goto, record_a_square_wave, settle, type_in


def _lines(app, key: str) -> list[str]:
    row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
    return row.message.splitlines()


async def test_an_answer_judged_against_a_newer_run_says_so_under_it(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        first = await answer_T_on_a_run(pilot)
        assert not [line for line in _lines(app, "own.T") if "judged again" in line]
        await goto(pilot, "task10")
        now = await record_a_square_wave(pilot, dev)
        assert now != first
        await goto(pilot, "task12")
        said = " ".join(" ".join(_lines(app, "own.T")).split())
        assert said.endswith(
            f"judged again, against run {now}: you gave it while run {first} was in use; "
            f"Ctrl+P 'Use run {first}' judges it there"
        ), said
        # K given on the new run: judged once, no such line
        await goto(pilot, "task11")
        await type_in(pilot, "own.K", "2.2")
        assert not [line for line in _lines(app, "own.K") if "judged again," in line]
        # back to the run T was given on: the line goes
        app.screen.use_run(first)
        await settle(pilot)
        await goto(pilot, "task12")
        assert not [line for line in _lines(app, "own.T") if "judged again," in line]
