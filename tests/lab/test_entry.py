"""What students type: every accepted and every refused form, with the values in SI by hand."""

from __future__ import annotations

import math

import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.content.expr import FormulaRefused, parse_formula
from minseg_tui.quantities import (
    EntryRefused,
    Plausible,
    format_quantity,
    format_reading,
    parse_quantity,
)


@pytest.mark.parametrize(
    ("text", "unit", "value", "typed"),
    [
        ("4.7", "V", 4.7, "V"),
        ("4,7", "V", 4.7, "V"),
        ("4.7 V", "V", 4.7, "V"),
        (" 4.7V ", "V", 4.7, "V"),
        ("4.7 volts", "V", 4.7, "V"),
        ("+4.7", "V", 4.7, "V"),
        ("4100 mV", "V", 4.1, "mV"),
        ("4.", "V", 4.0, "V"),
        (".5", "V", 0.5, "V"),
        (",5 v", "V", 0.5, "V"),
        ("47 mA", "mA", 0.047, "mA"),
        ("47mA", "mA", 0.047, "mA"),
        ("47", "mA", 0.047, "mA"),
        ("47 MA", "mA", 0.047, "mA"),
        ("0.047 A", "mA", 0.047, "A"),
        ("0,047A", "mA", 0.047, "A"),
        ("0.5 mA", "mA", 0.0005, "mA"),
        ("37.2 mA", "mA", 0.0372, "mA"),
        ("47000 µA", "mA", 0.047, "µA"),
        ("5,2 Ω", "Ω", 5.2, "Ω"),
        ("5.2 \u2126", "Ω", 5.2, "Ω"),
        ("5.2Ω", "Ω", 5.2, "Ω"),
        ("5.2 ohm", "Ω", 5.2, "Ω"),
        ("5.2 Ohms", "Ω", 5.2, "Ω"),
        ("5.2", "Ω", 5.2, "Ω"),
        ("3 kΩ", "Ω", 3000.0, "kΩ"),
        ("3kohm", "Ω", 3000.0, "kΩ"),
        ("1 MΩ", "Ω", 1e6, "MΩ"),
        ("5200 mΩ", "Ω", 5.2, "mΩ"),
        ("6.8 rad/s", "rad/s", 6.8, "rad/s"),
        ("60 rpm", "rad/s", 6.283185307179586, "rpm"),
        ("250 ms", "s", 0.25, "ms"),
        ("0.25", "s", 0.25, "s"),
        ("3.5 min", "min", 210.0, "min"),
        ("1.3e-3 kg m^2", "kg m^2", 1.3e-3, "kg m^2"),
        ("1,3e-3 kg·m²", "kg m^2", 1.3e-3, "kg m^2"),
        ("1.9 rad/(V s)", "rad/s/V", 1.9, "rad/s/V"),
        ("0.5 V s/rad", "V s/rad", 0.5, "V s/rad"),
        ("0.32 Nm/A", "N m/A", 0.32, "N m/A"),
        ("63 %", "%", 0.63, "%"),
        ("63", "%", 0.63, "%"),
        ("250 °C", "°C", 250.0, "°C"),
        ("0.25 C/W", "°C/W", 0.25, "°C/W"),
    ],
)
def test_accepted(text, unit, value, typed):
    p = parse_quantity(text, unit, label="x")
    assert p.value == pytest.approx(value, rel=1e-12)
    assert p.unit == typed


def test_exact_sub_units():
    """37.2 mA is stored as 0.0372 A exactly (no 0.037200000000000004 in the session file)."""
    assert parse_quantity("37.2 mA", "mA").value == 0.0372
    assert parse_quantity("63 %", "%").value == 0.63


def test_conversion_note():
    assert parse_quantity("0.047 A", "mA").note == "read as 47 mA"
    assert parse_quantity("47 mA", "mA").note == ""


