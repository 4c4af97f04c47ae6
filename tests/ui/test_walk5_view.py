"""The second walk of issue 20 on the screens (a new group at 80x24 on the virtual MinSeg):
Home/End on the rise cursor and its words at a sample, Enter's move said in F1, the model
check's legends, F8's notice, the arrows on the list of steps."""

from __future__ import annotations

import pytest
from textual.message import Message
from textual.notifications import Notification, Notify

from minseg_tui.lab.views.session import cursor_reading
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.keys import KEYMAP
from minseg_tui.ui.panels.results import HELD_END, ResponsePlot, ResultsPanel
from minseg_tui.ui.screens.help import KeyList
from minseg_tui.ui.widgets.plots import TracePlot
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    burst,
    goto,
    on_the_list,
    settle,
    shown,
    start,
    start_with_a_run,
    typing_box,
)


async def test_home_and_end_move_the_rise_cursor_to_the_ends_not_the_page(quiet):
    """Task 11, the plot focused: End and Home scrolled the step instead of moving the
    cursor; only ←/→ moved it. End puts it on the last column with a sample, Home on the
    first, and the step stays where it was."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        panel = app.screen.query_one(ResultsPanel)
        plot = panel.query_one(ResponsePlot)
        await pilot.press("shift+tab")
        await settle(pilot)
        assert app.focused is plot and panel.reading is not None
        pane = app.screen.pane
        view = panel.view
        assert view is not None
        rise = view.rises[0]
        z1 = max(rise.z1, rise.t1 - HELD_END)  # Task 11 shows the high level to its end
        x = view.t[(view.t >= rise.z0) & (view.t <= z1)] - rise.t0
        y = pane.scroll_y
        await pilot.press("end")
        await settle(pilot)
        assert pane.scroll_y == y
        assert panel.reading is not None and panel.reading.t == pytest.approx(x[-1], abs=1e-6)
        await pilot.press("home")
        await settle(pilot)
        assert pane.scroll_y == y
        assert panel.reading is not None and panel.reading.t == pytest.approx(x[0], abs=1e-6)
        keys = " ".join(f"{k.name} {k.help}" for k in KEYMAP)
        assert "Home/End" in keys


def test_the_cursor_on_a_sample_says_it_is_on_it():
    """t = 50.0 ms, a sample of a 25 ms log computed as a difference of times (a hair
    off 0.05 s), read "(between the samples at 25.0 ms and 50.0 ms)"."""
    t = [k * 0.025 + 1.3 for k in range(8)]
    x = [v - 1.3 for v in t]  # times after the edge, as the plot has them
    omega = [0.0, 1.0, 2.0, 3.0, 3.5, 3.8, 3.9, 4.0]
    reading = cursor_reading(x, omega, round(0.05, 6))
    assert reading is not None and x[2] != 0.05
    assert reading.omega == pytest.approx(2.0)
    assert "between" not in reading.text() and "the sample at 50.0 ms" in reading.text()
    between = cursor_reading(x, omega, 0.0625)
    assert between is not None and "between the samples at 50.0 ms and 75.0 ms" in between.text()


async def test_f1_says_that_enter_goes_on_to_the_next_field(quiet):
    """Enter stores and moves to the next field, so a Tab after it skipped one; F1 said only
    "Enter stores what you typed". The move stays (the bursts rely on it) and F1 says it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep5")
        await pilot.press("f1")
        await settle(pilot)
        said = " ".join(app.screen.query_one(KeyList).text.split())
        assert "Enter stores and goes on to the next field" in said


async def test_the_model_checks_legends_show_every_entry_once_in_view(quiet):
    """The model check at 80x24, the list of steps shown: each plot's legend wrapped to two
    lines, the second under the screen's edge, and the visible line read across both plots
    "++ extended ⠶⠶ first order -- noise ± ++ extended ⠶⠶" ('measured' missing, an entry
    twice). Each legend now holds on one line (short labels where the full ones do not
    fit), every entry of its plot in it once."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await settle(pilot)  # the screen laid out after the check's view came
        assert app.screen.query_one("#nav").display
        wanted = {"plot-check": 3, "plot-residual": 3}
        for plot_id, entries in wanted.items():
            plot = app.screen.query_one(f"#{plot_id}", TracePlot)
            shown = plot.query_one(".legend")
            lines = [s.text.strip() for s in shown.render_lines(shown.region.reset_offset)]
            assert len(lines) == 1, lines
            labelled = [t.short or t.label for t in plot.traces if t.label]
            assert len(labelled) == entries
            assert all(lines[0].count(label) == 1 for label in labelled), lines
            assert app.screen.can_view_entire(shown)  # at the landing, on its last row


async def test_the_f8_notice_expires_and_does_not_cover_the_entry_typed_in(tmp_path):
    """Walk 5 at 80x24: on the summary, the last entry typed in, F8's list of the files
    written covered that entry for 10 s. Notices now go to the half of the screen away
    from the entry, and F8's stays 5 s (Textual's default), not 10."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)
    notices: list[Notification] = []

    def hear(message: Message) -> None:
        if isinstance(message, Notify):
            notices.append(message.notification)

    async with app.run_test(size=(80, 24), notifications=True, message_hook=hear) as pilot:
        await start(pilot)
        await goto(pilot, "summary")
        await burst(pilot, *"why does f fall with speed")
        box = typing_box(app)
        assert box is not None and app.screen.can_view_entire(box)
        await burst(pilot, "f8")
        await settle(pilot, lambda: bool(app.exported))
        await settle(pilot, lambda: bool(app.screen.query("Toast")))
        toasts = list(app.screen.query("Toast"))  # the files written, and what is unanswered
        assert any("written:" in str(t.render()) for t in toasts)
        for toast in toasts:
            assert not toast.region.overlaps(box.region), (toast.region, box.region)
        assert all(n.timeout <= 8 for n in notices)


async def test_the_arrows_on_the_list_of_steps_stop_at_its_ends_and_pgup_goes_back_one(quiet):
    """Walk 5 at 80x24: from the model check, the list of steps focused, ↓ twice and PgUp
    showed Preparation 1: the second ↓ went round from the summary, the last step, to the
    first, and PgUp could go no further back; it read as PgUp jumping to the list's end.
    The arrows stop at the ends of the list, and PgUp/PgDn move one step from there."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await pilot.press("ctrl+l")
        await settle(pilot)
        assert on_the_list(app)
        for key, there in (("down", "summary"), ("down", "summary"), ("pageup", "model_check")):
            await pilot.press(key)
            await settle(pilot)
            assert shown(app, there), (key, app.screen.pane.step.id)
        app.screen.query_one("#nav").focus()
        await settle(pilot)
        await goto(pilot, "prep1", focus=None)
        for key, there in (("up", "prep1"), ("pagedown", "prep2")):
            await pilot.press(key)
            await settle(pilot)
            assert shown(app, there), (key, app.screen.pane.step.id)
