"""Walk 11's defects (issue 20), each as the walk met it, at 80x24 with Pilot on a real
session folder (/work/coord/WALK11.md)."""

from __future__ import annotations

import json
import threading

import pytest
from textual.widgets import DataTable

from minseg_tui.ui.keys import help_lines
from minseg_tui.ui.panels.model_check import ModelCheckPanel
from minseg_tui.ui.panels.results import ResponsePlot
from minseg_tui.ui.screens.boardcheck import BoardCheckScreen, WheelQuestionScreen
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.quit import RECORDING_CHOICES, QuitScreen
from minseg_tui.ui.widgets.plots import Canvas
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    burst,
    enter_all,
    goto,
    lab_screen,
    nav_mark,
    record_response_run,
    settle,
    standing,
    start,
    start_run_on,
    start_with_a_run,
    taken,
)


def _step(app) -> str:
    with app.session as s:
        return s.current_step


def _board_check(app) -> None:
    app.push_screen(BoardCheckScreen(True, "The wheel turns and the count follows."))


def _help(app) -> None:
    app.push_screen(HelpScreen(help_lines()))


def _quit_asked(app) -> None:
    app.push_screen(QuitScreen("Run steps-1 is being recorded.", "A run", RECORDING_CHOICES))


@pytest.mark.parametrize(
    ("open_it", "dialog", "close"),
    [
        (_board_check, BoardCheckScreen, "enter"),
        (_board_check, BoardCheckScreen, "escape"),
        (_help, HelpScreen, "escape"),
        (_help, HelpScreen, "q"),
        (_quit_asked, QuitScreen, "escape"),
        (_quit_asked, QuitScreen, "enter"),
    ],
    ids=["board-check-enter", "board-check-esc", "help-esc", "help-q", "quit-esc", "quit-enter"],
)
async def test_a_key_typed_right_after_the_key_that_closes_a_dialog_acts_beneath(
    quiet, open_it, dialog, close
):
    """D1: on Task 1, F10, then 'Enter PgDn' in one burst: the board check's answer closed
    and the PgDn was lost (4 times in 4; F1 then 'Esc PgDn' too). The dialog's screen was
    still the app's screen when the app read PgDn, and its own widgets had it. The key that
    closes a dialog now closes it before the app reads the next key, which acts on the
    screen beneath: here PgDn goes to the next step."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task1")
        open_it(app)
        await settle(pilot, lambda: isinstance(app.screen, dialog))
        await burst(pilot, close, "pagedown")
        await settle(pilot, lambda: not isinstance(app.screen, dialog))
        assert _step(app) == "task2"


async def test_arrows_before_enter_pick_the_answer_and_the_key_after_acts_beneath(quiet):
    """D1 on a dialog of answers ('did the wheel turn?'): 'Down Enter PgDn' in one burst
    answers what the arrow picked ('It did not turn'), and PgDn then goes to the next step."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task1")
        answers: list[str] = []
        app.push_screen(WheelQuestionScreen(), answers.append)
        await settle(pilot, lambda: isinstance(app.screen, WheelQuestionScreen))
        await burst(pilot, "down", "enter", "pagedown")
        await settle(pilot, lambda: not isinstance(app.screen, WheelQuestionScreen))
        assert answers == ["no"]
        assert _step(app) == "task2"


def _said(screen) -> str:
    return "\n".join(p.text for p in screen.query(Prose))


async def test_the_quit_dialogs_sample_count_follows_the_recording(quiet):
    """Issue 20's note: Ctrl+Q while a run was recorded asked 'Run steps-1 is being recorded
    (71 samples so far)', and the 71 stayed while the run went on behind the dialog (it
    ended with 487). The count follows the samples the run keeps."""
    device = QuietDevice(seed=1)
    app = quiet(device)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task10")
        seq = await start_run_on(pilot, device)
        await pilot.press("ctrl+q")
        await settle(pilot, lambda: isinstance(app.screen, QuitScreen))
        before = app.recording.samples
        assert f"({before} samples so far)" in _said(app.screen), _said(app.screen)
        device.feed(standing(40, seq))
        await taken(pilot, seq + 40)
        await settle(pilot, lambda: app.recording.samples >= before + 40)
        now = app.recording.samples
        assert f"({now} samples so far)" in _said(app.screen), (now, _said(app.screen))
        await pilot.press("escape")
        await settle(pilot)


async def _until(pilot, cond) -> None:
    """Rounds of the app's messages until ``cond()`` holds (for a wait while a worker is
    held on purpose, which :func:`settle` would wait for)."""
    for _ in range(1000):
        await pilot.pause(0)
        if cond():
            return
    raise AssertionError("the app never got there")


