"""The group's k_v edited by hand in session.json to the text "NaN" over its stored 0.5 V s/rad
(s38 attack, left): the report showed "NaN = 0.5 V s/rad" judged ✓, and the class view
counted it as the group's k_v, right. The text reads as no value, so the entry counts for
nothing: the report's row of Tasks 6-9 and its warnings, and the class view's row, say what
the file holds in the same line, and nothing judges it. Real folders, the real CLI."""

from __future__ import annotations

import json

from minseg_tui.cli import main
from minseg_tui.lab.state.entries import HAND_EDITED
from minseg_tui.lab.state.session import Session
from tests.classview.build import group

SAID = (
    f"{HAND_EDITED}: it holds the text 'NaN' with the value 0.5 V s/rad, but 'NaN' does not "
    "read as a value (your k_v: 'NaN' is not a number; expected a back-emf constant in V s/rad "
    "(e.g. 0.3 V s/rad)); it counts for nothing until the field is typed again"
)


def _k_v_row(report: str) -> str:
    (row,) = [line for line in report.splitlines() if line.startswith("| k_v (Task 7) |")]
    return row


def test_own_k_v_NaN_over_a_stored_value_is_said_and_not_judged(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=2, R="5.22 Ω")
    with Session.open(folder) as s:
        s.enter("own.k_v", "0.5")
    assert main(["report", str(folder)]) == 0  # as typed: judged right
    assert "✓ right" in _k_v_row((folder / "report.md").read_text(encoding="utf-8"))
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["own.k_v"]["text"] = "NaN"
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False), encoding="utf-8")
    held = path.read_bytes()

    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8").replace("\u00a0", " ")
    row = _k_v_row(report)
    assert "✓" not in row and "NaN" not in row.replace(SAID, "")
    assert f"| not answered ({SAID}) |" in row
    assert f"- Tasks 6-9, the group's k_v: {SAID}\n" in report
    capsys.readouterr()
    assert main(["class", "--sessions", str(folder.parent), "--json", "--workers", "1"]) == 0
    (group_row,) = json.loads(capsys.readouterr().out)["groups"]
    assert not any(o["key"] == "own.k_v" for o in group_row["own"])
    assert f"the group's k_v: {SAID}." in group_row["flags"]
    assert path.read_bytes() == held  # nothing the file holds was changed
