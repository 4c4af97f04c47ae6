"""Keys in bursts, as a hurried group types them (or a terminal hands them over): several keys
in one read, none waiting for the app. Every key must go where it would have gone had the
app been infinitely fast: the text typed before PgDn into the step being left, the keys
after it into the new step; after Enter, into the next entry."""

from __future__ import annotations

import pytest
from textual.command import CommandPalette

from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.fakes import QuietDevice, frozen_stream
from tests.ui.helpers import (
    box_text,
    burst,
    goto,
    settle,
    shown,
    start,
    start_with_a_run,
    stored_text,
    typing_box,
)

_typed = stored_text
_box = box_text


async def test_keys_typed_around_pgdn_land_in_their_own_steps(quiet):
    """Seen in tmux: 'PageDown 63 % Enter' put '63 %' into Preparation 4 (the step left),
    and '0,63 PageDown' kept nothing when the keys were still on their way."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep4")
        await burst(pilot, *"0,63", "pagedown", *"63 %", "enter", "pagedown", *"3,79", "enter")
        assert shown(app, "prep6")
        assert _typed(app, "prep4.fraction") == "0,63"
        assert _typed(app, "prep5.percent") == "63 %"
        assert _typed(app, "prep6.y10") == "3,79"
        assert _box(app, "prep6.y10") == "3,79"


async def test_keys_typed_after_enter_go_into_the_next_entry(quiet):
    """Seen in tmux: '90 Enter 12 min Enter 10 Enter' in one burst left '9012 min10' in the
    first entry of Preparation 7."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep7")
        await burst(pilot, *"90", "enter", *"12 min", "enter", *"8 min", "enter", *"0,09")
        assert _typed(app, "prep7.y_final") == "90"
        assert _typed(app, "prep7.t_63") == "12 min"
        assert _typed(app, "prep7.T") == "8 min"
        assert _box(app, "prep7.K") == "0,09"
        assert typing_box(app) is app.screen.query_one(f"#{field_id('prep7.K')}", FieldRow).input


async def test_a_panel_key_right_after_pgdn_works_on_the_new_step(quiet):
    """Candidate (a) of the last walk: F5 sent in the same burst right after PgDn was dropped
    (the new step's panel, which has the key, was not mounted yet). F3 on Task 3 the same."""
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, "pagedown", "f3")
        assert shown(app, "task3")
        assert dev.commands[-1:] == ["V 2.5"]
        await goto(pilot, "table")
        before = len(dev.commands)
        await burst(pilot, "pagedown", "f5")
        assert shown(app, "task10")
        assert dev.commands[before:] == ["STOP"]  # the run begins: motor off, wheel to stand


async def test_the_reading_typed_right_after_f4_goes_into_the_next_entry(quiet):
    """Seen in tmux on Task 4: 'F4 2,05 Enter' in one burst left u_ss at 2.5 V empty (the
    reading went into the omega_ss box the capture then overwrote), and the next burst
    'F4 2,9V Enter' at 3.5 V put 2.9 V into the 2.5 V row."""
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        assert app.requested == 2.5
        app.live.extend(frozen_stream(u=2.5))
        await burst(pilot, "f4", *"2,05", "enter")
        with app.session as s:
            assert s.value("omega_ss@2.5") is not None
        assert _typed(app, "u_ss@2.5") == "2,05"
        assert (
            typing_box(app) is app.screen.query_one(f"#{field_id('omega_ss@3.5')}", FieldRow).input
        )


async def test_keys_typed_right_after_the_names_land_in_the_lab(quiet):
    """Seen in tmux: 'Bo, Cy Enter PgDn PgDn PgDn 0,632 Enter' opened the lab at Preparation 1
    with nothing typed: the keys after Enter went to the start screen while it was replaced."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(
            pilot, *"Bo, Cy", "enter", "pagedown", "pagedown", "pagedown", *"0,632", "enter"
        )
        await settle(pilot, lambda: shown(app, "prep4"))
        assert _typed(app, "prep4.fraction") == "0,632"
        with app.session as s:
            assert list(s.members) == ["Bo", "Cy"]


async def test_keys_typed_after_tab_go_into_the_next_entry(quiet):
    """Seen in tmux (walk 4): '90 Tab 12 min Tab 8 min' in one burst left '9012 min8 min' in
    the first entry of Preparation 7: the keys after Tab went to the box Tab was leaving,
    which still had the focus while the Tab made its way up to the app."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep7")
        await burst(pilot, *"90", "tab", *"12 min", "tab", *"8 min", "shift+tab", *"11 min")
        assert _typed(app, "prep7.y_final") == "90"
        assert _typed(app, "prep7.T") == "8 min"  # stored by the Shift+Tab that left it
        assert _box(app, "prep7.t_63") == "11 min"  # Shift+Tab came back: typing replaced it
        assert typing_box(app) is app.screen.query_one(f"#{field_id('prep7.t_63')}", FieldRow).input


