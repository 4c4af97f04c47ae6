"""Walk 18's D3: on Task 12 at 80x24 the 63 % level is drawn at its own height, one braille
dot high, leaving the cells the speed passes through to the speed, not as a dashed text row (1.5 rad/s a row): a
group reading T where the speed meets the line read it 4 columns (10 ms, -19 %) early."""

from __future__ import annotations

import pytest

from minseg_tui.ui.panels.results import ResponsePlot
from minseg_tui.ui.widgets.plots import BRAILLE_BASE, DOT_ROW_BITS, Canvas
from tests.ui.helpers import enter_all, settle, start_with_a_run


def _braille(ch: str) -> int | None:
    """The dots of a braille cell as bits (None: not braille)."""
    return ord(ch) - BRAILLE_BASE if BRAILLE_BASE <= ord(ch) <= BRAILLE_BASE + 0xFF else None


def _area(lines: list[str]) -> tuple[int, int, int, int]:
    """The data area: its first and last text row, its first and last column."""
    top = next(k for k, ln in enumerate(lines) if "┌" in ln)
    bottom = next(k for k, ln in enumerate(lines) if "└" in ln)
    return top + 1, bottom - 1, lines[top].index("┌") + 1, lines[top].index("┐") - 1


def _level(lines: list[str]) -> tuple[int, int]:
    """The (text row, dot row from the top) of the line drawn across the data area: the one
    dot row that all but a few cells of a text row have (the cells the speed passes through
    are the speed's, the marks of the cursor and the input aside)."""
    r0, r1, c0, c1 = _area(lines)
    width = c1 - c0 + 1
    found = [
        (r, d)
        for r in range(r0, r1 + 1)
        for d, bits in enumerate(DOT_ROW_BITS)
        if sum((b := _braille(lines[r][c])) is not None and b == bits for c in range(c0, c1 + 1))
        > 0.75 * width
    ]
    assert len(found) == 1, ("no level drawn at a dot row's height", found, lines[r0 : r1 + 1])
    return found[0]


def _meets(lines: list[str], row: int, dot: int) -> float:
    """Where the plotted speed crosses the level, as read off the plot: half-way between the
    last column where all its dots lie under the level's dot row and the first where one lies
    above it (dots on the level's own row are the speed's or the level's alike)."""
    r0, _, c0, c1 = _area(lines)
    level = 4 * row + dot
    under, above = None, None
    for c in range(c0, c1 + 1):
        dots = [
            4 * r + d
            for r in range(r0, row + 2)
            for d, bits in enumerate(DOT_ROW_BITS)
            if (b := _braille(lines[r][c])) is not None and b & bits and 4 * r + d != level
        ]
        if above is None and dots and min(dots) < level:
            above = c
        if above is None and dots and min(dots) > level:
            under = c
    assert under is not None and above is not None, "the speed never crosses the level"
    return (under + above) / 2


async def _task12(pilot, answered: bool) -> Canvas:
    app = pilot.app
    await start_with_a_run(pilot, "task12")
    if answered:
        enter_all(app, {"own.T": "57"})
        app.lab_changed.publish(None)
    await settle(
        pilot,
        lambda: (
            "63 %" in {t.label for t in app.screen.query_one(ResponsePlot).traces}
            and (
                not answered
                or "crossing" in {t.label for t in app.screen.query_one(ResponsePlot).traces}
            )
        ),
    )
    return app.screen.query_one(ResponsePlot).query_one(Canvas)


@pytest.mark.parametrize("answered", [False, True])
@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
async def test_the_speed_meets_the_63_percent_level_where_it_reaches_it(quiet, size, answered):
    """The level is one dot row across the data area, and the first column where the speed
    touches it is within 1.5 columns of the 63 % crossing's time (3.85 ms a column at
    80x24); before, the speed entered the dashed row 4 columns early. Before the group has
    answered (the crossing's own marker hidden) as after."""
    app = quiet()
    async with app.run_test(size=size) as pilot:
        canvas = await _task12(pilot, answered)
        lines = canvas.render().plain.split("\n")
        row, dot = _level(lines)
        met = _meets(lines, row, dot)
        _, _, c0, c1 = _area(lines)
        view = app.screen.query_one("ResultsPanel").view
        T = view.rises[0].T_63
        lo, hi = canvas.xlim or (0.0, 0.0)
        exact = c0 + (c1 - c0) * (T - lo) / (hi - lo)
        assert abs(met - exact) <= 1.5, (met, exact, lines)
