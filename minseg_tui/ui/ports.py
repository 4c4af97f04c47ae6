"""What the UI needs from the layers below it, as small typed interfaces.

The screens talk to these Protocols (and the lab's step data, :mod:`minseg_tui.lab.steps`) only; :mod:`minseg_tui.ui.backend` adapts the real
device, lab and model modules to them. Units: volts, amperes, ohms, rad/s, seconds.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol

from minseg_tui.lab.steps import Step


@dataclass(frozen=True)
class DeviceInfo:
    """Who we talk to: ``virtual`` True for the simulated MinSeg; ``name`` for the status line."""

    name: str
    firmware: str
    virtual: bool
    port: str = ""


@dataclass(frozen=True)
class LinkHealth:
    """State of the link (``ok``, ``lost``, ``closed``) and the lines lost or refused so far."""

    state: str
    dropped: int = 0
    corrupt: int = 0


@dataclass(frozen=True)
class Batch:
    """Samples as the board sent them: board time ``t`` (s), encoder ``count``, command ``u_req`` (V)."""

    t: Sequence[float]
    count: Sequence[int]
    u_req: Sequence[float]
    events: Sequence[str] = field(default_factory=tuple)


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

    def run_steps(self, low: float, high: float, half: float, n: int, period: float) -> None:
        """Board-timed square wave low/high volts, ``half`` s each, ``n`` periods, sampled every ``period`` s."""

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
    """Columns, rows of cells, and the warnings the numbers raise (one line each)."""

    columns: tuple[str, ...]
    rows: tuple[tuple[Cell, ...], ...]
    results: tuple[tuple[str, Cell], ...] = ()
    warnings: tuple[str, ...] = ()


class Lab(Protocol):
    """The lab session as the UI sees it: steps, entries (parsed and autosaved), results."""

    steps: Sequence[Step]

    def text(self, key: str) -> str:
        """What the group typed for ``key`` (empty when nothing)."""

    def result(self, key: str) -> EntryResult | None:
        """The verdict on the stored entry for ``key`` (None when nothing was typed)."""

    def enter(self, key: str, text: str) -> EntryResult:
        """Parse, check and autosave one entry."""

    @property
    def current(self) -> str:
        """Id of the step the group is on."""

    def go(self, step_id: str) -> None:
        """Remember (autosave) the step the group is on."""

    def steady(self, t: Sequence[float], count: Sequence[int]) -> Steady:
        """Is the live speed settled, and its mean and spread over the settled window."""

    def capture_live(self, level: float, t: Sequence[float], count: Sequence[int]) -> EntryResult:
        """Capture omega_ss at requested ``level`` (V) from live samples (s, counts); autosaved."""

    def table(self) -> TableView:
        """Tasks 6-9 (and 11-15 when a step run exists) as rows of cells with formulas."""

    def store_run(self, name: str, t: Sequence[float], count: Sequence[int], u_req: Sequence[float],
                  complete: bool) -> None:
        """Keep a recorded run (board time s, counts, requested V) as a step log; autosaved."""

    def run(self, name: str) -> tuple[Sequence[float], Sequence[float]] | None:
        """A recorded run's time (s) and speed (rad/s) for plotting, or None."""

    def run_status(self) -> str:
        """One line on the runs recorded so far."""

    def results_text(self) -> str:
        """Tasks 11-15 computed, beside the group's own readings."""

    def model_check_text(self) -> str:
        """The model check's verdict with its evidence."""

    def export(self) -> Sequence[str]:
        """Write the report into the session folder; the files written."""


@dataclass(frozen=True)
class SessionSummary:
    """A saved session for the resume list: its folder, group, date, the step it is at."""

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
