"""A session.json edited by hand to hold a negative R (s38 attack): the report's warnings and the
class view's row said "--R: expected a positive resistance in ohm, got -5.22", naming a flag
of `identify` nobody gave. They name Task 2's R now. Real folders, the real CLI."""

from __future__ import annotations

import json

from minseg_tui.cli import main
from tests.classview.build import group

SAID = "R (Task 2): expected a positive resistance in ohm, got -5.22"


def test_a_negative_R_put_in_by_hand_is_named_as_the_session_holds_it(
    tmp_path, capsys, monkeypatch
):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=2, R="5.22 Ω")
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["R"]["value"] = -5.22
    path.write_text(json.dumps(data), encoding="utf-8")
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8")
    assert SAID in report and "--R" not in report
    capsys.readouterr()
    assert main(["class", "--sessions", str(folder.parent), "--json", "--workers", "1"]) == 0
    (row,) = json.loads(capsys.readouterr().out)["groups"]
    assert SAID in row["lacks"] and not any("--R" in x for x in row["lacks"])
