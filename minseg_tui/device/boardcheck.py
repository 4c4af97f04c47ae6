"""The board check: does the wheel turn when asked, and does the count follow it?

:func:`check_board` drives a small voltage (1.8 V) for half a second of board time, stops,
and reads the count and the board's ``DIAG`` before and after. It says what it found:

- the count rose: all is well;
- the count fell: the encoder counts the other way from the motor; with ``fix`` the board is
  told to count the other way (``DIR``, kept on the board), checked again, and the text says so;
- nothing was counted: what that means, and what to look at, by whether the wheel turned
  (the group's answer, or the virtual board's multimeter: a motor on the driver draws current).
  In Task 5 (jumper out, meter in series) a motor that does not turn is first asked about the
  meter.

:func:`count_revolution` counts while a hand turns the wheel once: 720 counts expected.

Both use only what a :class:`CheckedBoard` offers (a :class:`~minseg_tui.device.link.Link`
meets it); samples come from ``board.samples`` unless another source is handed in (the TUI
hands its own tap, since its stream worker drains the link). Voltages in V, times in s.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import asdict, dataclass
from typing import Any, Literal, Protocol

import numpy as np

from minseg_tui.device import protocol as P
from minseg_tui.device.samples import SampleBatch
from minseg_tui.errors import DeviceError
from minseg_tui.model.plant import MeterReading

CHECK_U = 1.8
"""Voltage the check drives, V: enough to break the NXT motor's dry friction, gentle."""
CHECK_S = 0.5
"""How long it drives, s of board time."""
MIN_COUNTS = 10
"""Fewer counts than this over the drive is "no counts" (the wheel turns about 150 at 1.8 V)."""
MIN_CURRENT = 0.005
"""A motor on the driver draws at least this while driven, A (the virtual multimeter)."""
CPR = 720
"""Counts per wheel revolution expected (x4 decoding of the NXT encoder)."""

Direction = Literal["forward", "reversed", "none"]


class CheckedBoard(Protocol):
    """What the check uses of a board's link (volts, seconds)."""

    port: str
    ident: P.Ident | None

    def samples(self) -> SampleBatch:
        """Every sample received since the last call."""
        ...

    def set_voltage(self, u: float) -> object:
        """Request ``u`` V; returns the voltage applied (V), where it says."""
        ...

    def stop(self) -> object:
        """Motor off."""
        ...

    def diag(self) -> P.Diag:
        """The board's $DIAG reply."""
        ...

    def meter(self) -> MeterReading | None:
        """The virtual board's multimeter, None on a real board."""
        ...

    def set_direction(self, enc: str, motor: str) -> object:
        """DIR: the encoder's counting direction and the motor's polarity."""
        ...


@dataclass(frozen=True)
class BoardCheckResult:
    """What the check found. ok: the count follows a positive voltage upwards (after a fix,
    if one was made); direction: what the count did ("forward", "reversed", "none");
    counts: the change of the count over the drive (before any fix); connector: the one the
    count follows, where known; text: what it means and what to do, in sentences;
    fixed: the direction was set on the board; wheel_turned: whether the wheel turned, where
    known (the group's answer or the multimeter); current: the current drawn while driven, A
    (the virtual board's multimeter; None on a real board)."""

    ok: bool
    direction: Direction
    counts: int
    connector: str | None
    text: str
    fixed: bool = False
    wheel_turned: bool | None = None
    current: float | None = None

    def as_json(self) -> dict[str, Any]:
        """The JSON of ``board-check --json``: ok, direction, counts, connector, text and the
        rest of the fields."""
        return asdict(self)


@dataclass(frozen=True)
class Drive:
    """One drive of the motor: the count's change over ``seconds`` (board time driven, s),
    the edges per connector, the DIAG after, the current drawn (A, virtual board only)."""

    counts: int
    seconds: float
    edges: dict[str, int]
    diag: P.Diag
    current: float | None


def _flip(d: str) -> str:
    return "REV" if d == "FWD" else "FWD"


