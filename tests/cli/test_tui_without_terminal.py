"""The lab assistant started without a terminal is refused in one line, exit 2 (s39 attack:
`minseg-tui < /dev/null 2> log` drew the start screen into the log and waited for keys for
ever). A real process; its sessions folder is left as it was."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

EXE = str(Path(sys.executable).with_name("minseg-tui"))


def test_without_a_terminal_the_tui_says_so_and_ends(tmp_path):
    out = subprocess.run(
        [EXE, "--sim", "--sessions", str(tmp_path / "sessions")],
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert out.returncode == 2 and out.stdout == ""
    assert out.stderr == (
        "minseg-tui tui: stdin: is not a terminal: the lab assistant runs in one; without a "
        "terminal use identify, analyze, report or class\n"
    )
    assert not (tmp_path / "sessions").exists() or not any((tmp_path / "sessions").iterdir())
