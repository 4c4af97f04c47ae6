"""What a new student met on a walk of the lab (issue 20's second walk): f typed in the unit
of another column, formulas written the way the steps write them, Task 14's model judged."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.steps import FIELD_STEP, FIELDS
from minseg_tui.lab.state.entries import read_entry
from tests.lab.test_compare import _lab

# -- (3) f in N m s/rad typed into the mN m s/rad field ---------------------------------------


def test_f_typed_in_newton_metres_gets_a_hint_not_minus_100_percent():
    e = read_entry(FIELDS["own.f"], "0.00186")
    assert not e.ok and "ambiguous" in e.message
    assert "'1.86 mN m s/rad'" in e.message and "'0.00186 N m s/rad'" in e.message
    assert "\n" not in e.message


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("1,855 mN m s/rad", 0.001855),  # as the table shows it, with a decimal comma
        ("1,855", 0.001855),
        ("0.00186 N m s/rad", 0.00186),
        ("0.00186 mN m s/rad", 0.00186e-3),  # said on purpose: taken, with a warning
    ],
)
def test_f_in_the_units_the_program_shows(text, value):
    e = read_entry(FIELDS["own.f"], text)
    assert e.ok and e.value == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "says"),
    [("1855", "a thousand times"), ("1.855 N m s/rad", "a thousand times")],
)
def test_f_a_thousand_times_off_gets_a_hint(text, says):
    e = read_entry(FIELDS["own.f"], text)
    assert e.ok and any(says in w for w in e.warnings)
    assert not read_entry(FIELDS["own.f"], "1.86").warnings


def test_f_hint_on_the_table_step(tmp_path):
    with _lab(tmp_path) as s:
        e = s.enter("own.f", "0.00186")
        assert not e.ok and "mN m s/rad" in e.message
        assert s.value("own.f") is None  # nothing compared as -100 %
        s.enter("own.f", "1,855 mN m s/rad")
        (c,) = [c for c in s.comparisons("table") if c.key == "own.f"]
        assert c.rel_diff is not None and abs(c.rel_diff) < 0.5


# -- (4a) formulas as the steps write them, arithmetic in number fields -----------------------


@pytest.mark.parametrize(
    ("key", "text"),
    [
        ("prep11.k_v", "(u_ss - R i_ss)/omega_ss"),  # the step's explanation writes it so
        ("prep11.k_v", "(u_ss - R i_ss) / omega_ss"),
        ("prep11.k_v", "k_v = (u_ss - R i_ss) / omega_ss"),
        ("prep12.f", "k_a i_ss / omega_ss"),
        ("prep14.T", "R J / (R f + k_v k_a)"),
        ("prep14.K", "k_a / (R f + k_v k_a)"),
        ("prep15.J", "T (R f + k_v k_a) / R"),
        ("prep15.J", "J = T(R f + k_v k_a)/R"),
    ],
)
def test_formulas_as_the_steps_write_them_are_right(tmp_path, key, text):
    with _lab(tmp_path) as s:
        e = s.enter(key, text)
        assert e.ok, e.message
        (fb,) = [fb for fb in s.feedback(FIELD_STEP[key]) if fb.key == key]
        assert fb.status == "right", fb.message


def test_names_run_together_are_still_refused_in_one_line():
    e = read_entry(FIELDS["prep8.T"], "ab")
    assert not e.ok and "write products with *" in e.message and "\n" not in e.message
    assert read_entry(FIELDS["prep8.T"], "a b").ok  # written apart: a product


@pytest.mark.parametrize(
    ("key", "text", "value"),
    [
        ("own.k_a", "0.65*0.49", 0.3185),  # Task 8: k_a = 0.65 k_v worked out in the field
        ("own.k_a", "0.65 * 0.49 N m/A", 0.3185),
        ("own.k_a", "0,65·0,49", 0.3185),
        ("own.T", "60/1000 s", 0.06),
        ("i_ss@2.5", "(4.05 - 2.05)/60 A", 2.0 / 60),
    ],
)
def test_arithmetic_in_a_number_field(key, text, value):
    e = read_entry(FIELDS[key], text)
    assert e.ok, e.message
    assert e.value == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize(
    ("key", "text", "says"),
    [
        ("own.k_a", "0.65*0.49 V", "'0.65*0.49 V' is a voltage"),
        ("R", "2*-3", "'2*-3' is negative"),
        ("own.k_a", "4.7 5.2", "more than one number"),
        ("own.k_a", "0.65*(0.49", "a '(' is not closed"),
    ],
)
def test_arithmetic_refused_in_one_line_about_what_was_typed(key, text, says):
    e = read_entry(FIELDS[key], text)
    assert not e.ok and says in e.message and "\n" not in e.message
