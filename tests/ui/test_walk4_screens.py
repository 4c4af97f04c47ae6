"""Walk 4's defects on the screens (issue 20; a new group at 80x24): the model check's ✓,
the focus seen without colour, the whole of "What to do" on one key, the cursor and the
zooms of Tasks 11-12, the virtual multimeter's R."""

from __future__ import annotations

import pytest
from textual.geometry import Region
from textual.strip import Strip

from minseg_tui.lab.content.steps import step
from minseg_tui.model.plant import MeterReading
from minseg_tui.ui.messages import MeterRead
from minseg_tui.ui.panels.meter import MeterPanel
from minseg_tui.ui.panels.results import ResponsePlot, ResultsPanel
from minseg_tui.ui.screens.help import KeyList
from minseg_tui.ui.widgets.fields import AnswerList, FieldRow, field_id
from minseg_tui.ui.widgets.plots import Canvas
from tests.ui.conftest import board_url, real_app
from tests.ui.helpers import (
    Heard,
    answering,
    goto,
    nav_mark,
    settle,
    start,
    start_with_a_run,
    typing_box,
)


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one("#" + field_id(key), FieldRow)


async def test_the_model_check_is_done_when_the_group_ticks_done_not_by_a_note(quiet):
    """The model check's ✓ came only once a note was typed, and nothing said why. The step
    now says what makes it done, and its done? choice does it, as on the steps that ask the
    group to read or to see for themselves; a note alone starts it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        todo = app.screen.query_one(".todo").render()
        assert "done when you tick done?" in " ".join(str(todo).split())
        assert nav_mark(app, "model_check") == " "
        assert app.screen.pane.scroll_y == 0  # it still lands at the top, on the plots
        notes = _row(app, "model_check.notes")
        notes.input.focus()
        await pilot.press(*"slower", "enter")
        await settle(pilot)
        assert nav_mark(app, "model_check") == "…"  # a note alone: started, not done
        done = _row(app, "model_check.done")
        assert answering(app) is done.query_one(AnswerList)  # Enter in the notes moved on to it
        await pilot.press("space")
        await settle(pilot)
        assert nav_mark(app, "model_check") == "✓"
        with app.session as s:
            assert s.step_status("model_check") == "done"
        assert typing_box(app) is None


def _drawn(widget) -> list[Strip]:
    """The lines ``widget`` draws on the screen now (it must be on it)."""
    assert widget.region.area and widget.screen.region.contains_region(widget.region)
    return list(widget.render_lines(Region(0, 0, *widget.outer_size)))


def _text(widget) -> str:
    return " ".join(" ".join(strip.text.split()) for strip in _drawn(widget)).strip()


def _cursor(answers: AnswerList) -> list[str]:
    """The answers drawn with the mark of the one Space would tick ('▶' before it)."""
    gutter, width = answers.styles.gutter, answers.outer_size.width
    inside = [s.crop(gutter.left, width - gutter.right).text for s in _drawn(answers)]
    marked = [line for line in inside if "▶" in line]
    starts = [" ".join(line[line.index("▶") + 3 :].split()) for line in marked]
    return [a for a in answers.answers if any(s and a.startswith(s) for s in starts)]


def _label(app, key: str) -> str:
    return _text(_row(app, key).query_one(".field-label, .choice-label"))


async def test_the_focused_field_is_marked_in_the_text_not_by_colour_alone(quiet):
    """Walk 4 at 80x24 in a plain terminal: the focused box looked like the others (its
    colour was all that told them apart). Space went into the notes instead of the done?
    choice; Tab moved on to the next summary question and Space ticked an answer there.
    The row the keys go to is marked '▶' before its label, and in a list of answers the
    one Space would tick is marked '▶' in place of its button's left edge; Tab goes down the rows in order."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep1")
        assert typing_box(app) is _row(app, "prep1.notes").input  # the first empty entry
        assert _label(app, "prep1.notes") == "▶ notes"
        assert _label(app, "prep1.done") == "done?"
        await pilot.press("tab")
        await settle(pilot)
        done = _row(app, "prep1.done")
        assert answering(app) is done.query_one(AnswerList)
        assert _label(app, "prep1.notes") == "notes"
        assert _label(app, "prep1.done") == "▶ done?"
        assert _cursor(done.query_one(AnswerList)) == ["we have read sections 2.1 and 2.6"]
        await pilot.press("space")
        await settle(pilot)
        with app.session as s:
            assert s.step_status("prep1") == "done" and s.entry("prep1.notes") is None

        await goto(pilot, "summary")
        questions = [f.key for f in step("summary").fields if f.options]
        first, second = (_row(app, k) for k in questions[:2])
        assert answering(app) is first.query_one(AnswerList)
        assert _label(app, questions[0]).startswith("▶ The MinSeg DC-motor is")
        await pilot.press("tab")  # the next question, marked; the first one no longer
        await settle(pilot)
        assert answering(app) is second.query_one(AnswerList)
        assert not _label(app, questions[0]).startswith("▶")
        assert _label(app, questions[1]).startswith("▶ The differential equation")
        options = second.query_one(AnswerList)
        assert _cursor(options) == ["a model"] and not _cursor(first.query_one(AnswerList))
        await pilot.press("down")
        await settle(pilot)
        assert _cursor(options) == ["a system"]
        for key in questions[2:]:  # Tab goes down the questions in order, then to the text
            await pilot.press("tab")
            await settle(pilot)
            assert _label(app, key).startswith("▶ ")
        await pilot.press("tab")
        await settle(pilot)
        assert typing_box(app) is _row(app, "summary.unclear").input
        assert _label(app, "summary.unclear").startswith("▶ Most unclear")
        with app.session as s:  # nothing was ticked on the way
            assert all(s.entry(k) is None for k in questions)


