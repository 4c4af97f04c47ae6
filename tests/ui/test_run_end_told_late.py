"""Stop 37's product finding (NOTE37, "The flaky walk test"): under heavy load the app's own
thread lags the board by a whole run; the stream's thread has ended the Task 10 procedure
(the run kept in the session) before the app handles the message that says so. A key that
starts the next run (F6 after F5, as the manual has it) handled in that gap began the new run
and the end of the old one was never told: its message found another procedure in place and
was dropped. The group saw no "run steps-2: N samples kept", no word that Tasks 11-15 now
use it, and the app held the ended run as the one being recorded.

The lag is made without load: the app's handling of the procedure's messages is held (a
test hook on the app's post_message, which the stream's thread calls), the run ends on the
stream's thread meanwhile, F6 is pressed, then the held messages are let go in order."""

from __future__ import annotations

import threading

from minseg_tui.device.link import LinkEvent
from minseg_tui.lab.saving.runs import RunInfo
from minseg_tui.lab.state.task10 import Task10
from minseg_tui.ui.messages import Task10Moved
from minseg_tui.ui.screens.quit import RECORDING_CHOICES, QuitScreen
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.helpers import (
    GUARD,
    TABLE,
    enter_all,
    goto,
    heard_notifications,
    record_response_run,
    settle,
    start,
    start_run_on,
    taken,
)


class Held:
    """Holds the Task10Moved messages posted to ``app`` (from the stream's thread) while
    :meth:`hold` is on; :meth:`release` posts them in order, as a late app thread meets
    them."""

    def __init__(self, app) -> None:
        self.app = app
        self.post = app.post_message
        self.messages: list[Task10Moved] = []
        self.holding = False
        self.lock = threading.Lock()
        app.post_message = self._post

    def _post(self, message) -> bool:
        with self.lock:
            if self.holding and isinstance(message, Task10Moved):
                self.messages.append(message)
                return True
        return self.post(message)

    def hold(self) -> None:
        with self.lock:
            self.holding = True

    def release(self) -> None:
        with self.lock:
            self.holding = False
            held, self.messages = self.messages, []
        for message in held:
            self.post(message)


async def _ended_unheard(pilot, dev: QuietDevice) -> tuple[Held, Task10, RunInfo, str]:
    """On Task 10, with a run before it (T read on it): F5's run recorded whole and ended on
    the stream's thread while the app's handling of the procedure's messages is held. The
    hold, the procedure, the run it kept and the run before."""
    app = pilot.app
    await start(pilot)
    enter_all(app, TABLE)
    with app.session as s:  # a run before, T read on it: the new run takes its place
        before = record_response_run(s)
        s.enter("own.T", "57 ms")
    await goto(pilot, "task10")
    held = Held(app)
    seq = await start_run_on(pilot, dev)  # F5: the run records
    task = app.task10
    assert task is not None and app.recording is not None
    held.hold()  # from here the app hears nothing of the procedure: it lags
    dev.feed(square_wave_stream(seq, (seq + 1) * 25_000, 12.0))
    dev.feed_event(LinkEvent("square_wave_done", "square wave done", 0.0))
    await taken(pilot, seq + 480)
    for _ in range(GUARD):  # ended on the stream's thread, the run kept in the session
        if task.outcome is not None:
            break
        await pilot.pause(0.01)
    assert task.outcome is not None and task.outcome.why == "done", task.outcome
    with app.session as s:
        steps = s.runs[-1]
    assert steps.name != before and not steps.interrupted
    return held, task, steps, before


async def test_a_run_that_ended_before_the_app_heard_is_told_when_f6_comes_first(quiet):
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        held, task, steps, before = await _ended_unheard(pilot, dev)
        await pilot.press("f6")  # handled before the app has heard the run end
        await settle(pilot)
        held.release()
        await settle(pilot)
        # the run that ended is told, as when the app hears it in time
        kept = f"run {steps.name}: {steps.samples} samples kept"
        assert any(kept in m for m in said), said
        assert any(f"Tasks 11-15 now use run {steps.name}, not {before}" in m for m in said), said
        assert app.recording is None or app.recording is not task.run  # not the ended run
        assert app.task10 is not None and app.task10 is not task  # F6's run goes on


async def test_ctrl_q_after_a_run_ended_unheard_asks_nothing_about_recording(quiet):
    """Ctrl+Q in that gap asked "A run is being recorded" (the ended run, still held as
    recording): the run has ended, is kept, and quitting cuts nothing."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        held, _task, steps, _before = await _ended_unheard(pilot, dev)
        await pilot.press("ctrl+q")
        await settle(pilot)
        asking = app.screen
        assert not (isinstance(asking, QuitScreen) and asking.choices is RECORDING_CHOICES)
        assert any(f"run {steps.name}: {steps.samples} samples kept" in m for m in said), said
        held.release()
