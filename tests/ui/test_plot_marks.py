"""Issue 20, item 5 and a walk at 80x24: Task 12's zoom puts the crossing marker on the column
of its value (it sat up to a column left of it: plotext cuts a value down to its column), and
the speed stays visible where it crosses the 63 % line (the dashes were drawn over it)."""

from __future__ import annotations

import pytest

from minseg_tui.ui.panels.results import ResponsePlot
from minseg_tui.ui.widgets.plots import Canvas
from tests.ui.helpers import enter_all, settle, start_with_a_run

BRAILLE = range(0x2801, 0x2900)  # a braille cell with at least one dot


def _lines(canvas: Canvas) -> list[str]:
    return str(canvas.render()).split("\n")


def _axis(lines: list[str]) -> tuple[dict[int, float], int]:
    """The x axis: {column of a tick: its value} and the row of the axis line."""
    row = next(k for k, ln in enumerate(lines) if "└" in ln)
    cols = [c for c, ch in enumerate(lines[row]) if ch == "┬"]
    labels = lines[row + 1].split()
    assert len(cols) == len(labels)
    return dict(zip(cols, map(float, labels), strict=True)), row


async def _zoomed(pilot) -> Canvas:
    app = pilot.app
    await start_with_a_run(pilot, "task12")
    enter_all(app, {"own.T": "57"})  # the crossing shows once the group has its T
    app.lab_changed.publish(None)
    await settle(
        pilot, lambda: "crossing" in {t.label for t in app.screen.query_one(ResponsePlot).traces}
    )
    return app.screen.query_one(ResponsePlot).query_one(Canvas)


@pytest.mark.parametrize("size", [(80, 24), (120, 40), (100, 30)])
async def test_the_crossing_marker_stands_where_the_speed_crosses_the_63_percent_line(quiet, size):
    """The marker is on its value's column of the axis (plotext rounds a value to its
    column: the first data column plus round((width - 1) (t - lo) / (hi - lo))), and the
    speed is seen crossing the level's line there, within a column."""
    app = quiet()
    async with app.run_test(size=size) as pilot:
        canvas = await _zoomed(pilot)
        (crossing,) = [t for t in canvas.traces if t.label == "crossing"]
        lines = _lines(canvas)
        _, axis = _axis(lines)
        cols = {c for ln in lines[:axis] for c, ch in enumerate(ln) if ch == "|"}
        assert len(cols) == 1, cols
        (col,) = cols
        top = next(ln for ln in lines if "┌" in ln)
        first, last = top.index("┌") + 1, top.index("┐") - 1
        lo, hi = canvas.xlim or (0.0, 0.0)
        exact = first + (last - first) * (float(crossing.x[0]) - lo) / (hi - lo)
        assert abs(col - exact) <= 0.5, (col, exact)
        # the 63 % level: a row of braille dots across the data area (walk 18, D3)
        (row,) = [
            ln for ln in lines[:axis] if sum(ord(ch) in BRAILLE for ch in ln) > 0.9 * (last - first)
        ]
        seen = [c for c, ch in enumerate(row) if ord(ch) in BRAILLE]
        assert seen and min(abs(c - col) for c in seen) <= 1, (row, col)
