"""identify's refusals of a table, R or a run log: the model gives a record (model/identify/
refusals.py), the words are made in lab/content/identify_says.py, and the table's reader,
the CLI and the session show them in one line."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.lab.content.identify_says import identify_refusal, identify_refusal_words
from minseg_tui.lab.state.results import compute
from minseg_tui.model.identify import IdentifyRefused, Reading, identify
from minseg_tui.model.identify.refusals import (
    MedianKvNotPositive,
    NoRisingEdge,
    NoRows,
    RNotPositive,
    RowImplausible,
    RowNotANumber,
    RowNotPositive,
)
from minseg_tui.model.runlog import RunLog

GOOD = [Reading(2, 1.55, 20, 40, line=2), Reading(3, 2.55, 30, 45, line=3)]


@pytest.mark.parametrize(
    ("row", "record", "words"),
    [
        (
            Reading(math.nan, 3.55, 40, 50, line=4),
            RowNotANumber("u_req", math.nan),
            "expected a number for u_req, got nan",
        ),
        (
            Reading(4, 3.55, 40, -math.inf, line=4),
            RowNotANumber("i_ss", -math.inf),
            "expected a number for i_ss, got -inf",
        ),
        (
            Reading(4, 3.55, 0.0, 50, line=4),
            RowNotPositive("omega_ss", 0.0),
            "expected omega_ss > 0 rad/s (a zero speed gives no k_v or f), got 0",
        ),
        (
            Reading(4, -3.55, 40, 50, line=4),
            RowNotPositive("u_ss", -3.55),
            "expected u_ss > 0 V (the voltage measured on the motor), got -3.55",
        ),
        (
            Reading(4, 3.55, 40, 0.0, line=4),
            RowNotPositive("i_ss", 0.0),
            "expected i_ss > 0 mA (the current measured in Task 5), got 0",
        ),
    ],
)
def test_a_bad_row_is_a_record_worded_above_the_model(row, record, words):
    """The row's record (nan compared by its repr), its words, the refusal's line with the
    row's line, and the session's line for the row it leaves out."""
    assert repr(row.problem()) == repr(record)
    assert identify_refusal_words(record) == words
    with pytest.raises(IdentifyRefused) as refused:
        identify([*GOOD, row], 5.0, source="t.csv")
    assert str(identify_refusal(refused.value)) == f"t.csv:4: {words}"
    said = compute(5.0, [*GOOD, row], None, Path("."))
    assert f"row {row.u_req:g} V left out: {words}" in said.problems


def test_a_bad_R_no_rows_and_a_negative_median_are_records_worded_above_the_model():
    with pytest.raises(IdentifyRefused) as refused:
        identify(GOOD, -5.0, source="t.csv")
    assert refused.value.why == RNotPositive(-5.0)
    assert str(identify_refusal(refused.value)) == (
        "--R: expected a positive resistance in ohm, got -5"
    )
    with pytest.raises(IdentifyRefused) as refused:
        identify([], 5.0, source="t.csv")
    assert refused.value.why == NoRows()
    assert str(identify_refusal(refused.value)) == (
        "t.csv: expected at least one row u_req,u_ss,omega_ss,i_ss"
    )
    # R = 4 ohm: (2 - 4 * 0.125) / 3 = +0.5 and (1 - 4 * 0.375) / 1 = -0.5, median 0
    negative = [Reading(2.5, 2.0, 3.0, 125.0, line=2), Reading(1.5, 1.0, 1.0, 375.0, line=3)]
    with pytest.raises(IdentifyRefused) as refused:
        identify(negative, 4.0, source="t.csv")
    assert refused.value.why == MedianKvNotPositive(0.0)
    words = (
        "expected the rows to give a positive k_v (V s/rad), their median is 0: u_ss - R i_ss "
        "is not above 0 on enough rows; check R and i_ss (mA)"
    )
    assert str(identify_refusal(refused.value)) == f"t.csv: {words}"
    assert compute(4.0, negative, None, Path(".")).problems == (f"table: {words}",)


def test_readings_too_small_for_a_finite_k_v_are_a_record_worded_above_the_model(tmp_path, capsys):
    tiny = Reading(4, 3.55, 1e-320, 50, line=4)
    with pytest.raises(IdentifyRefused) as refused:
        identify([*GOOD, tiny], 5.0, source="t.csv")
    why = refused.value.why
    assert isinstance(why, RowImplausible)
    assert why.R_i_ss == pytest.approx(0.25) and why.omega_ss == 1e-320
    assert why.k_v == math.inf and why.f == math.inf
    table = tmp_path / "table.csv"
    table.write_text("u_req,u_ss,omega_ss,i_ss\n2,1.55,1e-320,40\n")
    assert main(["identify", str(table), "--R", "5"]) == 2
    assert capsys.readouterr().err == (
        f"minseg-tui identify: {table}:2: expected readings of a plausible size (R i_ss = 0.2 V, "
        "omega_ss = 9.99989e-321 rad/s), they give k_v = inf and f = inf\n"
    )


def test_a_log_without_a_usable_rise_is_a_record_worded_above_the_model():
    t = np.arange(60) * 0.025
    late = np.where(t > t[-3], 4.0, 0.0)  # one rise, too near the end to be used
    log = RunLog(t=t, u=late, omega=np.zeros(60), source="late.csv", lines=np.arange(60) + 2)
    with pytest.raises(IdentifyRefused) as refused:
        identify(GOOD, 5.0, log)
    assert refused.value.why == NoRisingEdge("u", 5, 1)
    assert str(identify_refusal(refused.value)) == (
        "late.csv:2: expected a rising edge in u (V) with at least one sample before it and 5 "
        "after it; found 1 rising edge(s), none usable"
    )
