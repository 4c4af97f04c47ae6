"""Steps K and T cannot come from say so, in one sentence, wherever identify runs (issue 18,
item 4): a step that ends below the driver's drop in the table, steps that only go negative
(they rise to 0 V) and an angle (count or theta column) that never changes were each a
ZeroDivisionError: a traceback in the CLI, in report and in the TUI, on every resume."""

from __future__ import annotations

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.content.u_ss_says import zero_volt_refusal
from minseg_tui.lab.saving.files import read_run_log, read_table, write_run_log
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.model.identify import ZeroVoltRefusal, identify, response_alone
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.signals import timestamp_velocity

MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3)
TABLE_CSV = "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3.05,5.5,35\n4.5,4.0,7.2,40\n"
ENTRIES = {
    "R": "5",
    **{f"u_ss@{lv}": u for lv, u in (("2.5", "2.1"), ("3.5", "3.05"), ("4.5", "4.0"))},
    **{f"omega_ss@{lv}": w for lv, w in (("2.5", "3.6"), ("3.5", "5.5"), ("4.5", "7.2"))},
    **{f"i_ss@{lv}": f"{i} mA" for lv, i in (("2.5", 30), ("3.5", 35), ("4.5", 40))},
}

CASES = {
    # the log's steps rise to 0.3 V requested: the table puts that below the drop, 0 V
    "below the drop": ("0 V on the motor (below the driver's drop in the table)", 4.5, "drop"),
    # steps from 0 to -4.5 V: the rising edges end at 0 V, where the driver is off
    "negative only": ("0 V on the motor (the driver is off at 0 V)", -4.5, ""),
    "count never changes": ("its angle (the encoder count) never changes", 4.5, "count"),
    "theta never changes": ("its angle (the theta column) never changes", 4.5, "theta"),
}


