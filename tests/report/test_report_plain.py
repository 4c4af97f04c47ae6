"""Issue 20, second walk: the report's sentences a group and its instructor read without a
specialist beside them (the sampling said as "a sample every 25 ms", the capture windows
with the clock they count on, the two readings of T both fair). Real session folders
written with the Session API, the seeded simulated motor."""

from __future__ import annotations

import re
from datetime import datetime
from pathlib import Path

import numpy as np

from minseg_tui.lab.state.session import Session
from minseg_tui.report import content, markdown
from tests.seeded import Clock, record_square_wave


def _session(root: Path, jitter_us: float) -> Session:
    """A group with the table typed and a step run of the seeded plant, its loop late by up
    to ``jitter_us`` (0: every interval exactly 25 ms, as the virtual board samples)."""
    s = Session.create(root, ["Ada", "Bo"], date="2026-11-22", clock=Clock())
    s.enter("R", "5.26 Ω")
    for lv, u, w, i in ((2.5, "2.05", "3.82", "29.8"), (3.5, "3.05", "5.81", "33.5")):
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)
    record_square_wave(s, seed=21, jitter_us=jitter_us)
    return s


def _log_line(md: str) -> str:
    (line,) = [ln for ln in md.splitlines() if "The log:" in ln]
    return line


def test_the_sampling_is_said_as_how_often_a_sample_came(tmp_path: Path) -> None:
    """Issue 20, item 4: "sample times 25-25 ms around 25 ms" was the report's (and the
    model check's) sentence for a board that samples every 25 ms."""
    with _session(tmp_path / "even", 0.0) as s:
        line = _log_line(markdown.render(content.build(s)))
    assert "sample times" not in line and "25-25" not in line, line
    assert "The log: a sample every 25 ms;" in line, line
    with _session(tmp_path / "late", 800.0) as s:
        line = _log_line(markdown.render(content.build(s)))
    got = re.search(r"a sample every ([\d.]+)-([\d.]+) ms \(mostly 25 ms\)", line)
    assert got is not None, line
    assert float(got.group(1)) < 25 < float(got.group(2))


def test_the_warning_on_a_short_T_leaves_both_readings_fair(tmp_path: Path) -> None:
    """Issue 20, second walk: the warning on a T of a few samples said "The least-squares T
    models the sampling and is the one to use", while Task 12 accepts the group's 63 %
    reading as right. It now says why the two differ and which one the model uses."""
    with _session(tmp_path, 0.0) as s:
        s.enter("own.T", "57 ms")  # the 63 % reading, as the manual has the group read it
        md = markdown.render(content.build(s))
    warnings = md.split("## Warnings")[1].split("\n## ")[0]
    (short,) = [ln for ln in warnings.splitlines() if "sample periods" in ln]
    assert "one to use" not in md
    assert "Both are fair readings of T" in short, short
    assert "the program's model and its least-squares J use the least-squares one" in short
    assert "so the two differ" in short


def test_the_capture_windows_say_what_clock_they_count_on(tmp_path: Path) -> None:
    """Issue 20, second walk: the table's capture windows read "222–224 s" with nothing to
    say from when they count. The column names the board's clock, a sentence under the
    table says where it starts, and each window has the time of day it was captured."""
    with _session(tmp_path, 0.0) as s:
        t = 222.0 + 0.025 * np.arange(120)
        s.capture_omega(4.5, t.tolist(), (7.78 + 0.01 * np.sin(t)).tolist())
        at = datetime.fromisoformat(s.entry("omega_ss@4.5").at)
        md = markdown.render(content.build(s))
    steady = md.split("## Steady state")[1].split("\n## ")[0]
    assert "| capture window (board clock) |" in steady
    (row,) = [ln for ln in steady.splitlines() if ln.startswith("| 4.5 V")]
    assert f"223–225 s, captured {at.strftime('%H:%M:%S')} UTC" in row, row
    (typed,) = [ln for ln in steady.splitlines() if ln.startswith("| 2.5 V")]
    assert "| typed |" in typed
    assert content.CAPTURE_CLOCK in steady
    assert "starts near 0 s when the program connects to the board" in content.CAPTURE_CLOCK