@pytest.mark.parametrize(
    ("text", "unit", "fragment"),
    [
        ("", "V", "nothing typed"),
        ("   ", "mA", "nothing typed"),
        ("abc", "V", "not a number"),
        ("nan", "V", "not a number"),
        ("inf", "V", "not a number"),
        ("-inf", "V", "not a number"),
        ("1e999", "V", "not a finite number"),
        ("1e308 kΩ", "Ω", "not a finite number"),  # finite as typed, infinite in ohm
        ("1e306 MΩ", "Ω", "not a finite number"),
        ("1e308", "V", "far beyond any voltage in this lab (at most 1 kV)"),
        ("2000 A", "mA", "far beyond any current in this lab (at most 100 A)"),
        ("-1e300", "rad/s", "far beyond any angular velocity"),
        ("5 GΩ", "Ω", "not a unit"),
        ("4.7 5.2", "V", "more than one number"),
        ("1,234.5", "V", "more than one number"),
        ("4.7.1", "V", "more than one number"),
        ("4.7 V", "mA", "is a voltage"),
        ("47 mA", "V", "is a current"),
        ("5 Ω", "V", "is a resistance"),
        ("3k", "Ω", "a prefix needs its unit"),
        ("4.7 bananas", "V", "not a unit this field takes"),
        ("-4.7", "V", "negative"),
        ("-5 Ω", "Ω", "negative"),
        ("0.047", "mA", "ambiguous"),
        ("0,03", "mA", "ambiguous"),
    ],
)
def test_refused(text, unit, fragment):
    with pytest.raises(EntryRefused) as info:
        parse_quantity(text, unit, label="field")
    msg = str(info.value)
    assert fragment in msg
    assert "\n" not in msg
    assert msg.startswith("field: ")
    assert isinstance(info.value, InputError)


def test_refusals_say_what_was_expected():
    with pytest.raises(EntryRefused) as info:
        parse_quantity("4.7 V", "mA", label="i_ss")
    assert "expected a current in mA (e.g. 47 mA)" in str(info.value)
    with pytest.raises(EntryRefused) as info:
        parse_quantity("0.047", "mA", label="i_ss")
    assert "'47 mA'" in str(info.value) and "'0.047 A'" in str(info.value)


def test_zero_and_negative_policies():
    with pytest.raises(EntryRefused, match="zero"):
        parse_quantity("0", "Ω", allow_zero=False)
    assert parse_quantity("0", "V").value == 0.0
    assert parse_quantity("-3.2", "rad/s", allow_negative=True).value == -3.2


def test_format_quantity():
    # significant digits with their trailing zeros (issue 9: "K = 2" hid K = 1.996)
    assert format_quantity(0.0372, "mA") == "37.20 mA"
    assert format_quantity(5.26, "Ω", 3) == "5.26 Ω"
    assert format_quantity(210.0, "min") == "3.500 min"
    assert format_quantity(0.63, "%", 2) == "63 %"


def test_format_reading_keeps_the_digits_it_was_given():
    # a reading is not padded with zeros nobody read (5.26 is not 5.260), but is rounded
    # to four significant digits like any other number
    assert format_reading(5.26, "Ω") == "5.26 Ω"
    assert format_reading(0.047, "mA") == "47 mA"
    assert format_reading(parse_quantity("4,7", "V").value, "V") == "4.7 V"
    assert format_reading(3.14159, "rad/s") == "3.142 rad/s"


def test_plausible_warnings():
    rule = Plausible(1.0, 20.0, low="too low", high="too high")
    assert rule.warnings(0.5) == ["too low"]
    assert rule.warnings(25.0) == ["too high"]
    assert rule.warnings(5.0) == []


