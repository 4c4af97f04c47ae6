"""Walk 7, D10: Task 12's verdict read 'read as 0.085 s' above '✗ wrong: +49 % from 56.90
ms' for a T typed '85 ms': the echo was kept in session.json by the version that wrote it.
What an entry was read as is said in this program's words, T in ms (real session files)."""

from __future__ import annotations

import json
from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views


def test_an_old_sessions_echo_of_T_in_seconds_reads_in_ms_now(tmp_path: Path) -> None:
    s = Session.create(tmp_path, ["Lena Berg"], date="2026-11-27")
    s.enter("own.T", "85 ms")
    s.enter("own.J", "0,00271")
    folder = s.folder
    s.close()
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["own.T"]["message"] = "read as 0.085 s"  # as the walk's session holds it
    path.write_text(json.dumps(data), encoding="utf-8")
    s = Session.open(folder)
    try:
        T = views.entry(s, "own.T")
        assert T is not None and T.ok and T.message == "", T  # typed the lab's way: no echo
        s.enter("own.T", "0,085 s")
        T = views.entry(s, "own.T")
        assert T is not None and T.message == "read as 85 ms (typed 0,085 s)", T
        J = views.entry(s, "own.J")
        assert J is not None and J.message == "read as 0.00271 kg m^2", J
    finally:
        s.close()
