"""Pilot tests on the quiet device: start, wrong entries for every input kind, choices by
keys, resume, the stop key, help, palette entries, NO_COLOR."""

from __future__ import annotations

import pytest
from textual.filter import Monochrome, NoColor
from textual.message import Message
from textual.widgets import DataTable, OptionList

from minseg_tui.device.samples import SampleBatch
from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.ui.device import DeviceInfo, LinkState
from minseg_tui.ui.messages import CaptureRequested, RunRequested, VoltageRequested
from minseg_tui.ui.panels.live import LivePanel
from minseg_tui.ui.panels.square_wave import SquareWavePanel
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.screens.help import HelpScreen, KeyList
from minseg_tui.ui.screens.lab import LabScreen, StepCommands, StepPane
from minseg_tui.ui.widgets.fields import AnswerList, FieldRow, field_id
from minseg_tui.ui.widgets.status import status_text
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    record_response_run,
    resume,
    settle,
    shown,
    start,
    start_run_on,
    start_with_a_run,
    type_in,
    typing_box,
)


def _chosen(app, key: str) -> tuple[int, ...]:
    with app.session as s:
        return views.chosen(s, key)


def _run_in_use(app) -> str | None:
    with app.session as s:
        run = s.response_run()
    return run.name if run else None


async def test_new_session_lands_in_the_lab_and_saves(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        assert isinstance(app.screen, LabScreen)
        assert app.screen.step.id == "prep1"
    infos = list_sessions(tmp_path / "sessions")
    assert [i.members for i in infos] == [("Ada", "Bo")]
    assert infos[0].date == "2024-04-16"


async def test_empty_names_are_refused_with_a_message(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await pilot.press("enter")
        await settle(pilot)
        assert not isinstance(app.screen, LabScreen)
        assert "names first" in str(app.screen.query_one("#start-msg").render())
    assert list_sessions(tmp_path / "sessions") == []


async def test_wrong_entries_for_every_input_kind(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        # quantities
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "abc")
        assert (
            row.message.startswith("✗")
            and "not a number" in row.message
            and row.has_class("refused")
        )
        row = await type_in(pilot, "R", "5,2")
        said = row.message.replace("\u00a0", " ")  # the decimal comma read: said, not refused
        assert not row.has_class("refused") and said == "read as 5.2 Ω"
        row = await type_in(pilot, "R", "50 Ω")
        assert "above 20 Ω" in row.message and not row.has_class("refused")
        await goto(pilot, "task5")
        row = await type_in(pilot, "i_ss@2.5", "4.7 V")
        assert "is a voltage" in row.message and row.has_class("refused")
        row = await type_in(pilot, "i_ss@2.5", "0.047")
        assert "ambiguous" in row.message
        row = await type_in(pilot, "i_ss@3.5", "0.15 A")
        assert "above 100 mA" in row.message and not row.has_class("refused")
        row = await type_in(pilot, "i_ss@4.5", "47 mA")  # fine alone, but below 150 mA:
        assert row.message.startswith("! i_ss falls from 150 mA at 3.5 V to 47 mA at 4.5 V")
        await goto(pilot, "task4")
        row = await type_in(pilot, "u_ss@3.5", "3.1 A")
        assert row.has_class("refused")
        row = await type_in(pilot, "omega_ss@2.5", "")
        assert row.has_class("refused")
        # formulas: an unknown name, a broken expression, a wrong answer with its feedback
        await goto(pilot, "prep8")
        row = await type_in(pilot, "prep8.T", "a/x")
        assert row.has_class("refused") and row.message.startswith("✗")
        row = await type_in(pilot, "prep8.T", "b/a")
        assert "upside down" in row.message
        await goto(pilot, "prep4")
        row = await type_in(pilot, "prep4.fraction", "1 - exp(")
        assert row.has_class("refused")
        # a percentage typed as a fraction
        await goto(pilot, "prep5")
        row = await type_in(pilot, "prep5.percent", "0.63")
        assert "%" in row.message
        # free text is never refused
        await goto(pilot, "prep1")
        row = await type_in(pilot, "prep1.notes", "?? 42 Ω")
        assert not row.has_class("refused")
    s = Session.open(list_sessions(tmp_path / "sessions")[0].path, readonly=True)
    # nothing typed is lost, accepted or not
    assert s.entry("R").text == "50 Ω" and abs(s.value("R") - 50.0) < 1e-12
    assert s.entry("i_ss@2.5").text == "0.047" and not s.entry("i_ss@2.5").ok
    assert abs(s.value("i_ss@4.5") - 0.047) < 1e-12
    assert s.entry("u_ss@3.5").text == "3.1 A" and not s.entry("u_ss@3.5").ok
    assert s.entry("prep4.fraction").text == "1 - exp("
    assert s.entry("prep1.notes").text == "?? 42 Ω"


async def test_summary_answers_are_picked_with_keys(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "summary")
        radio = app.screen.query_one(f"#{field_id('summary.1')} AnswerList", AnswerList)
        radio.focus()
        await pilot.press("down", "enter")
        await settle(pilot)
        assert _chosen(app, "summary.1") == (1,)
        row = app.screen.query_one(f"#{field_id('summary.1')}", FieldRow)
        assert "system" in row.message  # the checker's feedback
        await pilot.press("up", "enter")  # a single-choice question keeps one answer
        await settle(pilot)
        assert _chosen(app, "summary.1") == (0,)
        sel = app.screen.query_one(f"#{field_id('summary.5')} AnswerList", AnswerList)
        sel.focus()
        await pilot.press("down", "space", "down", "space")
        await settle(pilot)
        assert _chosen(app, "summary.5") == (1, 2)
        await type_in(pilot, "summary.unclear", "why k_a is 0.65 k_v")
    s = Session.open(list_sessions(tmp_path / "sessions")[0].path, readonly=True)
    assert (
        s.entry("summary.5").value == (1, 2)
        and s.entry("summary.unclear").text == "why k_a is 0.65 k_v"
    )


async def test_resume_lands_where_the_group_left_off(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        await type_in(pilot, "i_ss@2.5", "31 mA")
    app2 = quiet()  # the first app released the session when it closed
    async with app2.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        assert isinstance(app2.screen, LabScreen)
        assert app2.screen.step.id == "task5"
        row = app2.screen.query_one(f"#{field_id('i_ss@2.5')}", FieldRow)
        assert row.input.value == "31 mA"


@pytest.mark.parametrize("step_id", ["table", "task4", "task10", "task11", "model_check"])
async def test_resume_on_a_step_with_a_panel(quiet, step_id):
    """A session left on a step with a panel resumes there, the panel built once (the list's
    first highlight on mount used to swap the pane mid-compose and crash the app)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, step_id)
    app2 = quiet()
    async with app2.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        assert isinstance(app2.screen, LabScreen) and app2.screen.step.id == step_id
        assert len(app2.screen.query(".panel")) == 1
        if step_id == "table":
            assert app2.screen.query_one("#table", DataTable).row_count == 3


async def test_run_log_keys_work_whatever_has_focus_but_leave_typing_alone(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task2")
        assert not app.screen.active_bindings[
            "f9"
        ].binding.show  # not in the footer where it does nothing
        await pilot.press("f9", "alt+right")  # says it is not part of this step; nothing breaks
        await settle(pilot)
        await goto(pilot, "task11")
        await settle(pilot)
        note = app.screen.query_one("#zoom-note")
        assert app.screen.active_bindings["f9"].binding.description == "Zoom"
        own = await type_in(pilot, "own.K", "")
        assert typing_box(app) is own.input
        await pilot.press("alt+right")
        await settle(pilot)
        assert "rise 2 of" in str(note.render())
        await pilot.press("left_square_bracket", "z")  # printable keys stay in the entry
        await settle(pilot)
        assert own.input.value == "[z" and "rise 2 of" in str(note.render())
        app.screen.query_one("#nav").focus()
        await pilot.press("ctrl+right")
        await settle(pilot)
        assert "rise 3 of" in str(note.render())
        await pilot.press("alt+left", "alt+left")
        await settle(pilot)
        assert "rise 1 of" in str(note.render())
        await pilot.press("f9", "f9")
        await settle(pilot)
        assert "rise 3 of" in str(note.render())


async def test_table_fits_80_columns_and_f7_gives_the_row_formula_with_its_numbers(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        await settle(pilot)
        table = app.screen.query_one("#table", DataTable)
        assert table.virtual_size.width <= table.size.width  # no sideways scrolling: f is in sight
        assert [str(c.label).split()[0] for c in table.columns.values()] == [
            "u",
            "u_ss",
            "omega_ss",
            "i_ss",
            "k_v",
            "f",
        ]
        table.focus()
        table.move_cursor(row=0, column=4)
        await pilot.press("f7")
        await settle(pilot)
        text = str(app.screen.query_one("#formula").render())
        # k_v = (u_ss - R i_ss) / omega_ss with row 1's numbers: (2.05 - 5.3 * 0.028) / 3.1
        # three significant digits with their zeros (issue 9), but R as the group typed it
        # (issue 20, walk 2 defect 11: '5,3' was shown as 5.30 Ω)
        assert "(2.05 V - 5.3 Ω × 0.0280 A) / 3.10 rad/s" in text and "= 0.6134 V s/rad" in text
        assert str(table.get_cell_at((0, 4))) == "0.6134"


async def test_the_palette_picks_the_run_tasks_11_to_15_use(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            first, second = record_response_run(s, seed=5), record_response_run(s, seed=6)
        texts = [t for t, _, _ in StepCommands(app.screen).entries()]
        assert (
            f"Use run {first} for Tasks 11-15" in texts
            and "Use the newest complete 25 ms run for Tasks 11-15" in texts
        )
        await goto(pilot, "task11")
        await settle(pilot)
        assert f"run {second}" in str(app.screen.query_one("#zoom-note").render())
        app.screen.use_run(first)
        await settle(pilot)
        assert f"run {first}" in str(app.screen.query_one("#zoom-note").render())
        app.screen.use_run(None)
        assert _run_in_use(app) == second
        app.screen.use_run(first)
        await goto(pilot, "task10")
        await start_run_on(pilot, dev)  # a new run recorded: the group's pick stays in use
        rec = app.recording
        rec.append(
            SampleBatch.from_rows([(k, 25_000 * k, 3 * k, 4500, 0, 0.0) for k in range(40, 80)])
        )
        app.finish_run("done")
        assert _run_in_use(app) == first
        app.screen.use_run(None)  # the default: the newest complete 25 ms run
        assert _run_in_use(app) == rec.name not in (first, second)


async def test_going_back_and_changing_r_recomputes_the_table(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        await settle(pilot)
        assert str(app.screen.query_one("#table", DataTable).get_cell_at((0, 4))) == "0.6134"
        await goto(pilot, "task2")
        await type_in(pilot, "R", "6 ohm")
        await goto(pilot, "table")
        await settle(pilot)
        # (2.05 V - 6 Ω × 0.028 A) / 3.1 rad/s = 0.6071 V s/rad
        assert str(app.screen.query_one("#table", DataTable).get_cell_at((0, 4))) == "0.6071"


async def test_a_voltage_set_on_task_3_is_still_the_request_on_task_4(quiet):
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task3")
        await pilot.press("f3")  # Task 3 says "set a voltage"
        await settle(pilot)
        assert dev.commands[-1] == "V 2.5"
        await goto(pilot, "task4")
        await pilot.press("f3")
        await settle(pilot)
        assert dev.commands[-1] == "V 3.5" and app.motor == "3.5 V"


async def test_stop_key_turns_the_motor_off_from_anywhere(quiet):
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await pilot.press("f3")
        await settle(pilot)
        assert dev.commands[-1] == "V 2.5" and app.motor == "2.5 V"
        await pilot.press("f3")
        await settle(pilot)
        assert dev.commands[-1] == "V 3.5"
        row = app.screen.query_one(f"#{field_id('u_ss@2.5')}", FieldRow)
        row.input.focus()
        await pilot.press("f2")
        await settle(pilot)
        assert dev.commands[-1] == "STOP" and app.motor == "off"
        await goto(pilot, "prep3")
        await pilot.press("f2")
        await settle(pilot)
        assert dev.commands[-1] == "STOP"


async def test_help_lists_the_keys_and_the_palette_has_the_actions(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await pilot.press("f1")
        await settle(pilot)
        assert isinstance(app.screen, HelpScreen)
        text = app.screen.query_one(KeyList).text
        for key in ("F2", "STOP", "F5", "F8", "Ctrl+P"):
            assert key in text
        await pilot.press("escape")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen)
        titles = {c.title for c in app.get_system_commands(app.screen)}
        assert {
            "Stop motor",
            "Export report",
            "Import a run log",
        } <= titles
        # on the virtual board already (walk 7: it was offered with VIRTUAL on the status line)
        assert "Switch to virtual board" not in titles
        await pilot.press("ctrl+p")
        await pilot.press(*"Task 10")
        await settle(pilot)
        await pilot.press("enter")
        await settle(pilot, lambda: shown(app, "task10"))


async def test_the_palette_offers_a_step_panel_action_only_on_its_steps(quiet):
    """Seen in the walk: 'Capture omega_ss' was offered on the model check (and on every
    step), where it only says that it is not part of this step."""
    panel_actions = {
        "Set step voltage",
        "Capture omega_ss",
        "Run the square wave",
        "Run the square wave fast",
    }
    offered = {
        "prep4": set(),
        "task3": {"Set step voltage"},
        "task4": {"Set step voltage", "Capture omega_ss"},
        "task10": {"Run the square wave", "Run the square wave fast"},
        "model_check": set(),
    }
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        for step_id, expected in offered.items():
            await goto(pilot, step_id)
            titles = {c.title for c in app.get_system_commands(app.screen)}
            assert titles & panel_actions == expected, step_id
            assert {"Stop motor", "Export report"} <= titles
        await pilot.press("ctrl+p")  # the palette asks about the screen under it
        await pilot.press(*"Capture")
        # the search is a worker's: wait for its list (a match, or the line saying none does)
        await settle(
            pilot,
            lambda: any(
                h.option_count for h in app.screen.query("CommandList").results(OptionList)
            ),
        )
        hits = app.screen.query_one("CommandList", OptionList)
        prompts = [str(hits.get_option_at_index(k).prompt) for k in range(hits.option_count)]
        assert not any("Capture omega_ss" in p for p in prompts)


async def test_navigator_collapses_and_marks_done_steps(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        nav = app.screen.query_one("#nav")
        assert nav.size.width <= 16
        await goto(pilot, "task2")
        await type_in(pilot, "R", "5.3")
        assert str(nav.get_option("task2").prompt).startswith("✓")
        await pilot.press("ctrl+t")
        await settle(pilot)
        assert not nav.display
        await pilot.press("ctrl+t")
        await settle(pilot)
        assert nav.display


async def test_no_color_is_respected(quiet, monkeypatch):
    monkeypatch.setenv("NO_COLOR", "1")
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        assert app.no_color
        assert any(isinstance(f, Monochrome | NoColor) for f in app.get_line_filters())
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "abc")
        assert row.message.startswith("✗")  # the refusal is in the text, not only in red
        with app.session as s:
            s.choose("summary.1", [1])
            s.choose("summary.5", [1, 2])
        await goto(pilot, "summary")
        await settle(pilot)
        radios = app.screen.query_one(f"#{field_id('summary.1')}", FieldRow).query_one(AnswerList)
        lines = radios.render().plain.splitlines()
        assert [line[1] for line in lines] == [" ", "●", " "]  # the choice, not a colour
        ticks = app.screen.query_one(f"#{field_id('summary.5')}", FieldRow).query_one(AnswerList)
        marks = [line[1] for line in ticks.render().plain.splitlines()]
        assert marks.count("X") == 2 and marks[1] == marks[2] == "X"


def test_status_line_fits_80_columns_in_every_state():
    info = DeviceInfo("Virtual", "minseg-virtual 1.0.0", True, "minseg://", fallback=True)
    board = DeviceInfo(
        "MinSegMega", "minseg-fw 1.0.0", False, "/dev/serial/by-id/usb-Arduino_Mega_2560-if00"
    )
    for i in (info, board):
        for event in (
            "",
            "board disconnected — everything recorded is kept",
            "watchdog stopped the motor",
        ):
            text = status_text(i, LinkState("ok", 12345, 678, event), "steps 0/4.5 V", 78)
            assert len(text) <= 78, text
            assert "motor steps" in text
    assert "no board found" in status_text(info, LinkState(), "off")
    assert "disconnected" in status_text(
        board, LinkState(event="board disconnected — everything recorded is kept"), "off", 78
    )


async def test_typing_lands_in_the_step_and_enter_moves_on(quiet, tmp_path):
    """Palette jump, then typing at once: the text goes into the first entry (never nowhere);
    Enter on an accepted entry moves to the next one; a refused retype keeps the accepted value."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await settle(pilot)
        await pilot.press(*"3,8", "enter")
        await settle(pilot)
        with app.session as session:
            assert session.value("omega_ss@2.5") == 3.8
        assert typing_box(app) is app.screen.query_one(f"#{field_id('u_ss@2.5')}", FieldRow).input
        await pilot.press(*"2,05 kg", "enter")
        await settle(pilot)
        await goto(pilot, "task2")  # typing on the list of steps goes into the entry too
        app.screen.query_one("#nav").focus()
        await pilot.press(*"5,3", "enter")
        await settle(pilot)
        with app.session as session:
            assert session.value("R") == 5.3
        row = await type_in(pilot, "R", "5,3 kg")
        assert row.has_class("refused") and "still using '5,3'" in row.message
        with app.session as session:
            assert session.value("R") == 5.3
    with Session.open(next(iter(list_sessions(tmp_path / "sessions"))).path) as again:
        assert again.entry("u_ss@2.5").typed == "2,05 kg"
        assert again.entry("R").typed == "5,3 kg" and again.value("R") == 5.3


async def test_the_entry_a_step_lands_in_stays_in_view_when_its_view_comes_later(quiet):
    """Task 12 at 80x24 lands in the group's T under the zoomed plot, which a worker builds:
    whether the view is drawn before or after the landing, the entry ends up in the same place
    and in full view (it came a row lower or out of sight, depending on the machine's load)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await settle(pilot)
        pane = app.screen.query(StepPane).last()
        box = typing_box(app)
        assert box is not None and box is pane.landing_row().input
        landed = pane.scroll_y
        assert landed > 0 and app.screen.can_view_entire(box)
        for elsewhere in (0.0, pane.max_scroll_y):  # where the step was when the view came
            pane.scroll_to(y=elsewhere, animate=False, immediate=True)
            panel = pane.panel
            assert isinstance(panel, ViewPanel) and panel.view is not None
            panel.receive(panel.view)
            await settle(pilot)
            assert pane.scroll_y == landed and app.screen.can_view_entire(box)


async def test_panels_ask_with_messages_and_show_the_apps_state(quiet):
    """F3, F4 and F5 reach the app and the screen as messages from the step's panel; what
    they change (the requested voltage, the motor, the run) is the app's state, which the
    panels show."""
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    heard: list[Message] = []
    async with app.run_test(size=(80, 24), message_hook=heard.append) as pilot:

        def asked(kind: type[Message]) -> list[Message]:
            return list({id(m): m for m in heard if isinstance(m, kind)}.values())

        await start(pilot)
        await goto(pilot, "task4")
        await pilot.press("f3")
        await settle(pilot)
        assert [m.level for m in asked(VoltageRequested)] == [2.5]
        assert app.requested == app.screen.query_one(LivePanel).requested == 2.5
        assert app.motor == "2.5 V" and dev.commands[-1] == "V 2.5"
        await pilot.press("f4")
        await settle(pilot)
        assert [m.level for m in asked(CaptureRequested)] == [2.5]
        with app.session as s:  # the double streams nothing: never settled, nothing stored
            assert s.entry("omega_ss@2.5") is None
        await goto(pilot, "task10")
        await start_run_on(pilot, dev)
        assert [m.plan for m in asked(RunRequested)] == ["manual"]
        assert app.recording is not None and dev.commands[-1] == "STEP 0 4.5 1.5 4"
        panel = app.screen.query_one(SquareWavePanel)
        assert panel.run_progress is not None and panel.run_progress.recording
        await pilot.press("f2")
        await settle(pilot)
        assert app.recording is None and dev.commands[-1] == "STOP"
        assert panel.run_progress.text.startswith("stopped: run steps-1: ")