async def test_one_key_shows_the_whole_of_what_to_do_from_anywhere_on_the_step(quiet):
    """At 80x24 the heading over a step scrolled down showed the first line of "What to do"
    cut off, and nothing told the group how to read the rest but scrolling up, away from
    the entry. The cut line ends with '… Ctrl+O more'; Ctrl+O, from the entry or from the
    plot, shows all of it over the top of the step, the entry still in sight and typed
    into; Ctrl+O again folds it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        pane = app.screen.pane
        heading = pane.query_one(".heading")
        todo = heading.query_one(".heading-todo")
        whole = "What to do: " + step("task12").todo
        assert heading.display and pane.scroll_y > 0  # landed on the entry, under the plot
        line = _text(todo)
        assert line.endswith("… Ctrl+O more") and len(line) < len(whole)
        assert whole.startswith(line.removesuffix("… Ctrl+O more"))
        entry = _row(app, "own.T").input
        for key in ("ctrl+o", "5"):  # typing goes on in the entry under the heading
            await pilot.press(key)
            await settle(pilot)
        assert _text(todo) == whole + " (Ctrl+O folds it)"
        assert typing_box(app) is entry and entry.value == "5"
        assert entry.region.y >= heading.region.bottom  # not under the heading
        await pilot.press("ctrl+o")
        await settle(pilot)
        assert _text(todo) == line
        await pilot.press("shift+tab")  # to the plot: the key works there too
        await settle(pilot)
        # focus scrolls the plot to the middle of the step, in an animation that ends on the
        # animator's timer: wait for it, or Ctrl+O acts at whatever row a busy machine left
        await pilot.wait_for_scheduled_animations()
        await settle(pilot)
        assert app.focused is not None and app.focused.id == "plot-log"
        await pilot.press("ctrl+o")
        await settle(pilot)
        await pilot.wait_for_scheduled_animations()
        await settle(pilot)
        # all of what to do is in sight: in the heading, or (walk 7, D3) in the step's own
        # text when that stands whole in view, where the heading would repeat its last line
        own = pane.query_children(".todo").first()
        assert heading.whole  # the key reached the step from the plot
        assert (heading.display and _text(todo) == whole + " (Ctrl+O folds it)") or (
            not heading.display and pane.can_view_entire(own)
        )
        await pilot.press("f1")
        await settle(pilot)
        assert "Ctrl+O" in app.screen.query_one(KeyList).text


def _cursor_columns(canvas: Canvas) -> set[int]:
    """The columns the cursor's line '┆' stands on, in the canvas."""
    return {c for ln in str(canvas.render()).split("\n") for c, ch in enumerate(ln) if ch == "┆"}


