"""The report says it as the screen does (issue 20, what the last stop left): the group's
value first, in the one unit of its quantity whatever unit they typed; the value read or
computed their way; the least-squares value; the same T with the same digits; and what was
not answered, said at the top (real session folder, real report files)."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import format_constant
from minseg_tui.report.write import write_report
from tests.lab.test_walk7_grading import _lab
from tests.report.test_own_first import _row, _section, _tables
from tests.report.test_report import _session


def _report(s: Session) -> str:
    return write_report(s).markdown.read_text(encoding="utf-8").replace("\u00a0", " ")


def test_an_omega_typed_in_rpm_stands_in_rad_per_s_and_T_reads_in_order(tmp_path: Path) -> None:
    s = _session(tmp_path)
    s.enter("own.omega_step", "80 rpm")
    s.enter("own.T", "57 ms")
    st = s.results().identification.step
    md = _report(s)
    s.close()
    results = _section(md, "Step response and model")
    (table,) = _tables(results)
    w = _row(table, "omega_ss in the steps")
    assert w["the group's value"] == "8.378 rad/s", w
    assert "rpm" not in results, results
    T = _row(table, "T (Task 12)")
    T_63, T_ls = format_constant(st.T_63, "s"), format_constant(st.T, "s")
    assert T["the group's value"] == "57 ms"
    assert T["computed or read the group's way"].startswith(f"{T_63} (the program's reading")
    assert T["the program's value (least squares)"].startswith(T_ls)
    # the one sentence on the two T: the difference with the digits of the T it comes from
    apart = format_constant(abs(st.T_63 - st.T), "s")
    assert f"here it is {apart} longer" in " ".join(results.split()), results


def test_the_report_says_first_what_was_not_answered(tmp_path: Path) -> None:
    s = _session(tmp_path)  # summary questions 1 and 5 answered, 2-4 and 6 not
    md = _report(s)
    s.close()
    warnings = " ".join(_section(md, "Warnings").split())
    assert warnings.startswith("- not answered when this report was written: "), warnings
    for n in (2, 3, 4, 6):
        assert f"question {n}: " in warnings, warnings
    assert "question 1: " not in warnings and "question 5: " not in warnings, warnings
    assert "Task 11: the static gain K: the group's K" in warnings, warnings
    summary = _section(md, "Summary and reflections")
    assert "not answered" in summary  # and where it stands


def test_a_negative_k_v_report_shows_K_T_and_the_63_percent_reading(tmp_path: Path) -> None:
    """Walk 7, D14: i_ss typed in A makes the table's k_v negative. The screen shows omega_ss
    in the steps, K, T and the 63 % reading from the run alone; the report said only "No
    step result yet". It now gives the same rows, with J waiting for the table and why."""
    s = _lab(tmp_path)
    s.enter("i_ss@3.5", "4.7 A")
    s.enter("i_ss@2.5", "4.7 A")
    s.enter("own.omega_step", "7.8")
    s.enter("own.K", "1.93")
    s.enter("own.T", "56 ms")
    res = s.results()
    assert res.identification is None and res.response is not None  # the run alone
    st = res.response
    md = _report(s)
    s.close()
    results = _section(md, "Step response and model")
    assert "No step result yet" not in results, results
    (table,) = _tables(results)
    K = _row(table, "K (Task 11)")
    assert K["the group's value"] == "1.93 rad/s/V" and "✓ right" in K["difference"], K
    assert K["the program's value (least squares)"].startswith(format_constant(st.K, "rad/s/V"))
    T = _row(table, "T (Task 12)")
    assert T["computed or read the group's way"].startswith(format_constant(st.T_63, "s"))
    assert T["the program's value (least squares)"].startswith(format_constant(st.T, "s"))
    J = _row(table, "J (Task 13)")
    assert "J needs R, k_v and f" in J["the program's value (least squares)"], J
    assert "positive k_v" in " ".join(results.split())  # why J waits
