"""A lab screen closed while a log is imported, the app running on (stop 38 tested the app
quitting only). The copy is handed to the UI thread, where the screen is known to be there or
not: after it closed, the copy is a run of no session and is removed, the session takes no
run, and nothing is said on the screen shown then (a refusal neither). Also when the screen
closes just as the copy is handed over (the worker past any check of its own)."""

from __future__ import annotations

import asyncio
import os
import threading

import pytest

from minseg_tui.ui.screens.help import HelpScreen
from tests.ui.helpers import heard_notifications, settle, start_with_a_run
from tests.ui.test_import_in_worker import HOLD_GUARD_S, HeldRead, importing


class Handed:
    """The app's ``call_from_thread`` as the import's worker calls it (others' calls as they
    are): :attr:`calling` is set when the worker hands its copy over, which then waits for :attr:`go`; :attr:`done` is
    set once the UI thread has dealt with it."""

    def __init__(self, app) -> None:
        self.calling = threading.Event()
        self.go = threading.Event()
        self.done = threading.Event()
        real = app.call_from_thread

        def handed(callback, *args, **kwargs):
            if "._copy." not in getattr(callback, "__qualname__", ""):  # not the import's
                return real(callback, *args, **kwargs)
            self.calling.set()
            assert self.go.wait(HOLD_GUARD_S)
            try:
                return real(callback, *args, **kwargs)
            finally:
                self.done.set()

        app.call_from_thread = handed


@pytest.mark.parametrize("when", ["reading", "handing over"])
@pytest.mark.parametrize("what", ["a log", "a refused log"])
async def test_a_lab_screen_closed_mid_import(quiet, tmp_path, monkeypatch, when, what):
    log = tmp_path / "elsewhere.csv"
    held = HeldRead(monkeypatch, log)
    app = quiet()
    said = heard_notifications(app)
    handed = Handed(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        with app.session as s:
            recorded = s.run_path(s.response_run().name).read_bytes()
            folder = s.folder
        log.write_bytes(recorded if what == "a log" else b"t,u,omega\n0,0,x\n")
        await importing(pilot, log)
        assert await asyncio.to_thread(held.reading.wait, HOLD_GUARD_S)
        if when == "handing over":
            held.let_go.set()
            assert await asyncio.to_thread(handed.calling.wait, HOLD_GUARD_S)
        said.clear()
        await app.pop_screen()  # the lab screen closed; the app runs on
        await settle(pilot)
        held.let_go.set()
        handed.go.set()
        assert await asyncio.to_thread(handed.done.wait, HOLD_GUARD_S)
        await settle(pilot)
        assert said == []  # nothing said on the screen shown now
        with app.session as s:
            assert [r.name for r in s.runs] == ["steps-1"]
        assert sorted(os.listdir(folder / "runs")) == ["steps-1.csv"]


async def test_an_import_done_under_help_is_taken(quiet, tmp_path, monkeypatch):
    """The lab screen under another (F1's help) is still there: the copy is taken."""
    log = tmp_path / "elsewhere.csv"
    held = HeldRead(monkeypatch, log)
    app = quiet()
    handed = Handed(app)
    handed.go.set()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        with app.session as s:
            log.write_bytes(s.run_path(s.response_run().name).read_bytes())
        await importing(pilot, log)
        assert await asyncio.to_thread(held.reading.wait, HOLD_GUARD_S)
        await pilot.press("f1")
        await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
        held.let_go.set()
        assert await asyncio.to_thread(handed.done.wait, HOLD_GUARD_S)
        await settle(pilot)
        with app.session as s:
            assert [r.name for r in s.runs] == ["steps-1", "imported-1"]