async def test_the_model_check_draws_no_empty_frames_while_it_works(quiet, monkeypatch):
    """Issue 20's note: while the check was fitting the run, its panel showed two empty
    plot frames titled 'measured vs models' and 'residual' (1-4 s in the walks), then the
    real plots. While it works, the panel says so and draws no frame; the plots come with
    the view."""
    release = threading.Event()
    build = ModelCheckPanel.build

    def held(panel, session):
        release.wait(60)
        return build(panel, session)

    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task10")
        monkeypatch.setattr(ModelCheckPanel, "build", held)
        lab_screen(app).go_to("model_check", "entry")

        def panel() -> ModelCheckPanel | None:
            found = app.screen.query(ModelCheckPanel)
            return found.first() if found else None

        try:
            await _until(pilot, lambda: panel() is not None and panel().is_mounted)
            check = panel()
            plots = check.query_one(".check-plots")
            assert not plots.display
            assert "computing" in check.query_one("#check-story", Prose).text
        finally:
            release.set()
        await settle(pilot, lambda: check.view is not None and plots.display)


async def test_the_table_shows_readings_with_the_digits_typed(quiet):
    """D4: i_ss typed '14' stood '14.0' in the Tasks 6-9 table, a digit the group never
    read off the meter (the README: readings keep the digits they were typed with); a
    u_ss typed with four digits lost one, and omega_ss typed 3,1 stood 3.10. The table's
    readings are shown as typed (a captured omega_ss, a mean, keeps its 3 digits and spread)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        typed = {"R": "5.3", "u_ss@2.5": "2.053", "omega_ss@2.5": "3,1", "i_ss@2.5": "14"}
        enter_all(app, typed | {"i_ss@3.5": "29,8"})
        await goto(pilot, "table", focus=None)
        table = app.screen.query_one("#table", DataTable)
        await settle(pilot, lambda: table.row_count == 3)
        first = [str(c) for c in table.get_row_at(0)]
        second = [str(c) for c in table.get_row_at(1)]
        assert first[1:4] == ["2.053", "3.1", "14"], first
        assert second[3] == "29.8", second


@pytest.mark.parametrize("step_id", ["task11", "task12"])
async def test_the_plot_calls_the_voltage_u_a_only_once_u_ss_maps_it(quiet, step_id):
    """D5: with a run and no u_ss typed, Task 11's plot drew the requested 4.5 V on its
    right axis titled 'u_A [V]' (legend '•• u_A [V], right axis'); with u_ss at 4.5 V the
    same axis reads 4.02. Without u_ss the trace is the requested voltage and says so."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, step_id)
        plot = app.screen.query_one(ResponsePlot)
        labels = [t.label for t in plot.query_one(Canvas).traces if t.right]
        assert labels == ["u requested [V]"], labels
        enter_all(app, {"u_ss@4.5": "4.02"})
        app.lab_changed.publish(None)
        await settle(
            pilot,
            lambda: [t.label for t in plot.query_one(Canvas).traces if t.right] == ["u_A [V]"],
        )


async def test_the_help_wraps_a_long_line_under_its_description(quiet):
    """D7: F1's line for F9 wrapped to the left edge at 80x24 ('log (check)' under 'F9'),
    where the keys stand. A wrapped description goes on under the description."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await pilot.press("f1")
        await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
        keys = app.screen.query_one("#help-keys")
        lines = [strip.text for strip in keys.render_lines(keys.region.reset_offset)]
        at = next(k for k, line in enumerate(lines) if line.startswith("F9 "))
        assert lines[at + 1].startswith(" " * 11), lines[at : at + 2]


async def test_a_blank_note_leaves_the_step_as_it_was(quiet):
    """D6: on Prep 2 a Space meant for 'done?' went into the notes (the step's first empty
    entry), was stored as ' ', and the list of steps showed Prep 2 as started ('…') while
    the report said its notes were not answered. A blank text starts nothing, and is not
    stored (walk 12's re-check: session.json still held ``prep2.notes: " "``)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep2")
        await burst(pilot, " ", "pagedown")
        with app.session as s:
            assert s.entry("prep2.notes") is None
            saved = json.loads((s.folder / "session.json").read_text(encoding="utf-8"))
        assert "prep2.notes" not in json.dumps(saved), saved
        await settle(pilot, lambda: _step(app) == "prep3")
        assert nav_mark(app, "prep2") == " ", nav_mark(app, "prep2")


async def test_a_note_cleared_is_stored_cleared_and_ctrl_z_brings_it_back(quiet):
    """The other side of the blank note: a note written and then cleared is a change the
    group made; it is stored (the note no longer stands), and Ctrl+Z brings it back."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep2")
        await burst(pilot, *"q on eq 2.6", "enter")
        with app.session as s:
            assert s.entry("prep2.notes").text == "q on eq 2.6"
        await burst(pilot, "shift+tab", "ctrl+u", " ", "enter")
        with app.session as s:
            assert not s.entry("prep2.notes").text.strip()
        await burst(pilot, "shift+tab", "ctrl+z")
        with app.session as s:
            assert s.entry("prep2.notes").text == "q on eq 2.6"
