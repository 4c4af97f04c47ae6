"""Tasks 6-9 from the table of steady-state readings: k_v, k_a and f per row and their medians.

Units: R ohm, u V, omega rad/s, i_ss mA as entered (A inside the formulas), k_v V s/rad,
k_a N m/A, f N m s/rad. Per row of the table

    k_v = (u_ss - R i_ss) / omega_ss        f = k_a i_ss / omega_ss

and the final k_v and f are the medians of the rows, k_a = 0.65 k_v.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal, get_args

import numpy as np

from minseg_tui.model.identify.refusals import (
    IdentifyRefused,
    Measured,
    MedianKvNotPositive,
    NoRows,
    RNotPositive,
    RowImplausible,
    RowNotANumber,
    RowNotPositive,
    RowProblem,
    TableColumn,
)
from minseg_tui.units import KA_OVER_KV


@dataclass(frozen=True)
class Reading:
    """One row of the table: requested u_req (V), u_ss (V), omega_ss (rad/s), i_ss (mA).

    ``line`` is the row's line in its file, for messages (None when typed in).
    """

    u_req: float
    u_ss: float
    omega_ss: float
    i_ss: float
    line: int | None = None

    def problem(self) -> RowProblem | None:
        """What is wrong with this row for Tasks 6-9, as a record (worded by lab/content/
        identify_says.py), or None."""
        values: dict[TableColumn, float] = {
            "u_req": self.u_req,
            "u_ss": self.u_ss,
            "omega_ss": self.omega_ss,
            "i_ss": self.i_ss,
        }
        for name, v in values.items():
            if not math.isfinite(v):
                return RowNotANumber(name, v)
        measured: tuple[Measured, ...] = ("omega_ss", "u_ss", "i_ss")
        for name in measured:
            if values[name] <= 0:
                return RowNotPositive(name, values[name])
        return None


@dataclass(frozen=True)
class Row:
    """A reading with its k_v (V s/rad, Task 6) and f (N m s/rad, Task 9)."""

    reading: Reading
    k_v: float
    f: float


def _check_R(R: float) -> None:
    if not (math.isfinite(R) and R > 0):
        raise IdentifyRefused("--R", None, RNotPositive(R))


def steady_state(
    readings: Sequence[Reading], R: float, source: str = "table"
) -> tuple[tuple[Row, ...], float, float, float]:
    """Tasks 6-9: the rows with k_v and f, and the final (median) k_v, k_a = 0.65 k_v and f.

    Raises :class:`~minseg_tui.model.identify.refusals.IdentifyRefused` for an R that is not
    positive, no rows, a row with a :meth:`Reading.problem`, readings that give no finite
    k_v or f, and a median k_v not above 0."""
    _check_R(R)
    if not readings:
        raise IdentifyRefused(source, None, NoRows())
    for r in readings:
        problem = r.problem()
        if problem:
            raise IdentifyRefused(source, r.line, problem)
    k_v_rows = [(r.u_ss - R * r.i_ss * 1e-3) / r.omega_ss for r in readings]
    k_v = float(np.median(k_v_rows))
    k_a = KA_OVER_KV * k_v
    rows = tuple(
        Row(reading=r, k_v=kv, f=k_a * r.i_ss * 1e-3 / r.omega_ss)
        for r, kv in zip(readings, k_v_rows, strict=True)
    )
    for row in rows:
        if not (math.isfinite(row.k_v) and math.isfinite(row.f)):
            r = row.reading
            implausible = RowImplausible(R * r.i_ss * 1e-3, r.omega_ss, row.k_v, row.f)
            raise IdentifyRefused(source, r.line, implausible)
    if not k_v > 0:  # no motor has it: every figure from here on would be false
        raise IdentifyRefused(source, None, MedianKvNotPositive(k_v))
    f = float(np.median([row.f for row in rows]))
    return rows, k_v, k_a, f


def u_ss_at(table: Sequence[tuple[float, float]], u_req: float) -> tuple[float, UssHow]:
    """The motor driver's mapping from a requested voltage to the one on the motor: u_ss (V)
    for ``u_req`` (V) from the table's ``(u_req, u_ss)`` pairs (V), and how it was found.

    This is the one mapping: the ``u`` column of a recorded run, K of Task 11 and the report
    all use it. Every row with a u_ss counts, whatever else it lacks (omega_ss, i_ss).

    - 'row': a row with that u_req (their mean if several);
    - 'interpolated': a straight line between the nearest rows on either side;
    - 'extrapolated': beyond the rows, u_req less the nearest row's driver drop
      (u_req - u_ss), never past 0 V;
    - 'off': u_req = 0 gives 0 V (the driver is off);
    - 'requested': the table has no u_ss yet, so u_ss = u_req (the drop is not known).

    A negative u_req maps as its size does, with its sign.
    """
    if u_req == 0:
        return 0.0, "off"
    if not table:
        return float(u_req), "requested"
    sign, level = math.copysign(1.0, u_req), abs(u_req)
    pts = sorted((abs(r), s) for r, s in table)
    same = [us for ur, us in pts if abs(ur - level) <= 1e-6 * max(1.0, level)]
    if same:
        return sign * float(np.mean(same)), "row"
    below = [p for p in pts if p[0] < level]
    above = [p for p in pts if p[0] > level]
    if below and above:
        (x0, y0), (x1, y1) = below[-1], above[0]
        return sign * (y0 + (y1 - y0) * (level - x0) / (x1 - x0)), "interpolated"
    x0, y0 = below[-1] if below else above[0]
    return sign * max(level - (x0 - y0), 0.0), "extrapolated"


UssHow = Literal["off", "extrapolated", "requested", "interpolated", "row", "log"]
"""How u_ss was found, a code: one of :func:`u_ss_at`'s, or 'log' (a log without u_req,
whose own u is the voltage on the motor). lab/content/u_ss_says.py says each in words."""

U_SS_HOW: tuple[UssHow, ...] = get_args(UssHow)
"""Every way u_ss is found, least direct first (a median of two found differently is said
the less direct way)."""


def table_of(rows: Sequence[Row]) -> list[tuple[float, float]]:
    """The ``(u_req, u_ss)`` pairs (V) of ``rows``, for :func:`u_ss_at`."""
    return [(row.reading.u_req, row.reading.u_ss) for row in rows]


def omega_ss_at(rows: Sequence[Row], u_req: float) -> float | None:
    """omega_ss (rad/s) the table gives for a requested u_req (V), interpolated between its
    rows; None outside the rows."""
    pts = sorted((row.reading.u_req, row.reading.omega_ss) for row in rows)
    xs = [p[0] for p in pts]
    if not (xs[0] - 1e-9 <= u_req <= xs[-1] + 1e-9):
        return None
    return float(np.interp(u_req, xs, [p[1] for p in pts]))
