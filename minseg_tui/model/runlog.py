"""A recorded run log as data, and where its edges (the changes of the voltage) are.

A run log has one row per sample: time ``t`` (s), the voltage on the motor ``u``
(V, u_A; in force from this row's instant until the next row), the measured speed
``omega`` (rad/s) and any other columns (``u_req`` V, ``theta`` rad, ``count``,
``t_us`` us, ...). The files live in :mod:`minseg_tui.lab.saving.files`; this module is the
data and the arithmetic on it (no I/O).

Two ``# key: value`` header lines have values the format defines (and
:func:`header_problem` checks); other keys are free text:

- ``# cpr:`` encoder counts per wheel revolution, a whole number above 0, at most
  :data:`MAX_CPR`;
- ``# omega_over:`` how omega was computed: ``interval`` (the angle change over each row's
  real sample interval) or ``nominal`` (over the nominal period ts).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Literal, TypeAlias

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui.units import COUNTS_PER_REV

FloatArray = NDArray[np.float64]


MAX_CPR: int = 1_000_000
"""Most encoder counts per revolution a ``# cpr:`` line may claim (a lab motor's encoder
has hundreds to a few ten thousands)."""


@dataclass(frozen=True)
class BadHeader:
    """A header line ``# key: value`` whose value the format does not take: ``key`` 'cpr'
    (not a whole number above 0 and at most :data:`MAX_CPR`) or 'omega_over' (neither
    'interval' nor 'nominal'), and the ``value`` given, stripped. A record, not words:
    lab/content/log_says.py says it."""

    key: Literal["cpr", "omega_over"]
    value: str


def header_problem(key: str, value: str) -> BadHeader | None:
    """Why a header line ``# key: value`` cannot be taken, or None (keys the format does not
    define are free text)."""
    v = value.strip()
    if key == "cpr":
        try:
            n = int(v)
        except ValueError:
            n = 0
        if not 0 < n <= MAX_CPR or str(n) != v.lstrip("+"):
            return BadHeader("cpr", v)
    if key == "omega_over" and v not in ("interval", "nominal"):
        return BadHeader("omega_over", v)
    return None


@dataclass(frozen=True)
class AngleFrom:
    """Where :meth:`RunLog.angle` took the wheel's angle from: the ``column`` 'theta' (rad)
    or 'count' (counts), or 'omega' (rad/s) summed over the sample intervals; ``euler_ts``
    (s): with 'omega', the fixed period it was computed over as an Euler speed of whole
    counts, each row's angle step omega_k euler_ts; None: each row's speed was read as the
    mean over its real interval. A record, not words: lab/content/log_says.py says it."""

    column: Literal["theta", "count", "omega"]
    euler_ts: float | None = None


MEAN_SPEED = AngleFrom("omega")
"""Where :meth:`RunLog.angle` took the angle from when it integrates the omega column over
the real sample intervals (the one source whose angle a stall's gap can leave off for good)."""


@dataclass(frozen=True, eq=False)
class RunLog:
    """One recorded run.

    t: sample times in s (strictly increasing); u: voltage applied to the motor (u_A) in V,
    in force from each row's instant on; omega: measured speed in rad/s (as recorded, for
    instance the mean speed over the previous sample interval); extra: the other columns by
    name (numbers as float or int arrays, text as str arrays); metadata: ``# key: value``
    comment lines; source: where it came from (a file name, for messages); lines: the file
    line (1-based) of each row, or None when the log was not read from a file.
    """

    t: FloatArray
    u: FloatArray
    omega: FloatArray
    extra: Mapping[str, NDArray[Any]] = field(default_factory=dict)
    metadata: Mapping[str, str] = field(default_factory=dict)
    source: str = ""
    lines: NDArray[np.int64] | None = None

    def __post_init__(self) -> None:
        n = len(self.t)
        sizes = {"u": len(self.u), "omega": len(self.omega)}
        sizes.update({k: len(v) for k, v in self.extra.items()})
        if self.lines is not None:
            sizes["lines"] = len(self.lines)
        wrong = {k: v for k, v in sizes.items() if v != n}
        if wrong:
            raise ValueError(f"columns differ in length from t ({n}): {wrong}")

    def __len__(self) -> int:
        return len(self.t)

    @property
    def columns(self) -> list[str]:
        """Column names in file order: t, u, omega, then the extra columns."""
        return ["t", "u", "omega", *self.extra]

    def column(self, name: str) -> NDArray[Any]:
        """A column by name (t, u, omega or an extra one); KeyError if absent."""
        if name in ("t", "u", "omega"):
            col: NDArray[Any] = getattr(self, name)
            return col
        return self.extra[name]

    def line_of(self, row: int) -> int | None:
        """File line (1-based) of row ``row`` (0-based), or None without a file."""
        if self.lines is None or not len(self.lines):
            return None
        return int(self.lines[min(max(row, 0), len(self.lines) - 1)])

    @property
    def ts(self) -> float:
        """Median sample period in s."""
        return float(np.median(np.diff(self.t))) if len(self.t) > 1 else float("nan")

    @property
    def cpr(self) -> int:
        """Encoder counts per wheel revolution: metadata ``cpr`` if given, else 720."""
        try:
            return int(self.metadata.get("cpr", COUNTS_PER_REV))
        except ValueError:
            return COUNTS_PER_REV

    @property
    def declared_cpr(self) -> int | None:
        """Counts per revolution when the log says (``# cpr:``), else None."""
        v = self.metadata.get("cpr")
        return None if v is None or header_problem("cpr", v) else int(v)

    @property
    def omega_over(self) -> str | None:
        """'interval' or 'nominal' when the log says how omega was computed
        (``# omega_over:``), else None."""
        v = self.metadata.get("omega_over")
        return None if v is None or header_problem("omega_over", v) else v.strip()

    def rows_from(self, first: int) -> RunLog:
        """The same log without its first ``first`` rows (file lines and metadata kept)."""
        return RunLog(
            t=self.t[first:],
            u=self.u[first:],
            omega=self.omega[first:],
            extra={k: v[first:] for k, v in self.extra.items()},
            metadata=self.metadata,
            source=self.source,
            lines=None if self.lines is None else self.lines[first:],
        )

    def board_time(self) -> FloatArray:
        """Sample times in s on the board's clock: from ``t_us`` when the log has it.

        ``t_us`` is the board's micros() (uint32, wraps after 71.6 min); it is unwrapped and
        placed so that the first row keeps its ``t``. Without ``t_us`` this is ``t``.
        """
        if "t_us" not in self.extra:
            return np.asarray(self.t, dtype=float)
        us = np.asarray(self.extra["t_us"], dtype=np.float64)
        d = np.mod(np.diff(us), 2.0**32)
        return float(self.t[0]) + np.concatenate(([0.0], np.cumsum(d))) * 1e-6

    def angle(self) -> tuple[FloatArray, AngleFrom]:
        """The wheel angle in rad at each row, and where it came from.

        From ``theta`` if present, else from ``count`` (``cpr`` counts per revolution), else
        rebuilt from ``omega`` read as the mean speed over each sample interval (the Euler
        velocity): theta_k = theta_k-1 + omega_k dt_k. dt_k is the nominal sample period when
        omega is the manual's Euler derivative at a fixed Ts (every omega_k Ts is then a whole
        number of counts), else the interval t_k - t_k-1.
        """
        if "theta" in self.extra and self.extra["theta"].dtype.kind in "fi":
            return np.asarray(self.extra["theta"], dtype=float), AngleFrom("theta")
        if "count" in self.extra and self.extra["count"].dtype.kind in "fi":
            th = np.asarray(self.extra["count"], dtype=float) * (2.0 * np.pi / self.cpr)
            return th, AngleFrom("count")
        t = self.board_time()
        w = np.asarray(self.omega[1:], float)
        ts = _euler_period(w, np.diff(t), 2.0 * np.pi / self.cpr)
        if ts is not None:
            dth = np.concatenate(([0.0], w * ts))
            return np.cumsum(dth), AngleFrom("omega", ts)
        dth = np.concatenate(([0.0], w * np.diff(t)))
        return np.cumsum(dth), MEAN_SPEED


def _euler_period(w: FloatArray, dt: FloatArray, q: float) -> float | None:
    """The fixed period Ts (s) with which ``w`` (rad/s) was computed as whole encoder counts
    of ``q`` rad per sample, if it was (nearly every w Ts / q within 0.001 of a whole
    number while the wheel turns); None otherwise. ``dt``: the sample intervals (s)."""
    moving = np.abs(w) > 0
    if np.count_nonzero(moving) < 3 or dt.size != w.size:
        return None
    guess = float(np.median(dt))
    counts = np.round(np.abs(w[moving]) * guess / q)
    if not np.all(counts >= 1):
        return None
    ts = float(np.median(q * counts / np.abs(w[moving])))
    x = np.abs(w[moving]) * ts / q
    whole = np.abs(x - np.round(x)) <= 1e-3
    return ts if np.mean(whole) >= 0.99 else None


@dataclass(frozen=True)
class Edge:
    """An edge of the command: rows ``start``..``end`` (0-based) carry the change.

    ``start`` is the first row at the new level (the edge happens at t[start]); before and
    after are the levels in V on either side; rising when after > before.
    """

    start: int
    end: int
    before: float
    after: float

    @property
    def rising(self) -> bool:
        """True for a rising edge."""
        return self.after > self.before


MIN_EDGE_V: float = 0.05
"""Smallest change of the command, in V, that counts as an edge."""


def _changes(v: FloatArray, small: float) -> list[tuple[int, int]]:
    """Runs (first, last) of rows whose change from the previous row exceeds ``small``,
    grouping consecutive changes of the same sign."""
    d = np.diff(v)
    big = np.abs(d) > small
    sign = np.sign(d)
    goes_on = np.zeros(d.size, dtype=bool)  # a change that continues the run before it
    goes_on[1:] = big[1:] & big[:-1] & (sign[1:] == sign[:-1])
    firsts = np.flatnonzero(big & ~goes_on)
    lasts = np.flatnonzero(big & ~np.concatenate((goes_on[1:], [False])))
    return [(int(a) + 1, int(b) + 1) for a, b in zip(firsts, lasts, strict=True)]


def find_edges(u: FloatArray) -> list[Edge]:
    """Edges of a command ``u`` (V): changes of at least 30 % of its range (and 0.05 V),
    done within a few rows. A ramp or noise is not an edge."""
    v = np.asarray(u, dtype=float)
    if v.size < 2:
        return []
    span = float(np.max(v) - np.min(v))
    if span < MIN_EDGE_V:
        return []
    edges = []
    for first, last in _changes(v, 0.1 * span):
        before, after = float(v[first - 1]), float(v[last])
        if abs(after - before) >= max(0.3 * span, MIN_EDGE_V) and last - first < 3:
            edges.append(Edge(first, last, before, after))
    return edges


def segment_end(u: FloatArray, edge: Edge) -> int:
    """Last row (0-based, inclusive) at the level the edge reached: the row before the
    command first departs from that level by more than 3 % of its range, or the last row.
    (A level, not a per-row change: at a coasting stop the motor voltage slides away.)"""
    v = np.asarray(u, dtype=float)
    span = float(np.max(v) - np.min(v))
    away = np.flatnonzero(np.abs(v[edge.end :] - edge.after) > 0.03 * span)
    return edge.end + int(away[0]) - 1 if away.size else v.size - 1


def command(log: RunLog) -> tuple[FloatArray, str]:
    """The column whose edges define the experiment: ``u_req`` when the log has it (clean
    even when the motor coasts), else ``u``; and its name."""
    if "u_req" in log.extra and log.extra["u_req"].dtype.kind in "fi":
        return np.asarray(log.extra["u_req"], dtype=float), "u_req"
    return np.asarray(log.u, dtype=float), "u"


MIN_ROWS: int = 8
"""Fewest rows an analysis of a run log works on."""

TS_RANGE: tuple[float, float] = (1e-4, 1.0)
"""Sample periods (s) an analysis accepts: the board samples every 2-100 ms."""

MAX_MAGNITUDE: float = 1e6
"""Largest |u| (V) and |omega| (rad/s) an analysis accepts (the lab's are below 10)."""


Column: TypeAlias = Literal["t", "u", "omega"]
"""A run log's three columns every analysis reads: t (s), u (V), omega (rad/s)."""

COLUMN_UNITS: Mapping[Column, str] = MappingProxyType({"t": "s", "u": "V", "omega": "rad/s"})
"""The unit of each of the three columns every run log has, in the file's column order."""


@dataclass(frozen=True)
class UnequalColumns:
    """t, u and omega of different lengths: the rows of each."""

    t: int
    u: int
    omega: int


@dataclass(frozen=True)
class TooFewRows:
    """Fewer than :data:`MIN_ROWS` rows: the ``rows`` the log has."""

    rows: int


@dataclass(frozen=True)
class NotFinite:
    """A value of ``column`` that is not a finite number (NaN or infinite)."""

    column: Column


@dataclass(frozen=True)
class TooLarge:
    """A value of ``column`` (u in V, omega in rad/s) whose size is above
    :data:`MAX_MAGNITUDE`: ``largest``, the largest |value|."""

    column: Literal["u", "omega"]
    largest: float


@dataclass(frozen=True)
class TimeNotIncreasing:
    """A time t (s) that does not increase from one row to the next."""


@dataclass(frozen=True)
class PeriodOutOfRange:
    """A sample ``period`` (s), given or the median interval of t, outside
    :data:`TS_RANGE`."""

    period: float


@dataclass(frozen=True)
class SpeedStill:
    """A speed that never changes: ``omega`` (rad/s) on every row, or on every row after the
    first ``glitch`` rows, a switch-on glitch (0: none)."""

    omega: float
    glitch: int = 0


LogProblem: TypeAlias = (
    UnequalColumns
    | TooFewRows
    | NotFinite
    | TooLarge
    | TimeNotIncreasing
    | PeriodOutOfRange
    | SpeedStill
)
"""Why a run log cannot be analysed (:func:`problem`): a record with the figures its words
need, not words (lab/content/log_says.py says it)."""


def problem(
    t: ArrayLike, u: ArrayLike, omega: ArrayLike, ts: float | None = None
) -> LogProblem | None:
    """Why a run log cannot be analysed (Tasks 11-15, the model check), or None.

    t: sample times, s; u: applied voltage, V; omega: measured speed, rad/s; ts: the nominal
    sample period, s (default: the median interval of t). Refused: unequal lengths, fewer
    than MIN_ROWS rows, values that are not finite or not of a plausible size, time that
    does not increase, a sample period outside TS_RANGE, and a speed that never changes.
    """
    t, u, y = (np.asarray(a, dtype=float) for a in (t, u, omega))
    if not (t.size == u.size == y.size):
        return UnequalColumns(t.size, u.size, y.size)
    if t.size < MIN_ROWS:
        return TooFewRows(t.size)
    columns: tuple[tuple[Column, FloatArray], ...] = (("t", t), ("u", u), ("omega", y))
    for name, v in columns:
        if not np.all(np.isfinite(v)):
            return NotFinite(name)
    sized: tuple[tuple[Literal["u", "omega"], FloatArray], ...] = (("u", u), ("omega", y))
    for size_name, v in sized:
        if float(np.max(np.abs(v))) > MAX_MAGNITUDE:
            return TooLarge(size_name, float(np.max(np.abs(v))))
    if not np.all(np.diff(t) > 0):
        return TimeNotIncreasing()
    period = float(np.median(np.diff(t))) if ts is None else float(ts)
    lo, hi = TS_RANGE
    if not (lo <= period <= hi):
        return PeriodOutOfRange(period)
    if float(np.ptp(y)) == 0.0:
        return SpeedStill(float(y[0]))
    return None


MAX_GLITCH_ROWS: int = 3
"""Most rows at the start of a log that are taken for switch-on glitches."""


def speed_lag(t: ArrayLike, omega: ArrayLike, theta: ArrayLike) -> float | None:
    """How late (s) a log's speed column runs behind its angle column: the speed summed over
    the sample intervals (each row's speed times its interval) falls behind the angle by the
    speed times this lag, fitted by least squares over the rows where the speed is above half
    its largest. A speed that is the mean over each interval (the angle's difference over it)
    sums to the angle itself: 0 (eight of the ten logs in ../shared, within 1 us); a filtered
    speed, or one a driver estimates on its own (ev3dev's ``speed`` attribute: 8.8-12.7 ms at
    6.3-6.5 ms a sample), lags. A speed over a nominal period on rows logged further apart
    sums ahead of the angle, a negative lag (the two n20-12v logs: -9 and -31 ms, their 11 ms
    rows). t: s; omega: rad/s; theta: rad. None when the speed never moves."""
    tt = np.asarray(t, dtype=float)
    w = np.asarray(omega, dtype=float)
    th = np.asarray(theta, dtype=float)
    if tt.size < 3:
        return None
    summed = np.concatenate(([th[0]], th[0] + np.cumsum(w[1:] * np.diff(tt))))
    moving = np.abs(w) > 0.5 * float(np.max(np.abs(w)))
    if not np.any(moving) or not float(np.max(np.abs(w))) > 0:
        return None
    ww = w[moving]
    return float(np.dot(th[moving] - summed[moving], ww) / np.dot(ww, ww))


def switch_on_glitches(u: ArrayLike, omega: ArrayLike) -> int:
    """How many rows at the very start of a log are switch-on glitches (0 when none).

    u: the command or applied voltage (V); omega: the measured speed (rad/s). A glitch row is
    one of the first :data:`MAX_GLITCH_ROWS` rows, before the command first changes, whose
    speed departs from the speed of the rest of that first level (their median) by more than
    the largest departure any later row of the log shows from it (after a 5-row running median,
    which takes out a logging stall's spike and the row that catches up after it): a reading
    above every steady
    speed the motor reaches, at a voltage that holds still. Only an unbroken run from row 0
    counts, or from row 1 after a first row of exactly 0 (a speed from counts has none there;
    the count includes that row), and at least three rows of the first level must remain.
    """
    v = np.asarray(u, dtype=float)
    w = np.asarray(omega, dtype=float)
    if w.size < 2 * MAX_GLITCH_ROWS + 8:
        return 0
    moved = np.flatnonzero(np.abs(v - v[0]) > max(MIN_EDGE_V, 1e-9))
    first_level = int(moved[0]) if moved.size else v.size
    if first_level < MAX_GLITCH_ROWS + 3:
        return 0
    level = float(np.median(w[MAX_GLITCH_ROWS:first_level]))
    rest = w[MAX_GLITCH_ROWS:]
    n = rest.size
    # a 5-row running median: a stall's spike and the catch-up row after it are out
    smooth = np.median(np.stack([rest[k : n - 4 + k] for k in range(5)]), axis=0)
    later = float(np.max(np.abs(smooth - level)))
    far = np.abs(w[:MAX_GLITCH_ROWS] - level) > max(later, 1e-9)
    # a zeroed first row (a speed from counts has no sample before row 0, and loggers write 0
    # there) may stand before the run: it is left out with the glitches after it
    n = 1 if w[0] == 0.0 and not far[0] and far[1] else 0
    while n < MAX_GLITCH_ROWS and far[n]:
        n += 1
    # a glitch run ends before the rows that hold the level: anything left after it within
    # the first MAX_GLITCH_ROWS must not be far
    return n if not np.any(far[n:]) else 0


def zeroed_first_row(omega: ArrayLike, glitches: int) -> bool:
    """Whether the first of ``glitches`` switch-on rows (:func:`switch_on_glitches`) is a
    zeroed first row, a speed of exactly 0 before the glitch rows, not a glitch itself."""
    w = np.asarray(omega, dtype=float)
    return glitches >= 2 and w[0] == 0.0 and w[1] != 0.0


CLOCK_AGREE: float = 0.02
"""How far (relative) the board's clock ``t_us`` may run from the ``t`` column over a log: a
board's resonator is good to 0.5 %, a host's time of reception jitters by milliseconds."""


@dataclass(frozen=True)
class ClockApart:
    """A ``t_us`` column that does not keep time with ``t`` (:func:`clock_problem`): how
    far each advances over the log, ``span_us`` and ``span_t``, in s."""

    span_us: float
    span_t: float


def clock_problem(t: ArrayLike, t_us: ArrayLike) -> ClockApart | None:
    """Why a ``t_us`` column (the board's micros(), us) cannot be the clock of the ``t`` column
    (s), or None: over the log the two must advance by the same time within
    :data:`CLOCK_AGREE` (or two median sample intervals of t, on a short log). (identify fits
    on t_us, the model check on t: a t_us that runs 10 times faster gave a T 10 times shorter
    from one command than the other.)"""
    tt = np.asarray(t, dtype=float)
    us = np.asarray(t_us, dtype=float)
    if tt.size < 2 or us.size != tt.size:
        return None
    span_t = float(tt[-1] - tt[0])
    span_us = float(np.sum(np.mod(np.diff(us), 2.0**32))) * 1e-6
    slack = max(CLOCK_AGREE * span_t, 2.0 * float(np.median(np.diff(tt))))
    if not span_t > 0 or abs(span_us - span_t) <= slack:
        return None
    return ClockApart(span_us, span_t)


@dataclass(frozen=True)
class StillAngle:
    """A wheel whose angle, taken from ``source``, never changes in the log: nothing to fit
    T, K and J to."""

    source: AngleFrom


Refusal: TypeAlias = LogProblem | ClockApart | StillAngle
"""Why an analysis refuses a run log, as a record (:class:`LogRefused`)."""


class LogRefused(Exception):
    """An analysis's refusal of a run log at ``source`` (a file name, '' for arrays) and
    ``line`` (1-based, or None), and ``why`` (a :data:`Refusal` record). A record, not
    words: the layer that shows it says it as an InputError (lab/content/log_says.py)."""

    def __init__(self, source: str, line: int | None, why: Refusal) -> None:
        super().__init__(source, line, why)
        self.source = source
        self.line = line
        self.why = why
