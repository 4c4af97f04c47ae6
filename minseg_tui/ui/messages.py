"""The UI's messages: small dataclasses, coalesced where they come in floods.

From the app's workers to the app: :class:`DeviceOpened`, :class:`SamplesArrived`,
:class:`LinkEventArrived`, :class:`MeterRead`, :class:`MotorKnown`, :class:`Task10Moved`,
:class:`BoardChecked`, :class:`RevolutionCounted`, :class:`NoCounts`. From the panels and the
screen up: the requests (:class:`RunRequested` for the app, which drives the device;
:class:`VoltageRequested`, :class:`CaptureRequested`, :class:`LogImportRequested` for the lab
screen, which holds the session's entries, and has the app put a voltage on the motor),
:class:`StepShown` and :class:`NoticesCrowd`.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from dataclasses import dataclass, field

from textual.message import Message

from minseg_tui.device.boardcheck import BoardCheckResult, RevolutionResult
from minseg_tui.device.link import LinkEvent, LinkStats
from minseg_tui.lab.content.steps import Step
from minseg_tui.lab.state.task10 import Task10
from minseg_tui.model.plant import MeterReading
from minseg_tui.ui.device import Device


@dataclass
class DeviceOpened(Message):
    """The connect worker finished: the device (``fallback``: the virtual MinSeg because no
    board was found), or None with the one-line ``error``."""

    device: Device | None
    error: str = ""
    fallback: bool = False


@dataclass
class SamplesArrived(Message):
    """New samples are in the live buffer (it holds them; this only says "redraw soon"), with
    the link's counters now. One pending message replaces another: a fast stream never
    floods the queue."""

    stats: LinkStats
    total: int

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, SamplesArrived)


@dataclass
class LinkEventArrived(Message):
    """Something the board said or the link did (never coalesced)."""

    event: LinkEvent


@dataclass
class MeterRead(Message):
    """The virtual multimeter now (None: it did not answer), read while the board was asked
    for ``requested`` V (None: no steady request, a square wave) and had been for ``held`` s."""

    reading: MeterReading | None
    requested: float | None = None
    held: float = 0.0

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, MeterRead)


@dataclass
class MotorKnown(Message):
    """The link's idea of the motor changed: ``u_req`` V requested as the stream read it (0:
    off; None: a board-timed square wave runs; after a reconnect or a board restart it is
    0). The app shows the link's motor as it is when it handles this, not ``u_req``: a
    check, a command or a board event may have changed it since the read. The worker that
    sends the board commands posts one (``u_req`` None) once the last is sent, if one was
    passed over meanwhile."""

    u_req: float | None


@dataclass
class Task10Moved(Message):
    """The Task 10 procedure ``task`` went on to its next phase (recording, the board's
    sequence, ended: its ``outcome`` says how)."""

    task: Task10


@dataclass
class VoltageRequested(Message):
    """F3: put ``level`` V on the motor; ``done`` is set once the lab screen has had the app
    do it (the key waits for it: the app reads the keys typed after F3 only then, and they
    see the new level; posted to the app, the request waited in its queue behind them)."""

    level: float
    done: asyncio.Event = field(default_factory=asyncio.Event, compare=False, repr=False)


@dataclass
class CommandFailed(Message):
    """A board command sent in the app's worker (``what``: ``stop`` or ``voltage``) failed,
    with the ``error`` in one line."""

    what: str
    error: str


@dataclass
class RunRequested(Message):
    """F5/F6: start Task 10's plan ``plan`` (``manual`` or ``fast``) on the board and record it."""

    plan: str


@dataclass
class CaptureRequested(Message):
    """F4: capture omega_ss at ``level`` V from the live stream; ``done`` is set once the
    lab screen has (the key waits for it: the keys typed after F4 go into the entry after
    omega_ss)."""

    level: float
    done: asyncio.Event = field(default_factory=asyncio.Event, compare=False, repr=False)


@dataclass
class RevealRequested(Message):
    """Ctrl+R (a lab assistant): show the computed values of step ``step_id`` before the group
    has entered its own."""

    step_id: str


@dataclass
class LogImportRequested(Message):
    """Load the run log at ``path`` (recorded elsewhere); ``reply`` gets the one line to show."""

    path: str
    reply: Callable[[str], None]


@dataclass
class StepShown(Message):
    """The lab screen now shows ``step``."""

    step: Step


@dataclass
class NoticesCrowd(Message):
    """The lab screen's notices cover the entry typed in or the one judged last, on the side
    with more room: the oldest of them goes (the app holds the notices)."""


@dataclass
class BoardChecked(Message):
    """The board check finished: its ``result``, or None with the one-line ``error``."""

    result: BoardCheckResult | None
    error: str = ""


@dataclass
class NoCounts(Message):
    """The stream shows the motor driven at ``u`` V for a while and the count standing still."""

    u: float


@dataclass
class RevolutionCounted(Message):
    """The hand check finished: its ``result``, or None with the one-line ``error`` (empty
    when the group cancelled it)."""

    result: RevolutionResult | None
    error: str = ""
