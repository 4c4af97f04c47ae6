"""The whole lab on the real virtual MinSeg (real factory, link and URL board, real time):
new session to exported report; an unplug during a run; kill -9 mid-session and resume.

The board runs on the host's clock, so these tests wait for what the app hears (the
stream's messages), never for a time: a busy machine makes them slower, not wrong."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from minseg_tui.device.virtual import named_board
from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.task10 import Task10
from minseg_tui.lab.views import session as views
from minseg_tui.model.motor import PUBLISHED
from minseg_tui.model.plant import MeterReading
from minseg_tui.ui.panels.live import LivePanel
from minseg_tui.ui.panels.report import ReportPanel
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.status import DeviceStatus
from tests.ui.conftest import board_url, real_app
from tests.ui.helpers import Heard, goto, paste_in, resume, settle, start

pytestmark = pytest.mark.slow


def _status(app) -> str:
    return str(app.screen.query_one(DeviceStatus).render())


def _held(app, level: float, seconds: float) -> bool:
    """The last ``seconds`` of the live stream (board time) are all at ``level`` V."""
    t, _count, u = app.live.snapshot()
    return t.size > 0 and t[-1] - t[0] >= seconds and bool((u[t >= t[-1] - seconds] == level).all())


def _settled_at(app, level: float) -> bool:
    """The whole capture window of the live stream is at ``level`` V and the speed is steady."""
    t, count, _u = app.live.snapshot()
    return _held(app, level, views.CAPTURE_WINDOW) and views.steady(t, count).settled


async def _fresh_meter(pilot, heard: Heard) -> MeterReading:
    """The multimeter's next reading (the one shown is forgotten first)."""
    app = pilot.app
    app.meter = None
    await heard.until(pilot, lambda: app.meter is not None)
    return app.meter


