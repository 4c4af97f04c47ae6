"""The keys that act from anywhere (F2, Ctrl+P, Ctrl+Q, PgDn, PgUp) act in the order typed.

The app reads a burst key by key and hands each to the focused widget's queue as it reads
it; a key whose binding the app ran at once, as it read it, acted before the keys typed
ahead of it had reached their entry. '5,3 F2' typed quickly stopped the motor with nothing
stored, and '0,63 PgDn' on the list of steps showed the next step before the reading went
in, so it landed in the new step's entry. Each test types a value and then the key in one
burst, and checks that the value was stored where it was typed, and that the key's action
came after it: at the moment the action happened, the value was already stored."""

from __future__ import annotations

import pytest
from textual.command import CommandPalette

from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.session import Session
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    box_text,
    burst,
    goto,
    on_the_list,
    settle,
    shown,
    start,
    stored_text,
)

PLACES = ["entry", "list of steps"]
"""Where the focus is when the value is typed: in the step's entry, or on the list of steps
(a character typed there goes into the step's first empty entry)."""


_typed = stored_text
_box = box_text


async def _on(pilot, step_id: str, place: str) -> None:
    await goto(pilot, step_id)
    if place == "list of steps":
        await pilot.press("ctrl+l")
        await settle(pilot, lambda: on_the_list(pilot.app))


@pytest.mark.parametrize("place", PLACES)
async def test_f2_stops_the_motor_after_the_value_typed_before_it_is_stored(quiet, place):
    dev = QuietDevice(seed=2)
    app = quiet(dev)
    at_stop: list[str] = []
    stop = dev.stop

    def stop_and_note() -> None:
        at_stop.append(_typed(app, "R"))
        stop()

    dev.stop = stop_and_note
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await _on(pilot, "task2", place)
        await burst(pilot, *"5,3", "f2")
        assert _typed(app, "R") == "5,3"
        assert at_stop[:1] == ["5,3"]
        assert app.motor == "off"


@pytest.mark.parametrize("place", PLACES)
async def test_ctrl_p_opens_the_palette_after_the_value_typed_before_it_is_stored(quiet, place):
    app = quiet()
    at_open: list[str] = []
    push = app.push_screen

    def push_and_note(screen, *args, **kwargs):
        if isinstance(screen, CommandPalette):
            at_open.append(_typed(app, "R"))
        return push(screen, *args, **kwargs)

    app.push_screen = push_and_note
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await _on(pilot, "task2", place)
        await burst(pilot, *"5,3", "ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        assert at_open == ["5,3"]
        assert _typed(app, "R") == "5,3"


@pytest.mark.parametrize("place", PLACES)
async def test_ctrl_q_quits_after_the_value_typed_before_it_is_stored(quiet, tmp_path, place):
    app = quiet()
    at_exit: list[str] = []
    leave = app.exit

    def exit_and_note(*args, **kwargs):
        at_exit.append(_typed(app, "R"))
        return leave(*args, **kwargs)

    app.exit = exit_and_note
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await _on(pilot, "task2", place)
        await burst(pilot, *"5,3", "ctrl+q")
    assert at_exit[:1] == ["5,3"]
    (info,) = list_sessions(tmp_path / "sessions")
    with Session.open(info.path) as s:
        assert s.entry("R").typed == "5,3"


@pytest.mark.parametrize("place", PLACES)
@pytest.mark.parametrize(
    ("key", "there", "value", "field", "after", "next_field"),
    [
        ("pagedown", "prep4", "0,63", "prep4.fraction", "prep5", "prep5.percent"),
        ("pageup", "prep5", "63 %", "prep5.percent", "prep4", "prep4.fraction"),
    ],
)
async def test_pgdn_and_pgup_move_after_the_value_typed_before_them_is_stored(
    quiet, place, key, there, value, field, after, next_field
):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await _on(pilot, there, place)
        await burst(pilot, *value, key)
        assert shown(app, after)
        assert _typed(app, field) == value
        assert _box(app, next_field) == ""  # nothing of it went into the step shown next
        assert _typed(app, next_field) == ""