async def test_the_rise_cursor_stops_on_the_last_sample_and_reads_it(quiet):
    """Shift+→ to the end of Task 12's close-up parked the cursor on the frame's last column,
    a hair past the last sample: it read 'no sample there' and its line vanished. On the
    edge it read 't = -6.94e-15 ms'. It now stops on the last column with a sample, drawn
    and read there, and the edge reads 0 ms."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        panel = app.screen.query_one(ResultsPanel)
        plot = panel.query_one(ResponsePlot)
        canvas = plot.query_one(Canvas)
        await pilot.press("shift+tab")
        await settle(pilot)
        assert app.focused is plot and panel.reading is not None
        said = " ".join(str(panel.query_one("#cursor").render()).split())
        assert said.startswith("┆ cursor: t = 0 ms after the edge") and "e-" not in said
        first, last = plot.columns or (0, 0)
        for _ in range(last - first):
            await pilot.press("shift+right")
        await settle(pilot)
        view = panel.view
        assert view is not None
        rise = view.rises[0]
        x = view.t[(view.t >= rise.c0) & (view.t <= rise.c1)] - rise.t0
        assert panel.reading is not None and panel.reading.t == pytest.approx(x[-1])
        assert len(_cursor_columns(canvas)) == 1 and max(_cursor_columns(canvas)) <= last
        assert "no sample there" not in str(panel.query_one("#cursor").render())


async def test_task11_zooms_on_the_whole_high_level_to_read_omega_ss(quiet):
    """Task 11's zoom ended 0.3 s after the edge, 5 T: the settled speed showed over a
    fifth of a second, in 1.5 rad/s rows, and was guessed. It now runs to the end of the
    high level (1.4 s after the edge on the manual's run), and the cursor reads the speed
    anywhere on it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        panel = app.screen.query_one(ResultsPanel)
        plot = panel.query_one(ResponsePlot)
        view = panel.view
        assert view is not None and view.rises
        rise = view.rises[0]
        lo, hi = plot.traces_xlim or (0.0, 0.0)
        ts = 0.025
        assert hi >= rise.t1 - rise.t0 - ts - 1e-9  # to the last sample of the high level
        assert hi > 4 * (rise.z1 - rise.t0)  # 0.3 s before
        note = " ".join(str(panel.query_one("#zoom-note").render()).split())
        assert "to the end of its high level" in note and "read omega_ss" in note
        await pilot.press("shift+tab")
        await settle(pilot)
        first, last = plot.columns or (0, 0)
        for _ in range((last - first) // 2):  # to the middle of the settled part
            await pilot.press("right")
        await settle(pilot)
        reading = panel.reading
        assert reading is not None and reading.t > 0.5
        assert abs(reading.omega - rise.omega_ss) < 0.5  # one count in 25 ms is 0.35 rad/s


async def test_the_virtual_multimeter_holds_its_R_between_readings(tmp_path):
    """The virtual multimeter read 5.3 or 5.4 ohm between readings (a one-sided noise half
    a digit wide on R = 5.26 ohm); a meter on a resistor settles on one value. R now reads
    the motor's with the leads' 0.04 ohm and a noise a tenth of a digit: 5.3 ohm, every
    reading. Seed 6: the old meter read 5.4 ohm in its 1st and 14th readings."""
    app = real_app(tmp_path / "sessions", board_url(seed=6))
    readings: list[MeterReading] = []
    heard = Heard()

    def hook(message) -> None:
        heard.hook(message)
        if isinstance(message, MeterRead) and message.reading is not None:
            readings.append(message.reading)

    async with app.run_test(size=(80, 24), message_hook=hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        await goto(pilot, "task2")
        await heard.until(pilot, lambda: len(readings) >= 20)
        assert {m.R for m in readings} == {5.3}
        line = str(app.screen.query_one(MeterPanel).render())
        assert line.endswith("· 5.3 Ω")
