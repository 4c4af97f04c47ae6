"""The lab as a group walks it (issue 9) and what a failed save or a reconnect looks like
(issue 10), on the device double: entries that land where the group looks and keep what
it typed whatever key it presses, numbers with their digits, Task 10 plotted as it
arrives and never started on a turning wheel, the zoom to one rise with its 63 % marks,
the model check at 80x24, the status line's save and motor words."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.device.link import LinkEvent
from minseg_tui.device.standstill import PRE_ROLL
from minseg_tui.lab.saving.store import SessionsUnreadable, list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import NO_BREAK, format_constant
from minseg_tui.ui import app as app_module
from minseg_tui.ui.panels.model_check import ModelCheckPanel
from minseg_tui.ui.panels.results import ResponsePlot, ResultsPanel
from minseg_tui.ui.panels.square_wave import SquareWavePanel
from minseg_tui.ui.screens.lab import LabScreen, StepPane
from minseg_tui.ui.screens.quit import QuitScreen, SaveElsewhereScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.plots import TracePlot
from minseg_tui.ui.widgets.prose import Prose, wrap
from minseg_tui.ui.widgets.status import DeviceStatus
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    heard_notifications,
    record_response_run,
    resume,
    settle,
    standing,
    start,
    start_with_a_run,
    taken,
    typing_box,
)


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _pane(app) -> StepPane:
    return app.screen.query(StepPane).last()


def _in_view(pane: StepPane, widget) -> bool:
    """``widget`` lies inside the part of the scrolled pane that is on screen."""
    top = widget.virtual_region.y
    return pane.scroll_y <= top and top + widget.outer_size.height <= pane.scroll_y + (
        pane.scrollable_content_region.height
    )


def _stored(app, key: str):
    with app.session as s:
        return s.entry(key)


def _status(app) -> str:
    return str(app.screen.query_one(DeviceStatus).render())


# -- item 3: typing lands in the first empty entry, in view, and never appends ----------------
async def test_typing_lands_in_the_first_empty_entry_in_view_and_replaces(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, {"i_ss@2.5": "30 mA"})
        await goto(pilot, "task5")
        assert typing_box(app) is _row(app, "i_ss@3.5").input  # not the filled one above it
        assert _in_view(_pane(app), _row(app, "i_ss@3.5"))
        await pilot.press(*"37.2 mA", "enter")
        await settle(pilot)
        assert _stored(app, "i_ss@3.5").text == "37.2 mA"
        assert _stored(app, "i_ss@2.5").text == "30 mA"  # the row above kept its current
        # Task 4 at 80x24: the first empty entry is far below the plots; it is scrolled in
        enter_all(app, {"omega_ss@2.5": "3.8", "u_ss@2.5": "2.05", "omega_ss@3.5": "5.8"})
        await goto(pilot, "task4")
        row = _row(app, "u_ss@3.5")
        assert typing_box(app) is row.input and _in_view(_pane(app), row)
        # every entry filled: the first one is focused with its text selected; keys replace it
        enter_all(app, {"i_ss@3.5": "33 mA", "i_ss@4.5": "37 mA"})
        await goto(pilot, "task5")
        assert typing_box(app) is _row(app, "i_ss@2.5").input
        await pilot.press(*"29,8", "enter")
        await settle(pilot)
        assert _stored(app, "i_ss@2.5").text == "29,8"  # not "30 mA29,8"
        # the focus stays on the last entry after Enter, the cursor at the end of the value
        # (walk 3, defect 6: a digit typed next goes on after it); Ctrl+U clears it
        await goto(pilot, "task2")
        await pilot.press(*"5,3", "enter")
        await settle(pilot)
        await pilot.press("ctrl+u", *"5,4", "enter")
        await settle(pilot)
        assert _stored(app, "R").text == "5,4"


async def test_typing_on_the_list_or_the_text_goes_into_the_first_empty_entry(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, {"i_ss@2.5": "30 mA"})
        await goto(pilot, "task5", focus=None)
        app.screen.query_one("#nav").focus()
        await pilot.press(*"33 mA", "enter")
        await settle(pilot)
        assert _stored(app, "i_ss@3.5").text == "33 mA"
        assert _stored(app, "i_ss@2.5").text == "30 mA"
        # the model check lands on its text (the arrows scroll it); typing goes to its notes
        await goto(pilot, "model_check")
        assert app.focused is _pane(app)
        await pilot.press(*"why 5 ms", "enter")
        await settle(pilot)
        assert _stored(app, "model_check.notes").text == "why 5 ms"


# -- item 4: whatever stands in an entry is stored, whatever key leaves it --------------------
@pytest.mark.parametrize(
    ("keys", "closes"),
    [
        (("pagedown",), ()),
        (("pageup",), ()),
        (("f2",), ()),
        (("f8",), ()),
        (("f1",), ("escape",)),
        (("ctrl+p",), ("escape",)),
        (("tab",), ()),
    ],
)
async def test_text_left_in_an_entry_is_stored_by_any_key(quiet, keys, closes):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press(*"5.3")  # no Enter
        await pilot.press(*keys)
        await settle(pilot)
        if closes:
            await pilot.press(*closes)
            await settle(pilot)
        e = _stored(app, "R")
        assert e is not None and e.text == "5.3" and e.ok
        await goto(pilot, "task2", focus=None)  # back: the field shows it
        assert _row(app, "R").input.value == "5.3"


async def test_refused_text_left_by_pgdn_is_kept_as_refused_and_pgup_shows_it(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press(*"5,3", "enter")
        await settle(pilot)
        await pilot.press("ctrl+u", *"5,4 kg", "pagedown")  # after Enter the cursor is at the end
        await settle(pilot)
        e = _stored(app, "R")
        assert e.text == "5,3" and e.typed == "5,4 kg" and e.refused is not None
        await pilot.press("pageup")
        await settle(pilot)
        row = _row(app, "R")
        assert row.input.value == "5,4 kg" and "still using '5,3'" in row.message


async def test_a_mouse_click_elsewhere_stores_the_text(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press(*"5,3")
        await pilot.click("#nav")
        await settle(pilot)
        assert _stored(app, "R").text == "5,3"


async def test_ctrl_q_stores_the_text_so_quitting_loses_nothing(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press(*"5,3", "ctrl+q")
        await settle(pilot)
    (info,) = list_sessions(tmp_path / "sessions")
    with Session.open(info.path) as s:
        assert s.entry("R").text == "5,3" and s.value("R") == 5.3


# -- item 6: digits and units on one line --------------------------------------------------------
async def test_numbers_keep_their_digits_and_units_stay_on_their_line(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
            K = s.results().identification.step.K
            s.enter("own.K", "1.9")  # the computed K is shown once the group has its own
        await goto(pilot, "task11")
        lines = str(app.screen.query_one("#results-lines").render())
        assert f"K = {K:.4g} rad/s/V" in lines  # four digits, as the value has them
        await goto(pilot, "table", focus=None)
        results = app.screen.query_one("#results", Prose)
        width = results.content_size.width
        assert width < len(results.text)  # the line must wrap at 80 columns
        for line in wrap(results.text, width):  # the wrap on screen: no unit torn apart
            assert not line.endswith(("mN", "mN m", "N m", "V")) and not line.startswith("s/rad")
        assert "f = " in results.text and " mN m s/rad" in results.text


def test_wrap_never_breaks_between_a_number_and_its_unit():
    text = "f = 2.216 mN m s/rad and k_v = 0.4939 V s/rad, from 0.0025 at 3.83 rad/s"
    for width in range(17, 60):  # (a quantity longer than the line must break: 16 here)
        for line in wrap(text, width):
            assert len(line) <= width and NO_BREAK not in line
        joined = "\n".join(wrap(text, width))
        for q in ("2.216 mN m s/rad", "0.4939 V s/rad", "3.83 rad/s"):
            assert q in joined


# -- items 1 and 7: Task 10 waits for the wheel, then is plotted as it arrives ----------------
async def test_task10_waits_for_the_wheel_then_plots_the_run_as_it_arrives(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task10")
        await pilot.press("f5")
        await settle(pilot)
        assert dev.commands[-1] == "STOP" and app.recording is None  # motor off, waiting
        panel = app.screen.query_one(SquareWavePanel)
        assert panel.run_progress.waiting and "once the wheel stands" in panel.run_progress.text
        # a wheel still coasting: no run
        dev.feed(
            SampleBatchOf([(k, (k + 1) * 25_000, 40 - k, 0) for k in range(4)])  # turning
        )
        await taken(pilot, 4)
        assert app.recording is None and not any(c.startswith("STEP") for c in dev.commands)
        seq = 4
        while not (dev.commands and dev.commands[-1].startswith("STEP")):
            dev.feed(standing(4, seq))
            seq += 4
            await taken(pilot, seq)
        rec = app.recording
        assert rec is not None and rec.samples >= PRE_ROLL  # the standing wheel is on record
        plot = app.screen.query_one("#plot-slow", TracePlot)
        assert plot.traces == () or len(plot.traces[0].x) <= rec.samples
        dev.feed(square_wave_stream(seq, (seq + 1) * 25_000, 2.0))
        await taken(pilot, seq + 80)
        x = np.asarray(plot.traces[0].x)
        assert x.size == rec.samples and x[-1] == pytest.approx(rec.recorded, abs=1e-9)
        omega = np.asarray(plot.traces[0].y)
        assert omega[:PRE_ROLL].max() == 0.0 and omega.max() > 6.0  # stood, then rose
        assert panel.run_progress.recording and 0 < panel.run_progress.fraction < 1


async def test_a_wheel_that_does_not_stand_keeps_the_run_from_starting(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task10")
        await pilot.press("f5")
        await settle(pilot)
        # 6 s of board time with the count moving every sample (a hand on the wheel)
        dev.feed(SampleBatchOf([(k, (k + 1) * 25_000, k, 0) for k in range(240)]))
        await taken(pilot, 240)
        assert app.recording is None and not any(c.startswith("STEP") for c in dev.commands)
        said = app.screen.query_one(SquareWavePanel).run_progress.text
        assert said.startswith("the wheel still turns 5 s after the motor was switched off")
        # F2 cancels a wait too
        await pilot.press("f5")
        await settle(pilot)
        await pilot.press("f2")
        await settle(pilot)
        dev.feed(standing(20, 240))
        await taken(pilot, 260)
        assert app.recording is None and "cancelled" in app.run_progress.text


def SampleBatchOf(rows):
    """A batch from (seq, t_us, count, u_mV) rows."""
    from minseg_tui.device.samples import SampleBatch

    return SampleBatch.from_rows([(q, t, c, u, 0, 0.0) for q, t, c, u in rows])


# -- item 2: the zoom to one rise, its 63 % level and crossing --------------------------------
async def test_the_zoom_shows_the_rise_with_its_63_percent_level_and_crossing(quiet):
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
            st = s.results().identification.step
        await goto(pilot, "task12")
        plot = app.screen.query_one(ResponsePlot)
        first = st.rises[0]
        # before the group has read T, the crossing (the answer) is neither drawn nor said
        assert "crossing" not in {tr.label for tr in plot.traces}
        note = app.screen.query_one("#zoom-note", Prose).text
        assert "read T there" in note and f"{first.T_63:.4g} s" not in note
        with app.session as s:
            s.enter("own.T", "50 ms")
        app.lab_changed.publish(None)
        await settle(pilot)
        by_label = {tr.label: tr for tr in plot.traces}
        x = np.asarray(by_label["omega"].x)  # time after the edge
        assert x[0] < 0 < x[-1]  # a little before the edge...
        # ...to several T after it: from 1 T (at least 3 samples) before to 5 T (at least 12
        # samples) after, at 25 ms
        assert -max(st.T, 3 * 0.025) - 0.025 <= x[0] and x[-1] <= max(5 * st.T, 0.3) + 1e-9
        level = first.omega0 + (1 - math.exp(-1)) * (first.omega_ss - first.omega0)
        assert list(by_label["63 %"].y) == pytest.approx([level, level])
        assert list(by_label["crossing"].x) == pytest.approx([first.T_63, first.T_63])
        note = app.screen.query_one("#zoom-note", Prose).text
        assert (
            "rise 1 of 4" in note and f"{format_constant(first.T_63, 's')} after the edge" in note
        )
        await pilot.press("alt+right")
        await settle(pilot)
        assert "rise 2 of 4" in app.screen.query_one("#zoom-note", Prose).text
        second = {tr.label: tr for tr in plot.traces}["crossing"]
        assert list(second.x) == pytest.approx([st.rises[1].T_63] * 2)
        # the group's reading goes in right under the plot it is read from
        panel = app.screen.query_one(ResultsPanel)
        row = _row(app, "own.T")
        assert panel.region.bottom <= row.region.y < app.screen.query_one("#results-lines").region.y
        assert _in_view(_pane(app), row) and _in_view(_pane(app), plot)


# -- item 8: the model check at 80x24 --------------------------------------------------------------
async def test_model_check_at_80x24_scrolls_with_the_arrows_and_shows_all_its_text(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        pane = _pane(app)
        nav = app.screen.query_one("#nav")
        at = nav.highlighted
        assert app.focused is pane and pane.scroll_y == 0
        for _ in range(40):
            await pilot.press("down")
        await settle(pilot)
        assert nav.highlighted == at and pane.scroll_y > 0  # the pane scrolled, not the list
        story = app.screen.query_one("#check-story", Prose)
        assert story.outer_size.height >= len(wrap(story.text, story.content_size.width))
        assert _in_view(pane, story) or pane.scroll_y == pane.max_scroll_y
        # causes in words, not the JSON contract's names; the details wait in their fold
        assert "Likely cause: dry friction" in story.text and "coulomb_friction" not in story.text
        lines = app.screen.query_one("#check-lines", Prose)
        assert not lines.region.height  # folded
        text = lines.text
        # the lead figure first
        assert text.index("wheel angle drifts") < text.index("Why dry friction")
        assert "cause: dry friction" in text
        panel = app.screen.query_one(ModelCheckPanel)
        assert panel.close_up and "close-up" in story.text
        for plot in app.screen.query(TracePlot):  # the legend is a line under the plot
            canvas, legend = plot.children
            assert legend.region.y >= canvas.region.bottom
        await pilot.press("f9")
        await settle(pilot)
        assert not panel.close_up and "the whole log" in story.text


# -- issue 10: saves that fail, quitting, another folder, damaged sessions, reconnects ----------
async def test_a_failed_save_says_so_retries_and_asks_before_quitting(quiet, tmp_path):
    app = quiet()
    root = tmp_path / "sessions"
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        root.rename(tmp_path / "gone")  # the stick is pulled out
        await pilot.press(*"6,1", "enter")
        await settle(pilot)
        assert _stored(app, "R").value == 6.1  # kept in memory
        status = _status(app)
        assert "not saved: No such file or directory" in status
        assert "Save the session to another folder" in status
        await pilot.press("ctrl+q")
        await settle(pilot, lambda: isinstance(app.screen, QuitScreen))
        await pilot.press("enter")  # keep working (the first answer)
        await settle(pilot)
        assert isinstance(app.screen, LabScreen) and app.is_running
        (tmp_path / "gone").rename(root)  # back in
        app.retry_save()
        await settle(pilot)
        assert "not saved" not in _status(app)
    (info,) = list_sessions(root)
    with Session.open(info.path) as s:
        assert s.value("R") == 6.1


async def test_quit_anyway_and_save_to_another_folder(quiet, tmp_path):
    app = quiet()
    root = tmp_path / "sessions"
    elsewhere = tmp_path / "home"
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        root.rename(tmp_path / "gone")
        await pilot.press(*"6,1", "enter")
        await settle(pilot)
        await pilot.press("ctrl+q")
        await settle(pilot, lambda: isinstance(app.screen, QuitScreen))
        await pilot.press("down", "enter")  # save the session to another folder…
        await settle(pilot, lambda: isinstance(app.screen, SaveElsewhereScreen))
        box = app.screen.query_one("#folder")
        box.value = str(elsewhere)
        await pilot.press("enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        assert "not saved" not in _status(app)
        with app.session as s:
            assert s.folder.parent == elsewhere and not s.unsaved
    (info,) = list_sessions(elsewhere)
    with Session.open(info.path) as s:
        assert s.value("R") == 6.1


async def test_quit_anyway_quits(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        (tmp_path / "sessions").rename(tmp_path / "gone")
        await pilot.press(*"6,1", "enter")
        await settle(pilot)
        await pilot.press("ctrl+q")
        await settle(pilot, lambda: isinstance(app.screen, QuitScreen))
        await pilot.press("down", "down", "enter")
        await settle(pilot, lambda: not app.is_running)


async def test_a_damaged_session_opens_read_only_and_says_why(quiet, tmp_path):
    root = tmp_path / "sessions"
    s = Session.create(root, ["Ada"], date="2024-04-16")
    s.enter("R", "5.2")
    s.close()
    data = json.loads((s.folder / "session.json").read_text())
    data["entries"]["R"]["history"] = 5
    (s.folder / "session.json").write_text(json.dumps(data))
    before = (s.folder / "session.json").read_bytes()
    app = quiet()
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#sessions")))
        label = str(app.screen.query_one("#sessions").get_option_at_index(0).prompt)
        assert "damaged" in label and "read-only" in label
        await resume(pilot)
        assert isinstance(app.screen, LabScreen) and app.screen.readonly
        assert any("opened read-only" in m and "entries.R.history" in m for m in said)
        await goto(pilot, "task2", focus=None)
        assert _row(app, "R").input.disabled
        await goto(pilot, "task10")
        await pilot.press("f5")
        await settle(pilot)
        assert app.recording is None
    assert (s.folder / "session.json").read_bytes() == before  # never written over


async def test_an_unreadable_sessions_folder_is_one_line_on_the_start_screen(quiet, monkeypatch):
    def unreadable(root: Path):
        raise SessionsUnreadable(str(root), None, "cannot list the sessions folder (gone)")

    monkeypatch.setattr(app_module, "list_sessions", unreadable)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#sessions")))
        label = str(app.screen.query_one("#sessions").get_option_at_index(0).prompt)
        assert label.startswith("✗") and "cannot list the sessions folder" in label
        await start(pilot)  # a new session still starts
        assert isinstance(app.screen, LabScreen)


async def test_after_a_reconnect_the_status_line_says_the_motor_is_off(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await pilot.press("f3")
        await settle(pilot)
        assert app.motor == "2.5 V"
        sent = len(dev.commands)
        dev.u_req = 0.0  # the board restarted: the link knows the motor is off
        dev.feed_event(LinkEvent("connected", "minseg://: reconnected", 0.0))
        dev.feed_event(
            LinkEvent(
                "motor",
                "minseg://: reconnected: the motor is off (it was at 2.5 V); nothing is "
                "restored, set the voltage again",
                0.0,
            )
        )
        dev.feed(standing(2))
        await taken(pilot, 2)
        await settle(pilot, lambda: app.motor == "off")
        status = _status(app)
        assert "motor off" in status and "nothing restored" in status
        assert app.requested is None
        assert dev.commands[sent:] == []  # nothing restored, silently or otherwise


async def test_a_resumed_session_with_recovery_notes_says_them(quiet, tmp_path):
    s = Session.create(tmp_path / "sessions", ["Ada"], date="2024-04-16")
    s.close()
    (s.folder / ".session.json.999999.tmp").write_text("{")
    app = quiet()
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        assert any("removed .session.json.999999.tmp" in m for m in said)
