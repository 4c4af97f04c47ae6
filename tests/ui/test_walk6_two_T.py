"""Walk 6, items 4 and 5, on the group's screen at 80x24 (Pilot, real session folder, the
seeded plant's step run): Tasks 11-15 said why the 63 % reading and the least-squares T
differ twice, in two different ways ("which is the whole difference. The least-squares fit
models the sampling, so its T is the one the model uses" under the results, a second reason
under Task 12's comparison), and the value the group's T is compared with read "computed
56.89 ms (the 63 % reading, ...)". Now one sentence says it (both fair; yours is graded
against the 63 % reading; the model and its J use the least-squares T; why they differ),
and the compared value is named as the program's reading by the group's method."""

from __future__ import annotations

from minseg_tui.lab.state.compare import two_T_of
from tests.ui.helpers import goto, settle, start_with_a_run, type_in


def _text(app, selector: str) -> str:
    widget = app.screen.query_one(selector)
    return " ".join(str(widget.render()).split()) if widget.display else ""


async def test_tasks_11_to_15_say_why_the_two_T_differ_once(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await type_in(pilot, "own.T", "57 ms")
        await settle(pilot)
        with app.session as s:
            step = s.results().identification.step
        said = " ".join(two_T_of(step).split())
        assert said.startswith("Both are fair readings of T: the 63 % reading (")
        assert "is the one yours is graded against" in said
        assert "is the one the program's model and its J use" in said
        for task in ("task12", "task13"):
            await goto(pilot, task)
            await settle(pilot)
            screen = _text(app, "#compare") + " " + _text(app, "#results-lines")
            assert screen.count("Both are fair readings of T") == 1, (task, screen)
            assert said in screen, (task, screen)
            assert "whole difference" not in screen and "one the model uses" not in screen
            assert "takes one sampled point" not in screen
        await goto(pilot, "task12")
        await settle(pilot)
        compare = _text(app, "#compare")
        assert "(the program's reading by your method: 63 % of each rise of this run" in compare
        assert "(the 63 % reading, median over the rises)" not in compare


async def test_the_table_keeps_T_back_and_points_to_task_12_once_answered(quiet):
    """Tasks 4-9's warnings gave T (42.9 ms) and the 63 % reading (56.9 ms) before the group
    had read T on Task 12, with a third account of why they differ. They now wait for the
    group's T, then give the facts in one warning that points to Task 12."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "table")
        await settle(pilot)
        before = _text(app, "#warnings")
        assert "63 % reading" not in before and "sample periods" not in before, before
        await goto(pilot, "task12")
        await type_in(pilot, "own.T", "57 ms")
        await goto(pilot, "table")
        await settle(pilot)
        after = _text(app, "#warnings")
        assert after.count("Task 12 says it") == 1, after
        assert "63 % reading" in after and "Both are fair" not in after, after
