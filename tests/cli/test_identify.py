"""`minseg-tui identify` end to end, with real files."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.lab.content.steps import FIELDS
from minseg_tui.lab.saving.files import write_run_log
from minseg_tui.lab.state.entries import read_entry
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.quantities import format_number, format_reading
from minseg_tui.signals import timestamp_velocity

MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3)
T_TRUE = 5.0 * 1.3e-3 / (5.0 * 6e-4 + 0.5 * 0.325)
TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3.05,5.5,35\n4.5,4.0,7.2,40\n"


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("identify")
    (d / "table.csv").write_text(TABLE)
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=0.5)
    rec = record(params, square_wave(0.0, 4.5, 40, 3, lead=20), ts=0.025, seed=7, jitter_us=2000)
    log = RunLog(
        t=rec.t,
        u=rec.u_A,
        omega=timestamp_velocity(rec.t, rec.count),
        extra={"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us},
    )
    write_run_log(d / "log.csv", log, {"source": "plant, seed 7"})
    return d


def test_human_report(files, capsys):
    code = main(
        ["identify", str(files / "table.csv"), "--R", "5", "--step", str(files / "log.csv")]
    )
    out = capsys.readouterr().out
    assert code == 0
    kv = sorted([(2.1 - 0.15) / 3.6, (3.05 - 0.175) / 5.5, (4.0 - 0.2) / 7.2])[1]
    assert f"k_v = {kv:.4g} V s/rad" in out
    assert f"k_a = {0.65 * kv:.4g} N m/A" in out
    for text in (
        "u_req V",
        "T, 63 % reading",
        "T, least squares",
        "95 % interval",
        "the model uses this T",
        "J = T (R f + k_v k_a) / R",
        "w' = -w +",
        "At u_A = 5 V",
        "What the numbers show:",
        "dry (Coulomb) friction",
        "rad/s per V +- ",  # K's 95 % interval
        "time shift of the steps",
        "half a sample late",  # why the 63 % reading is longer than T
    ):
        assert text in out


def test_f_is_in_mN_m_s_per_rad_in_the_human_text(files, capsys):
    """The table's column, the f line and the dry-friction sentence said N m s/rad while
    the TUI's table and Task 9's entry use mN m s/rad: one unit for f in all human text
    (the JSON keeps SI)."""
    assert main(["identify", str(files / "table.csv"), "--R", "5"]) == 0
    out = capsys.readouterr().out
    kv = sorted([(2.1 - 0.15) / 3.6, (3.05 - 0.175) / 5.5, (4.0 - 0.2) / 7.2])[1]
    f = sorted(0.65 * kv * i / w for i, w in ((0.030, 3.6), (0.035, 5.5), (0.040, 7.2)))[1]
    # with the four digits of the TUI's table (it had three, in the rows too)
    assert f"f   = {format_number(f * 1e3)} mN m s/rad (Task 9" in out
    assert "f mN m s/rad" in out  # the table's column
    assert "f falls with speed, from " in out
    assert " N m s/rad" not in out.replace("mN m s/rad", "")
    assert main(["identify", str(files / "table.csv"), "--R", "5", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["f"] == pytest.approx(f, rel=1e-12)


def test_json_is_one_object_with_the_contract(files, capsys):
    code = main(
        [
            "identify",
            str(files / "table.csv"),
            "--R",
            "5",
            "--step",
            str(files / "log.csv"),
            "--json",
        ]
    )
    out = capsys.readouterr().out
    assert code == 0 and out.count("\n") == 1
    j = json.loads(out)
    assert set(j) == {"R", "rows", "k_v", "k_a", "f", "step", "model", "omega_at_5V"} | {
        "omega_at_5V_with_friction"
    }
    added = {"K_ci", "T_63_model", "T_63_note", "method", "shift", "u_c"}
    added |= {"dead_time", "T_determined", "T_on_bound", "shift_on_bound"}
    added |= {"glitch_rows", "left_out_rows", "T_rise_rows", "T_shift_free"}
    assert set(j["step"]) == {"K", "T", "T_63", "T_ci", "J", "omega_ss"} | added
    assert set(j["model"]) == {"T", "K", "dead_time", "u_c", "K_above_u_c"}
    # a frictionless plant: no dry friction found, Task 15 has one answer
    assert j["model"]["u_c"] == 0 and j["model"]["K_above_u_c"] is None
    assert j["omega_at_5V_with_friction"] is None
    assert [set(r) for r in j["rows"]] == [{"u_req", "u_ss", "omega_ss", "i_ss", "k_v", "f"}] * 3
    assert j["rows"][2]["i_ss"] == 40.0
    assert j["R"] == 5.0
    lo, hi = j["step"]["T_ci"]
    assert lo < j["step"]["T"] < hi and lo < T_TRUE < hi
    # the table's 4.5 V row says u_ss = 4.0 V: K = omega_ss / 4.0
    assert j["step"]["K"] == pytest.approx(j["step"]["omega_ss"] / 4.0, rel=1e-12)
    assert j["omega_at_5V"] == pytest.approx(5 * j["step"]["K"], rel=1e-12)


def test_json_without_step(files, capsys):
    assert main(["identify", str(files / "table.csv"), "--R", "5.3", "--json"]) == 0
    assert set(json.loads(capsys.readouterr().out)) == {"R", "rows", "k_v", "k_a", "f"}


def _log(dt: float, omega_on: float = 3.0, u_on: float = 4.0) -> str:
    """12 rows every dt s: a step to u_on V at row 3, the speed omega_on rad/s from row 4."""
    return "t,u,omega\n" + "".join(
        f"{k * dt!r},{0.0 if k < 3 else u_on!r},{0.0 if k < 4 else omega_on!r}\n" for k in range(12)
    )


BAD = [
    ("table.csv", "", [], "table.csv:", "file is empty"),
    ("table.csv", "u_req,u_ss,omega_ss\n2.5,2,3\n", [], "table.csv:1:", "expected a column i_ss"),
    ("table.csv", "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,x,30\n", [], "table.csv:2:", "got 'x'"),
    (
        "table.csv",
        "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3,0,35\n",
        [],
        "table.csv:3:",
        "omega_ss > 0",
    ),
    ("log.csv", "", ["--step"], "log.csv:", "file is empty"),
    ("log.csv", "t,u\n0,0\n0.1,4\n", ["--step"], "log.csv:1:", "expected a column omega"),
    ("log.csv", "t,u,omega\n0,0,0\n0.025,4,nan\n", ["--step"], "log.csv:3:", "got 'nan'"),
    (
        "log.csv",
        "t,u,omega\n0,0,0\n0.05,4,1\n0.04,4,1\n",
        ["--step"],
        "log.csv:4:",
        "expected t (s) to increase",
    ),
    ("log.csv", "t,u,omega\n0,4,0\n0.025,4,1\n", ["--step"], "log.csv:2:", "expected a step"),
    (
        "log.csv",
        "t,u,omega\n0,4,0\n0.025,0,1\n0.05,0,1\n",
        ["--step"],
        "log.csv:2:",
        "expected a rising edge",
    ),
    (
        "table.csv",
        "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,1e308\n",
        [],
        "table.csv:2:",
        "plausible size",
    ),
    ("log.csv", _log(0.025, omega_on=0.0), ["--step"], "log.csv:", "omega stays at 0"),
    ("log.csv", _log(25.0), ["--step"], "log.csv:", "sample period"),
    ("log.csv", _log(1e-300), ["--step"], "log.csv:", "sample period"),
    ("log.csv", _log(0.025, u_on=1e300), ["--step"], "log.csv:", "|u (V)| below"),
    (
        "log.csv",
        "t,u,omega,t_us\n"
        + "".join(
            f"{k * 0.025},{4 * (k >= 3)},{3 * (k >= 4)},{(20 - k) * 25000}\n" for k in range(12)
        ),
        ["--step"],
        "log.csv:",
        "expected t_us (us) to keep time with t (s)",  # a t_us that runs backwards
    ),
]


@pytest.mark.parametrize(("name", "text", "flag", "where", "what"), BAD)
def test_bad_input_exits_2_with_one_line(tmp_path, capsys, name, text, flag, where, what):
    (tmp_path / "table.csv").write_text(TABLE)
    bad = tmp_path / name
    bad.write_text(text)
    args = ["identify", str(tmp_path / "table.csv"), "--R", "5"] + (
        [*flag, str(bad)] if flag else []
    )
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith(f"minseg-tui identify: {tmp_path / where}"), err
    assert what in err


@pytest.mark.parametrize("R", ["0", "-5", "abc", "nan"])
def test_bad_R_exits_2(files, capsys, R):
    with pytest.raises(SystemExit) as exc:
        main(["identify", str(files / "table.csv"), f"--R={R}"])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "expected a resistance in Ω" in err


def test_console_script(files):
    exe = Path(sys.executable).with_name("minseg-tui")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]
    ok = subprocess.run(
        [
            *cmd,
            "identify",
            str(files / "table.csv"),
            "--R",
            "5",
            "--step",
            str(files / "log.csv"),
            "--json",
        ],
        capture_output=True,
        text=True,
        timeout=60,
        env={**os.environ, "PYTHONWARNINGS": "error"},
    )
    assert ok.returncode == 0, ok.stderr
    assert np.isfinite(json.loads(ok.stdout)["step"]["T"])
    bad = subprocess.run(
        [*cmd, "identify", str(files / "missing.csv"), "--R", "5"],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert bad.returncode == 2 and bad.stdout == ""
    assert bad.stderr.strip().endswith(
        "missing.csv: cannot read the file (No such file or directory)"
    )
    assert "Traceback" not in bad.stderr


@pytest.mark.parametrize("typed", ["5,3", "5,3 ohm", "5.3 Ω", "5300 mΩ", "5,30", " 5.3ohms "])
def test_R_is_read_as_the_tui_reads_task_2s_entry(files, capsys, typed):
    """A lab assistant types R the way a student does: the decimal comma and a unit, which
    Task 2's entry reads ('5,3 ohm' is 5.3 Ω), were refused here ("expected a resistance in
    ohm, got '5,3'", exit 2). The CLI reads --R with the TUI's own reader."""
    tui = read_entry(FIELDS["R"], typed)
    assert tui.ok and tui.value == pytest.approx(5.3, rel=1e-15)
    assert main(["identify", str(files / "table.csv"), "--R", typed, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["R"] == tui.value
    assert main(["identify", str(files / "table.csv"), "--R", typed]) == 0
    # the digits typed, as the TUI keeps them (walk 13, D6): '5,30' is 5.30, not 5.3
    shown = "5.30" if typed == "5,30" else "5.3"
    assert capsys.readouterr().out.startswith(f"R = {shown} ohm (Task 2)\n")


@pytest.mark.parametrize("typed", ["5,3 V", "abc", "0", "-5", "6_1", "1e308", "3k"])
def test_R_refused_with_the_tui_entrys_words(files, capsys, typed):
    """A text Task 2's entry refuses is refused here with the same words, in one line."""
    tui = read_entry(FIELDS["R"], typed)
    assert not tui.ok
    with pytest.raises(SystemExit) as info:
        main(["identify", str(files / "table.csv"), f"--R={typed}"])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert err.startswith("minseg-tui identify: argument --R: "), err
    assert tui.message.removeprefix("R: ") + " (see " in err, err


@pytest.mark.parametrize("typed", ["53", "0,5", "25 ohm"])
def test_R_outside_the_usual_range_gets_the_tui_s_question_on_stderr(files, capsys, typed):
    """'--R 53' (5,3 typed without its comma) was taken with no word, while Task 2's entry
    asks whether a decimal comma was lost. The CLI asks the same, in the entry's words, in
    one line on stderr; the value stays accepted (exit 0), as in the TUI, and the output is
    computed with it."""
    tui = read_entry(FIELDS["R"], typed)
    assert tui.ok and len(tui.warnings) == 1
    for json_too in ([], ["--json"]):
        assert main(["identify", str(files / "table.csv"), "--R", typed, *json_too]) == 0
        got = capsys.readouterr()
        assert got.err.count("\n") == 1, got.err
        assert got.err == (
            f"minseg-tui identify: note: --R {typed}: {tui.warnings[0]}; "
            f"computed with R = {format_reading(tui.value, '', typed=typed)} ohm\n"
        )
    assert json.loads(got.out)["R"] == tui.value


def test_R_in_the_usual_range_gets_no_note(files, capsys):
    assert read_entry(FIELDS["R"], "5,3").warnings == ()
    assert main(["identify", str(files / "table.csv"), "--R", "5,3"]) == 0
    assert capsys.readouterr().err == ""


def test_R_the_table_refuses_gets_the_refusal_alone(files, capsys):
    """At 120 Ω the table's rows give no positive k_v: one line, the refusal (which says to
    check R), exit 2; the note is not added to it."""
    assert read_entry(FIELDS["R"], "120").warnings
    assert main(["identify", str(files / "table.csv"), "--R", "120"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "check R" in err and "note" not in err, err
