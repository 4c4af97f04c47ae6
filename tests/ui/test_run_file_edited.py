"""Task 12 on a run whose file was edited by hand, one omega changed, as many rows (s38 attack):
the lab's Tasks 11-15 said nothing (the report alone said a row deleted). The line the report
and the class view give stands under the results now (runs.changed_file, the one rule).
A real session folder, resumed in the real TUI through Pilot."""

from __future__ import annotations

from minseg_tui.lab.state.session import Session
from minseg_tui.ui.widgets.prose import Prose
from tests.lab.test_run_checksum import _one_value_changed
from tests.ui.helpers import TABLE, goto, record_response_run, resume, settle


def _results(app) -> str:
    return app.screen.query_one("#results-lines", Prose).text


async def test_task12_says_the_run_file_was_edited(quiet, tmp_path):
    with Session.create(tmp_path / "sessions", ["Ada", "Bo"], date="2024-04-16") as s:
        for key, text in TABLE.items():
            s.enter(key, text)
        name = record_response_run(s)
        path = s.run_path(name)
    _one_value_changed(path)
    async with quiet().run_test(size=(100, 40)) as pilot:
        await resume(pilot)
        await goto(pilot, "task12", focus=None)
        await settle(pilot, lambda: "computing" not in _results(pilot.app))
        text = " ".join(_results(pilot.app).split())
        assert (
            f"! run {name}: its file runs/{name}.csv was changed after the recording (edited "
            "by hand?)"
        ) in text
