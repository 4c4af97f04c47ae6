"""Task 10's view of the recorded runs is built once a run: showing the step again (or any
entry that changes the lab while it shows) hands back the runs' fits already made, instead
of fitting 2400 samples three times over (about 0.4 s a time, in the walk's session)."""

from __future__ import annotations

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from tests.ui.helpers import record_response_run


def test_a_runs_view_is_built_once_and_again_for_a_new_run(tmp_path):
    with Session.create(tmp_path / "sessions", ["Ada"], "2024-04-16") as s:
        first = record_response_run(s)
        (a,) = views.runs(s)
        (b,) = views.runs(s)
        assert a.name == first and b is a  # the same view, not fitted again
        second = record_response_run(s, seed=6)
        again, c = views.runs(s)  # every run is listed; the new one in use
        assert c.name == second and c is not a and c.in_use and not again.in_use
        assert again.name == first and again.t is a.t  # marked anew, not fitted again
