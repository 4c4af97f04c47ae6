"""Task 10 as one procedure: stop the motor, wait for the wheel to stand, record, run the
board's square wave, keep the run.

A square-wave run that starts with the wheel still turning has a first step that starts from
speed, so :class:`Task10` stops the motor first, waits until the wheel stands
(:class:`~minseg_tui.device.standstill.StandStill`, on board time), sets the plan's sample
period, starts the session's recording, takes :data:`PRE_ROLL` samples of the standing
wheel and only then asks the board for its sequence; the run ends with the board's
``square_wave_done`` (complete), a link event that ends it, or :meth:`Task10.stop` (F2, quit), and
is kept in the session (:meth:`~minseg_tui.lab.state.session.Session.finish_run`).

It does not read the device itself: whoever does feeds it every batch and event
(:meth:`Task10.feed`). The TUI's stream worker does (the one reader of the device); a
headless program calls :func:`record`, which reads a link until the run ends. Both count
board time, so a busy host makes the run slower, never different.

The session is used through ``session``, a context manager yielding it (the TUI's
``Shared`` lock, or :func:`contextlib.nullcontext` for one thread).
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from typing import Literal, Protocol

import numpy as np

from minseg_tui.device.link import LinkEvent
from minseg_tui.device.samples import SampleBatch
from minseg_tui.device.standstill import PRE_ROLL, StandStill
from minseg_tui.errors import DeviceError, MinsegError
from minseg_tui.lab.content.keys import key_name
from minseg_tui.lab.content.steps import RunPlan
from minseg_tui.lab.content.steps import step as lab_step
from minseg_tui.lab.saving.runs import Recorder, RunInfo
from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import format_fixed

RUN_KIND: dict[str, str] = {"manual": "steps", "fast": "fast"}
"""Task 10's plans (:mod:`minseg_tui.lab.content.steps`) to the session's run kinds."""

LAB_PERIOD: float = 0.025
"""Sample period restored after a run at another period, s (the manual's)."""

RUN_ENDED_BY: dict[str, str] = {
    "disconnected": "cable",
    "watchdog": "watchdog",
    "boot": "restart",
    "motor": "restart",
    "error": "link",
}
"""A link event that ends a run being recorded -> what interrupted it
(:data:`minseg_tui.lab.saving.runs.ENDED_BY`); ``square_wave_done`` ends it complete."""

WAIT_ENDS = frozenset({"disconnected", "watchdog", "boot", "error"})
"""Link events that end the wait for the wheel to stand (no run starts). Not ``silent``: the
link says so when no line came for a while on the host's clock, which a busy PC causes as
well as a board (the virtual MinSeg runs in the app's own process); the wait is on board
time and goes on when the lines do, and a board that is gone says ``disconnected``."""

HOST_GUARD: float = 30.0
"""Host seconds :func:`record` waits for samples at all (a board that sends nothing: a hang
guard, not a measure of the run)."""

Phase = Literal["idle", "waiting", "recording", "square_wave", "ended"]


class Board(Protocol):
    """What the procedure asks of the board (a :class:`~minseg_tui.device.link.Link`, the
    UI's device); DeviceError with one line when it does not answer. Volts and seconds."""

    def stop(self) -> object:
        """Motor off, any square wave aborted."""
        ...

    def set_period(self, ts: float) -> object:
        """Sample every ``ts`` s."""
        ...

    def square_wave(self, low: float, high: float, half_period: float, periods: int) -> object:
        """The board-timed square wave."""
        ...


@dataclass(frozen=True)
class RunProgress:
    """What the step-run panel says about the run: ``fraction`` done (0-1), one line of
    ``text``, ``recording`` (False once the run has ended), ``waiting`` (the motor is off
    and the run waits for the wheel to stand), the run's ``kind`` (steps or fast), the
    board time ``t0`` (s) of its first sample (None before it has one) and its ``duration``
    (s), for the plot drawn as the run arrives."""

    fraction: float
    text: str
    recording: bool = True
    waiting: bool = False
    kind: str = ""
    t0: float | None = None
    duration: float = 0.0


class ActiveRun:
    """A run being recorded: the session's :class:`Recorder` for plan ``plan``. Samples are
    appended (and flushed, :meth:`tick`) by whoever reads the device; the progress is read
    and the run closed from elsewhere; one lock between them."""

    def __init__(self, recorder: Recorder, plan: RunPlan, kind: str = "") -> None:
        self.recorder = recorder
        self.plan = plan
        self.kind = kind
        self._lock = threading.Lock()
        self.samples = 0
        self._first_us: int | None = None
        self._last_us: int | None = None
        self._u_last: float | None = None  # the requested voltage of the last sample, V
        self._asked: float | None = None  # the one in force when the sequence was asked for
        self._step_us: int | None = None  # board time of the sequence's first step, us
        self._ended = False

    @property
    def name(self) -> str:
        """The run's name (its file stem)."""
        return self.recorder.name

    def append(self, batch: SampleBatch) -> None:
        """Keep every sample of ``batch`` as the board sent it; nothing once the run has
        ended."""
        with self._lock:
            if self.recorder.closed or self._ended or not len(batch):
                return
            self.recorder.add(batch)
            if self._first_us is None:
                self._first_us = int(batch.t_us[0])
            self._last_us = int(batch.t_us[-1])
            self.samples += len(batch)
            self._u_last = float(batch.u_req[-1])
            if self._asked is not None and self._step_us is None:
                moved = np.flatnonzero(np.asarray(batch.u_req, dtype=float) != self._asked)
                if moved.size:
                    self._step_us = int(batch.t_us[moved[0]])

    def sequence_asked(self) -> None:
        """The board was asked for its sequence: the plan's time counts from its first step
        (the first sample whose requested voltage differs from the one in force now)."""
        with self._lock:
            if self._asked is None:
                self._asked = self._u_last if self._u_last is not None else 0.0

    def tick(self) -> None:
        """Flush to disk what is due (call a few times a second, off the UI's thread)."""
        with self._lock:
            if not self.recorder.closed:
                self.recorder.tick()

    def close(self) -> None:
        """No more samples; the file is complete."""
        with self._lock:
            self._ended = True
            self.recorder.close()

    @property
    def recorded(self) -> float:
        """Board time recorded so far, s: from the first sample (the standing wheel) on."""
        if self._first_us is None or self._last_us is None:
            return 0.0
        return (self._last_us - self._first_us) / 1e6

    @property
    def elapsed(self) -> float:
        """The plan's time gone by, s: board time from the sequence's first step to the
        newest sample, at most the plan's duration (0 before the step; the standing wheel
        recorded first is not the plan's, and under load the pre-roll reached 1.2 s: walk 16,
        D6, "12.9 of 12.0 s"; the samples after the sequence's end, in the batch that says
        it ended, are not the plan's either)."""
        if self._step_us is None or self._last_us is None:
            return 0.0
        return min((self._last_us - self._step_us) / 1e6, self.plan.duration)

    def progress(self) -> RunProgress:
        """How far the run is, for the panel."""
        duration = self.plan.duration
        fraction = min(1.0, self.elapsed / duration) if duration > 0 else 0.0
        where = (
            f"{format_fixed(self.elapsed, 1)} of {format_fixed(duration, 1, 's')}"
            if self._step_us is not None
            else "the wheel standing; the board's sequence starts next"
        )
        return RunProgress(
            fraction,
            f"recording {self.name}: {self.samples} samples, {where} · "
            f"{key_name('stop_motor')} stops",
            kind=self.kind,
            t0=None if self._first_us is None else self._first_us / 1e6,
            duration=duration,
        )


@dataclass(frozen=True)
class Outcome:
    """How a Task 10 procedure ended.

    ``why``: ``done`` (the board's sequence ended), ``turning`` (the wheel did not stand),
    a key of :data:`minseg_tui.lab.saving.runs.ENDED_BY` (``stopped``, ``quit``, ``cable``, ...:
    what interrupted it), ``not started`` (the board refused the sequence), ``no run``
    (the recording could not be made) or, for a wait that a link event ended, the event's
    kind. ``event``: that link event. ``run``: the name of the run recorded ("" when none
    started), ``info``: the run kept (None: none, or too short), ``samples`` recorded,
    ``problem``: a failure in one line ("" when none).
    """

    why: str
    run: str = ""
    info: RunInfo | None = None
    samples: int = 0
    problem: str = ""
    event: LinkEvent | None = None

    @property
    def started(self) -> bool:
        """A recording was started (whether or not it was kept)."""
        return bool(self.run)


class Task10:
    """The Task 10 procedure for plan ``plan`` (of kind ``kind``: ``steps`` or ``fast``) on
    ``board``, recorded in the session ``session`` yields. Thread-safe: one thread feeds it,
    any thread may stop it.

    Call :meth:`begin` (motor off), then :meth:`feed` with everything read from the device
    until :attr:`outcome` is set; :meth:`stop` ends it at once."""

    def __init__(
        self,
        session: AbstractContextManager[Session],
        board: Board,
        plan: RunPlan,
        kind: str = "steps",
        flush_interval: float | None = None,
    ) -> None:
        self.session = session
        self.board = board
        self.plan = plan
        self.kind = kind
        self._flush_interval = flush_interval
        self._lock = threading.RLock()
        self._stand: StandStill | None = None
        self._last_us: int | None = None  # board time of the last sample fed, us
        self.phase: Phase = "idle"
        self.run: ActiveRun | None = None
        """The run being recorded (None before the wheel stands and after it is kept)."""
        self.outcome: Outcome | None = None
        """How it ended (None while it goes on)."""

    @classmethod
    def of(
        cls, session: AbstractContextManager[Session], board: Board, plan: str = "manual"
    ) -> Task10:
        """The procedure for Task 10's plan ``plan`` (``manual``: 25 ms; ``fast``: 5 ms)."""
        return cls(session, board, dict(lab_step("task10").plans)[plan], RUN_KIND[plan])

    @property
    def active(self) -> bool:
        """Begun and not yet ended."""
        return self.phase in ("waiting", "recording", "square_wave")

    def begin(self) -> None:
        """Motor off; the run waits for the wheel to stand. DeviceError (nothing begun) when
        the board does not take the STOP."""
        with self._lock:
            if self.phase != "idle":
                raise ValueError("the procedure has begun already")
            self.board.stop()
            self._stand = StandStill()
            self.phase = "waiting"

    def progress(self) -> RunProgress:
        """What the step-run panel shows now."""
        with self._lock:
            if self.phase == "waiting":
                return RunProgress(
                    0.0,
                    "motor off; the run starts once the wheel stands · "
                    f"{key_name('stop_motor')} cancels",
                    recording=False,
                    waiting=True,
                    kind=self.kind,
                )
            if self.run is not None:
                return self.run.progress()
            return RunProgress(0.0, "", recording=False, kind=self.kind)

    def feed(self, batch: SampleBatch, events: Sequence[LinkEvent] = ()) -> bool:
        """The samples and link events read since the last call, in that order: the wait,
        the recording, the board's sequence and the end follow from them. True when the
        phase changed (the screen has something new to say beyond the progress)."""
        with self._lock:
            before = self.phase
            if self.phase == "waiting":  # the run takes the samples after the wheel stood
                self._wait(batch, events)
            elif self.phase in ("recording", "square_wave") and self.run is not None:
                run = self.run
                run.append(batch if run.samples else self._at_period(batch))
                if self.phase == "recording" and run.samples >= PRE_ROLL:
                    self._start_sequence()
                for ev in events:
                    if ev.kind == "square_wave_done":
                        self._finish("done")
                        break
                    if ev.kind in RUN_ENDED_BY:
                        self._finish(RUN_ENDED_BY[ev.kind], event=ev)
                        break
                else:
                    run.tick()  # the run's samples reach the disk within its flush interval
            if len(batch):
                self._last_us = int(batch.t_us[-1])
            return self.phase != before

    def _at_period(self, batch: SampleBatch) -> SampleBatch:
        """``batch`` from its first sample taken at the plan's period on: the samples the
        board sent before the new period took effect (25 ms apart before a 5 ms run) are no
        part of the run. Within half a period is the plan's (the board's jitter is less)."""
        t_us = batch.t_us.tolist()
        prev = self._last_us
        want = self.plan.ts * 1e6
        for k, t in enumerate(t_us):
            if prev is not None and abs(t - prev - want) <= want / 2:
                return SampleBatch(
                    *(
                        getattr(batch, f)[k:]
                        for f in ("seq", "t_us", "count", "u_req", "epoch", "t_host")
                    )
                )
            prev = t
        return SampleBatch.concat([])

    def _wait(self, batch: SampleBatch, events: Sequence[LinkEvent]) -> None:
        stand = self._stand
        assert stand is not None
        for ev in events:
            if ev.kind in WAIT_ENDS:
                self._ended(Outcome(ev.kind, event=ev))
                return
        if not len(batch):
            return
        state = stand.feed(batch)
        if state == "turning":
            self._ended(Outcome("turning"))
        elif state == "still":
            self._start_recording()

    def _start_recording(self) -> None:
        """The wheel stands: the plan's sample period and a new run."""
        try:
            self.board.set_period(self.plan.ts)
            with self.session as s:
                recorder = s.start_run(self.kind, self.plan, flush_interval=self._flush_interval)
        except MinsegError as exc:
            self._ended(Outcome("no run", problem=str(exc)))
            return
        self.run = ActiveRun(recorder, self.plan, self.kind)
        self.phase = "recording"

    def _start_sequence(self) -> None:
        """The run holds the standing wheel: the board starts the sequence."""
        plan = self.plan
        try:
            self.board.square_wave(plan.low, plan.high, plan.half_period, plan.periods)
        except MinsegError as exc:
            self._finish("not started", problem=str(exc))
            return
        if self.run is not None:
            self.run.sequence_asked()
        self.phase = "square_wave"

    def stop(self, ended_by: str = "stopped", motor_off: bool = True) -> Outcome | None:
        """End now: a wait ends without a run; a run being recorded is kept as interrupted
        by ``ended_by`` (a key of :data:`minseg_tui.lab.saving.runs.ENDED_BY`), or as complete
        with ``done``. ``motor_off``: the motor is switched off first (unless ``done``;
        False when the caller has done it). The outcome (None when the procedure never
        began)."""
        with self._lock:
            if self.phase == "idle":
                return None
            if motor_off and ended_by != "done" and self.phase != "ended":
                with contextlib.suppress(MinsegError):  # the run is kept all the same
                    self.board.stop()
            if self.phase == "waiting":
                self._ended(Outcome(ended_by))
            elif self.phase in ("recording", "square_wave"):
                self._finish(ended_by)
            return self.outcome

    def _ended(self, outcome: Outcome) -> None:
        self._stand = None
        self.phase = "ended"
        self.outcome = outcome

    def _finish(self, why: str, problem: str = "", event: LinkEvent | None = None) -> None:
        """Keep the run (complete when ``why`` is ``done``) and put the sample period back."""
        run = self.run
        assert run is not None
        run.close()
        self.run = None
        info = None
        try:
            with self.session as s:
                info = s.finish_run(
                    run.recorder,
                    stopped_early=why != "done",
                    ended_by="" if why == "done" else why,
                )
        except MinsegError as exc:
            problem = "; ".join(p for p in (problem, str(exc)) if p)
        if self.plan.ts != LAB_PERIOD:
            with contextlib.suppress(MinsegError):
                self.board.set_period(LAB_PERIOD)
        self._ended(Outcome(why, run.name, info, run.samples, problem, event))


class Link(Board, Protocol):
    """A board that :func:`record` reads itself (a :class:`~minseg_tui.device.link.Link`)."""

    def samples(self) -> SampleBatch:
        """Every sample received since the last call."""
        ...

    def events(self) -> list[LinkEvent]:
        """Every event since the last call, oldest first."""
        ...


def record(
    session: Session,
    link: Link,
    plan: RunPlan,
    kind: str = "steps",
    poll: float = 0.005,
    flush_interval: float | None = None,
) -> Outcome:
    """Task 10 headless: the whole procedure on ``link`` (read here, every ``poll`` s),
    recorded in ``session``; its outcome. DeviceError with one line when the board takes no
    STOP or sends nothing for :data:`HOST_GUARD` s (a run being recorded is kept first)."""
    task = Task10(contextlib.nullcontext(session), link, plan, kind, flush_interval)
    link.samples()  # what came before: the motor was still on
    link.events()
    task.begin()
    quiet_since = time.monotonic()
    while task.outcome is None:
        batch = link.samples()
        events = link.events()
        if any(ev.kind == "square_wave_done" or ev.kind in RUN_ENDED_BY for ev in events):
            # the samples the board sent before that event may come just after the read
            batch = SampleBatch.concat([batch, link.samples()])
        task.feed(batch, events)
        if len(batch) or events:
            quiet_since = time.monotonic()
        elif time.monotonic() - quiet_since > HOST_GUARD:
            task.stop("link")
            raise DeviceError(f"the board sent nothing for {HOST_GUARD:g} s during Task 10")
        else:
            time.sleep(poll)
    return task.outcome