# -- formulas ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "env", "value"),
    [
        ("2*pi/720", {}, 0.008726646259971648),
        ("2pi/720", {}, 0.008726646259971648),
        ("2π/720", {}, 0.008726646259971648),
        ("1 - e^-1", {}, 0.6321205588285577),
        ("1-exp(-1)", {}, 0.6321205588285577),
        ("0,632", {}, 0.632),
        ("1.5e-3", {}, 0.0015),
        (
            "(u_ss - R*i_ss)/omega_ss",
            {"u_ss": 4.0, "R": 5.0, "i_ss": 0.04, "omega_ss": 7.0},
            0.5428571428571428,
        ),
        (
            "(u_ss - R*i_ss)/ω_ss",
            {"u_ss": 4.0, "R": 5.0, "i_ss": 0.04, "omega_ss": 7.0},
            0.5428571428571428,
        ),
        ("2(a+b)", {"a": 1.0, "b": 2.0}, 6.0),
        ("sqrt(a)", {"a": 9.0}, 3.0),
        ("63 %", {}, 0.63),  # a fraction typed as a percentage (Preparation 4)
        ("63,2%", {}, 0.632),
        ("1 - 36.8 %", {}, 0.632),
        ("50 % * a", {"a": 4.0}, 2.0),
    ],
)
def test_formula_values(text, env, value):
    f = parse_formula(text, tuple(env))
    assert f.value(env) == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("", "nothing typed"),
        ("ab", "write products with *: a*b"),
        ("x", "unknown name 'x'"),
        ("__import__('os')", "only exp(x)"),
        ("a.b", "'.' has no place in a formula"),
        ("[1]", "'[' has no place in a formula"),
        ("'a'", "not a number"),
        ("a +", "'+' at the end"),
        ("a % b", "'%' goes right after a number"),
    ],
)
def test_formula_refused(text, fragment):
    with pytest.raises(FormulaRefused) as info:
        parse_formula(text, ("a", "b"), label="T")
    assert fragment in str(info.value)
    assert "\n" not in str(info.value)


def test_formula_without_names_must_be_finite():
    with pytest.raises(FormulaRefused, match="not a finite number"):
        parse_formula("1/0")
    assert math.isnan(parse_formula("a/b", ("a", "b")).value({"a": 1.0, "b": 0.0}))


def test_formula_math_errors_give_nan():
    assert math.isnan(parse_formula("sqrt(a)", ("a",)).value({"a": -1.0}))
    assert math.isnan(parse_formula("a^b", ("a", "b")).value({"a": -8.0, "b": 0.5}))
    assert math.isnan(parse_formula("a^b", ("a", "b")).value({"a": 10.0, "b": 400.0}))


def test_a_reading_keeps_the_digits_it_was_typed_with():
    """Walk 13 D6: '4,0' is "4.0 V", never "4 V"; the digits typed survive a unit change by
    a power of ten; arithmetic, a unit change by another factor and an integer's closing
    zeros leave the reading as without the text."""
    for text, form, unit, shown in (
        ("4,0", "V", "V", "4.0 V"),
        ("4", "V", "V", "4 V"),
        ("47,0 mA", "mA", "mA", "47.0 mA"),
        ("0.0470 A", "mA", "mA", "47.0 mA"),
        ("0,057", "s", "ms", "57 ms"),
        ("5.2600", "Ω", "Ω", "5.260 Ω"),
        ("5.263412", "Ω", "Ω", "5.263 Ω"),
        ("1200 mV", "V", "V", "1.2 V"),
        ("4.70e-2 A", "mA", "mA", "47.0 mA"),
        ("0", "V", "V", "0 V"),
    ):
        value = parse_quantity(text, form).value
        assert format_reading(value, unit, typed=text) == shown, text
    rpm = parse_quantity("80 rpm", "rad/s").value
    assert format_reading(rpm, "rad/s", typed="80 rpm") == "8.378 rad/s"
    assert format_reading(4.0, "V", typed="2*2,0") == "4 V"
    assert format_reading(4.0, "V", typed="4,5") == "4 V"  # not this reading's text
    assert format_reading(4.0, "V", typed="4e999") == "4 V"
    assert format_reading(4.0, "V", typed="4e99999") == "4 V"
