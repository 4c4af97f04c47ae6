"""The samples' numbers and board times over a link's life: unwrapping, gaps, epochs, and
refusing a sample no real gap explains.

The board numbers its samples (``seq``, uint32) and stamps them with its ``micros()``
(``t_us``, uint32); both wrap. :class:`Timeline` turns them into int64 that only grow,
counts the samples lost on the way (gaps in seq), and starts a new *epoch* when the board
restarts (on a reconnect; on a ``$BOOT`` once the samples after it start a new time base,
:meth:`Timeline.boot`, as an old ``$BOOT`` sent again is no restart), continuing seq at +1
and t_us by the host's estimate of the pause: the one place the host clock enters.

A line can pass the checksum and still be false (digits swapped or lost), or be true and
old (a USB hub or a serial bridge sending a block of lines again). A sample is kept at
once only when it *fits* the last kept one:

- seq moved forward and board time moved forward, no further than the host's clock
  moved since the last kept sample arrived (plus :data:`SLACK_S` of buffering): a board
  cannot send samples from its future; and no more samples than that time holds at the
  fastest period (1 kHz);
- the time step matches the seq step at the sample period the stream has shown (the
  median of its recent consecutive steps), within :func:`tolerance_us`: lost samples
  take their time;
- the encoder count moved no further than the motor can turn in that time
  (:func:`max_count_step`), unless the count was just zeroed (:meth:`Timeline.count_zeroed`).

A sample that does not fit is held, not kept. Held samples that fit each other (seq +1,
a period's time, a count the motor can make) become a *chain*; when a sample fits the
last kept one again, the chain was false and is refused: counted in ``replayed`` when its
seq was behind the last kept one (old lines sent again), else in ``refused``.

- A chain whose *time goes on* (forward, no further than the host's clock, as above)
  reaching :data:`CONFIRM` samples is the same stream going on (its period changed, the
  stream was paused, its seq jumped): kept, a seq jump of d counted as d - 1 lost samples.
  Never a restart. Its seq going back while its time goes on means the seq of the lines
  before was false (their times and counts were not): it is kept, numbered on from them,
  and counted in ``renumbered``.
- A chain whose time does not go on (old lines have old times) is a restart only when its *time base starts again*
  (:func:`starts_again`: the seq and micros() of a board just reset) and none of its lines
  is a copy of a line already kept (old lines of an epoch's start sent again); or, failing
  that, when it has gone on live for :data:`RESTART_S` of the host's clock with nothing
  fitting the last kept sample meanwhile (a board that restarts exactly as it did before,
  line for line, and whose ``$BOOT`` was lost). Anything else that goes back is a replay:
  dropped and counted, whatever its length.

Either way nothing the board really sent is lost, and no old line is kept as a new one.
The first samples of an epoch are held until two fit each other, so a false first sample
never becomes the reference.

Units: t_us in microseconds, clocks in seconds, counts in encoder counts (x4 decoding).
"""

from __future__ import annotations

import math
from collections import deque
from typing import NamedTuple

from minseg_tui.device.protocol import SampleLine
from minseg_tui.units import COUNTS_PER_REV

U32 = 2**32

SLACK_S = 0.5
"""How far (s) board time may run ahead of the host's clock between two kept samples: the
latency of the OS buffers and the reader."""

CONFIRM = 3
"""Held samples that fit each other and are taken as the truth (the stream went on)."""

CONFIRM_START = 2
"""Samples that must fit each other to start an epoch."""

PERIOD_US = (1000, 100000)
"""The sample periods a board can run at, us (PROTOCOL.md, command P: the real board's
floor is 2000 us, the virtual board's 1000 us)."""

BOOT_US = 15_000_000
"""Latest board time (us since reset) of the first samples a restarted board sends: its
``$BOOT`` comes at most 10 s after reset (the virtual board's longest boot delay; a Mega's
bootloader takes about 1.5 s), the first sample one period later, and a few seconds of
lines may be lost on the way."""

RESTART_S = 2.0
"""Host time (s) a chain that goes back must run live, with nothing fitting the last kept
sample, before it is taken for a restart whose ``$BOOT`` was lost and whose time base
cannot be told from a copy (see the module)."""

