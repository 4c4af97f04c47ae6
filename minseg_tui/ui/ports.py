"""What the UI needs from the layers below it, as small typed interfaces.

The screens talk to these Protocols (and the lab's step data, :mod:`minseg_tui.lab.steps`) only; :mod:`minseg_tui.ui.backend` adapts the real
device, lab and model modules to them. Units: volts, amperes, ohms, rad/s, seconds.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from minseg_tui.lab.steps import Step

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class DeviceInfo:
    """Who we talk to: ``virtual`` True for the simulated MinSeg, ``fallback`` True when it was
    chosen because no board was found; ``name`` (board profile), firmware and port."""

    name: str
    firmware: str
    virtual: bool
    port: str = ""
    fallback: bool = False


@dataclass(frozen=True)
class LinkHealth:
    """State of the link (``ok``, ``lost``, ``silent``, ``closed``), the lines lost or refused
    so far, and the reconnections."""

    state: str
    dropped: int = 0
    corrupt: int = 0
    reconnects: int = 0


@dataclass(frozen=True)
class Event:
    """Something the link or the board said: ``kind`` (connected, disconnected, silent, alive,
    watchdog, step, stepdone, boot, error) and its one-line ``message``."""

    kind: str
    message: str = ""


@dataclass(frozen=True)
class Batch:
    """Samples as the board sent them: sequence number ``seq`` and board time ``t_us`` (us,
    unwrapped), encoder ``count``, requested ``u_mV`` (mV); ``t`` is t_us in s and ``u_req``
    u_mV in V. ``events`` are the link's events since the last read."""

    seq: Sequence[int]
    t_us: Sequence[int]
    count: Sequence[int]
    u_mV: Sequence[int]
    events: Sequence[Event] = field(default_factory=tuple)

    @property
    def t(self) -> FloatArray:
        """Board time of each sample, s."""
        return np.asarray(self.t_us, dtype=float) / 1e6

    @property
    def u_req(self) -> FloatArray:
        """Requested voltage of each sample, V."""
        return np.asarray(self.u_mV, dtype=float) / 1000.0

    def __len__(self) -> int:
        return len(self.seq)


@dataclass(frozen=True)
class Meter:
    """What the virtual multimeter shows on M1A/M1B: u_A in V, i in A, R in ohm."""

    u_A: float
    i: float
    R: float


class Device(Protocol):
    """The board or the virtual MinSeg, as the UI drives it."""

    info: DeviceInfo

    def health(self) -> LinkHealth:
        """Current link state and counters."""

    def read(self, timeout: float) -> Batch:
        """Samples received since the last call (blocks at most ``timeout`` s); worker thread only."""

    def set_voltage(self, u: float) -> None:
        """Request u volts on the motor."""

    def stop(self) -> None:
        """Motor off, any step sequence aborted."""

    def set_period(self, period: float) -> None:
        """Sample every ``period`` s (board-timed)."""

    def run_steps(self, low: float, high: float, half: float, n: int) -> None:
        """Board-timed square wave low/high volts, ``half`` s each, ``n`` periods."""

    def meter(self) -> Meter | None:
        """The multimeter reading (virtual board only), else None."""

    def close(self) -> None:
        """Motor off and port closed."""


@dataclass(frozen=True)
class EntryResult:
    """What became of a typed text: ``ok`` False with a one-line ``message``, else stored.

    ``warnings`` are shown but never refuse; ``feedback`` is a checker's verdict on an answer.
    """

    ok: bool
    message: str = ""
    warnings: tuple[str, ...] = ()
    feedback: str = ""


@dataclass(frozen=True)
class Steady:
    """Live speed summary: ``settled``; ``mean`` and ``spread`` (rad/s) over ``window`` s."""

    settled: bool
    mean: float
    spread: float
    window: float
    note: str = ""


@dataclass(frozen=True)
class Cell:
    """A value in the table: the text shown and the formula with numbers behind it."""

    text: str
    formula: str = ""


@dataclass(frozen=True)
class TableView:
    """Columns, rows of cells, the final values, the warnings the numbers raise (one line
    each) and the group's own values beside the computed ones (label, yours, computed)."""

    columns: tuple[str, ...]
    rows: tuple[tuple[Cell, ...], ...]
    results: tuple[tuple[str, Cell], ...] = ()
    warnings: tuple[str, ...] = ()
    compare: tuple[tuple[str, str, str], ...] = ()


@dataclass(frozen=True)
class RunView:
    """A Task 10 run for the side-by-side panel: speeds (rad/s) at board times t (s), the
    manual's estimate ``omega_lab``, and the time constants read from it (s, None if none):
    T_63 on the timestamp speed, T_63_lab on the manual's filtered speed, T_ls with T_ci."""

    name: str
    kind: str
    ts: float
    samples: int
    interrupted: bool
    t: FloatArray
    omega: FloatArray
    omega_lab: FloatArray
    T_63: float | None
    T_63_lab: float | None
    T_ls: float | None
    T_ci: tuple[float, float] | None


@dataclass(frozen=True)
class StepWindow:
    """One rising step of the log: from ``t0`` to ``t1`` (s), its 63 % reading (s or None)."""

    t0: float
    t1: float
    T_63: float | None


