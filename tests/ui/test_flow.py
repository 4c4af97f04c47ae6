"""Pilot tests: start, entries (good and bad), autosave, resume, stop key, help."""

from __future__ import annotations

from minseg_tui.lab.session import Session
from minseg_tui.lab.store import list_sessions
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.fakes import FakeDevice


async def _start(pilot, names: str = "Ada, Bo") -> None:
    await pilot.pause()
    await pilot.press(*names)
    await pilot.press("enter")
    await pilot.pause()


async def _goto(pilot, app, step_id: str) -> None:
    app.go_to_step(step_id)
    await pilot.pause()
    await pilot.pause()


async def _type(pilot, app, key: str, text: str) -> FieldRow:
    row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
    row.input.focus()
    row.input.value = ""
    await pilot.press(*text) if text else None
    await pilot.press("enter")
    await pilot.pause()
    return row


async def test_new_session_lands_in_the_lab_and_saves(make, tmp_path):
    app = make()
    async with app.run_test(size=(80, 24)) as pilot:
        await _start(pilot)
        assert isinstance(app.screen, LabScreen)
        assert app.screen.step.id == "prep1"
    infos = list_sessions(tmp_path / "sessions")
    assert [i.members for i in infos] == [("Ada", "Bo")]
    assert infos[0].date == "2024-04-16"


async def test_empty_names_are_refused_with_a_message(make, tmp_path):
    app = make()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        await pilot.press("enter")
        await pilot.pause()
        assert not isinstance(app.screen, LabScreen)
        assert "names first" in str(app.screen.query_one("#start-msg").render())
    assert list_sessions(tmp_path / "sessions") == []


async def test_entries_accept_the_lab_forms_and_refuse_the_rest(make, tmp_path):
    app = make()
    async with app.run_test(size=(80, 24)) as pilot:
        await _start(pilot)
        await _goto(pilot, app, "task2")
        row = await _type(pilot, app, "R", "abc")
        assert "not a number" in row.message
        assert row.has_class("refused")
        row = await _type(pilot, app, "R", "5,2")
        assert not row.has_class("refused") and row.message == ""
        row = await _type(pilot, app, "R", "50 Ω")
        assert "above 20 Ω" in row.message
        await _goto(pilot, app, "task5")
        row = await _type(pilot, app, "i_ss@2.5", "4.7 V")
        assert "is a voltage" in row.message and row.has_class("refused")
        row = await _type(pilot, app, "i_ss@2.5", "0.047")
        assert "ambiguous" in row.message
        row = await _type(pilot, app, "i_ss@3.5", "0.15 A")
        assert "above 100 mA" in row.message and not row.has_class("refused")
        row = await _type(pilot, app, "i_ss@4.5", "47 mA")
        assert row.message == ""
        await _goto(pilot, app, "task4")
        row = await _type(pilot, app, "u_ss@2.5", "2,1 V")
        assert row.message == ""
        row = await _type(pilot, app, "u_ss@3.5", "3.1 A")
        assert row.has_class("refused")
    folder = list_sessions(tmp_path / "sessions")[0].path
    s = Session.open(folder, readonly=True)
    # nothing typed is lost, accepted or not
    assert s.entry("R").text == "50 Ω" and abs(s.value("R") - 50.0) < 1e-12
    assert s.entry("i_ss@2.5").text == "0.047" and not s.entry("i_ss@2.5").ok
    assert abs(s.value("i_ss@4.5") - 0.047) < 1e-12
    assert abs(s.value("u_ss@2.5") - 2.1) < 1e-12
    assert s.entry("u_ss@3.5").text == "3.1 A"
    assert s.current_step == "task4"


async def test_resume_lands_where_the_group_left_off(make, tmp_path):
    app = make()
    async with app.run_test(size=(80, 24)) as pilot:
        await _start(pilot)
        await _goto(pilot, app, "task5")
        await _type(pilot, app, "i_ss@2.5", "31 mA")
    app.lab.session.close()
    app2 = make()
    async with app2.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        app2.screen.query_one("#sessions").focus()
        await pilot.press("enter")
        await pilot.pause()
        await pilot.pause()
        assert isinstance(app2.screen, LabScreen)
        assert app2.screen.step.id == "task5"
        row = app2.screen.query_one(f"#{field_id('i_ss@2.5')}", FieldRow)
        assert row.input.value == "31 mA"


async def test_stop_key_turns_the_motor_off_from_anywhere(make):
    dev = FakeDevice(seed=2)
    app = make(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await _start(pilot)
        await _goto(pilot, app, "task4")
        await pilot.press("f3")
        await pilot.pause()
        assert dev.commands[-1] == "V 2.5"
        assert app.motor == "2.5 V"
        row = app.screen.query_one(f"#{field_id('u_ss@2.5')}", FieldRow)
        row.input.focus()
        await pilot.press("f2")
        await pilot.pause()
        assert dev.commands[-1] == "STOP" and app.motor == "off"


async def test_help_lists_the_keys(make):
    app = make()
    async with app.run_test(size=(80, 24)) as pilot:
        await _start(pilot)
        await pilot.press("f1")
        await pilot.pause()
        assert isinstance(app.screen, HelpScreen)
        text = str(app.screen.query_one("#help-keys").render())
        assert "F2" in text and "STOP" in text
        await pilot.press("escape")
        await pilot.pause()
        assert isinstance(app.screen, LabScreen)
