"""PgDn and PgUp in a burst (a held key, or the key pressed again while a step with plots
comes up on a slow machine): each press moves exactly one step, never more, wherever the
focus is, however long each step takes to come up."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.steps import STEPS
from minseg_tui.ui.screens.lab import StepPane
from tests.ui.helpers import burst, goto, settle, shown, start_with_a_run

IDS = [s.id for s in STEPS]


async def _focus(pilot, where: str) -> None:
    """Put the focus on the step's entry (as PgDn lands), the list of steps or the step."""
    app = pilot.app
    if where == "nav":
        await pilot.press("ctrl+l")
    elif where == "pane":
        app.screen.set_focus(app.screen.query(StepPane).last())
    await settle(pilot)


@pytest.mark.parametrize("where", ["entry", "nav", "pane"])
async def test_pgups_in_a_burst_move_back_one_step_each_from_the_results(quiet, where):
    """Seen in the walk: on Tasks 11-15 a step change took about 0.75 s, and PgUps pressed
    meanwhile seemed to overshoot. Four PgUps from the model check go back four steps."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await _focus(pilot, where)
        await burst(pilot, "pageup", "pageup", "pageup", "pageup")
        assert shown(app, "task12")


async def test_pgdns_and_pgups_in_one_burst_end_where_they_add_up_to(quiet):
    """Three PgDn, one Ctrl+B (PgUp's other key), one Ctrl+N and two PgUp from Task 11: one
    step forward in all, each key one step, the views of the steps passed through built
    (or given up) on the way."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        keys = ["pagedown"] * 3 + ["ctrl+b", "ctrl+n", "pageup", "pageup"]
        await burst(pilot, *keys)
        assert shown(app, "task12")
        with app.session as s:
            assert s.current_step == "task12"
        assert app.screen.query_one("#nav").highlighted == IDS.index("task12")


async def test_pgups_past_the_first_step_stop_at_it(quiet):
    """More PgUps than steps before: the lab stays at the first step (no wrap to the end)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "prep2")
        await burst(pilot, *["pageup"] * 3)
        assert shown(app, IDS[0])
        await goto(pilot, IDS[-2])
        await burst(pilot, *["pagedown"] * 3)
        assert shown(app, IDS[-1])
