"""A CSV as a German or Swedish spreadsheet saves it: columns separated by semicolons and
decimal commas (``t;u;omega``, ``0,025;4,5;3,61``). Stop 38 refused it in one line; it is
read now as the comma file it stands for when the whole file uses one decimal mark, and
refused in one line, naming both lines, when it mixes them (a point may then be a
thousands separator). Real files: identify's table through the CLI, a recorded run log
imported into a real session."""

from __future__ import annotations

import json

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.errors import InputError
from minseg_tui.lab.saving.files import read_run_log, write_run_log
from minseg_tui.lab.state.session import Session
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.signals import timestamp_velocity
from tests.seeded import Clock

TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3.05,5.5,35\n4.5,4.0,7.2,40\n"


def spreadsheet(text: str) -> str:
    """``text`` (a comma CSV) as a German spreadsheet saves it: data and header with
    semicolons and decimal commas, CRLF; comment lines kept as the text cells they are."""
    lines = [
        line if line.startswith("#") else line.replace(",", ";").replace(".", ",")
        for line in text.splitlines()
    ]
    return "\r\n".join(lines) + "\r\n"


def identify_out(path, capsys) -> tuple[int, str, str]:
    try:
        code = main(["identify", str(path), "--R", "5", "--json"])
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_identify_reads_a_semicolon_table_as_its_comma_twin(tmp_path, capsys):
    (tmp_path / "table.csv").write_text(TABLE, encoding="utf-8")
    (tmp_path / "tabelle.csv").write_text(spreadsheet(TABLE), encoding="utf-8")
    code, comma, _ = identify_out(tmp_path / "table.csv", capsys)
    assert code == 0
    code, semicolon, err = identify_out(tmp_path / "tabelle.csv", capsys)
    assert code == 0 and err == ""
    as_comma = json.loads(comma)
    as_semicolon = json.loads(semicolon)
    as_comma.pop("source", None)
    as_semicolon.pop("source", None)
    assert as_semicolon == as_comma


@pytest.mark.parametrize(
    ("text", "line", "said"),
    [
        (
            "u_req;u_ss;omega_ss;i_ss\n2.5;2.1;3.6;30\n3,5;3,05;5,5;35\n",
            3,
            "'3,5' has a decimal comma, and line 2 a decimal point ('2.5')",
        ),
        (
            "u_req;u_ss;omega_ss;i_ss\n2,5;2,1;3,6;30\n3,5;3,05;5,5;1.234,5\n",
            3,
            "'1.234,5' has both a point and a comma",
        ),
        (
            'u_req;u_ss;omega_ss;i_ss\n2,5;2,1;3,6;30\n# a note\n"3.5";3;5;35\n',
            4,
            "'3.5' has a decimal point, and line 2 a decimal comma ('2,5')",
        ),
    ],
)
def test_a_semicolon_table_with_both_marks_is_refused_in_one_line(
    tmp_path, capsys, text, line, said
):
    (tmp_path / "t.csv").write_text(text, encoding="utf-8")
    code, out, err = identify_out(tmp_path / "t.csv", capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f"t.csv:{line}: expected one decimal mark in a file separated by semicolons; " in err
    assert said in err


def _log(tmp_path):
    params = PlantParams(
        motor=MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3), tau_c=0.0, v_drop=0.5
    )
    rec = record(params, square_wave(0.0, 4.5, 40, 3, lead=20), ts=0.025, seed=7, jitter_us=2000)
    log = RunLog(
        t=rec.t,
        u=rec.u_A,
        omega=timestamp_velocity(rec.t, rec.count),
        extra={"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us},
    )
    write_run_log(tmp_path / "log.csv", log, {"source": "plant, seed 7"})
    return tmp_path / "log.csv"


def test_a_semicolon_run_log_imports_with_every_value(tmp_path):
    comma = _log(tmp_path)
    german = tmp_path / "Messung.csv"
    german.write_text(spreadsheet(comma.read_text(encoding="utf-8")), encoding="utf-8")
    want = read_run_log(comma)
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-28", clock=Clock()) as s:
        run = s.import_run(german)
        copy = read_run_log(s.folder / run.file)  # read again, as Tasks 11-15 read it
    assert run.samples == len(want)
    for got in (read_run_log(german), copy):
        for name in ("t", "u", "omega"):
            np.testing.assert_array_equal(getattr(got, name), getattr(want, name))
        for name in ("u_req", "count", "t_us"):
            np.testing.assert_array_equal(got.extra[name], want.extra[name])


def test_a_semicolon_run_log_with_both_marks_imports_nothing(tmp_path):
    text = spreadsheet(_log(tmp_path).read_text(encoding="utf-8")).splitlines()
    row = next(k for k, line in enumerate(text) if line[:1].isdigit() and "," in line) + 30
    text[row] = text[row].replace(",", ".")
    bad = tmp_path / "Messung.csv"
    bad.write_text("\n".join(text) + "\n", encoding="utf-8")
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-28", clock=Clock()) as s:
        with pytest.raises(InputError) as refused:
            s.import_run(bad)
        assert s.runs == [] or all(r.kind != "imported" for r in s.runs)
        assert not any((s.folder / "runs").glob("*imported*"))
    said = str(refused.value)
    assert said.startswith(f"{bad}:{row + 1}: expected one decimal mark") and "\n" not in said