async def test_whole_lab_on_the_virtual_minseg(tmp_path):
    app = real_app(tmp_path / "sessions", board_url(seed=4))
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        # Task 2: R from the virtual multimeter
        await goto(pilot, "task2")
        R = (await _fresh_meter(pilot, heard)).R
        await paste_in(pilot, "R", f"{R:.1f}".replace(".", ","))
        with app.session as s:
            assert abs(s.value("R") - PUBLISHED.R) < 0.2
        # Task 4: each voltage, wait for SETTLED, capture, type u_ss from the meter
        await goto(pilot, "task4")
        panel = app.screen.query_one(LivePanel)
        steady = app.screen.query_one("#steady")
        for level in (2.5, 3.5, 4.5):
            await pilot.press("f3")
            await settle(pilot)
            assert panel.requested == level
            await heard.until(
                pilot, lambda v=level: _settled_at(app, v) and "SETTLED" in str(steady.render())
            )
            await pilot.press("f4")
            await settle(pilot)
            row = app.screen.query_one(f"#{field_id(f'omega_ss@{level:g}')}", FieldRow)
            assert row.input.value  # the capture landed in the field
            meter = await _fresh_meter(pilot, heard)
            await paste_in(pilot, f"u_ss@{level:g}", f"{meter.u_A:.2f} V")
        # Task 5: the currents from the meter, in mA
        await goto(pilot, "task5")
        for level in (2.5, 3.5, 4.5):
            await pilot.press("f3")
            # 0.5 s at the voltage, a dozen time constants: the current has settled
            await heard.until(pilot, lambda v=level: _held(app, v, 0.5))
            meter = await _fresh_meter(pilot, heard)
            await paste_in(pilot, f"i_ss@{level:g}", f"{meter.i * 1000:.1f} mA")
        await pilot.press("f2")
        # Tasks 6-9: the table filled itself; k_v near the plant's
        await goto(pilot, "table")
        with app.session as s:
            rows = s.table()
        assert all(r.k_v is not None and abs(r.k_v / PUBLISHED.k_v - 1) < 0.1 for r in rows)
        assert all(r.f is not None and r.f > 0 for r in rows)
        shown = str(app.screen.query_one("#results").render())
        assert "k_v = " in shown and "k_a = " in shown
        # Task 10: the square wave on the board, recorded as it arrives. The procedure is
        # watched by a thread, as the stream's thread feeds it (the unplug test's pattern):
        # the app's own thread, which checks only between its messages, can hear that a run
        # began only after it has ended on a busy machine (stop 37), and a wait for
        # app.recording would then never end
        await goto(pilot, "task10")
        # the motor stops; the run starts once the wheel stands (the board's clock decides)
        await _run_to(pilot, heard, "f5")
        await heard.until(pilot, lambda: app.task10 is None)  # the app has taken the run in
        with app.session as s:
            run = s.runs[-1]
        assert run.kind == "steps" and 440 <= run.samples <= 520
        # two of its four periods (5 s at 5 ms): two rising steps for Tasks 11-15
        await _run_to(pilot, heard, "f6", samples=1000)
        await pilot.press("f2")  # stop safely: motor off, what was recorded is kept
        assert app.recording is None and app.motor == "off"
        with app.session as s:
            fast = s.runs[-1]
        assert fast.kind == "fast" and fast.samples > 300
        assert fast.interrupted and not run.interrupted  # F2 ended it before its plan did
        await settle(pilot)
        readings = str(app.screen.query_one("#t-readings").render())
        assert "steps-1" in readings and "fast-1" in readings
        # Tasks 11-15 use the newest complete 25 ms run (not the stopped fast one); the group's
        # own K beside the computed
        await goto(pilot, "task11")
        with app.session as s:
            res = s.results()
        K, T = res.lookup("step.K"), res.lookup("step.T")
        assert 1.5 < K < 2.1 and 0.03 < T < 0.06
        await paste_in(pilot, "own.K", "1.8")
        assert "yours 1.8" in str(app.screen.query_one("#compare").render())
        await pilot.press("f9")
        assert "rise 2" in str(app.screen.query_one("#zoom-note").render())
        # the model check
        await goto(pilot, "model_check")
        assert "Likely cause:" in str(app.screen.query_one("#check-story").render())
        # summary and the report
        await goto(pilot, "summary")
        await paste_in(pilot, "summary.unclear", "the filter")
        await pilot.press("f8")
        await settle(pilot, lambda: bool(app.exported))
        assert "report.md" in str(app.screen.query_one(ReportPanel).render())
    folder = list_sessions(tmp_path / "sessions")[0].path
    md = (Path(folder) / "report.md").read_text()
    assert f"{R:.1f}" in md.replace(",", ".") or f"{R:g}" in md
    assert "the filter" in md and (Path(folder) / "report.html").exists()
    assert (Path(folder) / run.file).exists()


def _watch(app, samples: int | None, seen: list[Task10], done: threading.Event) -> None:
    """Put the Task 10 procedure in ``seen`` as soon as a key made it, then return once it
    has ended, or its run holds ``samples`` samples (None: once it has ended), or ``done``
    is set. Polls the app's procedure, which the stream's thread feeds as the board sends,
    every 2 ms of host time."""
    while not done.is_set() and app.task10 is None:
        time.sleep(0.002)
    task = app.task10
    if task is None:
        return
    seen.append(task)
    while not done.is_set() and task.outcome is None:
        run = task.run
        if samples is not None and run is not None and run.samples >= samples:
            break
        time.sleep(0.002)


async def _run_to(pilot, heard: Heard, key: str, samples: int | None = None) -> Task10:
    """Press ``key`` (F5, F6) and wait until the procedure it starts has ended, or its run
    holds ``samples`` samples, as a thread watching the procedure sees it (:func:`_watch`):
    the procedure."""
    seen: list[Task10] = []
    done, reached = threading.Event(), threading.Event()

    def watch() -> None:
        try:
            _watch(pilot.app, samples, seen, done)
        finally:
            reached.set()

    watcher = threading.Thread(target=watch, daemon=True)
    watcher.start()
    try:
        await pilot.press(key)
        await heard.until(pilot, reached.is_set)
    finally:
        done.set()
        watcher.join()
    assert seen, f"{key} made no Task 10 procedure"
    return seen[0]


