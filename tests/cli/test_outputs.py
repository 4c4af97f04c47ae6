"""Outputs and arguments the headless commands must refuse without a hang or a traceback
(issue 18, items 6, 9 and 12): a FIFO or a device as --predictions, empty file names, a
closed stdout, a memory limit."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.lab.saving.files import write_run_log
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import make_log

TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,5.8,34\n4.5,4.05,7.8,37\n"


def _cli() -> list[str]:
    exe = Path(sys.executable).with_name("minseg-tui")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]


def _log(path: Path) -> Path:
    log = make_log("none", param=0, seed=3)
    write_run_log(path, RunLog(t=log.t, u=log.u, omega=log.omega, extra={"count": log.count}))
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


def _with_files(tmp_path, argv):
    """``argv`` with LOG and TABLE replaced by a run log and a table written in tmp_path."""
    _log(tmp_path / "log.csv")
    (tmp_path / "table.csv").write_text(TABLE)
    files = {"LOG": str(tmp_path / "log.csv"), "TABLE": str(tmp_path / "table.csv")}
    return [files.get(a, a) for a in argv]


@pytest.mark.parametrize(
    ("argv", "what"),
    [
        (["analyze", "LOG", "--predictions", ""], "--predictions: expected a file name"),
        (["identify", "TABLE", "--R", "5.3", "--step", ""], "--step: expected a run log file"),
    ],
)
def test_an_empty_file_name_is_refused(tmp_path, capsys, argv, what):
    argv = _with_files(tmp_path, argv)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and what in err, err


def _closed_stdout() -> None:
    os.close(1)


@pytest.mark.parametrize(
    "argv",
    [
        ["ports"],
        ["ports", "--json"],
        ["analyze", "LOG"],
        ["identify", "TABLE", "--R", "5.3"],
        ["--help"],
    ],
)
def test_a_closed_stdout_is_one_line_and_exit_2(tmp_path, argv):
    """`minseg-tui ports >&-`: Python starts with sys.stdout None; exit 2 as /dev/full does."""
    argv = _with_files(tmp_path, argv)
    proc = subprocess.run(
        [*_cli(), *argv],
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
        preexec_fn=_closed_stdout,
    )
    cmd = argv[0] if not argv[0].startswith("-") else ""
    _one_line(
        proc,
        2,
        f"minseg-tui{' ' if cmd else ''}{cmd}: cannot write the output (stdout is closed)",
        "",
    )


@pytest.fixture(scope="module")
def big_log(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """2M rows (59 MB, written once for the module: writing it takes seconds); the commands
    only read it."""
    return _big_log(tmp_path_factory.mktemp("big") / "log.csv", 2_000_000)


BLOCK_ROWS = 100_000
"""Rows :func:`_big_log` formats at once (a few MB of text)."""


def _big_log(path: Path, rows: int) -> Path:
    t = np.arange(rows) * 0.001
    u = np.where((t // 1.5) % 2 == 0, 2.5, 0.0)
    omega = 2 * u * (1 - np.exp(-(t % 1.5) / 0.045))
    # the text np.savetxt(fmt="%.6f", delimiter=",") writes, formatted a block of rows at a
    # time: savetxt formats row by row, about four times the CPU (some 8 s for 2M rows)
    table = np.column_stack([t, u, omega])
    with path.open("w") as fh:
        fh.write("t,u,omega\n")
        for block in np.array_split(table, max(1, rows // BLOCK_ROWS)):
            fh.write(("%.6f,%.6f,%.6f\n" * len(block)) % tuple(block.ravel().tolist()))
    return path


@pytest.mark.xdist_group("big-log")  # both on one worker (make test): big_log written once
@pytest.mark.parametrize(
    ("argv", "mib"),
    [(["analyze", "LOG"], 300), (["identify", "TABLE", "--R", "5.3", "--step", "LOG"], 500)],
)
def test_a_memory_limit_is_named_in_one_line(tmp_path, big_log, argv, mib):
    """2M rows under an address-space limit (ulimit -v): the limit said, no traceback."""
    log = big_log
    (tmp_path / "table.csv").write_text(TABLE)
    argv = [
        str(log) if a == "LOG" else str(tmp_path / "table.csv") if a == "TABLE" else a for a in argv
    ]
    limit = mib * 2**20

    def limited() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    proc = subprocess.run(
        [*_cli(), *argv],
        capture_output=True,
        text=True,
        timeout=600,
        preexec_fn=limited,
    )
    _one_line(
        proc,
        1,
        f"minseg-tui {argv[0]}: ran out of memory: this process may use at most {mib} MiB of "
        "address space (ulimit -v, RLIMIT_AS)",
        "raise that limit or give a shorter input",
    )
