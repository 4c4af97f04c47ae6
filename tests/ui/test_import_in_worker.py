"""s38 attack, left: a 227 MB run log imported at the model check froze the TUI for 97 s (39 s
to read it, 44 s to write the copy), as the import ran while the lab screen handled the
request. The log is now read, checked and copied in a worker: the box says "reading ..."
meanwhile and keys typed land as usual; a second log asked for meanwhile waits its turn;
the run that lands is the one before (its rows, and its file's checksum rule).

No big file is needed to show it: the read is held on an Event the test lets go of (the
real read_run_log then runs), so the test types while the log "is being read", whatever
the machine's load. Before the fix the hold was taken on the UI thread: the screen stood
still until the hold's guard ran out, and nothing typed meanwhile was seen."""

from __future__ import annotations

import asyncio
import hashlib
import os
import threading
from pathlib import Path

import numpy as np

from minseg_tui.lab.saving import runs
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox
from tests.ui.helpers import settle, start_with_a_run

HOLD_GUARD_S = 60.0
"""Longest the held read waits to be let go (a hang guard: the test lets go of it after a
few keys; reached only when the read holds the UI thread, as before the fix)."""


class HeldRead:
    """The import's read of ``log`` held until :attr:`let_go` is set (other runs read as
    usual: the views'); :attr:`reading` is set once it is held, :attr:`too_long` once the
    hold's guard ran out."""

    def __init__(self, monkeypatch, log: Path) -> None:
        self.log = log
        self.reading = threading.Event()
        self.let_go = threading.Event()
        self.too_long = False
        monkeypatch.setattr(runs, "read_run_log", self)

    def __call__(self, *args, **kwargs):
        if Path(args[0]) == self.log:  # the import's read, not a run read for a view
            self.reading.set()
            self.too_long = not self.let_go.wait(HOLD_GUARD_S)
        return read_run_log(*args, **kwargs)


async def importing(pilot, log: Path) -> TextBox:
    """Ask the lab screen (the model check) to import ``log``, as typed into its path box;
    the box."""
    app = pilot.app
    box = app.screen.query_one("#import-path", TextBox)
    box.focus()
    await settle(pilot, lambda: app.focused is box)
    box.value = str(log)
    await pilot.press("enter")
    return box


async def test_a_log_is_read_in_a_worker_and_keys_land_meanwhile(quiet, tmp_path, monkeypatch):
    log = tmp_path / "elsewhere.csv"
    held = HeldRead(monkeypatch, log)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        with app.session as s:
            recorded = s.run_path(s.response_run().name).read_bytes()
        # a log as another program writes it: a BOM, \r\n, a comment, full precision
        body = recorded.decode("utf-8").replace("\n", "\r\n")
        log.write_bytes(b"\xef\xbb\xbf# written elsewhere\r\n" + body.encode("utf-8"))
        box = await importing(pilot, log)
        assert await asyncio.to_thread(held.reading.wait, HOLD_GUARD_S)
        msg = app.screen.query_one("#import-msg", Prose)
        # while the log is being read: the box says so, and keys land
        await pilot.pause()
        assert msg.text == f"reading {log} ...", msg.text
        await pilot.press("end", "-", "2")
        assert box.value == f"{log}-2"
        await pilot.press("enter")  # a second log while the first is read: it waits its turn
        await pilot.pause()
        assert msg.text == f"still reading {log}: load {log}-2 once it is in", msg.text
        held.let_go.set()
        await settle(pilot, lambda: msg.text.startswith("imported"))
        assert not held.too_long
        assert " ".join(msg.text.split()).startswith(f"imported {log} as imported-1 (")
        with app.session as s:
            info = s.check_run()
            assert info.name == "imported-1"
            copy = s.folder / info.file
            folder = s.folder
            taken = s.load_run(info.name)
    # the copy: the bytes read and checked (its BOM left out), after the line naming them
    data = copy.read_bytes()
    assert data == f"# imported_from: {log}\n".encode() + log.read_bytes()[3:]
    assert info.sha256 == hashlib.sha256(data).hexdigest()
    assert runs.changed_file(folder, info) is None  # the checksum rule holds for it
    original = read_run_log(log)
    assert info.samples == len(original) and info.ts == original.ts
    for name in original.columns:  # the same rows, value for value
        assert np.array_equal(np.asarray(taken.column(name)), np.asarray(original.column(name)))
    assert [p.name for p in (folder / "runs").iterdir() if p.name.startswith(".")] == []


async def test_a_copy_made_after_the_app_stopped_is_not_left_in_runs(quiet, tmp_path, monkeypatch):
    """The app quits while the log is read: the copy then made is a run of no session
    (none took it), and is removed rather than left in runs/ unlisted."""
    log = tmp_path / "elsewhere.csv"
    held = HeldRead(monkeypatch, log)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        with app.session as s:
            log.write_bytes(s.run_path(s.response_run().name).read_bytes())
            folder = s.folder
        await importing(pilot, log)
        assert await asyncio.to_thread(held.reading.wait, HOLD_GUARD_S)
    held.let_go.set()  # the app has stopped: the worker reads and copies now
    await asyncio.get_running_loop().shutdown_default_executor()  # its thread is done
    assert sorted(os.listdir(folder / "runs")) == ["steps-1.csv"]