@dataclass(frozen=True)
class ResultsView:
    """Tasks 11-15: the log used (t s, omega rad/s, u V), its rising steps, result lines and
    the group's readings beside the computed ones (``compare``: label, yours, computed)."""

    run: str | None
    t: FloatArray
    omega: FloatArray
    u: FloatArray
    steps: tuple[StepWindow, ...]
    lines: tuple[str, ...]
    compare: tuple[tuple[str, str, str], ...] = ()
    problems: tuple[str, ...] = ()


@dataclass(frozen=True)
class CheckView:
    """The model check of one run: measured, baseline and extended speeds (rad/s) at t (s),
    residual = measured - baseline; ``cause`` and ``evidence`` in words; the full text."""

    run: str | None
    t: FloatArray = field(default_factory=lambda: np.zeros(0))
    omega: FloatArray = field(default_factory=lambda: np.zeros(0))
    baseline: FloatArray = field(default_factory=lambda: np.zeros(0))
    extended: FloatArray = field(default_factory=lambda: np.zeros(0))
    residual: FloatArray = field(default_factory=lambda: np.zeros(0))
    cause: str = ""
    evidence: str = ""
    extended_model: str = ""
    gain: str = ""
    text: str = ""
    problem: str = ""


class Recording(Protocol):
    """A run being recorded (Task 10): samples appended by the stream worker as they arrive."""

    name: str
    plan: object
    samples: int

    def append(self, batch: Batch) -> None:
        """Keep every sample of ``batch`` (worker thread)."""

    def tick(self) -> None:
        """Flush to disk what is due (a timer, a few times a second)."""

    def end(self) -> None:
        """Take no more samples (the run is over; finishing it follows on the event loop)."""

    @property
    def elapsed(self) -> float:
        """Board time recorded so far, s."""


class Lab(Protocol):
    """The lab session as the UI sees it: steps, entries (parsed and autosaved), results.

    The view methods (run_views, results_view, check_view, export) may take half a second:
    call them from a worker."""

    steps: Sequence[Step]

    def text(self, key: str) -> str:
        """What the group typed for ``key`` (empty when nothing)."""

    def result(self, key: str) -> EntryResult | None:
        """The verdict on the stored entry for ``key`` (None when nothing was typed)."""

    def enter(self, key: str, text: str) -> EntryResult:
        """Parse, check and autosave one entry."""

    def choose(self, key: str, indices: Sequence[int]) -> EntryResult:
        """Pick options (0-based) of a choice field; autosaved."""

    def chosen(self, key: str) -> tuple[int, ...]:
        """The options (0-based) stored for a choice field."""

    @property
    def current(self) -> str:
        """Id of the step the group is on."""

    def go(self, step_id: str) -> None:
        """Remember (autosave) the step the group is on."""

    def status(self, step_id: str) -> str:
        """done, started, todo or info."""

    def steady(self, t: Sequence[float], count: Sequence[int]) -> Steady:
        """Is the live speed settled, and its mean and spread over the settled window."""

    def capture_live(self, level: float, t: Sequence[float], count: Sequence[int]) -> EntryResult:
        """Capture omega_ss at requested ``level`` (V) from live samples (s, counts); autosaved."""

    def table(self) -> TableView:
        """Tasks 6-9 as rows of cells with formulas."""

    def start_recording(self, name: str) -> Recording:
        """Start recording Task 10's plan ``name``."""

    def finish_recording(self, rec: Recording) -> str:
        """Keep the recorded run; one line on what was kept."""

    def runs(self) -> tuple[str, ...]:
        """Names of the recorded runs."""

    def use_run(self, name: str | None) -> str:
        """Tasks 11-15 and the model check use run ``name`` (None: the latest step run); one
        line saying which run they use now."""

    def run_views(self) -> tuple[RunView, ...]:
        """The latest 25 ms and fast runs with their T readings."""

    def results_view(self, step_id: str) -> ResultsView:
        """Tasks 11-15 computed, beside the group's own readings."""

    def check_view(self) -> CheckView:
        """The model check of the run Tasks 11-15 use."""

    def import_run(self, path: str) -> str:
        """Load a step log recorded elsewhere (InputError when it is not one)."""

    def export(self) -> tuple[str, ...]:
        """Write the report into the session folder; the files written."""

    def close(self) -> None:
        """Release the session."""


@dataclass(frozen=True)
class SessionSummary:
    """A saved session for the resume list: its folder, group, date, the step it is at, and
    why it cannot be opened ("damaged — ...", "in use by ..."; empty when it can)."""

    path: str
    members: str
    date: str
    step: str
    damaged: str = ""


class Store(Protocol):
    """The sessions folder: list, create and open sessions."""

    def list(self) -> Sequence[SessionSummary]:
        """Saved sessions, newest first (damaged ones carry a message and cannot be opened)."""

    def new(self, members: str, date: str) -> Lab:
        """A new session, already saved."""

    def open(self, path: str) -> Lab:
        """Resume a saved session (raises MinsegError with a one-line message when it cannot)."""
