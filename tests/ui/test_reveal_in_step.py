"""Ctrl+R (a lab assistant shows a step's computed values before the group answers) says so
in the step's own text, not in a notice over the step (issue 20: on Task 12 at 80x24, its
notice "computed values shown; the report says they were revealed before answering" covered
the step's title and three rows of the plot the group reads T from, for 5 s). Each value
shown is marked in the comparisons under the entries, which the step brings into view
(Tasks 13-15; on Tasks 11-12 the plot being read stays, tests/ui/test_reveal_keeps_plot.py):
"revealed before answering (Ctrl+R): the report says so"."""

from __future__ import annotations

import pytest

from tests.ui.helpers import burst, heard_notifications, lab_screen, settle, start_with_a_run

SAID = "revealed before answering (Ctrl+R): the report says so"


@pytest.mark.parametrize("step_id", ["task11", "task12", "task13", "task14", "task15"])
async def test_ctrl_r_is_said_in_the_step_not_over_it(quiet, step_id):
    """Ctrl+R on each of Tasks 11-15 at 80x24, the keys in the step's first entry: no notice
    (none over the step's title or its plot); the comparisons under the entry mark every
    value shown with SAID, in view between the step's heading and the footer on Tasks
    13-15 (on Tasks 11-12 the plot zoomed to a rise stays in view instead); the session
    records them as revealed."""
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start_with_a_run(pilot, step_id)
        said = heard_notifications(app)
        await burst(pilot, "ctrl+r")
        await settle(pilot)
        with app.session as s:
            revealed = s.revealed()
        assert revealed, "Ctrl+R revealed nothing"
        assert said == [] and not app.screen.query("Toast"), said
        pane = lab_screen(app).pane
        compare = app.screen.query_one("#compare")
        lines = str(compare.render()).split("\n")
        assert len([line for line in lines if SAID in line]) == len(revealed), lines
        if step_id in ("task11", "task12"):
            return  # the plot zoomed to a rise, being read, stays in view there instead
            # (tests/ui/test_reveal_keeps_plot.py): the comparisons come into view on Enter
        view = pane.scrollable_content_region
        assert view.y + pane.heading_rows <= compare.region.y, (compare.region, pane.scroll_y)
        assert compare.region.y < view.bottom, (compare.region, view)
