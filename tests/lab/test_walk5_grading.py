"""A second walk at 80x24 on the virtual MinSeg (issue 20), graded as a new group typed it:
a J off by the factor 1000 of f's unit is marked wrong with the slip named, a unitless T of
57 is refused as ambiguous, an answer with nothing to compare it with is not ticked, w_ss
means omega_ss in a formula, and '5,3 ohm' says what was stored. On a real session folder
with a run of the seeded plant (tests/lab/test_compare.py's)."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.expr import parse_formula
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from tests.lab.test_compare import _compare, _lab


def test_a_J_with_f_in_mN_m_s_per_rad_is_marked_wrong_and_told_the_unit(tmp_path):
    with _lab(tmp_path) as s:
        s.enter("own.T", "57 ms")
        s.enter("own.J", "0.057*(5.3*1.85+0.495*0.322)/5.3")  # f as the table shows it
        comp = _compare(s, "task13")["your J"][1]
        assert (
            "wrong: off by more than the 10 %" in comp
            and "f goes into this formula in N m s/rad" in comp
        )
        assert s.step_status("task13") == "wrong"
        assert views.judged(s, "own.J") == "marked wrong"
        ident = s.results().identification
        assert ident is not None
        J = 0.057 * (ident.R * ident.f + ident.k_v * ident.k_a) / ident.R
        s.enter("own.J", f"{J:.4g}")
        assert (
            s.step_status("task13") == "done" and "wrong" not in _compare(s, "task13")["your J"][1]
        )


def test_a_J_with_T_in_ms_is_told_so(tmp_path):
    with _lab(tmp_path) as s:
        s.enter("own.T", "57 ms")
        ident = s.results().identification
        assert ident is not None
        J = 57 * (ident.R * ident.f + ident.k_v * ident.k_a) / ident.R
        s.enter("own.J", f"{J:.4g}")
        assert "T goes into this formula in s, not ms" in _compare(s, "task13")["your J"][1]
        assert s.step_status("task13") == "wrong"


def test_far_off_readings_of_tasks_11_to_15_are_marked_wrong_close_ones_done(tmp_path):
    with _lab(tmp_path) as s:
        st = s.results().identification.step  # type: ignore[union-attr]
        s.enter("own.T", f"{st.T_63 * 1.1 * 1e3:.3g} ms")
        assert s.step_status("task12") == "done"
        s.enter("own.T", f"{st.T_63 * 2 * 1e3:.3g} ms")
        assert s.step_status("task12") == "wrong"
        s.enter("own.omega_step", f"{st.omega_ss:.3g}")
        s.enter("own.K", "19")
        assert s.step_status("task11") == "wrong"


def test_a_unitless_0_057_for_T_is_refused_as_ambiguous_not_taken_as_57_us(tmp_path):
    """T's entry is in ms: a bare 57 is 57 ms; a bare 0.057 (seconds typed without the unit)
    is refused with both readings offered."""
    with Session.create(tmp_path, ["A"]) as s:
        e = s.enter("own.T", "0.057")
        assert not e.ok and "'0.057' is ambiguous" in e.message
        assert "'57 ms' or '0.057 s'" in e.message
        assert s.enter("own.T", "57").ok and s.value("own.T") == pytest.approx(0.057)
        assert s.enter("own.T", "0.057 s").ok and s.enter("own.T", "57 s").ok


def test_an_answer_with_nothing_to_compare_it_with_is_stored_not_ticked(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:  # no table, no run
        assert s.enter("own.T", "57").ok
        assert s.step_status("task12") == "unjudged"
        view = views.entry(s, "own.T")
        # what the value it is judged by waits for, and where (walk 8, D7); the 63 % reading
        # needs only the run's speed, no u_ss (walk 18, D4)
        assert view is not None and view.feedback == (
            "○ stored, not judged yet: the value to compare with needs a step run (Task 10)"
        )
        assert s.enter("own.f", "1,855").ok
        assert s.step_status("table") == "unjudged"


def test_the_unjudged_mark_is_its_own_and_f1_says_what_it_means():
    """Issue 20: "stored, not judged yet" shared '…' with a step merely begun; it has a mark
    of its own, told apart from done, wrong, refused, started and not begun without colour."""
    marks = [mark for _, mark, _ in views.STATUS_MARKS]
    assert len(set(marks)) == len(marks) and " " not in marks
    assert f"{views.MARK['unjudged']} stored, not judged yet" in views.marks_legend()


def test_w_ss_and_w_and_omega_mean_omega_ss_in_a_formula():
    names = ("u_ss", "R", "i_ss", "omega_ss")
    env = {"u_ss": 2.0, "R": 1.0, "i_ss": 1.0, "omega_ss": 4.0}
    for spelt in ("w_ss", "w", "ω", "ω_ss", "omega"):
        assert parse_formula(f"(u_ss - R i_ss)/{spelt}", names).value(env) == 0.25


def test_prep11_with_w_ss_is_checked_not_refused(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        e = s.enter("prep11.k_v", "(u_ss - R*i_ss)/w_ss")
        assert e.ok, e.message
        assert s.step_status("prep11") == "done"


def test_a_decimal_comma_and_ohm_spelt_out_say_what_was_stored(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        e = s.enter("R", "5,3 ohm")
        assert e.ok and e.message == "read as 5.3 Ω"
        view = views.entry(s, "R")
        assert view is not None and view.message == "read as 5.3 Ω"
        assert s.enter("R", "5.3").message == ""  # written as the lab writes it: no echo
