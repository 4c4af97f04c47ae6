"""Walk 7's grading defects on the screen (Pilot at 80x24, a real session folder, the seeded
plant's step run): K divided by the requested 4.5 V marked wrong by name (D6), a table with
a negative k_v keeping the run and the 63 % reading (D14), Task 14's model resting on a
wrong T marked "!" (the observation), exponent notation echoed and an implausible T warned
(D13, T)."""

from __future__ import annotations

from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    nav_mark,
    record_response_run,
    start,
    start_with_a_run,
    type_in,
)


def _text(app, selector: str) -> str:
    return str(app.screen.query_one(selector).render())


async def test_K_over_the_requested_voltage_is_marked_wrong_by_name(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7,9")
        row = await type_in(pilot, "own.K", "1,76")  # 7.9 / 4.5; u_ss at 4.5 V is 4.02 V
        assert "\n✗ wrong" in row.message, row.message
        assert "this is omega_ss / 4.5 V, the requested voltage" in row.message
        assert "u_ss = 4.02 V" in row.message
        assert nav_mark(app, "task11") == "✗"
        row = await type_in(pilot, "own.K", "1,97")  # 7.9 / 4.02
        assert "\n✓ right" in row.message, row.message
        assert nav_mark(app, "task11") == "✓"


async def test_a_negative_k_v_keeps_the_run_on_tasks_11_and_12(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE | {"i_ss@2.5": "4.7 A", "i_ss@3.5": "4.7 A"})
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task12")
        row = await type_in(pilot, "own.T", "56 ms")
        assert row.message.startswith("✓ right"), row.message
        note = _text(app, "#zoom-note")
        assert "no run recorded yet" not in note and "steps-1" in note, note
        lines = _text(app, "#results-lines")
        assert "T (63 %) = " in lines and "J: waits for R, k_v and f" in lines
        assert "positive k_v" in lines


async def test_a_model_resting_on_a_wrong_T_is_not_a_plain_tick(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7,9")
        await type_in(pilot, "own.K", "1,97")
        await goto(pilot, "task12")
        await type_in(pilot, "own.T", "85 ms")
        assert nav_mark(app, "task12") == "✗"
        await goto(pilot, "task14")
        row = await type_in(pilot, "own.model", "0,085 omega' = -omega + 1,97 u_A")
        assert "✓ right: T = 85 ms and K = 1.97 rad/s/V" in row.message, row.message
        assert "consistent with your T and K, and your T was marked wrong (Task 12)" in (
            row.message.replace("\n", " ")
        )
        assert nav_mark(app, "task14") == "!"


async def test_exponent_notation_is_echoed_and_a_T_of_57_s_warned(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task2")
        row = await type_in(pilot, "R", "1e3")
        assert "read as 1000 Ω" in row.message, row.message
        await goto(pilot, "task12")
        row = await type_in(pilot, "own.T", "57 s")
        assert "tens of ms" in row.message and row.has_class("warned"), row.message
