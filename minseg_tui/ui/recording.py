"""The Task 10 run being recorded, between the stream worker and the event loop."""

from __future__ import annotations

import threading
from dataclasses import dataclass

from minseg_tui.device.samples import SampleBatch
from minseg_tui.lab.runs import Recorder
from minseg_tui.lab.steps import RunPlan


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
    """A run being recorded: the session's :class:`Recorder` for plan ``plan``. The stream
    worker appends every batch as it arrives and flushes (:meth:`tick`); the event loop reads
    the progress and closes it; one lock between them."""

    def __init__(self, recorder: Recorder, plan: RunPlan, kind: str = "") -> None:
        self.recorder = recorder
        self.plan = plan
        self.kind = kind
        self._lock = threading.Lock()
        self.samples = 0
        self._first_us: int | None = None
        self._last_us: int | None = None
        self._ended = False
        self.armed = False
        """The stream worker said the run holds its first samples (the sequence may start)."""
        self.started = False
        """The board's step sequence was asked for."""

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

    def end(self) -> None:
        """Take no more samples (the sequence ended or the board went); finishing the run
        follows on the event loop."""
        with self._lock:
            self._ended = True

    def tick(self) -> None:
        """Flush to disk what is due (call a few times a second, from the worker)."""
        with self._lock:
            if not self.recorder.closed:
                self.recorder.tick()

    def close(self) -> None:
        """No more samples; the file is complete."""
        with self._lock:
            self.recorder.close()

    @property
    def elapsed(self) -> float:
        """Board time recorded so far, s."""
        if self._first_us is None or self._last_us is None:
            return 0.0
        return (self._last_us - self._first_us) / 1e6

    def progress(self) -> RunProgress:
        """How far the run is, for the panel."""
        duration = self.plan.duration
        fraction = min(1.0, self.elapsed / duration) if duration > 0 else 0.0
        return RunProgress(
            fraction,
            f"recording {self.name}: {self.samples} samples, "
            f"{self.elapsed:.1f} of {duration:.1f} s · F2 stops",
            kind=self.kind,
            t0=None if self._first_us is None else self._first_us / 1e6,
            duration=duration,
        )