class _Collector:
    """Samples gathered from ``take`` until a condition on all of them holds."""

    def __init__(self, port: str, take: Callable[[], SampleBatch]) -> None:
        self.port = port
        self.take = take
        self.got: list[SampleBatch] = []

    def until(self, cond: Callable[[SampleBatch], bool], timeout: float) -> SampleBatch:
        """All samples so far, once ``cond`` holds for them; DeviceError after ``timeout``
        s (wall clock) without a new sample: a board that stopped sending. A busy host that
        takes the samples slowly is not one."""
        end = time.monotonic() + timeout
        while True:
            new = self.take()
            if len(new):
                end = time.monotonic() + timeout
            self.got.append(new)
            batch = SampleBatch.concat(self.got)
            self.got = [batch]
            if cond(batch):
                return batch
            if time.monotonic() > end:
                raise DeviceError(
                    f"{self.port}: the board sent too few samples for the check "
                    f"({len(batch)}, then none for {timeout:g} s)"
                )
            time.sleep(0.01)


def drive(
    board: CheckedBoard,
    samples: Callable[[], SampleBatch] | None = None,
    u: float = CHECK_U,
    seconds: float = CHECK_S,
) -> Drive:
    """Drive ``u`` V for ``seconds`` of board time, then stop; the count's change over the
    first ``seconds`` of the drive (the stop comes a batch of samples later), the encoder edges per connector (DIAG after minus before), the current drawn
    halfway (virtual board only)."""
    take = samples or board.samples
    board.stop()
    before = board.diag()
    take()  # what came before the drive
    said = board.set_voltage(u)
    applied = float(said) if isinstance(said, float | int) else u
    collect = _Collector(board.port, take)

    def span(b: SampleBatch) -> float:
        t = b.t[np.abs(b.u_req - applied) < 1e-6]
        return float(t[-1] - t[0]) if t.size > 1 else 0.0

    try:
        collect.until(lambda b: span(b) >= seconds / 2, 4 * seconds + 2.0)
        reading = board.meter()
        batch = collect.until(lambda b: span(b) >= seconds, 4 * seconds + 2.0)
    finally:
        board.stop()
    on = np.flatnonzero(np.abs(batch.u_req - applied) < 1e-6)
    first = int(on[0])
    # the samples arrive in batches and the stop follows the one that completes the span, so
    # the motor runs on past ``seconds`` (by a batch, or more on a busy host or a virtual
    # clock): the count is taken over the first ``seconds`` of the drive, as said
    on = on[batch.t[on] <= batch.t[first] + seconds + 1e-9]
    start = int(batch.count[first - 1]) if first > 0 else int(batch.count[first])
    counts = int(batch.count[on[-1]]) - start
    driven = float(batch.t[on[-1]] - batch.t[first])
    after = board.diag()
    edges = {}
    for c in after.connectors:
        was = before.connector(c.name)
        edges[c.name] = (c.edges - (was.edges if was else 0)) % 2**32
    return Drive(counts, driven, edges, after, None if reading is None else reading.i)


def _connector(d: Drive) -> str | None:
    if d.diag.active != "NONE":
        return d.diag.active
    best = max(d.edges.items(), key=lambda kv: kv[1], default=None)
    return best[0] if best and best[1] > 0 else None


def _pins(d: Drive) -> str:
    """The encoder pins in words (for the "no counts" text)."""
    states = ", ".join(f"{c.name} {c.pins}" for c in d.diag.connectors)
    if d.diag.connectors and all(c.pins == "11" for c in d.diag.connectors):
        return f"The encoder pins read {states}: both high, as an unplugged encoder reads."
    return f"The encoder pins read {states}." if states else ""


TURNED = (
    "The wheel turned but the encoder counted nothing: the encoder cable is not in, not all "
    "the way in, or in another connector than the motor cable's; or the firmware's board "
    "profile does not match this board (minseg-tui flash --profile NAME)."
)
NOT_TURNED = (
    "The wheel did not turn: is the power switch on (the battery or the supply on)? is the "
    "motor cable in, at the connector whose encoder is used? is the current jumper in (taken "
    "out for Task 5)? If all are, the motor driver may be damaged."
)
NOT_TURNED_TASK5 = (
    "The wheel did not turn: with the jumper out for Task 5 the current flows only through "
    "the meter. Is the meter on mA, in series across the jumper pins (not on V, not on the "
    "fused 10 A input)? Then check the power switch and the motor cable."
)


