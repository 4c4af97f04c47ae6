"""What identify says is true of the files it was given (issue 18, item 12, the lab's part):
how u_ss was found, 'the step fits the model' only with a step, omega_ss typed in rpm
flagged as i_ss in A is, and a row with a negative request refused."""

from __future__ import annotations

import numpy as np

from minseg_tui.cli import main
from minseg_tui.lab.saving.files import read_run_log, read_table, write_run_log
from minseg_tui.model.identify import identify
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.signals import timestamp_velocity

MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3)
TABLE_CSV = "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3.05,5.5,35\n4.5,4.0,7.2,40\n"
# k_v 0.5 V s/rad on every row and one f: nothing unusual to say about the table
QUIET_TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,1.944,3.6,28.8\n3.5,2.97,5.5,44\n4.5,3.888,7.2,57.6\n"


def _identify(tmp_path, capsys, table: str, *more: str) -> tuple[int, str, str]:
    (tmp_path / "table.csv").write_text(table)
    code = main(["identify", str(tmp_path / "table.csv"), "--R", "5", *more])
    out, err = capsys.readouterr()
    return code, out, err


def test_u_ss_is_said_extrapolated_when_the_median_step_was(tmp_path, capsys):
    """Steps requested at 2, 3 and 2 V against rows at 2.5, 3.5 and 4.5 V: the median u_ss
    is a 2 V step's, extrapolated; the middle step in time (3 V) was interpolated, and that
    is what was said."""
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=0.5)
    rec = record(params, square_wave(0.0, 4.5, 40, 3, lead=20), ts=0.025, seed=7, jitter_us=2000)
    high = rec.u_req > 0
    number = np.cumsum(np.diff(np.concatenate(([0], high.astype(int)))) == 1)  # step 1, 2, 3
    u_req = np.where(high, np.array([0.0, 2.0, 3.0, 2.0])[number], 0.0)
    log = RunLog(
        t=rec.t,
        u=rec.u_A,
        omega=timestamp_velocity(rec.t, rec.count),
        extra={"u_req": u_req, "count": rec.count, "t_us": rec.t_us},
    )
    write_run_log(tmp_path / "log.csv", log, {})
    (tmp_path / "t.csv").write_text(TABLE_CSV)
    result = identify(read_table(tmp_path / "t.csv"), 5.0, read_run_log(tmp_path / "log.csv"))
    assert result.step is not None
    assert sorted(s.u_req for s in result.step.rises) == [2.0, 2.0, 3.0]
    assert result.step.u_ss_how == "extrapolated"
    code, out, _ = _identify(tmp_path, capsys, TABLE_CSV, "--step", str(tmp_path / "log.csv"))
    assert code == 0 and "(extrapolated from the table)" in out


def test_no_run_log_claims_no_step(tmp_path, capsys):
    code, out, _ = _identify(tmp_path, capsys, QUIET_TABLE)
    assert code == 0
    assert "nothing unusual" in out and "step fits" not in out and "no run log" in out


def test_omega_ss_in_rpm_is_flagged_as_i_ss_in_amperes_is(tmp_path, capsys):
    rpm = 60.0 / (2.0 * np.pi)
    table = "u_req,u_ss,omega_ss,i_ss\n" + "".join(
        f"{lv},{u},{w * rpm:.4g},{i}\n"
        for lv, u, w, i in ((2.5, 2.1, 3.6, 30), (3.5, 3.05, 5.5, 35), (4.5, 4.0, 7.2, 40))
    )
    code, out, _ = _identify(tmp_path, capsys, table)
    assert code == 0
    assert out.count("looks like rpm, the table wants rad/s") == 3
    assert "(3.6 rad/s?)" in out
    code, out, _ = _identify(tmp_path, capsys, TABLE_CSV)  # in rad/s: nothing said
    assert code == 0 and "rpm" not in out


def test_a_negative_request_with_a_forward_speed_is_refused(tmp_path, capsys):
    table = TABLE_CSV.replace("\n3.5,", "\n-3.5,")
    code, out, err = _identify(tmp_path, capsys, table)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "table.csv:3: expected u_req > 0 V" in err
