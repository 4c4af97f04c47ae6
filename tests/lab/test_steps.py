"""The lab's steps as data: complete, sound, and every checker telling right from wrong."""

from __future__ import annotations

import math

import pytest

from minseg_tui.lab.content import answers, steps
from minseg_tui.lab.content.answers import check_answer
from minseg_tui.lab.content.expr import parse_formula
from minseg_tui.lab.content.steps import CHECKS, FIELDS, LEVELS, STEPS, step


def _f(key: str, text: str):
    return answers.read_formula(FIELDS[key], text)


def test_data_is_sound():
    assert steps.validate() == []


def test_every_step_has_own_words_and_the_lab_is_in_order():
    ids = [s.id for s in STEPS]
    assert ids[:15] == [f"prep{k}" for k in range(1, 16)]
    assert ids[15:] == [
        "task1",
        "task2",
        "task3",
        "task4",
        "task5",
        "table",
        "task10",
        "task11",
        "task12",
        "task13",
        "task14",
        "task15",
        "model_check",
        "summary",
    ]
    for s in STEPS:
        assert s.title and s.goal and s.todo, s.id


def test_parts_in_order():
    assert steps.PARTS == (
        "Preparation",
        "Set-up",
        "Steady state",
        "Table",
        "Step response",
        "Results",
        "Model check",
        "Summary",
    )


def test_table_fields_for_each_level():
    assert LEVELS == (2.5, 3.5, 4.5)
    for lv in ("2.5", "3.5", "4.5"):
        assert FIELDS[f"u_ss@{lv}"].unit == "V"
        assert FIELDS[f"omega_ss@{lv}"].unit == "rad/s"
        assert FIELDS[f"i_ss@{lv}"].unit == "mA"
        assert steps.FIELD_STEP[f"i_ss@{lv}"] == "task5"
    assert FIELDS["R"].unit == "Ω"


def test_task10_plans():
    plans = dict(step("task10").plans)
    assert (
        plans["manual"].low == 0.0 and plans["manual"].high == 4.5 and plans["manual"].ts == 0.025
    )
    assert plans["fast"].ts == 0.005
    assert plans["manual"].duration == 2 * 1.5 * 4


@pytest.mark.parametrize(
    ("key", "text"),
    [
        ("prep4.fraction", "0.632"),
        ("prep4.fraction", "1 - exp(-1)"),
        ("prep4.fraction", "1-e^-1"),
        ("prep6.y10", "3.79"),
        ("prep6.y10", "6*(1-exp(-1))"),
        ("prep8.T", "a/b"),
        ("prep8.T", "(a)/(b)"),
        ("prep8.K", "c/b"),
        ("prep8.K", "c*b^-1"),
        ("prep10.gain", "2*pi/720"),
        ("prep10.gain", "0.008727"),
        ("prep10.gain", "pi/360"),
        ("prep11.k_v", "(u_ss - R*i_ss)/omega_ss"),
        ("prep11.k_v", "u_ss/omega_ss - R*i_ss/omega_ss"),
        ("prep12.f", "k_a*i_ss/omega_ss"),
        ("prep14.T", "R*J/(R*f + k_v*k_a)"),
        ("prep14.T", "J/(f + k_v*k_a/R)"),
        ("prep14.K", "k_a/(R*f + k_v*k_a)"),
        ("prep15.J", "T*(R*f + k_v*k_a)/R"),
        ("prep15.J", "T*f + T*k_v*k_a/R"),
    ],
)
def test_right_formulas(key, text):
    fb = check_answer(CHECKS[key], _answer(key, text), {})
    assert fb.status == "right", fb


def _answer(key: str, text: str):
    f = _f(key, text)
    return f.value({}) if not FIELDS[key].names else f


