"""One mapping from requested to applied voltage, end to end (issue 9, item 5).

A row with u_ss is a row for this purpose whatever else it lacks: the recorded run's u
column, K of Task 11, its text on screen and the report all take u_ss from the same row,
and say so; with no row at the step's level all of them say it is extrapolated.
"""

from __future__ import annotations

import numpy as np
import pytest

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.check_says import resolution_how
from minseg_tui.model.plant import PlantParams, record
from minseg_tui.report.write import write_report

R = "5.26 Ω"
COMPLETE = (
    (2.5, "2.05 V", "3.82", "29.8 mA"),
    (3.5, "3.05 V", "5.81", "33.5 mA"),
)


def _record(s: Session, seed: int = 4) -> str:
    """A Task 10 run (0 V / 4.5 V steps) on the simulated MinSeg; its name."""
    plan = dict(step("task10").plans)["manual"]
    n = int(round(plan.duration / plan.ts))
    k = np.arange(n)
    u = np.where((k * plan.ts // plan.half_period) % 2 == 0, plan.high, plan.low)
    u = np.concatenate((np.zeros(20), u))
    data = record(PlantParams(), u, ts=plan.ts, seed=seed, jitter_us=1000)
    rec = s.start_run("steps", plan)
    for j in range(u.size):
        rec.append(int(data.seq[j]), int(data.t_us[j]), int(data.count[j]), int(round(u[j] * 1000)))
    info = s.finish_run(rec)
    assert info is not None
    return info.name


def _session(tmp_path, rows_45: dict[str, str]) -> Session:
    s = Session.create(tmp_path, ["A"], date="2026-11-22")
    s.enter("R", R)
    for lv, u, w, i in COMPLETE:
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)
    for name, text in rows_45.items():
        s.enter(f"{name}@4.5", text)
    return s


def _report_row(md: str, label: str) -> str:
    (line,) = [ln for ln in md.splitlines() if ln.startswith(f"| {label}")]
    return line


def _task11(s: Session) -> str:
    return "\n".join(views.results(s, "task11").lines)


def test_a_row_with_u_ss_but_no_i_ss_is_the_one_every_place_uses(tmp_path):
    """The issue's case: the 4.5 V row holds u_ss = 3.8 V (and omega_ss) but no i_ss yet."""
    with _session(tmp_path, {"u_ss": "3.8 V", "omega_ss": "7.6"}) as s:
        name = _record(s)
        log = s.load_run(name)
        high = np.asarray(log.extra["u_req"]) == 4.5
        assert set(np.asarray(log.u)[high]) == {3.8}  # the run's own log
        assert "4.5 V -> 3.8 V (the table's row)" in log.metadata["u"]
        st = s.results().identification.step
        assert (st.u_ss, st.u_ss_how) == (3.8, "row")  # Task 11
        assert st.K == pytest.approx(st.omega_ss / 3.8)
        assert len(s.readings()) == 2  # Tasks 6-9 still use the complete rows only
        text = _task11(s)
        assert "3.8" in text and "extrapolated" not in text
        md = write_report(s).markdown.read_text(encoding="utf-8")
        assert "u_ss = 3.8 V, the table's row" in _report_row(md, "K (Task 11)")
        assert "extrapolated" not in md and "No table row has" not in md
        # a new u_ss in that incomplete row: the run's u column and K follow at once
        s.enter("u_ss@4.5", "3.9 V")
        log2 = s.load_run(name)
        assert set(np.asarray(log2.u)[high]) == {3.9}
        assert s.results().identification.step.u_ss == pytest.approx(3.9)


def test_a_row_with_only_u_ss_counts(tmp_path):
    """No omega_ss and no i_ss at 4.5 V: its u_ss still maps the 4.5 V steps."""
    with _session(tmp_path, {"u_ss": "3.95 V"}) as s:
        name = _record(s)
        log = s.load_run(name)
        assert set(np.asarray(log.u)[np.asarray(log.extra["u_req"]) == 4.5]) == {3.95}
        st = s.results().identification.step
        assert (st.u_ss, st.u_ss_how) == (3.95, "row")
        assert not any(n.source.startswith("u_ss_") for n in s.warnings())


def test_no_row_at_the_level_is_extrapolated_and_said_so_everywhere(tmp_path):
    """No u_ss at 4.5 V: the 3.5 V row's driver drop (0.45 V) gives 4.05 V in the run, in
    Task 11 and in the report, each saying it is extrapolated."""
    with _session(tmp_path, {"omega_ss": "7.6"}) as s:
        name = _record(s)
        log = s.load_run(name)
        high = np.asarray(log.extra["u_req"]) == 4.5
        assert np.asarray(log.u)[high] == pytest.approx(4.05)
        assert "4.5 V -> 4.05 V (extrapolated" in log.metadata["u"]
        st = s.results().identification.step
        assert st.u_ss_how == "extrapolated" and st.u_ss == pytest.approx(4.05)
        assert "extrapolated" in _task11(s)
        md = write_report(s).markdown.read_text(encoding="utf-8")
        assert "extrapolated" in _report_row(md, "K (Task 11)")
        # the 4.5 V row is there (omega_ss 7.6): its u_ss is what is missing (walk 7, D15)
        assert "No table row has" not in md
        assert "u_ss at 4.5 V is not entered (Task 4)" in md and "extrapolated from" in md


def test_recorded_runs_say_how_their_speed_was_taken(tmp_path):
    """Every recorded run's header says # cpr: 720 and # omega_over: interval, and the model
    check of the session takes them from there instead of detecting them."""
    with _session(tmp_path, {"u_ss": "3.8 V"}) as s:
        head = s.run_path(_record(s)).read_text(encoding="utf-8").split("\nt,", 1)[0]
        assert "# cpr: 720" in head.splitlines() and "# omega_over: interval" in head.splitlines()
        samp = s.model_check().result.sampling
        assert samp.how == "header" and samp.over_interval
        assert resolution_how(samp) == "# cpr: 720"
        assert samp.resolution == pytest.approx(2 * np.pi / 720 / 0.025)