HOLD_MAX = 50_000
"""Most samples held at once; older ones are refused (a replay longer than any buffer)."""

OMEGA_MAX = 72.0
"""Fastest the wheel can turn, rad/s, for refusing a count no motor made. The NXT motor's
no-load speed is about 170 rpm at 9 V (17.8 rad/s, 1.98 rad/s per V); at 12 V, the highest
supply the board accepts (command SUP), that is 23.8 rad/s. Three times that (72 rad/s,
690 rpm) leaves room for a motor faster than the published one, a supply above its rating
and a hand helping the wheel, and is still far below what a swapped digit in the count
makes (an error of 90 counts or more in 5 ms is 157 rad/s)."""

COUNT_SLACK = 4
"""Counts a step may add to :data:`OMEGA_MAX`'s: the x4 decoding's quantisation and edges
counted between the sample's time and its reading."""

_RECENT = 8
"""Consecutive steps the period estimate is the median of."""

_HISTORY = 200_000
"""Most early lines (board time below :data:`BOOT_US`) remembered for telling a copy."""

Row = tuple[int, int, int, int, int, float]
"""A kept sample: (seq, t_us, count, u_mV, epoch, t_host); seq and t_us unwrapped."""


def tolerance_us(dseq: int, period_us: float) -> float:
    """How far (us) the time of ``dseq`` sample steps may stray from dseq periods: a
    third of a period, 2 % of the span and 2 ms of loop jitter."""
    return 0.3 * period_us + 0.02 * dseq * period_us + 2000.0


def max_count_step(dt_us: int, cpr: int = COUNTS_PER_REV) -> int:
    """Most encoder counts the wheel can move in ``dt_us`` microseconds at
    :data:`OMEGA_MAX` (rad/s), with ``cpr`` counts per revolution, plus
    :data:`COUNT_SLACK` counts."""
    return math.ceil(OMEGA_MAX * dt_us * 1e-6 * cpr / (2 * math.pi)) + COUNT_SLACK


def starts_again(line: SampleLine) -> bool:
    """The sample could be one of the first of a board just reset: micros() below
    :data:`BOOT_US` and no more samples than one per 1 ms since then."""
    return line.t_us <= BOOT_US and line.seq <= line.t_us // PERIOD_US[0] + 1


class _Seen(NamedTuple):
    """A sample as received: the raw line, the link clock at arrival (s), host time (s)."""

    line: SampleLine
    clock: float
    t_host: float


_MASK = U32 - 1
_HALF = U32 // 2


def _steps(a: _Seen, b: _Seen) -> tuple[int, int]:
    """(seq step, time step in us) from ``a`` to ``b``, both modulo 2**32 (a step back is
    a number of 2**31 or more)."""
    return (b.line.seq - a.line.seq) & _MASK, (b.line.t_us - a.line.t_us) & _MASK


def _forward(dseq: int, dt: int, elapsed: float) -> bool:
    """seq and time moved forward by ``dseq`` and ``dt`` (us), time no further than the
    clock moved (``elapsed`` s) and the slack, and no more samples than that time holds at
    the fastest period."""
    return (
        0 < dseq < _HALF
        and 0 < dt < _HALF
        and dt <= (max(elapsed, 0.0) + SLACK_S) * 1e6
        and dseq <= dt // PERIOD_US[0] + 1
    )


def _behind(a: _Seen, b: _Seen) -> bool:
    """``b``'s seq is before ``a``'s (modulo 2**32)."""
    return (b.line.seq - a.line.seq) & _MASK >= _HALF


