"""``-`` on the command line (s36 attack, left: `identify -` said "No such file"): the CSV
inputs of identify and analyze read stdin, as /dev/stdin already did, named "stdin" in
their messages; stdin is read once; a terminal on stdin is refused at once; an argument
naming a folder or a file to write refuses ``-`` in one line instead of making a file or
folder called '-'. The real CLI as a process (its stdin a pipe, a file, a terminal)."""

from __future__ import annotations

import json
import os
import pty
import subprocess
import sys
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.saving.files import write_run_log
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import make_log

TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,5.8,34\n4.5,4.05,7.8,37\n"


def _cli() -> list[str]:
    exe = Path(sys.executable).with_name("minseg-tui")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]


def _run(argv: list[str], stdin: bytes | None, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*_cli(), *argv],
        input=None if stdin is None else stdin.decode(),
        stdin=subprocess.DEVNULL if stdin is None else None,
        capture_output=True,
        text=True,
        timeout=120,
        cwd=cwd,
    )


def test_identify_reads_its_table_from_stdin(tmp_path):
    (tmp_path / "table.csv").write_text(TABLE)
    by_name = _run(["identify", "table.csv", "--R", "5.3", "--json"], None, tmp_path)
    piped = _run(["identify", "-", "--R", "5.3", "--json"], TABLE.encode(), tmp_path)
    assert piped.returncode == 0 and piped.stderr == ""
    assert json.loads(piped.stdout) == json.loads(by_name.stdout)


def test_analyze_reads_its_log_from_stdin_and_names_it_stdin(tmp_path):
    log = make_log("none", param=0, seed=3)
    write_run_log(
        tmp_path / "log.csv",
        RunLog(t=log.t, u=log.u, omega=log.omega, extra={"count": log.count, "u_req": log.u_req}),
    )
    data = (tmp_path / "log.csv").read_bytes()
    piped = _run(["analyze", "-", "--json"], data, tmp_path)
    by_name = _run(["analyze", "log.csv", "--json"], None, tmp_path)
    assert piped.returncode == 0 and piped.stderr == ""
    assert json.loads(piped.stdout) == json.loads(by_name.stdout)
    broken = _run(["analyze", "-"], data.replace(b"t,u,omega", b"t,u,speed", 1), tmp_path)
    assert broken.returncode == 2
    assert broken.stderr.startswith("minseg-tui analyze: stdin:"), broken.stderr
    assert broken.stderr.count("\n") == 1 and "Traceback" not in broken.stderr


def test_an_empty_stdin_is_one_line(tmp_path):
    proc = _run(["identify", "-", "--R", "5.3"], None, tmp_path)
    assert proc.returncode == 2
    assert proc.stderr == (
        "minseg-tui identify: stdin: expected a header row 'u_req,u_ss,omega_ss,i_ss', "
        "the file is empty\n"
    )


def test_stdin_is_read_once(tmp_path, capsys):
    assert main(["identify", "-", "--R", "5.3", "--step", "-"]) == 2
    err = capsys.readouterr().err
    assert err == (
        "minseg-tui identify: TABLE.csv and --step -: stdin can be read only once: give all "
        "but one of these as a file\n"
    )


def test_a_terminal_on_stdin_is_refused_at_once(tmp_path):
    primary, secondary = pty.openpty()
    try:
        proc = subprocess.run(
            [*_cli(), "identify", "-", "--R", "5.3"],
            stdin=secondary,
            capture_output=True,
            text=True,
            timeout=60,  # before: read the terminal, then 10 s of "nothing arrived"
        )
    finally:
        os.close(primary)
        os.close(secondary)
    assert proc.returncode == 2
    assert proc.stderr == (
        "minseg-tui identify: stdin: is a terminal: pipe the file in (< FILE.csv) or give "
        "its name\n"
    )


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["report", "-"], "SESSION"),
        (["report", "g", "--sessions", "-"], "--sessions"),
        (["class", "--sessions", "-"], "--sessions"),
        (["class", "--sessions", "s", "--out", "-"], "--out"),
        (["analyze", "log.csv", "--predictions", "-"], "--predictions"),
    ],
)
def test_dash_is_no_folder_or_output_name(tmp_path, capsys, monkeypatch, argv, flag):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s").mkdir()
    (tmp_path / "log.csv").write_text("t,u,omega\n0,0,0\n")
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"minseg-tui {argv[0]}: {flag}: expected "), err
    assert err.count("\n") == 1 and ", got - (" in err
    assert not (tmp_path / "-").exists() and not (tmp_path / "s" / "-").exists()


@pytest.mark.parametrize(
    ("value", "said"),
    [
        ("", "minseg-tui tui: --sessions: expected a folder, got ''\n"),
        (
            "-",
            "minseg-tui tui: --sessions: expected the folder of the sessions, got - (only a CSV "
            "to read, as identify's TABLE.csv, takes - for stdin)\n",
        ),
    ],
)
def test_the_lab_assistant_refuses_an_empty_or_dash_sessions_folder(
    tmp_path, capsys, monkeypatch, value, said
):
    """'--sessions ""' listed the folder it was started in as the sessions folder (Path('')
    is '.'); '--sessions -' made a folder called '-'."""
    monkeypatch.chdir(tmp_path)
    assert main(["--sim", "--sessions", value]) == 2
    assert capsys.readouterr().err == said
    assert list(tmp_path.iterdir()) == []