def _pull_at(app, name: str, samples: int, seen: list[Task10], done: threading.Event) -> None:
    """Pull the named board's cable once the Task 10 procedure's run holds ``samples``
    samples (not at all when the procedure ended first: the test then fails on its
    outcome); the procedure is put in ``seen`` as soon as F5 made it (:func:`_watch`). The
    board's clock pauses while the process is stalled, so a busy machine makes this slower,
    never late."""
    _watch(app, samples, seen, done)
    if seen and seen[0].outcome is None and not done.is_set():
        named_board(name).unplug()


async def test_unplug_during_a_run_keeps_the_samples(tmp_path):
    url = board_url(seed=2)
    name = url.split("//")[1].split("?")[0]
    app = real_app(tmp_path / "sessions", url)
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        await goto(pilot, "task10")
        # The run starts once the wheel stands; the cable is pulled once 80 samples of it are
        # recorded, by a thread that watches the procedure itself. The app's own thread, which
        # checks only between its messages, missed the whole 12 s run on a busy machine (it
        # painted every frame at load 14 on 2 cores, and had not yet heard that the run began
        # when it ended: stop 37).
        seen: list[Task10] = []
        done = threading.Event()
        puller = threading.Thread(target=_pull_at, args=(app, name, 80, seen, done), daemon=True)
        puller.start()
        try:
            await pilot.press("f5")
            await heard.until(pilot, lambda: bool(seen) and seen[0].outcome is not None)
        finally:
            done.set()
            puller.join()
        assert seen[0].outcome is not None and seen[0].outcome.why == "cable", seen[0].outcome
        await heard.until(pilot, lambda: "disconnected" in heard.kinds and app.task10 is None)
        assert "board disconnected — everything recorded is kept" in _status(app)
        with app.session as s:
            run = s.runs[-1]
        assert run.ended_by == "cable", run  # cut by the cable, not ended complete before it
        assert run.samples >= 60 and app.motor == "off"
        heard.kinds.clear()
        named_board(name).replug()
        await heard.until(pilot, lambda: "connected" in heard.kinds)
        assert app.motor == "off"  # nothing restored after the reconnect


SCRIPT = """
import asyncio, sys, threading, time
from pathlib import Path
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import make_app
from minseg_tui.ui.config import UiConfig
from tests.ui.helpers import Heard, goto, paste_in, settle, start

async def main():
    app = make_app(UiConfig(device="minseg://kill?clock=real&seed=3", sessions=Path(sys.argv[1]),
                            today="2024-04-16", animations=False),
                   lambda s: write_report(s).paths)
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        await goto(pilot, "task2")
        await paste_in(pilot, "R", "5,3")
        await goto(pilot, "task5")
        await paste_in(pilot, "i_ss@2.5", "47 mA")
        await goto(pilot, "task10")
        # 80 samples (2 s) in memory: all but the last half second of them are on disk. Said
        # by a thread that watches the procedure, which the stream's thread feeds: the app's
        # own thread can hear of a run only once it has ended on a busy machine (stop 37)
        def ready():
            while app.task10 is None:
                time.sleep(0.002)
            task = app.task10
            while task.outcome is None and (task.run is None or task.run.samples < 80):
                time.sleep(0.002)
            print("READY" if task.outcome is None else f"ENDED {task.outcome}", flush=True)
        threading.Thread(target=ready, daemon=True).start()
        await pilot.press("f5")
        await asyncio.sleep(600)

asyncio.run(main())
"""


async def test_kill_9_mid_session_and_resume(tmp_path):
    root = tmp_path / "sessions"
    proc = subprocess.Popen(
        [sys.executable, "-c", SCRIPT, str(root)],
        stdout=subprocess.PIPE,
        cwd=Path(__file__).parents[2],
        text=True,
    )
    try:
        assert proc.stdout.readline().strip() == "READY"
    finally:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    app = real_app(root, board_url(seed=3))
    async with app.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        assert isinstance(app.screen, LabScreen) and app.screen.step.id == "task10"
        with app.session as s:
            assert s.entry("R").text == "5,3" and abs(s.value("R") - 5.3) < 1e-12
            assert s.entry("i_ss@2.5").text == "47 mA"
            assert s.recovered == ["steps-1"]
            assert s.runs[0].interrupted and s.runs[0].samples >= 40  # the last second at most
