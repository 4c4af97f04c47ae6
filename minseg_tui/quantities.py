"""Quantities: the units, how a typed value is read, and how a number is written for people.

Written (:func:`format_number`, :func:`format_value`, :func:`format_quantity`): the one way
numbers are written for people (the TUI, the report, the CLI): a fixed count of significant
digits, trailing zeros kept (K = 1.996 rad/s/V, never "2"; 2.50, never "2.5"); a reading
keeps the digits it was typed with (:func:`format_reading`). :func:`join_units` marks where a
line must not break (between a number and its unit, inside a unit of several words) so that
a screen that wraps text keeps "2.216 mN m s/rad" on one line.

Read: what a student types, read as a quantity in SI units, or refused with one line.

A field has a *form unit* (the unit its label shows, e.g. mA for i_ss); a bare number
is read in that unit. A number with a unit is converted when the unit measures the same
thing (``0.047 A`` in a mA field is 0.047 A), and refused when it does not (``4.7 V`` in
a mA field). Values come back in SI: volts, amperes, ohms, rad/s, seconds.

Accepted, for every field:

- a decimal point or a decimal comma: ``4.7``, ``4,7``; a leading ``+``; an exponent
  (``1.3e-3``, ``1,3e-3``);
- the unit after the number, with or without a space: ``4.7 V``, `` 4.7V ``, ``47mA``;
  units are read case-insensitively (``ma``, ``OHM``), with two exceptions that
  keep their case: ``MΩ`` (megaohm, what an open circuit shows) against ``mΩ``;
- Ω written as ``Ω`` (U+03A9 or U+2126), ``ohm`` or ``ohms``.

Refused, with a message saying what was expected:

- empty text, text that is not a number, ``nan``, ``inf``, a number too large to be finite,
  or one far beyond any value of its quantity in this lab (:data:`CEILING`: ``1e308`` V),
  or, for a meter's reading, one outside what the meter shows (``within``: ``1e9`` Ω);
- two numbers (``4.7 5.2``, ``1,234.5``, ``4.7.1``);
- a unit of another quantity (``4.7 V`` for a current) or an unknown unit;
- a prefix without its unit: ``3k`` is refused (write ``3 kΩ``), because a lone letter
  after a number is as often a typo as a prefix;
- a negative number (or zero) where the field cannot be negative (or zero);
- **a bare number below 1 in a mA field** (``0.047`` for i_ss): the lab's currents are
  20-50 mA, so such a number is most likely amperes typed without the unit, but it could
  also be a real reading in mA; rather than guess, it is refused and the message asks for
  ``47 mA`` or ``0.047 A``. An explicit ``0.047 A`` or ``0.5 mA`` is accepted. A bare
  number below 0.05 in a mN m s/rad field (f typed in N m s/rad, ``0.00186``) is refused
  the same way, a bare number above 1 in a field in s (T typed in ms, ``57``), and one
  below 1 in a field in ms (Task 12's T typed in s, ``0.057``) (:data:`_BARE`).

Plausibility is separate from parsing: :class:`Plausible` ranges on a field give warnings
(data, not refusals), e.g. R outside 1-20 ohm.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation

from minseg_tui.errors import InputError

RPM: float = 2.0 * math.pi / 60.0
"""One revolution per minute in rad/s (a speed typed in rpm where rad/s was asked)."""

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


MISSING = "—"
"""The mark of a value that is not there (a cell, a reading, a figure): the em dash. The en
dash '–' has the other meaning, the one that joins a range's ends ('42.10 – 43.02 ms')."""


def format_number(value: float | None, digits: int = DIGITS) -> str:
    """``value`` with ``digits`` significant digits, trailing zeros kept and no exponent
    for 1e-4 <= |value| < 1e6 (1.996, 2.000, 0.04270, 1235); :data:`MISSING` for None or
    a value that is not finite."""
    if value is None or not math.isfinite(value):
        return MISSING
    if value == 0:
        return "0"
    rounded = float(f"{value:.{digits - 1}e}")  # the exponent after rounding (9.9996 -> 10.00)
    exponent = math.floor(math.log10(abs(rounded)))
    if exponent < -4 or exponent >= 6:
        return f"{value:.{digits - 1}e}"
    decimals = max(digits - 1 - exponent, 0)
    return f"{rounded:.{decimals}f}"


