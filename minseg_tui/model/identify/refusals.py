"""identify's refusals as records (issue 19 items 3-4: the model gives records, the words
are written outside it): a row of the table, R, the table as a whole, and a run log without a
usable rising edge. The model raises them as :class:`IdentifyRefused`; lab/content/
identify_says.py says each as the one line the CLI, the session and the report show.

Units as the table's: u_req and u_ss V, omega_ss rad/s, i_ss mA, R ohm, k_v V s/rad,
f N m s/rad.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, TypeAlias

TableColumn: TypeAlias = Literal["u_req", "u_ss", "omega_ss", "i_ss"]
"""A column of the table of steady-state readings (Tasks 4-5)."""

Measured: TypeAlias = Literal["omega_ss", "u_ss", "i_ss"]
"""The readings of a row that must be above 0 to give k_v and f."""


@dataclass(frozen=True)
class RowNotANumber:
    """A row's ``column`` whose ``value`` is not a finite number (nan or inf)."""

    column: TableColumn
    value: float


@dataclass(frozen=True)
class RowNotPositive:
    """A row's ``column`` (u_ss V, omega_ss rad/s or i_ss mA) at or below 0: ``value``.
    A zero speed gives no k_v or f; u_ss and i_ss are what was measured on the motor."""

    column: Measured
    value: float


RowProblem: TypeAlias = RowNotANumber | RowNotPositive
"""What is wrong with one row for Tasks 6-9 (:meth:`~minseg_tui.model.identify.steady.
Reading.problem`)."""


@dataclass(frozen=True)
class RNotPositive:
    """An R (ohm) that is not a positive finite number."""

    R: float


@dataclass(frozen=True)
class NoRows:
    """A table without a row."""


@dataclass(frozen=True)
class RowImplausible:
    """A row whose readings give no finite k_v or f: the drop ``R_i_ss`` = R i_ss (V), its
    ``omega_ss`` (rad/s), and the ``k_v`` (V s/rad) and ``f`` (N m s/rad) they give."""

    R_i_ss: float
    omega_ss: float
    k_v: float
    f: float


@dataclass(frozen=True)
class MedianKvNotPositive:
    """Rows whose median ``k_v`` (V s/rad) is not above 0: u_ss - R i_ss is not above 0 on
    enough of them (R or i_ss misread, no motor has it)."""

    k_v: float


@dataclass(frozen=True)
class NoRisingEdge:
    """A run log whose command ``column`` (u_req, else u) has no usable rising edge: one
    with at least a sample before it and ``after`` samples after it. ``rising`` is how many
    rising edges it has, none usable; ``reverse``: with none, the levels (V) of its first
    step from rest into negative voltage, a run in reverse (None otherwise)."""

    column: str
    after: int
    rising: int
    reverse: tuple[float, float] | None = None


@dataclass(frozen=True)
class RiseNotFitted:
    """A log whose usable rises give no fit (cannot happen once :class:`NoRisingEdge` and a
    wheel that never turns are refused; keeps the types honest)."""


IdentifyRefusal: TypeAlias = (
    RowProblem
    | RNotPositive
    | NoRows
    | RowImplausible
    | MedianKvNotPositive
    | NoRisingEdge
    | RiseNotFitted
)
"""Why identify refuses a table, R or a run log, as a record (:class:`IdentifyRefused`)."""


class IdentifyRefused(Exception):
    """identify's refusal at ``source`` (a file name, 'table', or '--R') and ``line`` (1-based,
    or None), and ``why`` (an :data:`IdentifyRefusal` record). A record, not words: the layer
    that shows it says it as an InputError (lab/content/identify_says.py)."""

    def __init__(self, source: str, line: int | None, why: IdentifyRefusal) -> None:
        super().__init__(source, line, why)
        self.source = source
        self.line = line
        self.why = why


__all__ = [
    "IdentifyRefusal",
    "IdentifyRefused",
    "Measured",
    "MedianKvNotPositive",
    "NoRisingEdge",
    "NoRows",
    "RNotPositive",
    "RiseNotFitted",
    "RowImplausible",
    "RowNotANumber",
    "RowNotPositive",
    "RowProblem",
    "TableColumn",
]
