"""Issue 20, item 1 in the TUI: what the group's screen showed, and when, is recorded in the
session as the views are drawn (Pilot, real session folder, the seeded plant's step run), so
that the report can say "revealed before answering" when the model check came first."""

from __future__ import annotations

import json

from minseg_tui.lab.state import shown as lab_shown
from tests.ui.helpers import goto, settle, start_with_a_run, type_in


def _shown(app) -> dict:
    with app.session as s:
        folder = s.folder
    return json.loads((folder / "session.json").read_text(encoding="utf-8")).get("shown", {})


async def test_opening_the_model_check_before_answering_is_recorded(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        assert _shown(app) == {}  # T hidden on Task 12: nothing shown yet
        await goto(pilot, "model_check", focus=None)
        await settle(pilot, lambda: "own.T" in _shown(app))
        got = _shown(app)
        assert {k: (v["by"], v["answer"]) for k, v in got.items()} == {
            k: (lab_shown.MODEL_CHECK, None) for k in ("own.K", "own.T", "own.model")
        }
        await goto(pilot, "task13")
        await type_in(pilot, "own.J", "0.001")
        await settle(pilot, lambda: "own.J" in _shown(app))
        got = _shown(app)
        assert (got["own.J"]["by"], got["own.J"]["answer"]) == (lab_shown.AFTER_ANSWER, "0.001")
        assert got["own.T"]["by"] == lab_shown.MODEL_CHECK  # the first showing stays
