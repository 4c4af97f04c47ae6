"""Issue 20, what stop 36 left (item 3 of /work/coord/B37-fix.md): on Task 12 at 80x24,
Ctrl+R scrolled the step by 14 rows to bring the comparisons under the entry into view, and
the plot the group reads T from went off the screen. The group is reading that plot: a
reveal on a plot zoomed to a rise (Tasks 11-12) leaves it in view, the entry too, and the
values revealed show on the plot's own lines; the comparisons come into view once the
group answers."""

from __future__ import annotations

import pytest

from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import burst, lab_screen, settle, start_with_a_run, type_in


def _in_view(app, widget, title_rows: int = 0) -> bool:
    """``widget`` is wholly on screen in the step, below its heading and above the footer,
    but for its first ``title_rows`` (a plot's title, which the heading covers as the step
    lands at 80x24)."""
    pane = lab_screen(app).pane
    view = pane.scrollable_content_region
    r = widget.region
    return bool(r) and r.y + title_rows >= view.y + pane.heading_rows and r.bottom <= view.bottom


def _frame_in_view(app, plot) -> bool:
    """The plot's data rows, axes, ticks and legend wholly on screen: all but its title line
    and the frame's top border (Task 11's reveal adds a line to the plot's caption, and the
    entry under it, kept whole in view, scrolls the step by that one row)."""
    return _in_view(app, plot, title_rows=2)


@pytest.mark.parametrize(
    ("step_id", "shown"),
    [("task12", "ms after the edge"), ("task11", "63 % of the change is")],
)
async def test_ctrl_r_on_a_rise_being_read_keeps_the_plot_in_view(quiet, step_id, shown):
    """Ctrl+R at 80x24 on Tasks 11-12, the keys in the entry under the plot: the plot's frame
    stays whole on screen, as does the entry; the revealed values are on the plot's lines."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, step_id)
        screen = lab_screen(app)
        plot = screen.query_one("#plot-log")
        row = screen.pane.typing
        assert row is not None
        assert _frame_in_view(app, plot) and _in_view(app, row.input)
        note = screen.query_one("#zoom-note", Prose)
        assert shown not in note.text
        await burst(pilot, "ctrl+r")
        await settle(pilot, lambda: shown in note.text)
        with app.session as s:
            assert s.revealed()
        assert _frame_in_view(app, plot), (plot.region, screen.pane.scroll_y)
        assert _in_view(app, row.input), (row.input.region, screen.pane.scroll_y)


async def test_the_comparison_comes_into_view_once_t_is_answered(quiet):
    """After Ctrl+R on Task 12 the group reads T off the plot and types it: Enter brings the
    comparison of their T under the entry into view, as an answer does."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await burst(pilot, "ctrl+r")
        await settle(pilot)
        with app.session as s:
            T_63 = s.results().step.T_63
        await type_in(pilot, "own.T", f"{T_63 * 1e3:.3g} ms")
        compare = app.screen.query_one("#compare")
        assert "yours" in str(compare.render())
        pane = lab_screen(app).pane
        view = pane.scrollable_content_region
        assert view.y + pane.heading_rows <= compare.region.y < view.bottom, compare.region
