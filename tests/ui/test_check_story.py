"""Issue 20, item 4: the model check a second-year student can read. Under the close-up, two
or three sentences about it (what the first-order model gets wrong at its step, the cause in
everyday words, the gain in one figure); the criteria, the whitened residual, the intervals
and the noise floors wait in a fold that Enter opens."""

from __future__ import annotations

import re

from textual.widgets import Collapsible

from minseg_tui.ui.panels.model_check import ModelCheckPanel
from minseg_tui.ui.widgets.plots import TracePlot
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import settle, start_with_a_run

JARGON = ("whitened", "criterion", "coulomb_friction", "# cpr", "sample times", "noise floor")


async def test_the_model_check_leads_with_sentences_about_its_close_up(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        story = app.screen.query_one("#check-story", Prose).text
        for word in JARGON:
            assert word not in story, word
        assert "Likely cause: dry friction" in story and "constant braking torque" in story
        assert re.search(r"falls from [0-9.]+ rad to [0-9.]+ rad, [0-9.]+ times smaller", story)
        # the step the words speak of is the one the close-up shows (a walk read 'drop at
        # t = 4.650 s' beside a close-up of 1.6-1.9 s)
        m = re.search(r"drops from [0-9.]+ V to 0 V at t = ([0-9.]+) s", story)
        assert m is not None
        lo, hi = app.screen.query_one("#plot-check", TracePlot)._canvas.xlim or (0.0, 0.0)
        assert lo < float(m.group(1)) < hi


async def test_the_details_wait_in_a_fold_that_enter_opens(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        fold = app.screen.query_one("#check-details", Collapsible)
        lines = app.screen.query_one("#check-lines", Prose)
        assert fold.collapsed and lines.region.height == 0
        # all of it, folded; in a student's words, the specialist's left to the CLI
        assert "wheel angle drifts" in lines.text and "whitened" not in lines.text
        await pilot.press("tab")  # from the step's text to the fold's title
        await settle(pilot)
        assert app.focused is not None and fold in app.focused.ancestors
        await pilot.press("enter")
        await settle(pilot)
        assert not fold.collapsed and lines.region.height > 0
        assert app.screen.query_one(ModelCheckPanel).close_up  # Enter did not zoom or move


async def test_the_details_name_the_model_simulated_and_whose_T_tasks_11_12_show(quiet):
    """The walk of 11-27: nothing on the screen said which first-order model the check
    simulated, and its T was read as the group's. The details give the check's own fit with
    its parameters, and say the T of Tasks 11-12 it differs from is the program's
    least-squares reading, not the group's."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        story = app.screen.query_one("#check-story", Prose).text
        assert re.search(
            r"the first-order model the check fitted to this run \(T = [0-9.]+ ms, "
            r"K = [0-9.]+ rad/s/V\)",
            story,
        ), story
        lines = app.screen.query_one("#check-lines", Prose).text
        assert re.search(
            r"The simple model, the first-order line on the plots, is the first-order model the "
            r"check fitted to this run "
            r"itself and ran on the recorded voltage: T = [0-9.]+ ms, K = ",
            lines,
        ), lines
        assert (
            "The program's least-squares reading of the run used in Tasks 11-12 (not the "
            "group's own values) gives T = " in lines
        ), lines