def _no_counts(d: Drive, turned: bool | None, task5: bool) -> str:
    head = (
        f"No counts: the board drove {CHECK_U:g} V for {d.seconds:.1f} s and the encoder "
        f"counted {abs(d.counts)}."
    )
    moved = {k: v for k, v in d.edges.items() if v >= MIN_COUNTS}
    if moved:
        where = ", ".join(f"{k} {v}" for k, v in moved.items())
        return (
            f"{head} Yet the encoder pins changed ({where} edges) and the count did not "
            "follow them: reset the board (unplug and plug the USB cable) and check again."
        )
    pins = _pins(d)
    not_turned = NOT_TURNED_TASK5 if task5 else NOT_TURNED
    if turned is True:
        body = TURNED
    elif turned is False:
        body = not_turned
    else:
        body = f"Did the wheel turn? If it did: {TURNED[len('The wheel turned but ') :]} " + (
            f"If it did not: {not_turned[len('The wheel did not turn: ') :]}"
        )
    return " ".join(x for x in (head, pins, body) if x)


def check_board(
    board: CheckedBoard,
    *,
    samples: Callable[[], SampleBatch] | None = None,
    fix: bool = True,
    wheel_turned: Callable[[], bool | None] | bool | None = None,
    task5: bool = False,
) -> BoardCheckResult:
    """Drive the motor briefly and say whether the count follows (see the module).

    ``wheel_turned``: whether the group saw the wheel turn, or a function that asks them
    (called only when nothing was counted); without an answer the virtual board's multimeter
    decides, and on a real board the text gives both branches. ``task5``: the jumper is out
    and the meter in series. Raises DeviceError when the board does not answer.
    """
    d = drive(board, samples)
    connector = _connector(d)
    turned: bool | None = None
    if d.current is not None:
        turned = abs(d.current) >= MIN_CURRENT
    if d.counts >= MIN_COUNTS:
        return BoardCheckResult(
            True,
            "forward",
            d.counts,
            connector,
            f"The wheel turns and the count follows: {d.counts} counts for {CHECK_U:g} V over "
            f"{d.seconds:.1f} s" + (f", on connector {connector}." if connector else "."),
            wheel_turned=True,
            current=d.current,
        )
    if d.counts <= -MIN_COUNTS:
        return _reversed(board, samples, d, connector, fix)
    if turned is None and wheel_turned is not None:
        turned = wheel_turned() if callable(wheel_turned) else wheel_turned
    return BoardCheckResult(
        False,
        "none",
        d.counts,
        connector,
        _no_counts(d, turned, task5),
        wheel_turned=turned,
        current=d.current,
    )


def _reversed(
    board: CheckedBoard,
    samples: Callable[[], SampleBatch] | None,
    d: Drive,
    connector: str | None,
    fix: bool,
) -> BoardCheckResult:
    ident = board.ident
    enc, motor = (ident.enc_dir, ident.motor_dir) if ident else ("FWD", "FWD")
    new = f"DIR,{_flip(enc)},{motor}"
    head = (
        f"The count falls for a positive voltage ({d.counts} counts for {CHECK_U:g} V): the "
        "encoder counts the other way from the motor."
    )
    if not fix:
        return BoardCheckResult(
            False,
            "reversed",
            d.counts,
            connector,
            f"{head} Not fixed: run minseg-tui board-check without --no-fix, or send {new} "
            "(the board keeps it over a reset).",
            wheel_turned=True,
            current=d.current,
        )
    board.set_direction(_flip(enc), motor)
    again = drive(board, samples)
    if again.counts >= MIN_COUNTS:
        return BoardCheckResult(
            True,
            "reversed",
            d.counts,
            connector,
            f"{head} Fixed: the board now counts the other way ({new}, kept on the board over "
            f"a reset) and the count rises ({again.counts} counts in a second try).",
            fixed=True,
            wheel_turned=True,
            current=d.current,
        )
    return BoardCheckResult(
        False,
        "reversed",
        d.counts,
        connector,
        f"{head} The board was told to count the other way ({new}), but a second try counted "
        f"{again.counts}: check the encoder cable and run the check again.",
        fixed=True,
        wheel_turned=True,
        current=d.current,
    )