def format_signed(value: float, digits: int = DIGITS) -> str:
    """:func:`format_number` with its sign always written: a shift or a difference (+1.20,
    -0.0350; 0 stays "0")."""
    text = format_number(value, digits)
    return f"+{text}" if value > 0 and math.isfinite(value) else text


def format_percent(fraction: float) -> str:
    """A share or a relative difference (``fraction``, 0.17 for 17 %) in whole percent, as
    the sentences about the numbers write it: "17 %"."""
    return f"{fraction * 100:.0f} %"


def format_diff(rel: float) -> str:
    """A relative difference (``rel``, 0.39 for 39 %) as the group reads it: "+39 %", "-2 %";
    under 0.5 % with one more digit ("+0.3 %"); under 0.05 % as "0 %", never "+0 %": the
    same number (9.65 typed, 5 V x 1.93 computed) and one the same to the digits shown (1.95
    typed, 7.9 / 4.05 = 1.9506 computed) both match, and read alike."""
    pct = rel * 100.0
    if abs(pct) >= 0.5:
        return f"{pct:+.0f} %"
    if abs(pct) >= 0.05:
        return f"{pct:+.1f} %"
    return "0 %"


def format_difference(
    own: float | str | None, computed: float | str | None, digits: int = DIGITS
) -> str:
    """The group's value ``own`` against the value ``computed`` their way (same unit) as
    :func:`format_diff` writes it, taken from the two numbers as they stand side by side:
    ``computed`` to the ``digits`` it is shown with (:func:`format_number`). J typed 0.00182
    beside 0.001819 reads "+0.1 %" (the full 0.0018192 is 0.04 % off and read "0 %"); 9.65
    beside 9.650 reads "0 %". The one formatter of a difference on the screens, in the
    report and in the class view; a grade keeps the full value. :data:`MISSING` unless both
    are numbers and ``computed`` is not 0."""
    if not isinstance(own, int | float) or not isinstance(computed, int | float) or not computed:
        return MISSING
    shown = float(format_number(computed, digits)) if math.isfinite(computed) else computed
    return format_diff(own / (shown or computed) - 1.0)


def format_fixed(value: float, decimals: int, unit: str = "") -> str:
    """``value`` (already in ``unit``) with a fixed number of ``decimals``, as an instrument or
    a clock shows it: the virtual multimeter ("2.05 V", "29.8 mA"), a live mean ("3.82"), a
    run's seconds ("4.2 of 8.0 s"), a board time ("4.625 s")."""
    return f"{value:.{decimals}f} {unit}".rstrip()


def format_spread(spread: float, unit: str = "") -> str:
    """The spread of a captured speed around its mean, as the live readout, the table and
    the report write it: "± 0.03 rad/s" (two decimals, the speed's in rad/s)."""
    return f"± {format_fixed(spread, 2, unit)}"


def format_ticks(values: Sequence[float]) -> list[str]:
    """The labels of evenly spaced axis ticks, on the screen's plots and the report's
    figures alike: as many decimals as their step and values need (a step of 2.5 one more
    than 2), the same for every tick (0.0, 0.5, 1.0), never '-0'."""
    if len(values) < 2:
        return [f"{v:g}" for v in values]
    step = values[1] - values[0]
    least = max(0, -math.floor(math.log10(step) + 1e-9))
    decimals = next(
        (
            d
            for d in range(least, least + 4)
            if all(abs(round(v, d) - v) < step * 1e-6 for v in values)
        ),
        least + 4,
    )
    return [f"{round(v, decimals) + 0.0:.{decimals}f}" for v in values]


NO_WIDTH = "not determined: the interval has no width"
"""What an interval whose ends are one number says instead of 'x – x'."""

NOT_DETERMINED = "not determined by this log"
"""What a 95 % interval the log does not determine says instead of numbers."""


