"""`minseg-tui sim --link PATH` never replaces what is not its own link (issue 18, item 2)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest


def _cli() -> list[str]:
    exe = Path(sys.executable).with_name("minseg-tui")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]


def _sim(link: Path | str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*_cli(), "sim", "--link", str(link)],
        capture_output=True,
        text=True,
        timeout=60,
    )


@pytest.mark.parametrize("name", ["notes.txt", "session.json", "a.new-taken"])
def test_an_existing_file_is_refused_and_left_as_it_was(tmp_path, name):
    target = tmp_path / name
    if name == "a.new-taken":  # the name the link is made under is taken
        target = tmp_path / "a"
        (tmp_path / "a.new").write_text("keep me\n")
    else:
        target.write_text("keep me\n")
    proc = _sim(target)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr, proc.stderr
    assert proc.stderr.startswith("minseg-tui sim: "), proc.stderr
    assert "expected a new path for the device link" in proc.stderr
    kept = tmp_path / ("a.new" if name == "a.new-taken" else name)
    assert kept.read_text() == "keep me\n"


def test_a_folder_another_symlink_and_an_empty_path_are_refused(tmp_path):
    (tmp_path / "d").mkdir()
    (tmp_path / "notes.txt").write_text("keep me\n")
    os.symlink(tmp_path / "notes.txt", tmp_path / "to-notes")
    for link, what in [
        (tmp_path / "d", "this is a folder"),
        (tmp_path / "to-notes", "this is a symlink"),
        ("", "expected a path for the device link, got ''"),
    ]:
        proc = _sim(link)
        assert proc.returncode == 2, proc.stderr
        assert proc.stderr.count("\n") == 1 and what in proc.stderr, proc.stderr
    assert os.readlink(tmp_path / "to-notes") == str(tmp_path / "notes.txt")
    assert (tmp_path / "notes.txt").read_text() == "keep me\n" and (tmp_path / "d").is_dir()


def test_a_link_a_killed_sim_left_is_replaced_and_removed_at_the_end(tmp_path):
    link = tmp_path / "minseg0"
    os.symlink("/dev/pts/9999", link)  # left by a sim that was killed
    proc = subprocess.Popen(
        [*_cli(), "sim", "--link", str(link)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert proc.stdout is not None
        assert proc.stdout.readline().strip() == str(link)
        assert os.readlink(link).startswith("/dev/pts/") and os.readlink(link) != "/dev/pts/9999"
    finally:
        proc.send_signal(signal.SIGTERM)
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == 0, err
    assert not os.path.lexists(link)
