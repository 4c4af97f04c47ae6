"""Issue 20, left by stop 34: Task 14's line on the group's model dropped the trailing zeros
they typed ("0,0850 ... 1,970" was "T = 85 ms and K = 1.97 rad/s/V") while every reading
of theirs elsewhere keeps its digits (quantities.format_reading, walk 13's D6)."""

from __future__ import annotations

from tests.ui.helpers import goto, start_with_a_run, type_in


async def test_the_model_line_keeps_the_digits_typed(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7,9")
        await type_in(pilot, "own.K", "1,97")
        await goto(pilot, "task12")
        await type_in(pilot, "own.T", "85 ms")
        await goto(pilot, "task14")
        row = await type_in(pilot, "own.model", "0,0850 omega' = -omega + 1,970 u_A")
        assert "✓ right: T = 85.0 ms and K = 1.970 rad/s/V" in row.message, row.message
        row = await type_in(pilot, "own.model", "0,0400 omega' = -omega + 1,970 u_A")
        assert "T = 40.0 ms where" in row.message, row.message
