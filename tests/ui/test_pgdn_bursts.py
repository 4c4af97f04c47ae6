"""Issue 20, walk 5, item 9: under load a second PgDn seemed to skip a step. PgDn runs in the
order typed (``fields.after_typed_keys``): each move reads the step it starts from when it
runs, so two PgDn move two steps and one moves one, wherever the focus is. Sent as one
burst (the second PgDn read while the first is still being handled), two PgDn from Task 3
or Task 4 crashed the app: the readout of the step left, already removed, ran a lift
deferred to after the refresh (``Readout._target``: NoScreen). Pilot at 80x24, a real
session folder, the seeded plant's run."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.steps import STEPS
from minseg_tui.ui.screens.lab import StepPane
from tests.ui.helpers import burst, goto, settle, start_with_a_run

IDS = [s.id for s in STEPS]
FROM = ("task2", "task3", "task4", "task5", "table", "task10", "task11", "task15")
"""Steps with each kind of panel (none, live plots with the readout, the table, the square
wave, the results, then the model check), PgDn pressed there."""


def _shown(app) -> str:
    return app.screen.query_one(StepPane).step.id


@pytest.mark.parametrize("before", [(), ("tab",)], ids=["entry", "tab"])
async def test_two_pgdn_in_one_burst_move_two_steps_and_one_moves_one(quiet, before):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, FROM[0])
        for step_id in FROM:
            k = IDS.index(step_id)
            await goto(pilot, step_id)
            await burst(pilot, *before, "pagedown", "pagedown")
            await settle(pilot)
            assert _shown(app) == IDS[k + 2], (step_id, before)
            await goto(pilot, step_id)
            await burst(pilot, *before, "pagedown")
            await settle(pilot)
            assert _shown(app) == IDS[k + 1], (step_id, before)
