"""Issue 18 in the TUI, through Pilot: a step identify cannot use says what is missing (and
the session resumes); names and notes with Rich markup in them shown as typed; a session
file with a long integer listed as damaged beside the sound ones; Task 10 after a run is
saved late."""

from __future__ import annotations

from minseg_tui.lab.session import Session
from minseg_tui.ui.widgets.prose import Prose
from tests.lab.test_identify_guards import CASES, ENTRIES, _log
from tests.ui.helpers import goto, resume, settle


def _results(app) -> str:
    return app.screen.query_one("#results-lines", Prose).text


async def test_a_step_without_k_says_what_is_missing_on_every_resume(quiet, tmp_path):
    """A run whose rising steps end below the driver's drop: a ZeroDivisionError traceback
    on showing Task 11, again on every resume."""
    words, high, how = CASES["below the drop"]
    _log(tmp_path / "log.csv", high, how)
    with Session.create(tmp_path / "sessions", ["Ada"], date="2024-04-16") as s:
        for key, text in ENTRIES.items():
            s.enter(key, text)
        s.import_run(tmp_path / "log.csv")
    for _ in range(2):  # and again after a resume
        async with quiet().run_test(size=(100, 40)) as pilot:
            await resume(pilot)
            await goto(pilot, "task11", focus=None)
            await settle(pilot, lambda: "computing" not in _results(pilot.app))
            text = _results(pilot.app)
            assert words in text and "gives no step result" in text
