"""Walk 6 (issue 20, item 5), on the session alone: a step whose entry stands with the
program's own warning has a mark of its own, which F1's legend explains."""

from __future__ import annotations

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as views
from minseg_tui.quantities import format_diff
from minseg_tui.report.content import build as build_report
from minseg_tui.report.markdown import render as markdown
from tests.lab.test_compare import _compare, _lab


def test_a_warned_step_has_its_own_mark_in_the_legend():
    marks = [mark for _, mark, _ in views.STATUS_MARKS]
    assert len(set(marks)) == len(marks) and " " not in marks
    assert f"{views.MARK['warned']} stored with a warning: look again" in views.marks_legend()


def test_a_u_ss_above_the_request_marks_task_4_warned(tmp_path):
    with Session.create(tmp_path, ["Ada", "Bo"], date="2026-11-27") as s:
        _task4(s)


def _task4(s: Session) -> None:
    for level, u, w in ((2.5, "2.05", "3.1"), (3.5, "3.04", "4.9"), (4.5, "40.5", "6.7")):
        assert s.enter(f"u_ss@{level:g}", u).ok
        assert s.enter(f"omega_ss@{level:g}", w).ok
    assert s.step_status("task4") == "warned"
    assert s.enter("u_ss@4.5", "4.02").ok
    assert s.step_status("task4") == "done"


def test_one_unit_and_the_typed_digits_for_each_quantity(tmp_path):
    """Walk 6, defect 6: f typed in N m s/rad came back as 'computed 0.001861 N m s/rad'
    under its entry and in the report while the table says mN m s/rad; u_ss typed '4,05'
    read '4.050 V' in K's working; a T typed in s came back in s beside T in ms; an exact
    match read '< 0.05 %'; the report's Preparation table gave '3,79' where the others
    normalise."""
    with _lab(tmp_path) as s:
        s.enter("own.f", "0,00186 N m s/rad")
        (_, (own, comp)), *_ = [(k, v) for k, v in _compare(s, "table").items() if "f" in k]
        assert (
            own == "1.86 mN m s/rad"
            and " mN m s/rad" in comp
            and " N m s/rad" not in (comp.replace("mN m s/rad", ""))
        ), (own, comp)
        f_view = views.entry(s, "own.f")
        assert f_view is not None and "mN m s/rad" in f_view.feedback, f_view.feedback
        assert " N m s/rad" not in f_view.feedback.replace("mN m s/rad", "")
        s.enter("own.omega_step", "7,8")
        s.enter("own.K", "1,93")
        (k,) = [c for c in s.comparisons("task11") if c.key == "own.K"]
        assert "÷ 4.05 V" in k.how, k.how
        s.enter("own.T", "57")
        (_, (own, comp)), *_ = _compare(s, "task12").items()
        assert own == "57 ms" and " s (" not in comp and " ms" in comp, (own, comp)
        s.enter("own.omega_5", "9,65")
        (w5,) = [c for c in s.comparisons("task15") if c.key == "own.omega_5"]
        assert w5.rel_diff is not None and format_diff(w5.rel_diff) == "0 %"
        said = views.entry(s, "own.omega_5")
        assert said is not None and said.feedback.startswith("✓ right: 0 % from "), said
        s.enter("prep6.y10", "3,79")
        rows = own_first.table_rows(s)
        f_row = next(r for r in rows if r.key == "own.f").cells
        assert f_row[1] == "1.86 mN m s/rad" and " mN m s/rad (" in f_row[2], f_row
        md = markdown(build_report(s))
    prep = next(line for line in md.splitlines() if line.startswith("| Preparation 6"))
    assert "| 3.79 |" in prep and "3,79" not in prep, prep
    assert "4.050" not in md