@dataclass(frozen=True)
class RevolutionResult:
    """The hand check: counts (the change of the count while the wheel was turned, signed),
    ok (within 5 % of 720 either way), text."""

    ok: bool
    counts: int
    text: str


def revolution_text(counts: int) -> RevolutionResult:
    """What ``counts`` for one revolution by hand means (720 expected)."""
    n = abs(counts)
    ok = abs(n - CPR) <= 0.05 * CPR
    if ok:
        text = f"{n} counts for one revolution: {CPR} expected, the encoder is read in full."
    elif n < MIN_COUNTS:
        text = (
            f"{n} counts: the encoder counted nothing. If the wheel did turn a whole revolution, "
            "check the encoder cable and the board profile (run the board check); if it did "
            "not, turn it and count again."
        )
    elif abs(n - CPR / 2) <= 0.1 * CPR / 2:
        text = f"{n} counts, half of {CPR}: only one of the encoder's two channels is read."
    elif abs(n - CPR / 4) <= 0.1 * CPR / 4:
        text = f"{n} counts, a quarter of {CPR}: the encoder is read on one edge of one channel."
    else:
        text = (
            f"{n} counts, {CPR} expected: was it one whole revolution? Mark the wheel and turn "
            "it once more, exactly."
        )
    return RevolutionResult(ok, counts, text)


LAST_US = 100_000
"""Board time the hand check still reads after the hand is done, us (the turn's last samples)."""
LAST_WAIT_S = 5.0
"""...waiting for them until the board has been silent this long in host time, s (no new
sample read: a board that went silent)..."""
LAST_GIVE_UP_S = 30.0
"""...and in all at most this long in host time, s (a board that streams samples whose
times never reach the end of the turn)."""


def board_time_at(batches: list[SampleBatch], host_t: float) -> int | None:
    """The board time (us) at host time ``host_t`` (s, the clock the samples' ``t_host`` were
    stamped with on arrival), at least: a sample taken at board time b that arrived at host
    time h says the board's clock was already past b at h, and both clocks run at one rate,
    so the board's time at ``host_t`` is at least b + (host_t - h); the least delayed sample
    bounds it best. None without samples."""
    offsets = [
        int(np.max(b.t_us - np.round(b.t_host * 1e6).astype(np.int64))) for b in batches if len(b)
    ]
    return max(offsets) + round(host_t * 1e6) if offsets else None


