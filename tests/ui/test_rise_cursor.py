"""A walk at 80x24: Task 12's T read off the zoomed rise came out 40 ms, -30 % from the 63 %
reading (56.9 ms): a column of the 0.375 s zoom was 7.2 ms, the 63 % line's row 1.5 rad/s
tall, and the speed crossed that row over four columns. Task 12 now zooms on the first few
T (3.8 ms a column) and a cursor, moved with the arrow keys on the plot, prints t and the
plotted omega at its column: the group reads T to a column, and the cursor gives the log's
values, never the program's T."""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

import numpy as np
import pytest

from minseg_tui.ui.panels.results import ResponsePlot, ResultsPanel
from minseg_tui.ui.widgets.plots import Canvas
from tests.ui.helpers import burst, settle, start_with_a_run


@asynccontextmanager
async def _task12(quiet) -> AsyncIterator[tuple]:
    """The lab at 80x24 on Task 12 with the seeded step run: (app, pilot, the results panel,
    its zoomed plot)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        panel = app.screen.query_one(ResultsPanel)
        yield app, pilot, panel, panel.query_one(ResponsePlot)


def _frame(canvas: Canvas) -> tuple[int, int]:
    """The first and the last column of the plot's data area, read off the drawn frame."""
    top = next(ln for ln in str(canvas.render()).split("\n") if "┌" in ln)
    return top.index("┌") + 1, top.index("┐") - 1


def _cursor_column(canvas: Canvas) -> int:
    """The one column the cursor's line '┆' stands on, in the canvas."""
    lines = str(canvas.render()).split("\n")
    cols = {c for ln in lines for c, ch in enumerate(ln) if ch == "┆"}
    assert len(cols) == 1, cols
    return cols.pop()


async def test_the_cursor_reads_T_to_a_few_ms_at_80x24(quiet):
    async with _task12(quiet) as (app, pilot, panel, plot):
        canvas = plot.query_one(Canvas)
        view = panel.view
        assert view is not None and "own.T" in view.hidden  # the group has no T yet
        rise = view.rises[0]
        lo, hi = canvas.xlim or (0.0, 0.0)
        first, last = _frame(canvas)
        ms_per_column = 1000 * (hi - lo) / (last - first)
        assert ms_per_column <= 4.0, ms_per_column  # 7.2 ms on the 0.375 s zoom
        await pilot.press("shift+tab")  # from the group's T to the plot
        await settle(pilot)
        assert app.focused is plot and panel.reading is not None
        assert abs(panel.reading.t) <= 1e-3 * ms_per_column  # it starts on the edge
        # the group moves it right until the speed reaches the 63 % line
        for _ in range(last - first):
            if panel.reading.omega >= rise.level:
                break
            await pilot.press("right")
            await settle(pilot)
        reading = panel.reading
        assert reading.omega >= rise.level
        assert rise.T_63 is not None
        assert abs(reading.t - rise.T_63) <= 1e-3 * ms_per_column, (reading.t, rise.T_63)
        # the cursor's line stands on the column of its time, and prints the plotted line's
        # value there: the straight line between the two samples around it
        exact = first + (last - first) * (reading.t - lo) / (hi - lo)
        assert abs(_cursor_column(canvas) - exact) <= 0.5
        x = view.t - rise.t0
        assert reading.t_before <= reading.t <= reading.t_after
        assert reading.omega == pytest.approx(float(np.interp(reading.t, x, view.omega)))
        said = str(panel.query_one("#cursor").render())
        assert "ms after the edge" in said and "rad/s" in said
        # the program's T stays hidden until the group enters its own
        assert "crossing" not in {t.label for t in plot.traces}
        assert all("T (63 %)" not in line for line in view.lines)


async def test_shift_arrows_jump_and_the_cursor_stays_in_the_plot(quiet):
    async with _task12(quiet) as (app, pilot, panel, plot):
        plot.focus()
        await settle(pilot)
        start = panel.cursor
        assert start is not None
        await pilot.press("shift+right")
        await settle(pilot)
        assert panel.cursor == start + 5
        first, last = plot.columns or (0, 0)
        for _ in range(last - first + 5):
            await pilot.press("shift+right")
        await settle(pilot)
        assert panel.cursor == last - first  # the last column, not past it
        await pilot.press("left")
        await settle(pilot)
        assert panel.cursor == last - first - 1


async def test_a_click_on_the_rise_puts_the_cursor_on_that_column(quiet):
    async with _task12(quiet) as (app, pilot, panel, plot):
        first, _last = _frame(plot.query_one(Canvas))
        await pilot.click(ResponsePlot, offset=(first + 20, 6))
        await settle(pilot)
        assert app.focused is plot
        assert panel.cursor == 20 and panel.reading is not None
        assert _cursor_column(plot.query_one(Canvas)) == first + 20


async def test_the_plots_own_characters_act_on_it_and_type_nothing(quiet):
    """On the focused plot, ] and [ pick the next and the previous rise and z shows the whole
    log or the rise again, typed one by one or in one burst; none of them goes into an
    entry. The step form took every character a plot passed up for the first empty entry,
    before Textual ran the plot's binding: z typed 'z' into the group's T."""
    async with _task12(quiet) as (app, pilot, panel, plot):
        form = app.screen.pane
        await pilot.press("shift+tab")  # from the group's T to the plot
        await settle(pilot)
        assert app.focused is plot and panel.zoom == 0
        await pilot.press("right_square_bracket")
        await settle(pilot)
        assert panel.zoom == 1
        await pilot.press("left_square_bracket", "z")
        await settle(pilot)
        assert panel.zoom is None
        await burst(pilot, "z", "right_square_bracket")
        assert panel.zoom == 1
        assert all(not r.input.value for r in form.rows() if not r.field.options)