def _log(path, high: float, how: str) -> None:
    """A seeded plant's square wave 0 <-> ``high`` V as a run log, altered as ``how`` says."""
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=0.5)
    rec = record(params, square_wave(0.0, high, 40, 3, lead=20), ts=0.025, seed=7, jitter_us=2000)
    extra = {"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us}
    if how == "drop":
        extra["u_req"] = rec.u_req * (0.3 / high)
    elif how == "count":
        extra["count"] = rec.count * 0
    elif how == "theta":
        del extra["count"]
        extra["theta"] = rec.count * 0.0 + 1.0
    omega = timestamp_velocity(rec.t, rec.count)  # the speed column as logged
    write_run_log(path, RunLog(t=rec.t, u=rec.u_A, omega=omega, extra=extra), {})


@pytest.mark.parametrize("case", list(CASES))
def test_identify_says_what_is_missing_in_one_line(tmp_path, capsys, case):
    words, high, how = CASES[case]
    (tmp_path / "table.csv").write_text(TABLE_CSV)
    _log(tmp_path / "log.csv", high, how)
    code = main(
        ["identify", str(tmp_path / "table.csv"), "--R", "5", "--step", str(tmp_path / "log.csv")]
    )
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and words in err and "Traceback" not in err


@pytest.mark.parametrize("case", list(CASES))
def test_the_session_and_report_say_what_is_missing_and_reopen(tmp_path, capsys, case):
    words, high, how = CASES[case]
    _log(tmp_path / "log.csv", high, how)
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-26") as s:
        for key, text in ENTRIES.items():
            s.enter(key, text)
        # chosen for Tasks 11-15 (an import alone feeds the model check: walk 16, D3)
        s.select_run(s.import_run(tmp_path / "log.csv").name)
        res = s.results()
        assert res.identification is not None and res.identification.step is None
        assert any(words in p for p in res.problems)
        folder = s.folder
    with Session.open(folder) as again:  # a resume computes the same, without a crash
        assert any(words in p for p in again.results().problems)
    assert main(["report", str(folder)]) == 0
    capsys.readouterr()
    (md,) = folder.glob("*.md")
    assert words in md.read_text(encoding="utf-8")


@pytest.mark.parametrize(
    ("high", "how", "u_req", "how_u"),
    [(4.5, "drop", 0.3, "extrapolated"), (-4.5, "", 0.0, "off"), (-4.5, "noureq", None, "log")],
)
def test_a_rise_at_0_V_is_refused_with_a_record_and_worded_above_the_model(
    tmp_path, high, how, u_req, how_u
):
    """The model refuses a rise that ends at 0 V on the motor with a record (when, the level
    requested, how its u_ss was found), not words; lab/content/u_ss_says.py words it, the
    sentence the CLI and the session show."""
    (tmp_path / "table.csv").write_text(TABLE_CSV)
    _log(tmp_path / "log.csv", high, "drop" if how == "drop" else "")
    log = read_run_log(str(tmp_path / "log.csv"))
    if how == "noureq":  # a log without u_req: its own u (0 V at the top of each rise)
        log = RunLog(t=log.t, u=log.u, omega=log.omega, source=log.source, lines=log.lines)
    readings = read_table(str(tmp_path / "table.csv"))
    with pytest.raises(ZeroVoltRefusal) as refused:
        identify(readings, 5.0, log, source="table.csv")
    rise = refused.value.rise
    assert rise.how == how_u
    assert rise.u_req == (None if u_req is None else pytest.approx(u_req))
    assert refused.value.source == log.source and refused.value.line is not None
    with pytest.raises(ZeroVoltRefusal):  # Tasks 11-12 alone refuse it the same way
        response_alone(log, [(2.5, 2.1), (3.5, 3.05), (4.5, 4.0)])
    said = str(zero_volt_refusal(refused.value))
    assert said.startswith(f"{log.source}:{refused.value.line}: expected each rising edge")
    why = {
        "extrapolated": "below the driver's drop in the table",
        "off": "the driver is off at 0 V",
        "log": "the log's applied voltage",
    }[how_u]
    assert f"0 V on the motor ({why}), so K = omega_ss / u_ss cannot be computed" in said


def test_a_recorded_run_whose_count_never_changes_is_shown_without_a_fit(tmp_path):
    """An encoder not read while Task 10 records: every count 0. Task 10's view of the run
    was a ZeroDivisionError (the fit of T divided by a residual of zero)."""
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-26") as s:
        for key, text in ENTRIES.items():
            s.enter(key, text)
        rec = s.start_run("steps", ts=0.025)
        for k in range(400):
            rec.append(k, 25_000 * k, 0, 4500 if (k // 80) % 2 == 0 and k >= 4 else 0)
        info = s.finish_run(rec)
        assert info is not None
        (view,) = views.runs(s)
        assert view.name == info.name and view.T_ls is None and view.T_63 is None
        problems = " ".join(s.results().problems)
        assert f"run {info.name} gives no step result" in problems
        assert "omega stays at 0 rad/s" in problems
        assert views.results(s, "task11").problems


ODD_RUNS = {
    # the count moves once, on a negative step's plateau: the steps' own fit is exact (a
    # residual of zero that was divided by); the steps end at 0 V, so no K either
    "one count": (-4500, lambda k: 1 if k > 200 else 0, True),
    # the wheel turns backwards at one speed whatever the steps do (a singular matrix in
    # the fit before issue 18); identify may fit it or refuse it, never a traceback
    "a steady backward ramp": (4500, lambda k: -3 * k, False),
}


@pytest.mark.parametrize("case", list(ODD_RUNS))
def test_a_run_the_fit_cannot_take_is_a_sentence_everywhere(tmp_path, capsys, case):
    """Beyond the issue's three ways in, two recorded runs that were a traceback in the TUI
    and the CLI."""
    level, count, refused = ODD_RUNS[case]
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-26") as s:
        for key, text in ENTRIES.items():
            s.enter(key, text)
        rec = s.start_run("steps", ts=0.025)
        for k in range(400):
            rec.append(k, 25_000 * k, count(k), level if (k // 80) % 2 == 0 and k >= 4 else 0)
        info = s.finish_run(rec)
        assert info is not None
        views.runs(s)
        res = s.results()
        said = any(f"run {info.name} gives no step result" in p for p in res.problems)
        assert said == refused
        assert res.identification is not None and (res.identification.step is None) == refused
        views.results(s, "task11")
        log = s.run_path(info.name)
    (tmp_path / "table.csv").write_text(TABLE_CSV)
    code = main(["identify", str(tmp_path / "table.csv"), "--R", "5", "--step", str(log)])
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert (code, err.count("\n")) == ((2, 1) if refused else (0, 0))
