"""`minseg-tui sim --link -` (s38 attack, left by stop 37): it made a symlink called '-' in the
current folder and ran, where every other folder or file to write refuses '-' in one line.
The real CLI in a child process (before the fix it ran until killed: the timeout fails it)."""

from __future__ import annotations

import os
import subprocess
import sys


def test_sim_link_dash_is_refused_in_one_line(tmp_path):
    done = subprocess.run(
        [sys.executable, "-m", "minseg_tui", "sim", "--link", "-"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr == (
        "minseg-tui sim: --link: expected a path for the device link, got - (stdout holds "
        "the device's path)\n"
    )
    assert not os.path.lexists(tmp_path / "-") and not os.listdir(tmp_path)