async def test_tab_tab_enter_on_the_start_screen_resumes_the_session(quiet, tmp_path):
    """Seen in tmux (walk 4): 'Tab Tab Enter PgUp PgUp 9,69 Enter' on the start screen, to
    resume the saved session, made a new session named '9,69': the Enter read the focus
    before the Tabs had moved it from the names to the list of sessions."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot, "Ann K, Ben L")
        await goto(pilot, "task15")
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(pilot, "tab", "tab", "enter", "pageup", *"4,7", "enter")
        await settle(pilot, lambda: shown(app, "task14"))
        with app.session as s:
            assert list(s.members) == ["Ann K", "Ben L"]
        assert _typed(app, "own.model") == "4,7"
    assert len(list((tmp_path / "sessions").iterdir())) == 1


async def test_keys_typed_on_a_step_shown_by_pgdn_all_land_in_its_entry(quiet):
    """Seen in tmux (walk 4): 'PgDn PgDn why 0 rising steps?' in one burst from Task 14 left
    'wh' in the model check's notes: the keys were handed to the step (which has the focus on
    a step with a panel and no entry to land in) and passed on to the screen, which lost
    those that came after the focus had moved into the notes."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task14")
        await burst(pilot, "pagedown", "pagedown", *"why 0 rising steps?", "f8")
        assert shown(app, "model_check")
        assert _box(app, "model_check.notes") == "why 0 rising steps?"
        assert _typed(app, "model_check.notes") == "why 0 rising steps?"  # F8 stored it


async def test_keys_typed_on_the_list_of_steps_all_go_into_one_entry(quiet):
    """Seen in tmux (walk 3, stop 24): '7,8 Enter Tab 7,8/4,05' in one burst on Task 11. Enter
    stored omega_ss and moved to K, Tab moved to the list of steps, and the keys typed there
    go into the first empty entry, K. The first did; the rest, handed to the list before the
    focus reached K, looked for the first empty entry again, found K filled by the first, and
    replaced omega_ss ('7' stored as K, ',8/4,05' over omega_ss)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await goto(pilot, "task11")
        await burst(pilot, *"7,8", "enter", "tab", *"7,8/4,05", "enter")
        assert _typed(app, "own.omega_step") == "7,8"
        assert _box(app, "own.omega_step") == "7,8"
        assert _typed(app, "own.K") == "7,8/4,05"


async def test_two_enters_in_the_palette_leave_the_lab_on_screen(quiet):
    """Seen in tmux: 'Ctrl+P task 6 Enter 0,497 Tab ... Enter' in one burst left an empty
    terminal and a traceback: the palette closes itself once per Enter it is handed, and
    the second close took the lab screen under it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await pilot.press("ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        await pilot.press(*"task 6")
        await settle(pilot)
        await pilot.press("down")  # a command highlighted: Enter runs it
        await settle(pilot)
        await burst(pilot, "enter", "enter")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen) and shown(app)
        assert [type(s) for s in app.screen_stack[1:]] == [LabScreen]


@pytest.mark.parametrize(
    "keys",
    [
        ["ctrl+u", *"0,63", "enter"],
        ["ctrl+u", *"0,63"],
        ["end", "backspace", "backspace", "backspace", *"0,63", "enter"],
        ["end", "backspace", "backspace", "backspace", *"0,63"],
        ["home", "shift+end", "delete", *"0,63", "enter"],
    ],
)
async def test_editing_keys_in_a_burst_act_before_the_text_typed_after_them(quiet, keys):
    """Found in a walk: 'Ctrl+U 0,63 Enter' in one burst on an answered entry stored 0,63 but
    left the box empty ('End Backspace x3 0,63' left '0'): the text went in first, the
    editing keys after it; leaving the step then stored the box over the answer."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep4")
        await burst(pilot, *"0,5", "enter")
        await goto(pilot, "prep4")
        await burst(pilot, *keys)
        assert _box(app, "prep4.fraction") == "0,63"
        if keys[-1] == "enter":
            assert _typed(app, "prep4.fraction") == "0,63"
        await burst(pilot, "pagedown")
        assert shown(app, "prep5")
        assert _typed(app, "prep4.fraction") == "0,63"
