"""The report as walk 10 read it (issue 20): each sentence true of the session in hand (real
session folder, real report files)."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.report.write import write_report
from tests.report.test_own_first import _row, _section, _tables
from tests.report.test_report import _session
from tests.seeded import Clock, record_square_wave

STEP = "Step response and model"


def _report(s: Session) -> str:
    return write_report(s).markdown.read_text(encoding="utf-8").replace("\u00a0", " ")


def _no_step_result(md: str) -> str:
    section = _section(md, STEP)
    (line,) = [x for x in section.splitlines() if x.startswith("No step result yet")]
    return line


def test_a_run_without_u_ss_names_only_the_u_ss_as_missing(tmp_path: Path) -> None:
    """D4 (walk 10, 'Per A, Kim'): after F5 with an empty table the report said the step
    results waited for R (Task 2) and a complete row (Tasks 4-5); they need neither, only
    the run and a u_ss to divide by."""
    with Session.create(tmp_path, ["Per A", "Kim"], date="2026-11-27", clock=Clock()) as s:
        record_square_wave(s, seed=21)
        section = _section(_report(s), STEP)
        # omega_ss and T need only the run: they stand, as on Tasks 11-12 (walk 18, D4);
        # what waits names only the u_ss
        assert (
            "K, J, the model and omega at 5 V: not yet, needs u_ss at the steps' voltage "
            "(Task 4); omega_ss and T need only the speed." in section
        ), section
        assert "No step result yet" not in section
        (table,) = _tables(section)
        assert [r[0] for r in table[1:]] == ["omega_ss in the steps (Task 11)", "T (Task 12)"]
        assert "ms (95 %" in _row(table, "T (Task 12)")["the program's value (least squares)"]
        s.enter("u_ss@4.5", "4.05 V")  # and then there are results, R and i_ss still empty
        md = _report(s)
    assert "No step result yet" not in _section(md, STEP)


def test_a_table_of_u_ss_without_a_run_names_only_the_run_as_missing(tmp_path: Path) -> None:
    """D4 (walk 10, 'lisa'): u_ss entered at all three voltages, no run: the report listed R
    and a complete row before the run."""
    with Session.create(tmp_path, ["lisa"], date="2026-11-27", clock=Clock()) as s:
        for level, u in ((2.5, "2,05"), (3.5, "3,05"), (4.5, "4,05")):
            s.enter(f"u_ss@{level:g}", u)
        line = _no_step_result(_report(s))
    assert line == "No step result yet: needs a step run (Task 10).", line


def _model_row(s: Session) -> dict[str, str]:
    (table,) = _tables(_section(_report(s), STEP))
    return _row(table, "the model (Task 14)")


def test_the_group_s_model_stands_in_the_one_form_as_every_value_does(tmp_path: Path) -> None:
    """D7 (walk 10): the group's model stood as typed ('0,057 omega' = -omega + 1,93 u_A')
    while every other value of the table is normalised ('1,93' is 1.93 rad/s/V); the model
    is now written T omega' = -omega + K u_A with the group's T and K as they typed them,
    and a model written another way is given that way too, with the text typed."""
    s = _session(tmp_path)
    s.enter("own.model", "0,057 omega' = -omega + 1,93 u_A")
    assert _model_row(s)["the group's value"] == "0.057 omega' = -omega + 1.93 u_A"
    s.enter("own.model", "omega' = -omega/0,057 + 33,9 u_A")
    mine = _model_row(s)["the group's value"]
    s.close()
    assert mine == "0.057 omega' = -omega + 1.932 u_A (typed \"omega' = -omega/0,057 + 33,9 u_A\")"
