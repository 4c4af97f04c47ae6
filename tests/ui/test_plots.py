"""The terminal plots' axes: round ticks, the value of a flat trace on its own labelled row."""

from __future__ import annotations

from textual.geometry import Size

from minseg_tui.quantities import format_ticks as tick_labels
from minseg_tui.ui.widgets.plots import Canvas, TracePlot, row_ticks, thin, ticks
from tests.ui.helpers import goto, standing, start


def _rows(plot: TracePlot) -> list[str]:
    """The plot as drawn, one string per row (colours dropped)."""
    return str(plot.query_one(Canvas).render()).split("\n")


async def test_a_wheel_standing_still_reads_0_on_the_row_of_its_line(quiet):
    """Seen in the walk on Task 3: the motor off, the speed's flat line sat on the row
    labelled 0.33 (ticks -1.00, -0.33, 0.33, 1.00): a group reads 0.33 rad/s."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        app.live.extend(standing(80))
        await goto(pilot, "task3")
        rows = _rows(app.screen.query_one("#plot-speed", TracePlot))
        line = [r for r in rows if "•" in r]
        assert len(line) == 1
        assert line[0].split("┤")[0].strip() == "0"
        labels = [r.split("┤")[0].strip() for r in rows if "┤" in r]
        assert "0" in labels and not any(lab.startswith("-0") for lab in labels)


def test_ticks_are_round_numbers_inside_the_values():
    assert ticks(-0.043, 0.214) == (-0.043, 0.214, [0.0, 0.1, 0.2])
    assert ticks(0.0, 12.1) == (0.0, 12.1, [0.0, 5.0, 10.0])
    assert ticks(0.0, 8.8)[2] == [0.0, 2.5, 5.0, 7.5]


def test_every_row_of_a_y_axis_stands_for_a_round_value():
    """Limits a whole number of round steps apart, one step a row: a label is exactly the
    value of its row, and 0 is a labelled row when it is in range."""
    assert row_ticks(-0.26, 0.26, 7) == (-0.3, 0.3, [-0.2, 0.0, 0.2])
    assert row_ticks(0.0, 8.8, 4) == (0.0, 9.0, [0.0, 3.0, 6.0, 9.0])
    lo, hi, at = row_ticks(0.0, 0.0, 4)  # a wheel standing still
    assert (lo, hi) == (-1.0, 2.0) and 0.0 in at


def test_tick_labels_never_say_minus_zero():
    assert tick_labels([-1.0, -0.5, -0.0, 0.5]) == ["-1.0", "-0.5", "0.0", "0.5"]
    assert tick_labels([0.0, 2.5, 5.0, 7.5]) == ["0.0", "2.5", "5.0", "7.5"]
    assert tick_labels([-0.1, 0.0, 0.1, 0.2]) == ["-0.1", "0.0", "0.1", "0.2"]


def test_thinning_keeps_the_ends_and_every_peak_in_order():
    """A 5 ms run has 2419 samples; the plot hands plotext about four a column, and what
    it draws keeps each run of samples' lowest and highest (a one-sample spike too)."""
    x = [k * 0.005 for k in range(2419)]
    y = [0.0] * 2419
    y[1000], y[1701] = 9.0, -3.0
    tx, ty = thin(x, y, 200)
    assert len(tx) <= 202 and tx == sorted(tx)
    assert (tx[0], tx[-1]) == (x[0], x[-1])
    assert 9.0 in ty and -3.0 in ty and tx[ty.index(9.0)] == x[1000]
    assert thin(x[:50], y[:50], 200) == (x[:50], y[:50])


async def test_a_plot_painted_at_a_new_size_before_its_resize_event_has_that_sizes_ticks(
    monkeypatch,
):
    """The model check's close-up snapshot once showed the y ticks 8, 4, 0 of a draw made
    for another height where the plot was painted at 80x24 (9, 6, 3): a frame painted after
    the layout changed the canvas's size and before its Resize event ran its draw. The
    build the screen paints is made for the size it paints (here the Resize never runs)."""
    from textual.app import App

    from minseg_tui.ui.widgets.plots import Trace

    monkeypatch.setattr(Canvas, "on_resize", lambda self: None)

    class One(App[None]):
        def compose(self):
            yield TracePlot("t", "t [s]", "omega [rad/s]", id="p")

    app = One()
    async with app.run_test(size=(60, 40)) as pilot:
        plot = app.query_one(TracePlot)
        plot.styles.height = 12
        plot.show([Trace([0.0, 1.0, 2.0], [0.0, 8.8, 4.0], "m", "dot")])
        await pilot.pause()
        small = [r.split("┤")[0].strip() for r in _rows(plot) if "┤" in r]
        plot.styles.height = 30
        await pilot.pause()
        canvas = plot.query_one(Canvas)
        rows = canvas.size.height - 3 - 1 - 1  # the title's row and the labels' row
        _, _, at = row_ticks(0.0, 8.8, rows)
        labels = [r.split("┤")[0].strip() for r in _rows(plot) if "┤" in r]
        assert labels == list(reversed(tick_labels(at))), (small, labels, at)


async def test_a_legend_is_measured_for_the_width_the_layout_asks_about():
    """The model check's legend at 80x24 was once two rows high, its second empty: Textual
    measured the legend made for the width it had before (its full labels, which wrap) and
    kept that height for the width asked. Measured for a width, it is the legend made for
    that width: one row where the short labels fit."""
    from textual.app import App

    from minseg_tui.ui.widgets.plots import Legend, Trace, legend

    traces = [
        Trace([0.0], [0.0], "extended", "+", short="ext."),
        Trace([0.0], [0.0], "first order", "braille", short="1st order"),
        Trace([0.0], [0.0], "measured", "dot", short="meas."),
    ]
    narrow = len(legend(traces, 1).plain) + 1  # the short labels fit, the full ones do not
    assert len(legend(traces).plain) > narrow

    class One(App[None]):
        def compose(self):
            yield Legend()

    app = One()
    async with app.run_test(size=(80, 10)) as pilot:
        shown = app.query_one(Legend)
        shown.show(traces)
        await pilot.pause()
        assert shown.content_size.width > len(legend(traces).plain)  # laid out wide
        assert shown.get_content_height(Size(80, 10), Size(80, 10), narrow) == 1