class Timeline:
    """Unwraps, numbers and checks the samples of one link (see the module).

    Counters: ``dropped`` (samples the board sent that never came: gaps in seq),
    ``refused`` (lines that passed the checksum but no real gap explains, among them a
    count no motor makes), ``replayed`` (old lines sent again: seq behind the last kept
    sample, no restart), ``repeated`` (the last kept line received again), ``renumbered``
    (times the stream went on with its seq set back: see the module).
    ``cpr``: the encoder's counts per wheel revolution.
    """

    def __init__(self, cpr: int = COUNTS_PER_REV) -> None:
        self.cpr = cpr
        self.epoch = -1
        self.dropped = 0
        self.refused = 0
        self.replayed = 0
        self.repeated = 0
        self.renumbered = 0
        self._ref: _Seen | None = None  # the last kept sample of this epoch
        self._out: tuple[int, int, float] | None = None  # its (seq, t_us) out, its t_host
        self._steps: deque[int] = deque(maxlen=_RECENT)
        self._period: float | None = None  # median of _steps
        self._held: list[_Seen] = []
        self._count_free = False  # the count was zeroed: the next step may jump
        self._early: set[tuple[int, int]] = set()  # raw (seq, t_us) kept near a reset
        self._boot_pending = False  # a $BOOT came; the restart waits for its time base
        self.false_boots = 0

    @property
    def period_us(self) -> float | None:
        """The sample period the stream has shown (median of recent steps), us; None yet."""
        return self._period

    def new_epoch(self) -> None:
        """The board restarted (a reconnect, a confirmed ``$BOOT``): what comes next starts
        anew."""
        self.epoch += 1
        self._boot_pending = False
        self._drop_held()
        self._ref = None
        self._learn_anew()
        self._count_free = False

    @property
    def boot_pending(self) -> bool:
        """A ``$BOOT`` came and the samples have not yet shown whether it was a restart."""
        return self._boot_pending

    def boot(self) -> None:
        """A ``$BOOT`` line came. It is a restart once the samples after it show a time base
        that starts again (:func:`starts_again`, or a chain that does not go on); a sample
        that still fits the last kept one means it was an old line sent again (counted in
        ``false_boots``), and nothing restarts."""
        if self._ref is None:
            self.new_epoch()
        else:
            self._boot_pending = True

    def count_zeroed(self) -> None:
        """The board zeroed its encoder count (``$OK,Z``): the next sample's count may jump."""
        self._count_free = True

    def _learn_anew(self) -> None:
        self._steps.clear()
        self._period = None

    def _drop_held(self) -> None:
        """Refuse the held samples: replayed when behind the last kept one, else refused."""
        ref = self._ref
        for seen in self._held:
            if ref is not None and _behind(ref, seen):
                self.replayed += 1
            else:
                self.refused += 1
        self._held = []

    def _count_ok(self, a: _Seen, b: _Seen, dt: int) -> bool:
        """``b``'s count is one the wheel can reach from ``a``'s in ``dt`` us."""
        return abs(b.line.count - a.line.count) <= max_count_step(dt, self.cpr)

    def _fits(self, ref: _Seen, seen: _Seen, dseq: int, dt: int) -> bool:
        period = self._period
        return (
            period is not None
            and _forward(dseq, dt, seen.clock - ref.clock)
            and abs(dt - dseq * period) <= tolerance_us(dseq, period)
            and (self._count_free or self._count_ok(ref, seen, dt))
        )

    def _next_of(self, a: _Seen, b: _Seen) -> bool:
        """``b`` is the sample right after ``a`` (seq +1, a possible period of time, a count
        the wheel can reach)."""
        dseq, dt = _steps(a, b)
        return (
            dseq == 1
            and _forward(dseq, dt, b.clock - a.clock)
            and dt <= 1.5 * PERIOD_US[1]
            and self._count_ok(a, b, dt)
        )

    def place(self, line: SampleLine, clock: float, t_host: float) -> list[Row]:
        """Take one sample (``clock``: the link's clock at arrival, s; ``t_host``: host
        monotonic time, s); the samples to keep now, oldest first (none, it, or a chain)."""
        seen = _Seen(line, clock, t_host)
        ref = self._ref
        if ref is not None:
            dseq, dt = _steps(ref, seen)
            if dseq == 0 and dt == 0:
                self.repeated += 1
                return []
            if self._fits(ref, seen, dseq, dt):
                self._drop_held()
                if self._boot_pending:  # the stream went on: that $BOOT was an old line
                    self._boot_pending = False
                    self.false_boots += 1
                return [self._keep(seen, dseq, dt)]
            if self._boot_pending and starts_again(line):
                self.new_epoch()  # the $BOOT, and a time base that starts again
                ref = None
        if self._held and self._next_of(self._held[-1], seen):
            self._held.append(seen)
            if len(self._held) > HOLD_MAX:  # a replay longer than any buffer: its oldest go
                oldest = self._held.pop(0)
                if ref is not None and _behind(ref, oldest):
                    self.replayed += 1
                else:
                    self.refused += 1
        else:
            self._drop_held()
            self._held = [seen]
        chain = self._held
        if ref is None:
            if len(chain) < CONFIRM_START:
                return []
            self._held = []
            return self._chain(self._start(chain[0]), chain)
        if len(chain) < CONFIRM:
            return []
        dseq, dt = _steps(ref, chain[0])
        elapsed = chain[0].clock - ref.clock
        if _forward(1, dt, elapsed):
            # time went on as the host's clock did: the same stream (its period changed,
            # or its seq jumped); old lines have old times, a restart's time starts again
            self._held = []
            self._learn_anew()
            if _forward(dseq, dt, elapsed):
                first = self._keep(chain[0], dseq, dt)  # a jump of d: d - 1 lost
            else:  # seq went back while time went on (seq of earlier lines was false)
                self.renumbered += 1
                first = self._keep(chain[0], 1, dt)
            return self._chain(first, chain)
        if self._restarted(chain):
            self._held = []
            self.new_epoch()  # the board restarted and its $BOOT never came
            return self._chain(self._start(chain[0]), chain)
        return []  # held: a replay until the stream goes on, or a restart seen live

    def _restarted(self, chain: list[_Seen]) -> bool:
        """A chain whose time does not go on is a restart (see the module): a ``$BOOT``
        came before it; or its time base starts again and none of it is a copy of a kept
        line (old lines of an epoch's start); or it ran live long enough."""
        if self._boot_pending or chain[-1].clock - chain[0].clock >= RESTART_S:
            return True
        if not starts_again(chain[0].line):
            return False
        return not any((s.line.seq, s.line.t_us) in self._early for s in chain)

    def _chain(self, first: Row, chain: list[_Seen]) -> list[Row]:
        out = [first]
        for a, b in zip(chain, chain[1:], strict=False):
            out.append(self._keep(b, *_steps(a, b)))
        return out

    def _start(self, seen: _Seen) -> Row:
        """The first sample of an epoch: its own numbers in epoch 0, else continuing the last
        kept sample at seq +1 and t_us + the host's pause (at least 1 us)."""
        if self._out is None:
            seq, t_us = seen.line.seq, seen.line.t_us
        else:
            gap = max(round((seen.t_host - self._out[2]) * 1e6), 1)
            seq, t_us = self._out[0] + 1, self._out[1] + gap
        return self._emit(seen, seq, t_us)

    def _keep(self, seen: _Seen, dseq: int, dt: int) -> Row:
        """Keep ``seen``, ``dseq`` and ``dt`` (us) after the last kept sample."""
        assert self._out is not None
        self.dropped += dseq - 1
        if dseq == 1:
            steps = self._steps
            steps.append(dt)
            ordered = sorted(steps)
            n = len(ordered)
            self._period = (
                float(ordered[n // 2]) if n % 2 else (ordered[n // 2 - 1] + ordered[n // 2]) / 2
            )
        return self._emit(seen, self._out[0] + dseq, self._out[1] + dt)

    def _emit(self, seen: _Seen, seq: int, t_us: int) -> Row:
        self._ref = seen
        self._out = (seq, t_us, seen.t_host)
        self._count_free = False
        s = seen.line
        if s.t_us <= BOOT_US and len(self._early) < _HISTORY:
            self._early.add((s.seq, s.t_us))
        return (seq, t_us, s.count, s.u_mV, self.epoch, seen.t_host)


__all__ = [
    "BOOT_US",
    "CONFIRM",
    "CONFIRM_START",
    "OMEGA_MAX",
    "PERIOD_US",
    "RESTART_S",
    "SLACK_S",
    "Row",
    "Timeline",
    "max_count_step",
    "starts_again",
    "tolerance_us",
]
