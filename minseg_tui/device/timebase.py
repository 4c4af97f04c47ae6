"""The samples' numbers and board times over a link's life: unwrapping, gaps, epochs, and
refusing a sample no real gap explains.

The board numbers its samples (``seq``, uint32) and stamps them with its ``micros()``
(``t_us``, uint32); both wrap. :class:`Timeline` turns them into int64 that only grow,
counts the samples lost on the way (gaps in seq), and starts a new *epoch* when the board
restarts (the link says so on ``$BOOT`` and on a reconnect), continuing seq at +1 and
t_us by the host's estimate of the pause: the one place the host clock enters.

A line can pass the checksum and still be false (digits swapped or lost). A sample is
kept at once only when it *fits* the last kept one:

- seq moved forward and board time moved forward, no further than the host's clock
  moved since the last kept sample arrived (plus :data:`SLACK_S` of buffering): a board
  cannot send samples from its future;
- the time step matches the seq step at the sample period the stream has shown (the
  median of its recent consecutive steps), within :func:`tolerance_us`: lost samples
  take their time.

A sample that does not fit is held, not kept. Held samples that fit each other (seq +1,
a period's time) become a *chain*; when a sample fits the last kept one again, the chain
was false and is refused (counted in ``refused``); when the chain reaches :data:`CONFIRM`
samples it is the truth: either the same stream went on (seq and time forward, the period
changed: the gap is counted, the epoch stays) or the board restarted without its
``$BOOT`` reaching us (a new epoch). Either way nothing the board really sent is lost.
The first samples of an epoch are held until two fit each other, so a false first sample
never becomes the reference.

Units: t_us in microseconds, clocks in seconds.
"""

from __future__ import annotations

from collections import deque
from typing import NamedTuple

from minseg_tui.device.protocol import SampleLine

U32 = 2**32

SLACK_S = 0.5
"""How far (s) board time may run ahead of the host's clock between two kept samples: the
latency of the OS buffers and the reader."""

CONFIRM = 3
"""Held samples that fit each other and are taken as the truth (the stream went on)."""

CONFIRM_START = 2
"""Samples that must fit each other to start an epoch."""

PERIOD_US = (2000, 100000)
"""The sample periods a board can run at, us (PROTOCOL.md, command P)."""

_RECENT = 8
"""Consecutive steps the period estimate is the median of."""

Row = tuple[int, int, int, int, int, float]
"""A kept sample: (seq, t_us, count, u_mV, epoch, t_host); seq and t_us unwrapped."""


def tolerance_us(dseq: int, period_us: float) -> float:
    """How far (us) the time of ``dseq`` sample steps may stray from dseq periods: a
    third of a period, 2 % of the span and 2 ms of loop jitter."""
    return 0.3 * period_us + 0.02 * dseq * period_us + 2000.0


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
    clock moved (``elapsed`` s) and the slack."""
    return 0 < dseq < _HALF and 0 < dt < _HALF and dt <= (max(elapsed, 0.0) + SLACK_S) * 1e6


def _next_of(a: _Seen, b: _Seen) -> bool:
    """``b`` is the sample right after ``a`` (seq +1, a possible period of time)."""
    dseq, dt = _steps(a, b)
    return dseq == 1 and _forward(dseq, dt, b.clock - a.clock) and dt <= 1.5 * PERIOD_US[1]


class Timeline:
    """Unwraps, numbers and checks the samples of one link (see the module).

    Counters: ``dropped`` (samples the board sent that never came: gaps in seq),
    ``refused`` (lines that passed the checksum but no real gap explains), ``repeated``
    (a line received twice).
    """

    def __init__(self) -> None:
        self.epoch = -1
        self.dropped = 0
        self.refused = 0
        self.repeated = 0
        self._ref: _Seen | None = None  # the last kept sample of this epoch
        self._out: tuple[int, int, float] | None = None  # its (seq, t_us) out, its t_host
        self._steps: deque[int] = deque(maxlen=_RECENT)
        self._period: float | None = None  # median of _steps
        self._held: list[_Seen] = []

    @property
    def period_us(self) -> float | None:
        """The sample period the stream has shown (median of recent steps), us; None yet."""
        return self._period

    def new_epoch(self) -> None:
        """The board restarted (a ``$BOOT`` line, a reconnect): what comes next starts anew."""
        self.epoch += 1
        self._ref = None
        self._learn_anew()
        self.refused += len(self._held)
        self._held = []

    def _learn_anew(self) -> None:
        self._steps.clear()
        self._period = None

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
            period = self._period
            if (
                period is not None
                and _forward(dseq, dt, clock - ref.clock)
                and abs(dt - dseq * period) <= tolerance_us(dseq, period)
            ):
                if self._held:
                    self.refused += len(self._held)
                    self._held = []
                return [self._keep(seen, dseq, dt)]
        if self._held and _next_of(self._held[-1], seen):
            self._held.append(seen)
        else:
            self.refused += len(self._held)
            self._held = [seen]
        if len(self._held) < (CONFIRM if ref is not None else CONFIRM_START):
            return []
        chain, self._held = self._held, []
        if ref is None or not _forward(*_steps(ref, chain[0]), chain[0].clock - ref.clock):
            if ref is not None:
                self.new_epoch()  # the board restarted and its $BOOT never came
            first = self._start(chain[0])
        else:
            self._learn_anew()  # the same stream at another period
            first = self._keep(chain[0], *_steps(ref, chain[0]))
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
        s = seen.line
        return (seq, t_us, s.count, s.u_mV, self.epoch, seen.t_host)


__all__ = ["CONFIRM", "CONFIRM_START", "PERIOD_US", "SLACK_S", "Row", "Timeline", "tolerance_us"]
