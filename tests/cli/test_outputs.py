"""Outputs and arguments the headless commands must refuse without a hang or a traceback
(issue 18, items 6, 9 and 12): a FIFO or a device as --predictions, empty file names, a
closed stdout, a memory limit."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.files import write_step_log
from minseg_tui.model.steplog import StepLog
from minseg_tui.model.synth import make_log

TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,5.8,34\n4.5,4.05,7.8,37\n"


def _cli() -> list[str]:
    exe = Path(sys.executable).with_name("minseg-tui")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]


def _log(path: Path) -> Path:
    log = make_log("none", param=0, seed=3)
    write_step_log(path, StepLog(t=log.t, u=log.u, omega=log.omega, extra={"count": log.count}))
    return path


def _one_line(proc: subprocess.CompletedProcess[str], code: int, start: str, what: str) -> None:
    assert proc.returncode == code, proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert proc.stderr.startswith(start), proc.stderr
    assert what in proc.stderr, proc.stderr


def test_predictions_into_a_fifo_nobody_reads_is_refused_at_once(tmp_path):
    log = _log(tmp_path / "log.csv")
    fifo = tmp_path / "out.csv"
    os.mkfifo(fifo)
    proc = subprocess.run(
        [*_cli(), "analyze", str(log), "--predictions", str(fifo)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    _one_line(
        proc, 2, f"minseg-tui analyze: {fifo}: ", "expected a regular file for the predictions"
    )
    assert "FIFO" in proc.stderr and proc.stdout == ""


def test_predictions_into_a_device_are_refused(tmp_path, capsys):
    log = _log(tmp_path / "log.csv")
    assert main(["analyze", str(log), "--predictions", "/dev/null"]) == 2
    err = capsys.readouterr().err
    assert err == (
        "minseg-tui analyze: /dev/null: expected a regular file for the predictions; "
        "this is a device, not written\n"
    )


@pytest.mark.parametrize(
    ("argv", "what"),
    [
        (["analyze", "LOG", "--predictions", ""], "--predictions: expected a file name"),
        (["identify", "TABLE", "--R", "5.3", "--step", ""], "--step: expected a step log file"),
    ],
)
def test_an_empty_file_name_is_refused(tmp_path, capsys, argv, what):
    _log(tmp_path / "log.csv")
    (tmp_path / "table.csv").write_text(TABLE)
    argv = [
        str(tmp_path / "log.csv")
        if a == "LOG"
        else str(tmp_path / "table.csv")
        if a == "TABLE"
        else a
        for a in argv
    ]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and what in err, err
