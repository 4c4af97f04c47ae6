"""Round trips of the entries' units (hypothesis, derandomised and without a database, so
every run tries the same examples): whatever the program writes for a quantity, with its
unit, a group can type back into an entry of that unit and get the same value to the four
significant digits shown, with a decimal point or a decimal comma."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from minseg_tui.quantities import CEILING, UNITS, format_quantity, parse_quantity

SHOWN = sorted(s for s in UNITS if s)
FAST = settings(max_examples=300, derandomize=True, database=None, deadline=None)


@st.composite
def shown_values(draw: st.DrawFn) -> tuple[str, float]:
    """A unit the program shows and a positive value (SI) below its quantity's ceiling."""
    unit = draw(st.sampled_from(SHOWN))
    ceiling = CEILING[UNITS[unit].quantity][0]
    exponent = draw(st.floats(-6.0, math.log10(ceiling) - 0.01))
    mantissa = draw(st.floats(1.0, 9.99))
    return unit, min(mantissa * 10**exponent, 0.99 * ceiling)


@FAST
@given(shown_values(), st.booleans())
def test_a_shown_value_typed_back_reads_as_itself(case, comma):
    unit, value = case
    shown = format_quantity(value, unit)
    typed = shown.replace(".", ",") if comma else shown
    got = parse_quantity(typed, unit).value
    assert math.isclose(got, value, rel_tol=5e-4), (typed, got, value)
