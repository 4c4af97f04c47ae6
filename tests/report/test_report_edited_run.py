"""A run CSV edited by hand after the recording (s37 attack): with a row removed, the
report's table of runs said "500" samples, the number session.json recorded, beside a model
check that found a sample lost in the same file; now it says how many the file holds and
that it was changed. An untouched run is said as before."""

from __future__ import annotations

import os

from minseg_tui.cli import main
from tests.classview.build import group


def test_a_row_removed_by_hand_is_said(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    path = folder / "runs" / "steps-1.csv"
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    del lines[30]
    path.write_text("".join(lines), encoding="utf-8")
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8")
    assert "| steps-1 | steps | 499 (500 recorded) | 25 ms |" in report
    assert (
        "Run steps-1: its file runs/steps-1.csv was changed after the recording (edited by "
        "hand?): it holds 499 samples where 500 were recorded; what is computed from it uses "
        "the file as it is now."
    ) in report


def test_an_untouched_run_is_said_as_recorded(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8")
    assert "| steps-1 | steps | 500 | 25 ms | 0 | not interrupted | runs/steps-1.csv |" in report
    assert "were recorded" not in report


def test_a_fifo_or_a_device_in_place_of_a_run_file_is_not_read(tmp_path, capsys):
    """A FIFO put where runs/steps-1.csv was waited 10 s at every read of the run (three in
    one report, two per group in the class view); a link to /dev/zero read 4 KiB first."""
    fifo = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    zero = group(tmp_path / "s", ["Cy", "Di"], seed=4)
    (fifo / "runs" / "steps-1.csv").unlink()
    os.mkfifo(fifo / "runs" / "steps-1.csv")
    (zero / "runs" / "steps-1.csv").unlink()
    (zero / "runs" / "steps-1.csv").symlink_to("/dev/zero")
    for folder, what in ((fifo, "a FIFO (a named pipe)"), (zero, "a device or a socket")):
        assert main(["report", str(folder)]) == 0
        report = (folder / "report.md").read_text(encoding="utf-8")
        assert (
            f"Run steps-1 cannot be read: {folder / 'runs' / 'steps-1.csv'}: expected the "
            f"run's log file; this is {what}, not read"
        ) in report