def count_revolution(
    board: CheckedBoard,
    done: Callable[[], bool],
    *,
    samples: Callable[[], SampleBatch] | None = None,
    timeout: float = 30.0,
    poll: float = 0.02,
    turned_at: Callable[[], float | None] = lambda: None,
    clock: Callable[[], float] = time.monotonic,
) -> RevolutionResult:
    """Count while a hand turns the wheel, until ``done()`` says it is done (or ``timeout``
    s pass): the counts and what they mean. The motor is off meanwhile. ``samples``: a tap
    of the samples, from the newest one read when the check was asked for on (else the
    link's own, read from its newest sample on). The count reads on until the board's clock is :data:`LAST_US` past
    the moment the hand was done, that moment (host time by ``clock``, the one the samples'
    arrival is stamped with) mapped to board time (:func:`board_time_at`), so that a host
    reading the samples late does not cut the end of the turn. ``turned_at()``: the board
    time (s) at which a simulated hand turned the wheel, when one did (the virtual
    MinSeg's): the last samples read reach past it too."""
    take = samples or board.samples
    board.stop()
    # where the count begins: a tap (``samples``) holds the newest sample read when the
    # check was asked for, then those read after, so its first sample; the link's own
    # backlog may hold rows from before (the motor driven), so its newest. A hand that
    # turns as soon as it is asked, before the board's next sample, is counted either way.
    first = take()
    got: list[SampleBatch] = [first] if samples is not None else []
    start = int(first.count[-1]) if samples is None and len(first) else None
    arrived = [first]  # every batch, for the board's time when the hand was done
    end = clock() + timeout
    heard = clock()  # when a sample last arrived (the board streams while the motor is off)
    while not done() and clock() < end:
        got.append(take())
        arrived.append(got[-1])
        if len(got[-1]):
            heard = clock()
        time.sleep(poll)
    pressed = clock()
    # the last samples of the turn: until the board's own clock is LAST_US past the moment
    # the hand was done (a busy host reads them late, never too early): the newest sample
    # seen then, or later, that moment in board time
    seen = [int(b.t_us[-1]) for b in got if len(b)]
    turn = turned_at()
    if turn is not None:
        seen.append(int(turn * 1e6))
    at_board = board_time_at(arrived, pressed)
    if at_board is not None:
        seen.append(at_board)
    since = max(seen) if seen else None
    quiet_until = clock() + LAST_WAIT_S
    give_up = quiet_until - LAST_WAIT_S + LAST_GIVE_UP_S
    while True:
        now = clock()
        late = now >= quiet_until or now >= give_up
        # past the wait, read once more: a host that stalled for the whole wait finds the
        # samples that arrived meanwhile (a busy machine read the turn's end late, not never)
        b = take()
        got.append(b)
        if len(b):
            heard = clock()
        if late:
            break
        if len(b):
            quiet_until = clock() + LAST_WAIT_S
            # a sample that arrives after Enter bounds the board's time at Enter as well
            # (taken at b, arrived at h: at least b - (h - pressed)); with none read before
            # Enter, this alone places it (a host that had read nothing yet)
            at = board_time_at([b], pressed)
            if at is not None:
                since = at if since is None else max(since, at)
            if since is not None and int(b.t_us[-1]) >= since + LAST_US:
                break
        time.sleep(poll)
    batch = SampleBatch.concat(got)
    if len(batch) == 0:
        raise DeviceError(f"{board.port}: no samples came from the board while the wheel turned")
    silent = clock() - heard
    if silent >= LAST_WAIT_S:  # s37 attack: a board killed (a cable pulled) mid-count was
        # said to have counted what it sent before ("0 counts: the encoder counted nothing")
        raise DeviceError(
            f"{board.port}: the board stopped sending {silent:.0f} s before the count ended "
            "(cable pulled, or the board reset?): what the wheel turned after that is not "
            "known; connect it and count again"
        )
    return revolution_text(int(batch.count[-1]) - (int(batch.count[0]) if start is None else start))


WATCH_S = 1.0
"""How long the motor must be driven without counts before :class:`NoCountWatch` speaks, s."""
WATCH_U = 1.5
"""The smallest voltage it watches, V (below it a real NXT motor may stick on dry friction)."""


class NoCountWatch:
    """Watches the sample stream for the motor driven and the count standing still: at least
    ``min_u`` V requested for ``seconds`` of board time while the count moved fewer than
    :data:`MIN_COUNTS`. :meth:`feed` returns the voltage (V) once per such stretch; a count
    that moves, or the motor off, starts the watch again."""

    def __init__(self, seconds: float = WATCH_S, min_u: float = WATCH_U) -> None:
        self.seconds = seconds
        self.min_u = min_u
        self._since: float | None = None
        self._count0 = 0
        self._fired = False

    def feed(self, batch: SampleBatch) -> float | None:
        """The voltage (V) when this batch completes a stretch of driven, uncounted samples."""
        said: float | None = None
        t, counts, us = batch.t, batch.count, batch.u_req
        for k in range(len(batch)):
            u = float(us[k])
            if not abs(u) >= self.min_u:
                self._since, self._fired = None, False
                continue
            c = int(counts[k])
            if self._since is None or abs(c - self._count0) >= MIN_COUNTS:
                self._since, self._count0, self._fired = float(t[k]), c, False
                continue
            if not self._fired and float(t[k]) - self._since >= self.seconds:
                self._fired = True
                said = u
        return said
