"""Task 14 with no T at all, neither the group's own (Task 12) nor a 63 % reading of the
run: the model is not judged, and it says what it lacks and where to give it, on the screen
and in the report; it no longer takes the least-squares model for the one "computed your
way" (issue 20's leftovers). A real session folder and the seeded plant's run; the run's
63 % reading taken out of its results, as a run with no readable rise has none."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as views
from tests.seeded import record_square_wave
from tests.ui.helpers import TABLE


def test_a_model_with_no_T_to_judge_it_by_says_what_it_needs(tmp_path: Path) -> None:
    with Session.create(tmp_path, ["A B"], date="2026-11-27") as s:
        for key, text in TABLE.items():
            s.enter(key, text)
        assert record_square_wave(s, seed=3) is not None
        s.enter("own.model", "0.057 w' = -w + 1.9 u")
        res = s.results()
        ident = res.identification
        assert ident is not None and ident.step is not None and ident.step.T_63 is not None
        none = replace(res, identification=replace(ident, step=replace(ident.step, T_63=None)))
        (c,) = s.comparisons("task14", none)
        assert c.right is None and c.computed is None and c.least_squares is None
        assert c.verdict == (
            "the model your way needs a T: your own T (Task 12), or a 63 % reading of the "
            "run, which reads none on any rise"
        )
        assert views.under_entry(s, c) == f"○ not judged: {c.verdict}"
        (row,) = [r for r in own_first.step_rows(s, none) if r.key == "own.model"]
        assert row.cells[2] == (
            "not computed: the model the group's way needs a T: the group's own T (Task 12), "
            "or a 63 % reading of the run, which reads none on any rise"
        )
        # the group's own T given: judged with it
        s.enter("own.T", "57 ms")
        (c,) = s.comparisons("task14", none)
        assert c.right is True, c
