"""What a second walk of the lab in tmux found (after issue 9 was merged): keys typed faster
than the focus moves, the u_A of the zoomed rise drawn as the board applies it, titles and
answers that fit 80 columns."""

from __future__ import annotations

import numpy as np
import pytest
from textual import events
from textual.geometry import Region

from minseg_tui.ui.panels.results import ResponsePlot
from minseg_tui.ui.widgets.fields import AnswerList, FieldRow, field_id
from minseg_tui.ui.widgets.plots import Canvas, drawing_order
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    record_response_run,
    settle,
    start,
    start_with_a_run,
)


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _stored(app, key: str):
    with app.session as s:
        return s.entry(key)


async def test_keys_typed_faster_than_the_focus_moves_all_land_in_the_entry(quiet):
    """On the list of steps, a burst of keys (a quick typist, a busy app, tmux send-keys)
    arrives before the entry has taken the focus: every key lands, none replaces the one
    before it (it stored " 2.6" for "read 2.1 and 2.6")."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2", focus=None)
        app.screen.query_one("#nav").focus()
        await settle(pilot)
        for c in "5,3 ohm":
            app.post_message(events.Key(c if c != " " else "space", c))  # one burst
        await settle(pilot)
        assert _row(app, "R").input.value == "5,3 ohm"
        await pilot.press("enter")
        await settle(pilot)
        assert _stored(app, "R").text == "5,3 ohm"


async def test_the_zoomed_rise_draws_u_a_as_the_board_holds_it_rising_at_the_edge(quiet):
    """The board applies u_A from the sample that reports it until the next one: drawn as
    a line between the samples, u_A climbed during the sample before the edge (t < 0 of the
    zoom) while the speed was still flat. Drawn held, it changes only on vertical segments,
    and rises at t = 0."""
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start_with_a_run(pilot, "task11")
        plot = app.screen.query_one(ResponsePlot)
        labels = [tr.label for tr in plot.traces]
        k = drawing_order(plot.traces).index(labels.index("u_A [V]"))  # plotext's signal
        monitor = plot.query_one(Canvas).plt.monitor  # what plotext was asked to draw
        x, u = np.asarray(monitor.x[k]), np.asarray(monitor.y[k])
        changes = np.flatnonzero(np.diff(u) != 0)
        assert changes.size == 1  # one rise in the window of one step
        j = changes[0]
        assert x[j] == x[j + 1] == 0.0  # a vertical segment, at the edge
        assert np.all(u[x < 0] == 0) and u[-1] > 4  # nothing before it, u_ss after


@pytest.mark.parametrize("step_id", ["task4", "task10", "task11", "model_check"])
async def test_every_plot_shows_its_title_at_80x24(quiet, step_id):
    """plotext leaves out a title wider than the plot: at 80x24 the model check's close-up
    ("close-up: where the cause acts") had none."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, step_id)
        canvases = list(app.screen.query(Canvas))
        assert canvases
        for canvas in canvases:
            assert canvas.plot_title in str(canvas.render()).splitlines()[0]


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
async def test_the_model_checks_two_plots_share_their_axes_rows(quiet, size):
    """The residual's legend took a line more than the speed's, so its plot sat a row
    higher and its unit landed beside the other plot's last tick ("1.93 rad/s")."""
    app = quiet()
    async with app.run_test(size=size) as pilot:
        await start_with_a_run(pilot, "model_check")
        for _ in range(2):  # the close-up, then the whole log
            check, residual = (
                app.screen.query_one(f"#{n}").query_one(Canvas)
                for n in ("plot-check", "plot-residual")
            )
            assert check.region.y == residual.region.y
            assert check.region.height == residual.region.height
            await pilot.press("f9")
            await settle(pilot)


def _shown_text(widget) -> str:
    """What ``widget`` shows inside its border and padding, its lines joined by spaces (a
    wrapped line joins back)."""
    w, h = widget.outer_size
    gutter = widget.styles.gutter
    lines = widget.render_lines(Region(0, 0, w, h))[gutter.top : h - gutter.bottom]
    shown = [strip.crop(gutter.left, w - gutter.right) for strip in lines]
    return " ".join(" ".join(strip.text.split()) for strip in shown).strip()


async def test_the_summary_questions_and_answers_show_whole_at_80x24(quiet):
    """At 80 columns the answer 'the ratio between the output and input amplitudes in
    steady-state' ended in 'in …' and a question in '(tick all that ap'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "summary")
        lists = list(app.screen.query(AnswerList))
        labels = list(app.screen.query(".choice-label"))
        assert lists and labels
        for widget, text in [(a, answer) for a in lists for answer in a.answers] + [
            (lb, str(lb.render())) for lb in labels
        ]:
            assert " ".join(text.split()) in _shown_text(widget)


async def test_typing_on_the_summarys_answers_goes_into_its_text_entry(quiet):
    """On the summary the first empty entry is a question to tick; keys typed on the list of
    steps or on an answer list (where letters do nothing) went nowhere, and the group's
    'most unclear' text was lost. They go into the step's first empty text entry; Space
    still picks an answer. Typed on an answer list once that text is there, they go after
    it (walk 16, D2: typed over it, the group's text was lost)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "summary", focus=None)
        app.screen.query_one("#nav").focus()
        await pilot.press(*"why T", "enter")
        await settle(pilot)
        assert _stored(app, "summary.unclear").text == "why T"
        radio = app.screen.query(AnswerList).last()
        radio.focus()
        await settle(pilot)
        await pilot.press("space")  # picks the highlighted answer, as before
        await settle(pilot)
        assert _stored(app, "summary.6") is not None
        radio.focus()
        await settle(pilot)
        for c in "and K":  # a burst, spaces in it
            app.post_message(events.Key(c if c != " " else "space", c))
        await settle(pilot)
        await pilot.press("enter")
        await settle(pilot)
        assert _stored(app, "summary.unclear").text == "why Tand K"


WALK_TABLE = {
    "R": "5,3",
    "omega_ss@2.5": "3.826",
    "u_ss@2.5": "2.05 V",
    "omega_ss@3.5": "5.805",
    "u_ss@3.5": "3,05",
    "omega_ss@4.5": "7.786",
    "u_ss@4.5": "4.04",
    "i_ss@2.5": "29.8 mA",
    "i_ss@3.5": "33.6 mA",
    "i_ss@4.5": "37,2",
}
"""The table of the tmux walk, as typed."""


async def test_the_dry_friction_note_gives_f_with_the_tables_digits(quiet):
    """The table said f = 2.504 mN m s/rad at 2.5 V and the note under it 'from 0.0025':
    two digits, the zeros dropped by :.3g."""
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start(pilot)
        enter_all(app, WALK_TABLE)
        await goto(pilot, "table")
        text = " ".join(p.text for p in app.screen.query(Prose))
        assert "f falls with speed, from 2.504 mN m s/rad at" in text
        assert "to 1.536 mN m s/rad" in text
