"""Constants of the MinSeg hardware, with their units; and how a number is written with one.

:func:`format_number` and :func:`format_value` are the one way numbers are written for
people (the TUI, the report): a fixed count of significant digits, trailing zeros kept
(K = 1.996 rad/s/V, never "2"; 2.50, never "2.5"). :func:`join_units` marks where a line
must not break (between a number and its unit, inside a unit of several words) so that a
screen that wraps text keeps "2.216 mN m s/rad" on one line.
"""

from __future__ import annotations

import math
import re

COUNTS_PER_REV: int = 720
"""Encoder counts per wheel revolution (x4 quadrature decoding, 48 x gear ratio 15)."""

RAD_PER_COUNT: float = 2.0 * math.pi / COUNTS_PER_REV
"""Wheel angle per encoder count, rad (the scaling gain of Preparation 10)."""

LAB_TS: float = 0.025
"""The manual's sample period, s."""

LAB_FIR_TAPS: int = 20
"""Length of the manual's moving-average velocity filter (coefficients 0.05), samples."""

RPM: float = 2.0 * math.pi / 60.0
"""One revolution per minute in rad/s (a speed typed in rpm where rad/s was asked)."""

KA_OVER_KV: float = 0.65
"""The manual's ratio k_a / k_v (equation 3.3)."""

NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\Z")
"""A number as a lab file or a command-line option writes it: ASCII decimal, no
underscores, no nan or inf (Python's float() and int() also read ``3_6`` as 36, and
Arabic-Indic or full-width digits, which no one means there)."""


DIGITS: int = 4
"""Significant digits of a computed value on screen and in the report."""

NO_BREAK = "\u00a0"
"""A space a line must not break at (NO-BREAK SPACE)."""

DISPLAY_UNITS: tuple[str, ...] = (
    "mN m s/rad",
    "N m s/rad",
    "V s/rad",
    "N m/A",
    "mN m",
    "N m",
    "kg m^2",
    "rad/s/V",
    "rad/s",
    "rad",
    "rpm",
    "mV",
    "V",
    "mA",
    "A",
    "kΩ",
    "Ω",
    "ohm",
    "ms",
    "s",
    "min",
    "°C/W",
    "°C",
    "%",
)
"""Units as this program writes them (longest first), for :func:`join_units`."""

_UNIT_RE = re.compile(
    r"(?<![\w.])(-?\d[\d.,]*(?:e[-+]?\d+)?(?:\.\.-?\d[\d.,]*(?:e[-+]?\d+)?)?) "
    r"(" + "|".join(re.escape(u) for u in DISPLAY_UNITS) + r")(?![\w/^])"
)


def format_number(value: float, digits: int = DIGITS) -> str:
    """``value`` with ``digits`` significant digits, trailing zeros kept and no exponent
    for 1e-4 <= |value| < 1e6 (1.996, 2.000, 0.04270, 1235); '—' when it is not finite."""
    if not math.isfinite(value):
        return "—"
    if value == 0:
        return "0"
    rounded = float(f"{value:.{digits - 1}e}")  # the exponent after rounding (9.9996 -> 10.00)
    exponent = math.floor(math.log10(abs(rounded)))
    if exponent < -4 or exponent >= 6:
        return f"{value:.{digits - 1}e}"
    decimals = max(digits - 1 - exponent, 0)
    return f"{rounded:.{decimals}f}"


NO_WIDTH = "not determined: the interval has no width"
"""What an interval whose ends are one number says instead of 'x – x'."""


def format_interval(
    lo: float, hi: float, unit: str = "", digits: int = DIGITS, sep: str = " – "
) -> str:
    """A finite interval (lo, hi) in ``unit``: its ends with ``digits`` significant digits,
    or with as many more as it takes to tell them apart, so that a narrow interval shows its
    real width ("12.3004 – 12.3012 rad/s/V", never "12.30 – 12.30"); an interval without
    width (lo == hi) is :data:`NO_WIDTH`."""
    if not hi > lo:
        return NO_WIDTH
    a, b = format_number(lo, digits), format_number(hi, digits)
    d = digits
    while a == b and d < 17:
        d += 1
        a, b = format_number(lo, d), format_number(hi, d)
    return f"{a}{sep}{b} {unit}".rstrip()


def format_value(value: float | None, unit: str = "", digits: int = DIGITS) -> str:
    """``value`` (already in ``unit``) with ``digits`` significant digits and its unit:
    ``format_value(1.9962, "rad/s/V") == "1.996 rad/s/V"``; '—' for None or not finite."""
    if value is None or not math.isfinite(value):
        return "—"
    return f"{format_number(value, digits)} {unit}".rstrip()


def join_units(text: str) -> str:
    """``text`` with a no-break space between every number and the unit after it and inside
    units of several words ("2.216 mN m s/rad" stays one piece when a line is wrapped)."""

    def joined(m: re.Match[str]) -> str:
        return m.group(1) + NO_BREAK + m.group(2).replace(" ", NO_BREAK)

    return _UNIT_RE.sub(joined, text)