@pytest.mark.parametrize(
    ("key", "text", "message"),
    [
        ("prep4.fraction", "0.368", "still missing"),
        ("prep4.fraction", "0.5", "not right yet"),
        ("prep6.y10", "6", "where the curve ends"),
        ("prep6.y10", "3*(1-exp(-1))", "multiply by c"),
        ("prep8.T", "b/a", "upside down"),
        ("prep8.K", "c/a", "divide by b"),
        ("prep10.gain", "720/(2*pi)", "upside down"),
        ("prep10.gain", "0.5", "degrees"),
        ("prep11.k_v", "u_ss/omega_ss", "R i_ss"),
        ("prep11.k_v", "(u_ss + R*i_ss)/omega_ss", "sign"),
        ("prep12.f", "i_ss/omega_ss", "k_a i_ss"),
        ("prep14.T", "J/(R*f + k_v*k_a)", "R is missing"),
        ("prep15.J", "T*R/(R*f + k_v*k_a)", "upside down"),
        ("prep15.J", "T*R", "not right yet"),
    ],
)
def test_wrong_formulas_get_specific_feedback(key, text, message):
    fb = check_answer(CHECKS[key], _answer(key, text), {})
    assert fb.status == "wrong"
    assert message in fb.message


def test_percent_answer():
    chk = CHECKS["prep5.percent"]
    assert check_answer(chk, 0.632, {}).status == "right"
    assert check_answer(chk, 0.63, {}).status == "right"
    assert check_answer(chk, 0.60, {}).status == "wrong"
    fb = check_answer(chk, 0.00632, {})  # "0.632" typed in a % field
    assert fb.status == "wrong" and "reads as 0.632 %: did you mean 63.2 %?" in fb.message
    fb = check_answer(chk, 0.005, {})  # "0.5": its own value, never the answer (walk 9, D1)
    assert fb.status == "wrong" and "reads as 0.5 %: did you mean 50 %?" in fb.message
    assert "37 %" in check_answer(chk, 0.37, {}).message


def test_oven_checks_use_the_groups_own_readings():
    entries = {"prep7.y_final": 250.0, "prep7.t_63": 14.0 * 60}
    T, K = CHECKS["prep7.T"], CHECKS["prep7.K"]
    assert check_answer(T, 10.0 * 60, entries).status == "right"  # 14 min - 4 min
    fb = check_answer(T, 14.0 * 60, entries)
    assert fb.status == "wrong" and "4 min" in fb.message
    assert check_answer(K, 0.25, entries).status == "right"  # 250 degC / 1000 W
    fb = check_answer(K, 250.0, entries)
    assert fb.status == "wrong" and "1000 W" in fb.message
    assert check_answer(K, 0.25, {}).status == "missing"


def test_missing_answer():
    assert check_answer(CHECKS["prep8.T"], None, {}).status == "missing"


def test_summary_choices():
    assert check_answer(CHECKS["summary.1"], (1,), {}).status == "right"  # a system
    assert check_answer(CHECKS["summary.1"], (0,), {}).status == "wrong"
    assert check_answer(CHECKS["summary.2"], (0,), {}).status == "right"  # a model
    assert check_answer(CHECKS["summary.5"], (1, 2), {}).status == "right"
    fb = check_answer(CHECKS["summary.5"], (2,), {})
    assert fb.status == "wrong" and "partly" in fb.message
    assert check_answer(CHECKS["summary.5"], (0, 1, 2), {}).status == "wrong"
    assert FIELDS["summary.3"].options[0] == "how fast the system reacts to changing inputs"
    assert FIELDS["summary.unclear"].kind == "text"


def test_checks_at_sample_points_are_seeded_and_positive():
    pts = answers._samples(("a", "b"))
    assert pts == answers._samples(("a", "b"))
    assert all(0.5 <= v <= 2.0 for p in pts for v in p.values())


def test_expected_values_by_hand():
    # the numbers the checkers accept, computed here independently
    assert parse_formula(CHECKS["prep10.gain"].expected).value({}) == pytest.approx(
        0.0087266, rel=1e-4
    )
    assert parse_formula(CHECKS["prep6.y10"].expected).value({}) == pytest.approx(
        6 * (1 - math.exp(-1))
    )
