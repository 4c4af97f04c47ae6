"""Walk 7's key defects (D1, D2, D12, D5, D11, D3, D17): keys in bursts land where and when
they were typed; a step arrives with its values drawn."""

from __future__ import annotations

import threading
from collections.abc import Callable
from pathlib import Path

from textual import events
from textual.command import CommandPalette
from textual.pilot import Pilot
from textual.widgets import Input

from minseg_tui.lab.views.session import marks_legend
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.screens.help import INTRO
from minseg_tui.ui.screens.lab import LabScreen
from tests.ui.fakes import QuietDevice, frozen_stream
from tests.ui.helpers import ROUNDS, box_text, burst, goto, settle, shown, start, stored_text
from tests.ui.textual_internals import key_name


async def test_names_typed_in_a_burst_with_backspaces_are_kept(quiet):
    """Walk 7 (D1): 'Kim Parkk' BSpace BSpace 'k' Enter in one burst created 'Kim Parkkk'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(pilot, *"Abcd", "backspace", "backspace", "x")
        assert app.screen.query_one("#members", Input).value == "Abx"
        await burst(pilot, *"yz")
        assert app.screen.query_one("#members", Input).value == "Abxyz"


async def test_a_group_typed_in_one_burst_with_backspaces_gets_its_names(quiet):
    """Walk 7 (D1): 'Lena Berg, Omra' BSpace x3 'mar Haddad' Enter created the session of
    'Lena Berg', 'Omrr Haddad' (the name in the session id, the report, the class view)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(pilot, *"Lena Berg, Omra", *["backspace"] * 3, *"mar Haddad", "enter")
        await settle(pilot, lambda: shown(app))
        assert app.session is not None
        with app.session as s:
            assert list(s.members) == ["Lena Berg", "Omar Haddad"]


async def test_keys_typed_right_after_ctrl_p_go_into_the_palette(quiet):
    """Walk 7 (D12): 'Ctrl+P Task 5' in one burst on Task 2 opened an empty palette and put
    'Task 5' into the R box under it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, *"5.3", "enter")
        assert stored_text(app, "R") == "5.3"
        await burst(pilot, "ctrl+p", *"Task 5")
        assert isinstance(app.screen, CommandPalette)
        assert app.screen.query_one(Input).value == "Task 5"
        await burst(pilot, "escape")
        assert isinstance(app.screen, LabScreen)
        assert box_text(app, "R") == "5.3"
        assert stored_text(app, "R") == "5.3"


class SlowBoard(QuietDevice):
    """A board whose answer to V and STOP comes only once the test lets it (``answer``), as a
    board on a loaded machine answers seconds late. ``stalled``: a command waited
    :attr:`GUARD` s for it, which happens only when the app waited for the board on its own
    thread (the test, on that thread too, could not let it answer)."""

    GUARD = 20.0
    """A hang guard, s: never reached by an app that sends its commands in a worker."""

    def __init__(self) -> None:
        super().__init__(seed=2)
        self.answer = threading.Event()
        self.answer.set()
        self.stalled = False

    def _wait(self) -> None:
        if not self.answer.wait(self.GUARD):
            self.stalled = True

    def set_voltage(self, u: float) -> float:
        self._wait()
        return super().set_voltage(u)

    def stop(self) -> None:
        self._wait()
        super().stop()


async def pump(pilot: Pilot[None], until: Callable[[], bool]) -> None:
    """Let the app handle its messages until ``until()`` holds, without waiting for its
    workers (the board's answer is held back meanwhile)."""
    for _ in range(ROUNDS):
        await pilot.pause(0)
        if until():
            return
    raise AssertionError("the app never got there")


def post_keys(app: LabApp, *keys: str) -> None:
    """Queue ``keys`` on the app at once, as a terminal hands over a burst."""
    for key in keys:
        event = events.Key(key_name(key), key if len(key) == 1 else None)
        event.set_sender(app)
        app.post_message(event)


async def test_pgdn_right_after_f2_moves_at_once_while_the_board_answers(quiet):
    """Walk 7 (D2): on Task 3, F2 then PgDn: the screen stayed on Task 3 for seconds (the app
    waited for the board's answer to STOP), and the PgDn applied late carried the group past
    Task 4 together with the next one."""
    dev = SlowBoard()
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task3")
        await burst(pilot, "f3")
        assert dev.commands[-1:] == ["V 2.5"]
        dev.answer.clear()
        post_keys(app, "f2", "pagedown")
        await pump(pilot, lambda: shown(app, "task4") or dev.stalled)
        assert not dev.stalled
        assert app.motor == "off" and app.requested is None
        dev.answer.set()
        await settle(pilot)
        assert shown(app, "task4")
        assert dev.commands[-1:] == ["STOP"]


async def test_f4_right_after_f3_captures_at_the_new_level(quiet):
    """Walk 7 (D2): on Task 4 at 2.5 V (settled), 'F3 F4' in one burst: F4 captured the 2.5 V
    row, and the motor went to 3.5 V only seconds later. F4 must act after F3: at 3.5 V,
    where the wheel has not settled yet (no sample of it has come), nothing is captured."""
    dev = SlowBoard()
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        app.live.extend(frozen_stream(u=2.5))
        dev.answer.clear()
        post_keys(app, "f3", "f4")
        await pump(pilot, lambda: app.requested == 3.5 or dev.stalled)
        assert not dev.stalled
        dev.answer.set()
        await settle(pilot)
        assert dev.commands[-2:] == ["V 2.5", "V 3.5"]
        with app.session as s:
            assert s.value("omega_ss@2.5") is None
            assert s.value("omega_ss@3.5") is None


def test_readme_lists_every_mark_as_f1_does():
    """Walk 7 (D4): '?' (an entry refused) was missing from README's marks, which F1 lists."""
    text = " ".join((Path(__file__).parents[2] / "README.md").read_text().split())
    assert marks_legend() in text
    assert marks_legend() in " ".join(INTRO.split())
