"""Issue 20, walk 4: a refused formula names its actual fault ("(u_ss - R*i_ss/omega_ss"
was refused with "write products with *"). A table of the cases, and with hypothesis: a
valid formula broken in one known way is refused with that fault named, in one line."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from minseg_tui.lab.content.expr import FormulaRefused, parse_formula
from minseg_tui.lab.content.steps import FIELDS
from minseg_tui.lab.state.entries import read_entry

NAMES = ("u_ss", "R", "i_ss", "omega_ss")

CASES = [
    ("(u_ss - R*i_ss/omega_ss", "a '(' is not closed: add the ')'"),
    ("((u_ss - R*i_ss/omega_ss", "2 '(' are not closed: add 2 ')'"),
    ("u_ss - R*i_ss)/omega_ss", "the ')' after 'u_ss - R*i_ss' has no '(' left to close"),
    ("(u_ss - R*i_ss))/omega_ss", "has no '(' left to close"),
    ("u_ss -* R", "two operators in a row ('-*')"),
    ("u_ss // R", "two operators in a row ('//')"),
    ("u_ss -", "'-' at the end: something must come after it"),
    ("* u_ss", "'*' at the start: something must come before it"),
    ("(/u_ss)", "'/' right after '('"),
    ("(u_ss +)", "nothing between '+' and ')'"),
    ("u_ss*()", "'()' with nothing inside"),
    ("", "nothing typed"),
    ("   ", "nothing typed"),
    ("x", "unknown name 'x'"),
    ("uss", "unknown name 'uss' (did you mean u_ss?)"),
    ("1.2.3*u_ss", "'1.2.3' is not a number: one decimal point at most"),
    ("2 3", "two numbers side by side (2 3)"),
    ("u_ss, R", "a ',' outside a number"),
    ("u_ss = R", "an '=' in the formula"),
    ("u_ss & R", "'&' has no place in a formula"),
    ("u_ss $ R", "'$' has no place in a formula"),
    ("sqrt 4", "sqrt takes its argument in parentheses: sqrt(x)"),
    ("R % u_ss %", "'%' goes right after a number"),
]


@pytest.mark.parametrize(("text", "fault"), CASES)
def test_each_refusal_names_its_fault(text, fault):
    with pytest.raises(FormulaRefused) as info:
        parse_formula(text, NAMES, label="k_v")
    said = str(info.value)
    assert said.startswith("k_v: ") and fault in said, said
    assert "\n" not in said and "products with" not in said


@pytest.mark.parametrize(
    ("text", "hint"),
    [
        ("Ri_ss", "unknown name 'Ri_ss' (write products with *: R*i_ss)"),
        ("u_ssomega_ss", "(write products with *: u_ss*omega_ss)"),
        ("Rpi", "(write products with *: R*pi)"),
        ("omegass", "(did you mean omega_ss?)"),
    ],
)
def test_an_unknown_name_says_what_it_probably_is(text, hint):
    with pytest.raises(FormulaRefused) as info:
        parse_formula(text, NAMES)
    assert hint in str(info.value), str(info.value)


def test_an_unknown_name_like_none_of_them_gets_no_guess():
    with pytest.raises(FormulaRefused) as info:
        parse_formula("zz", NAMES)
    assert "unknown name 'zz';" in str(info.value) and "(" not in str(info.value)


@pytest.mark.parametrize(
    ("key", "text", "fault"),
    [
        ("i_ss@2.5", "(4.05 - 2.05/60 mA", "a '(' is not closed"),
        ("i_ss@2.5", "4.05 - 2.05)/60", "has no '(' left to close"),
        ("own.k_a", "(0.65 * 0.49 N m/A", "a '(' is not closed"),
        ("own.k_a", "0.65 ** / 0.49", "two operators in a row"),
    ],
)
def test_arithmetic_in_a_quantity_field_names_its_fault_too(key, text, fault):
    e = read_entry(FIELDS[key], text)
    assert not e.ok and fault in e.message and "\n" not in e.message, e.message


def test_the_same_arithmetic_closed_is_read():
    e = read_entry(FIELDS["i_ss@2.5"], "(4.05 - 2.05)/60 mA")
    assert e.ok and e.value == pytest.approx(2.0 / 60 * 1e-3)


def _formulas() -> st.SearchStrategy[str]:
    leaves = st.sampled_from(["a", "b", "2", "0,5", "3.25", "pi"])

    def grow(inner: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        return st.one_of(
            st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "^"]), inner).map(
                lambda t: f"{t[0]} {t[1]} {t[2]}"
            ),
            inner.map(lambda x: f"({x})"),
            inner.map(lambda x: f"sqrt({x})"),
            inner.map(lambda x: f"-{x}"),
        )

    return st.recursive(leaves, grow, max_leaves=8)


OPS = st.sampled_from(["+", "-", "*", "/", "^"])


@settings(max_examples=200, derandomize=True, deadline=None)
@given(left=_formulas(), right=_formulas(), op=OPS, how=st.integers(0, 4))
def test_a_formula_broken_one_way_is_refused_with_that_fault(left, right, op, how):
    whole = f"{left} {op} {right}"
    parse_formula(whole, ("a", "b"))  # the formula itself is read
    broken, fault = [
        (f"({whole}", "a '(' is not closed: add the ')'"),
        (f"{left}) {op} {right}", "has no '(' left to close"),
        (f"{left} {op}/ {right}", "two operators in a row"),
        (f"{whole} {op}", f"'{op}' at the end"),
        (f"{left} {op} ({right}", "a '(' is not closed"),
    ][how]
    with pytest.raises(FormulaRefused) as info:
        parse_formula(broken, ("a", "b"), label="T")
    said = str(info.value)
    assert fault in said and "\n" not in said, (broken, said)