def format_interval(
    lo: float, hi: float, unit: str = "", digits: int = DIGITS, sep: str = " – "
) -> str:
    """A finite interval (lo, hi) in ``unit``: its ends with ``digits`` significant digits,
    or with as many more as it takes to tell them apart, so that a narrow interval shows its
    real width ("12.3004 – 12.3012 rad/s/V", never "12.30 – 12.30"); an interval without
    width (lo == hi) is :data:`NO_WIDTH`; an end the log does not bound (infinite) is said."""
    if not (math.isfinite(lo) and math.isfinite(hi)):
        if math.isfinite(lo):
            return f"{format_number(lo, digits)} {unit} or more: no upper bound from this log"
        if math.isfinite(hi):
            return f"up to {format_number(hi, digits)} {unit}: no lower bound from this log"
        return "not bounded by this log"
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
    ``format_value(1.9962, "rad/s/V") == "1.996 rad/s/V"``; :data:`MISSING` for None or not
    finite."""
    if value is None or not math.isfinite(value):
        return MISSING
    return f"{format_number(value, digits)} {unit}".rstrip()


def axis_label(name: str, unit: str) -> str:
    """A plot axis's label on screen: the quantity, then its unit in brackets ('t [s]');
    :func:`axis_unit` reads the unit back."""
    return f"{name} [{unit}]"


def axis_unit(label: str) -> str | None:
    """The unit of an :func:`axis_label` ('omega [rad/s]' -> 'rad/s'); None for a label
    without one."""
    unit = re.search(r"\[(.+)\]", label)
    return unit.group(1) if unit else None


def printed_label(name: str, unit: str) -> str:
    """A quantity with its unit as a sentence names it, in parentheses ('expected t (s) to
    increase'); a plot's axis, on screen or in the report, is an :func:`axis_label`."""
    return f"{name} ({unit})"


TIME_AXIS = axis_label("t", "s")
"""The time axis of every plot on screen: seconds into the run."""

SPEED_AXIS = axis_label("omega", "rad/s")
"""The speed axis of the plots on screen that show the wheel's speed."""


def join_units(text: str) -> str:
    """``text`` with a no-break space between every number and the unit after it and inside
    units of several words ("2.216 mN m s/rad" stays one piece when a line is wrapped)."""

    def joined(m: re.Match[str]) -> str:
        return m.group(1) + NO_BREAK + m.group(2).replace(" ", NO_BREAK)

    return _UNIT_RE.sub(joined, text)


@dataclass(frozen=True)
class Unit:
    """A unit: its display ``symbol``, what it measures, and ``scale`` (SI value per unit)."""

    symbol: str
    quantity: str
    scale: float
    spellings: tuple[str, ...]


_UNITS: tuple[Unit, ...] = (
    Unit("V", "voltage", 1.0, ("v", "volt", "volts")),
    Unit("mV", "voltage", 1e-3, ("mv", "millivolt", "millivolts")),
    Unit("A", "current", 1.0, ("a", "amp", "amps", "ampere", "amperes")),
    Unit("mA", "current", 1e-3, ("ma", "milliamp", "milliamps", "milliampere", "milliamperes")),
    Unit("µA", "current", 1e-6, ("µa", "μa", "ua")),
    Unit("Ω", "resistance", 1.0, ("Ω", "ohm", "ohms")),
    Unit("kΩ", "resistance", 1e3, ("kΩ", "kohm", "kohms")),
    Unit("MΩ", "resistance", 1e6, ("MΩ", "Mohm", "Mohms")),
    Unit("mΩ", "resistance", 1e-3, ("mΩ", "mohm", "mohms")),
    Unit("rad/s", "angular velocity", 1.0, ("rad/s", "rad/sec", "rads^-1", "rad*s^-1")),
    Unit("rpm", "angular velocity", RPM, ("rpm", "r/min", "rev/min")),
    Unit("s", "time", 1.0, ("s", "sec", "secs", "second", "seconds")),
    Unit("ms", "time", 1e-3, ("ms", "msec")),
    Unit("min", "time", 60.0, ("min", "mins", "minute", "minutes")),
    Unit(
        "rad/s/V",
        "gain",
        1.0,
        ("rad/s/v", "rad/(sv)", "rad/(vs)", "(rad/s)/v", "rad/vs", "rads^-1v^-1"),
    ),
    Unit("V s/rad", "back-emf constant", 1.0, ("vs/rad", "v/(rad/s)", "v/rad/s", "vsrad^-1")),
    Unit("N m/A", "torque constant", 1.0, ("nm/a", "n/a*m", "nma^-1")),
    Unit("N m s/rad", "friction coefficient", 1.0, ("nms/rad", "nm/(rad/s)", "nmsrad^-1")),
    Unit(
        "mN m s/rad",
        "friction coefficient",
        1e-3,
        ("mnms/rad", "mnm/(rad/s)", "mnmsrad^-1"),
    ),
    Unit("kg m^2", "inertia", 1.0, ("kgm^2", "kgm2")),
    Unit("°C", "temperature", 1.0, ("°c", "c", "degc", "deg", "°", "degrees")),
    Unit("°C/W", "oven gain", 1.0, ("°c/w", "c/w", "k/w", "degc/w", "deg/w")),
    Unit("%", "percentage", 0.01, ("%", "percent")),
    Unit("", "number", 1.0, ()),
)

CEILING: dict[str, tuple[float, str]] = {
    "voltage": (1e3, "1 kV"),
    "current": (1e2, "100 A"),
    "resistance": (1e9, "1000 MΩ"),
    "angular velocity": (1e5, "100 000 rad/s"),
    "time": (1e6, "a million seconds"),
    "gain": (1e6, "a million rad/s/V"),
    "back-emf constant": (1e3, "1000 V s/rad"),
    "torque constant": (1e3, "1000 N m/A"),
    "friction coefficient": (1e3, "1000 N m s/rad"),
    "inertia": (1e3, "1000 kg m^2"),
    "temperature": (1e5, "100 000 °C"),
    "oven gain": (1e6, "a million °C/W"),
    "percentage": (1e3, "100 000 %"),
    "number": (1e12, "10^12"),
}
"""Quantity -> the largest magnitude (SI) an entry may have, and that limit in words: far
beyond anything the lab's meters, board or answers give, so only a slip of the keyboard
(1e308) is refused, and no figure computed from an entry overflows."""

UNITS: dict[str, Unit] = {u.symbol: u for u in _UNITS}
"""Every unit by its display symbol (``"mA"``, ``"Ω"``, ``"rad/s"``, ``""`` for a pure number)."""

_CASE_KEPT = {s for u in _UNITS if u.quantity == "resistance" for s in u.spellings if s[0] in "mM"}

_NUMBER = re.compile(
    r"""^(?P<sign>[+-]?)\s*
        (?P<mant>\d+(?:[.,]\d*)?|[.,]\d+)
        (?:[eE](?P<exp>[+-]?\d+))?
        (?P<rest>.*)$""",
    re.VERBOSE | re.DOTALL,
)
_PREFIXES = {"k", "m", "M", "µ", "u", "G"}


@dataclass(frozen=True)
class _Bare:
    """What a bare number (typed without a unit) in a field of one form unit may not be:
    ``below`` or above ``bound`` (in the form unit) it is refused as ambiguous, since the
    field's values are ``usual`` and such a number is most likely ``other`` (a unit
    ``ratio`` times the form unit: A is 1000 mA, ms 0.001 s) typed without its name;
    ``looks``: ``other`` in words."""

    bound: float
    below: bool
    usual: str
    looks: str
    other: str
    ratio: float


_BARE: dict[str, _Bare] = {
    "mA": _Bare(1.0, True, "currents here are 20-50 mA", "amperes", "A", 1000.0),
    "mN m s/rad": _Bare(
        0.05, True, "f of this motor is a few mN m s/rad", "N m s/rad", "N m s/rad", 1000.0
    ),
    "s": _Bare(1.0, False, "this motor's time constant is tens of ms", "milliseconds", "ms", 0.001),
    "ms": _Bare(1.0, True, "this motor's time constant is tens of ms", "seconds", "s", 1000.0),
}
"""Form unit -> when a bare number in a field of that unit is refused as ambiguous: 0.047
for i_ss (47 mA typed in A), 0.00186 for f (1.86 mN m s/rad typed in N m s/rad), 57 for T
(57 ms: as seconds, far longer than the 1.5 s steps of Task 10 could show), 0.057 for T in a
field in ms (Task 12's: 57 ms typed in s)."""


class EntryRefused(InputError):
    """A typed text that is not an acceptable value; ``str()`` is the one-line message."""


@dataclass(frozen=True)
class Parsed:
    """An accepted entry: ``value`` in SI units, the ``unit`` it was typed in, and a note."""

    value: float
    unit: str
    note: str = ""


def _normalise_unit(text: str) -> str:
    """Unit text without spaces, '*', '·', '.', with Ω unified and superscripts spelled out."""
    t = text.strip().replace("\u2126", "Ω").replace("ω", "Ω") if text else ""
    t = re.sub(r"[\s*·⋅]", "", t).replace("²", "^2").replace("⁻¹", "^-1")
    if t in _CASE_KEPT:
        return t
    low = t.lower()
    return low.replace("ω", "Ω")


_BY_SPELLING: dict[str, Unit] = {_normalise_unit(s): u for u in _UNITS for s in u.spellings}


def _scaled(number: Decimal, scale: float) -> float:
    """number * scale; exact in decimal for power-of-ten units, so 37.2 mA is 0.0372 A."""
    exponent = math.log10(scale)
    if abs(exponent - round(exponent)) < 1e-12:
        return float(number.scaleb(round(exponent)))
    return float(number) * scale


def lookup_unit(text: str) -> Unit | None:
    """The unit a typed unit text names, or None when it names none."""
    key = _normalise_unit(text)
    if not key:
        return UNITS[""]
    return _BY_SPELLING.get(key)


def describe(unit: str) -> str:
    """'a current in mA' for the form unit ``unit`` (a display symbol of :data:`UNITS`)."""
    u = UNITS[unit]
    if not u.symbol:
        return "a number"
    article = "an" if u.quantity[0] in "aeiou" else "a"
    return f"{article} {u.quantity} in {u.symbol}"


def example(unit: str) -> str:
    """A typical entry for a field in ``unit``, for messages (e.g. ``47 mA``): a value of the
    magnitude the lab's motor gives, but never within a factor 1.5 of the virtual board's
    answer for Tasks 6-15 (k_v, k_a, f, omega, K, T, J): a refusal is no place to learn it
    (1.9 rad/s/V was K within 3 %, 0.32 N m/A was k_a)."""
    samples = {
        "V": "4.1 V",
        "mV": "4100 mV",
        "A": "0.047 A",
        "mA": "47 mA",
        "Ω": "5.2 Ω",
        "rad/s": "4.6 rad/s",
        "s": "0.12 s",
        "ms": "120 ms",
        "min": "3.5 min",
        "rad/s/V": "1.2 rad/s/V",
        "V s/rad": "0.3 V s/rad",
        "N m/A": "0.2 N m/A",
        "N m s/rad": "0.0045 N m s/rad",
        "mN m s/rad": "4.5 mN m s/rad",
        "kg m^2": "0.0008 kg m^2",
        "°C": "250 °C",
        "°C/W": "0.25 °C/W",
        "%": "50 %",
        "": "0.5",
    }
    return samples.get(unit, f"1 {unit}")


def parse_quantity(
    text: str,
    unit: str,
    *,
    label: str = "",
    allow_negative: bool = False,
    allow_zero: bool = True,
    within: tuple[float, float, str] | None = None,
) -> Parsed:
    """Read ``text`` as a quantity for a field whose form unit is ``unit``; value in SI.

    ``unit`` is a display symbol from :data:`UNITS` (``"mA"``, ``"V"``, ``"Ω"``, ...).
    ``within``: for an instrument's reading, the magnitudes (SI, low and high) it can show
    and that span in words (``"a multimeter on Ω shows, 1 mΩ to 500 MΩ"``); a nonzero value
    outside it is refused with those words, in place of the quantity's :data:`CEILING`.
    Raises :class:`EntryRefused` (an InputError naming ``label``) with a one-line message.
    """
    form = UNITS[unit]
    want = f"expected {describe(unit)} (e.g. {example(unit)})"

    def refuse(why: str) -> EntryRefused:
        return EntryRefused(label, None, f"{why}; {want}")

    stripped = text.strip()
    if not stripped:
        return _raise(refuse("nothing typed"))
    m = _NUMBER.match(stripped)
    if m is None:
        return _raise(refuse(f"{stripped!r} is not a number"))
    mant = m.group("mant").replace(",", ".")
    try:
        exact = Decimal(
            ("-" if m.group("sign") == "-" else "")
            + mant
            + (f"e{m.group('exp')}" if m.group("exp") else "")
        )
    except InvalidOperation:  # an exponent beyond any Decimal's (1e999999999999999999)
        return _raise(refuse(f"{stripped!r} is not a finite number"))
    number = float(exact)
    rest = m.group("rest").strip()
    if not math.isfinite(number):
        return _raise(refuse(f"{stripped!r} is not a finite number"))
    typed = lookup_unit(rest)
    if typed is None:
        if re.search(r"\d", rest) and not re.search(r"\^|[a-zA-Z]2", rest):
            return _raise(refuse(f"{stripped!r} holds more than one number"))
        if rest in _PREFIXES:
            return _raise(
                refuse(
                    f"{stripped!r}: a prefix needs its unit (write e.g. '{number:g} {rest}{form.symbol}')"
                )
            )
        return _raise(refuse(f"{rest!r} in {stripped!r} is not a unit this field takes"))
    if typed.symbol and typed.quantity != form.quantity:
        return _raise(
            refuse(
                f"{stripped!r} is {'an' if typed.quantity[0] in 'aeiou' else 'a'} {typed.quantity}"
            )
        )
    note = ""
    if not typed.symbol:
        typed = form
        bare = _BARE.get(form.symbol)
        if bare is not None and (
            0 < abs(number) < bare.bound if bare.below else abs(number) > bare.bound
        ):
            return _raise(
                EntryRefused(
                    label,
                    None,
                    f"{stripped!r} is ambiguous: {bare.usual}, so this looks like {bare.looks}; "
                    f"type '{_fmt(number * bare.ratio)} {form.symbol}' or "
                    f"'{stripped} {bare.other}' (or '{stripped} {form.symbol}' if you mean it)",
                )
            )
    elif typed.symbol != form.symbol:
        note = f"read as {_fmt(number * typed.scale / form.scale)} {form.symbol}"
    value = _scaled(exact, typed.scale)
    if not math.isfinite(value):  # 1e308 kΩ: finite as typed, not in the form's SI unit
        return _raise(refuse(f"{stripped!r} is not a finite number in {form.symbol}"))
    ceiling, in_words = CEILING[form.quantity]
    if within is not None and value != 0 and not within[0] <= abs(value) <= within[1]:
        return _raise(refuse(f"{stripped!r} is outside the range {within[2]}"))
    if abs(value) > ceiling:
        return _raise(
            refuse(
                f"{stripped!r} is far beyond any {form.quantity} in this lab (at most {in_words})"
            )
        )
    if value < 0 and not allow_negative:
        return _raise(
            refuse(
                f"{stripped!r} is negative, which this field cannot be (swapped leads? type the magnitude)"
            )
        )
    if value == 0 and not allow_zero:
        return _raise(refuse(f"{stripped!r} is zero, which this field cannot be"))
    return Parsed(value=value, unit=typed.symbol, note=note)


def _raise(exc: EntryRefused) -> Parsed:
    raise exc


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def format_quantity(value: float | None, unit: str, digits: int = DIGITS) -> str:
    """``value`` (SI) shown in the form unit ``unit`` with ``digits`` significant digits,
    trailing zeros kept (:func:`format_value`); :data:`MISSING` for None."""
    if value is None:
        return MISSING
    return format_value(_in_unit(value, UNITS[unit]), unit, digits)


F_UNIT = "mN m s/rad"
"""The one unit f is shown to people in (the table, the entries, the warnings, the CLI's
text); machine output (JSON, CSV) keeps SI, N m s/rad."""


TIME_CONSTANT_UNIT = "ms"
"""The one unit a time constant or a delay (T, the model check's delays and second time
constants, all in s in machine output) is shown to people in, as :data:`F_UNIT` is f's."""

SHOWN_UNITS: dict[str, str] = {"s": TIME_CONSTANT_UNIT, "N m s/rad": F_UNIT}
"""The unit a constant of the motor or of the model check, given in its SI unit (the key), is
shown to people in; a unit not listed is shown as it is."""


def shown_unit(unit: str) -> str:
    """The unit people read a constant in SI ``unit`` in (:data:`SHOWN_UNITS`)."""
    return SHOWN_UNITS.get(unit, unit)


def format_constant(value: float, unit: str, digits: int = DIGITS) -> str:
    """A constant ``value`` in SI ``unit`` as people read it (:func:`shown_unit`): T =
    0.04261 s is '42.61 ms', f = 0.001855 N m s/rad '1.855 mN m s/rad'; '—' if not finite."""
    shown = shown_unit(unit)
    if shown == unit or not math.isfinite(value):
        return format_value(value, unit, digits)
    return format_quantity(value, shown, digits)


def format_constant_interval(lo: float, hi: float, unit: str, digits: int = DIGITS) -> str:
    """A 95 % interval of a constant in SI ``unit``, in the unit people read it in
    (:func:`format_interval`, :func:`shown_unit`)."""
    shown = shown_unit(unit)
    scale = UNITS[shown].scale if shown != unit else 1.0
    return format_interval(lo / scale, hi / scale, shown, digits)


def in_unit(value: float, unit: str) -> float:
    """``value`` (SI) as a number in the form unit ``unit`` (f 0.00186 -> 1.86 mN m s/rad)."""
    return _in_unit(value, UNITS[unit])


def _in_unit(value: float, u: Unit) -> float:
    """``value`` (SI) in the unit ``u``: multiplied by a whole 1/scale where there is one
    (mA: 1000, exact), else divided by the scale (rpm: 2 pi/60)."""
    inverse = 1.0 / u.scale
    if u.scale < 1.0 and abs(inverse - round(inverse)) < 1e-9 * inverse:
        return value * round(inverse)
    return value / u.scale


def format_typed(value: float, digits: int = DIGITS) -> str:
    """A typed number with at most ``digits`` significant digits and no zeros it was not
    given: 0,057 is "0.057", never "0.05700" (the number of :func:`format_reading`)."""
    return f"{float(format_number(value, digits)):g}"


def format_reading(value: float, unit: str, digits: int = DIGITS, typed: str = "") -> str:
    """A reading (typed, captured or from the meter; ``value`` SI) in the form unit ``unit``
    with at most ``digits`` significant digits and no zeros it was not given: R typed as
    5.26 stays "5.26 Ω", never "5.260 Ω" (a computed value uses :func:`format_quantity`).

    ``typed``: the text the reading was typed as. When it is one number (with or without a
    unit) that is the reading shifted by a power of ten, the reading is written with the
    significant digits typed, its trailing zeros kept (at most ``digits``): '4,0' is
    "4.0 V", '47,0 mA' "47.0 mA", '0.0470 A' in mA "47.0 mA" (walk 13, D6); the zeros
    closing a number without a decimal point do not count ('1200 mV' is "1.2 V"). Any other
    text (arithmetic, '80 rpm' read in rad/s) leaves the reading as without it."""
    u = UNITS[unit]
    shown = _in_unit(value, u)
    sig = _typed_digits(typed, shown)
    number = format_typed(shown, digits) if sig is None else format_number(shown, min(sig, digits))
    return f"{number} {u.symbol}".rstrip()


def _typed_digits(typed: str, shown: float) -> int | None:
    """The significant digits of ``typed`` when it is one number, perhaps with a unit, that
    is ``shown`` times a power of ten (the same reading in another unit of that ratio);
    None otherwise (:func:`format_reading`)."""
    m = _NUMBER.match(typed.strip())
    if m is None or lookup_unit(m.group("rest")) is None or not math.isfinite(shown):
        return None
    mant, exp = m.group("mant").replace(",", "."), m.group("exp") or "0"
    if len(exp.lstrip("+-")) > 3 or abs(int(exp)) > 300:  # 1e999: no reading of this lab
        return None
    number = float(mant) * 10.0 ** int(exp)
    if number == 0 or shown == 0 or not math.isfinite(number):
        return None
    shift = math.log10(abs(shown / number))
    if abs(shift - round(shift)) > 1e-9:
        return None
    digits = mant.replace(".", "").lstrip("0")
    if "." not in mant:
        digits = digits.rstrip("0")
    return max(len(digits), 1)


@dataclass(frozen=True)
class Plausible:
    """A range a value (SI) usually lies in; outside it, ``low``/``high`` is the warning.

    ``lo``/``hi`` may be None for an open end. Warnings never refuse an entry.
    """

    lo: float | None
    hi: float | None
    low: str = ""
    high: str = ""

    def warnings(self, value: float) -> list[str]:
        """The warning for ``value`` (SI), or none."""
        if self.lo is not None and value < self.lo and self.low:
            return [self.low]
        if self.hi is not None and value > self.hi and self.high:
            return [self.high]
        return []
