"""Task 14 says, under the group's model, why it is not judged yet, true to the session:
no run at all (record one in Task 10), or runs that were all interrupted (record a complete
one, or choose one with Ctrl+P), not a bare "nothing computed" (issue 20's leftovers). Pilot
at 80x24, a real session folder, the seeded plant's runs."""

from __future__ import annotations

from tests.seeded import record_square_wave
from tests.ui.helpers import TABLE, enter_all, goto, nav_mark, settle, start, type_in

_MODEL = "0.057 w' = -w + 1.9 u"


def _said(row) -> str:
    return " ".join(row.message.split())


async def test_the_model_without_a_run_says_to_record_one(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task14")
        row = await type_in(pilot, "own.model", _MODEL)
        await settle(pilot)
        assert _said(row) == (
            "○ stored, not judged yet: the value to compare with needs a step run (Task 10)"
        )
        assert nav_mark(app, "task14") == "○"
        assert row.region.bottom <= 23


async def test_the_model_with_only_interrupted_runs_says_what_to_do(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            got = record_square_wave(s, seed=3, periods=1, stopped_early=True, ended_by="quit")
            assert got is not None and got.interrupted and s.response_run() is None
        await goto(pilot, "task14")
        row = await type_in(pilot, "own.model", _MODEL)
        await settle(pilot)
        said = _said(row)
        assert said == (
            "○ stored, not judged yet: the value to compare with needs a complete step run "
            "(Task 10; every run recorded was interrupted: Ctrl+P 'Use run' uses one all the "
            "same)"
        ), said
        assert "needs a step run (Task 10)" not in said
        # the group does as it says: the interrupted run chosen, the model is judged on it
        app.screen.use_run(got.name)
        await settle(pilot)
        await goto(pilot, "task14")
        with app.session as s:
            assert s.response_run() is not None and s.response_run().name == got.name
        assert nav_mark(app, "task14") in ("✓", "✗")
