"""The virtual multimeter as the lab reads it: what it shows for an entry of each unit, and a
group's reading judged against what it showed.

Only the virtual MinSeg has a multimeter the program can read; on a real board the group
reads the one on the bench, and nothing here is used (the session records nothing, so
nothing is judged this way). What the virtual meter showed is a fact the session records
with the entry typed (:attr:`~minseg_tui.lab.state.entries.Entry.meter`), as plain numbers:
nothing of the device reaches the judging. Pure functions, no state, no I/O.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from minseg_tui.lab.content.steps import Feedback, Field
from minseg_tui.model.plant import MeterReading
from minseg_tui.quantities import format_fixed, format_reading, in_unit, shown_unit


@dataclass(frozen=True)
class Display:
    """How the meter shows a quantity: its ``unit`` (a field's), ``decimals`` in that unit
    (its last digit), and ``mode``, what it is set to for it (as the steps say)."""

    unit: str
    decimals: int
    mode: str

    @property
    def digit(self) -> float:
        """The meter's last digit, SI (0.1 Ω, 0.01 V, 0.1 mA = 1e-4 A)."""
        return 10.0**-self.decimals / in_unit(1.0, self.unit)


DISPLAYS: dict[str, Display] = {
    "Ω": Display("Ω", 1, "on Ω"),
    "V": Display("V", 2, "on V="),
    "mA": Display("mA", 1, "on mA, jumper out"),
}
"""The meter's display for an entry of each unit (Tasks 2, 4 and 5, as their steps say): a
meter shows the one quantity it is set to measure, the current only where the jumper is out;
at 0.1 Ω, 0.01 V and 0.1 mA (:meth:`minseg_tui.model.plant.Plant.multimeter`)."""

SETTLE_S = 0.5
"""A voltage's u_ss and i_ss are taken from the meter only once the request has stood this
long, s: about ten time constants of the virtual motor (43-57 ms), so the current has come
down from its start."""

KEPT = 12
"""How many of the meter's last readings are kept for each entry (3 s at the app's 0.25 s):
the values it flickered between while the group read it."""

SLACK = 0.02
"""How far from what the meter showed a reading may be and still be right, as a share of
it, beyond one last digit: a reading rounded to a digit less (2.1 V for 2.05 V), never a
slip (3.5 Ω for 5.3 Ω, 33.5 mA for 37.2 mA, the 3.5 V row's u_ss typed in the 2.5 V row)."""


def shown(unit: str, reading: MeterReading) -> float:
    """What the meter shows, SI, set for an entry of ``unit`` ("Ω", "V", "mA")."""
    return {"Ω": reading.R, "V": reading.u_A, "mA": reading.i}[unit]


def text(unit: str, value: float) -> str:
    """A value the meter shows (SI) as its display writes it: '5.3 Ω', '2.05 V', '29.9 mA'."""
    d = DISPLAYS[unit]
    return format_fixed(in_unit(value, unit), d.decimals, unit)


def _texts(unit: str, seen: Sequence[float]) -> str:
    lo, hi = min(seen), max(seen)
    if text(unit, lo) == text(unit, hi):
        return text(unit, lo)
    return f"{text(unit, lo).removesuffix(' ' + unit)}-{text(unit, hi)}"


def agrees(fld: Field, value: float, seen: Sequence[float]) -> bool:
    """Whether ``value`` (SI) is what the meter showed for ``fld``: within one last digit and
    :data:`SLACK` of the values it showed (``seen``, SI)."""
    d = DISPLAYS[fld.unit]
    lo, hi = min(seen), max(seen)
    slack = d.digit + SLACK * max(abs(lo), abs(hi))
    return lo - slack <= value <= hi + slack


def judge(fld: Field, value: float, typed: str, seen: Sequence[float]) -> Feedback:
    """The verdict on the group's reading ``value`` (SI, typed as ``typed``) in ``fld`` against
    what the virtual meter showed while they were on its step (``seen``, SI): right, with
    nothing to say (the echo says how it was read), or wrong, saying what the meter showed
    ('wrong: the virtual multimeter showed 5.3 Ω, not 3.5 Ω: read it again')."""
    if agrees(fld, value, seen):
        return Feedback(fld.key, "right", "")
    at = f"at {fld.level:g} V " if fld.level is not None else ""
    meter = _texts(fld.unit, seen)
    yours = format_reading(value, shown_unit(fld.unit), typed=typed)
    return Feedback(
        fld.key,
        "wrong",
        f"✗ wrong: {at}the virtual multimeter showed {meter}, not {yours}: read it again",
        f"the virtual multimeter showed {meter} {at}when the group typed {yours}",
    )


__all__ = ["DISPLAYS", "KEPT", "SETTLE_S", "SLACK", "Display", "agrees", "judge", "shown", "text"]
