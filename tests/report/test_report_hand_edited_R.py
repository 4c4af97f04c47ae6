"""A session.json edited by hand to hold a negative R under its text "5.22 Ω" (s38 attack): the
report's warnings and the class view's row said "--R: expected a positive resistance in ohm,
got -5.22", naming a flag of `identify` nobody gave, and went on with R = -5.22 Ω (stop 38:
"R (Task 2): expected a positive resistance in ohm, got -5.22"). The stored value is not what
the text reads as, so R counts for nothing now, and both say what the file holds, in the
same line (s38b-entry). Real folders, the real CLI."""

from __future__ import annotations

import json

from minseg_tui.cli import main
from minseg_tui.lab.state.entries import HAND_EDITED
from minseg_tui.lab.state.session import EDITED_R
from minseg_tui.report.content import EDITED_CELL
from tests.classview.build import group

SAID = (
    f"{HAND_EDITED}: it holds the text '5.22 Ω' with the value -5.22 Ω, but '5.22 Ω' reads as "
    "5.22 Ω; it counts for nothing until the field is typed again"
)


def test_a_negative_R_put_in_by_hand_is_said_as_the_session_holds_it(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=2, R="5.22 Ω")
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["R"]["value"] = -5.22
    path.write_text(json.dumps(data), encoding="utf-8")
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8").replace("\u00a0", " ")
    assert f"- Task 2, R: {SAID}\n" in report and f"- {EDITED_R}\n" in report
    assert f"R (Task 2): {EDITED_CELL}" in report
    assert "-5.22 Ω" not in report.replace(SAID, "") and "--R" not in report
    capsys.readouterr()
    assert main(["class", "--sessions", str(folder.parent), "--json", "--workers", "1"]) == 0
    (row,) = json.loads(capsys.readouterr().out)["groups"]
    assert row["R"] is None and f"R: {SAID}." in row["flags"]
    assert EDITED_R in row["lacks"] and not any("--R" in x for x in row["lacks"])
