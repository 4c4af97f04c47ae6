"""How numbers are written for people: significant digits with their trailing zeros, and a
unit that never leaves its number (issue 9, item 6)."""

from __future__ import annotations

import math

import pytest

from minseg_tui.quantities import NO_BREAK, format_number, format_value, join_units


@pytest.mark.parametrize(
    ("value", "digits", "text"),
    [
        (1.9962, 4, "1.996"),
        (1.9962, 3, "2.00"),  # never "2": the digits say how well it is known
        (2.0, 4, "2.000"),
        (0.042671, 4, "0.04267"),
        (0.00135, 4, "0.001350"),
        (5.801, 3, "5.80"),
        (9.99996, 4, "10.00"),  # rounding up adds a digit before the point, not after
        (1234.6, 4, "1235"),
        (12345.6, 4, "12350"),
        (-3.8, 3, "-3.80"),
        (0.0, 4, "0"),
        (1.234e-5, 4, "1.234e-05"),
        (math.nan, 4, "—"),
    ],
)
def test_format_number(value, digits, text):
    assert format_number(value, digits) == text


def test_format_value_puts_the_unit_after_the_number():
    assert format_value(1.9962, "rad/s/V") == "1.996 rad/s/V"
    assert format_value(2.216, "mN m s/rad") == "2.216 mN m s/rad"
    assert format_value(None, "s") == "—"
    assert format_value(3.0) == "3.000"


def test_join_units_keeps_numbers_and_units_together():
    text = "f = 2.216 mN m s/rad, from 0.0025 at 3.83 rad/s; CI 0.0426..0.0428 s, 63 % of it"
    joined = join_units(text)
    assert f"2.216{NO_BREAK}mN{NO_BREAK}m{NO_BREAK}s/rad" in joined
    assert f"3.83{NO_BREAK}rad/s" in joined
    assert f"0.0426..0.0428{NO_BREAK}s" in joined
    assert f"63{NO_BREAK}%" in joined
    assert "0.0025 at" in joined  # a number before a word that is no unit: a normal space
    assert joined.replace(NO_BREAK, " ") == text
    assert join_units("u_2 V and x2 s") == "u_2 V and x2 s"  # inside names: left alone


def test_a_signed_number_keeps_its_sign_and_its_zeros():
    from minseg_tui.quantities import format_signed

    assert format_signed(0.0123, 3) == "+0.0123"
    assert format_signed(-1.2, 3) == "-1.20"
    assert format_signed(12.0) == "+12.00"
    assert format_signed(0.0) == "0" and format_signed(math.nan) == "—"


def test_percents_spreads_and_ticks_are_written_one_way():
    from minseg_tui.quantities import format_percent, format_spread, format_ticks

    assert format_percent(0.174) == "17 %" and format_percent(0.0) == "0 %"
    assert format_spread(0.0312, "rad/s") == "± 0.03 rad/s" and format_spread(0.2) == "± 0.20"
    assert format_ticks([0.0, 0.5, 1.0]) == ["0.0", "0.5", "1.0"]  # the report wrote "1"
    assert format_ticks([0.0, 20.0, 40.0]) == ["0", "20", "40"]
