"""An entry an older minseg-tui read under a reading rule changed since keeps the value that
program read, in effect, said as such (stop 38 left the decision: it opened counting for
nothing, as a hand edit does, so an instructor grading old sessions lost the group's answer).

``old_sessions/before-840d117`` was written by that program itself (the tree of 840d117^,
run with this venv): Ada and Bo typed own.f bare as "0.00186", which it read as 0.00186
mN m s/rad (the field's unit; this program asks which unit), and own.T bare as "0.057", which
it read as 0.057 s (T was in s then; in ms now, so it asks). A stored value that no older
rule gives, or one typed after the rule changed, is still a hand edit."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.entries import HAND_EDITED
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import classread
from minseg_tui.lab.views import session as views

OLD = Path(__file__).parent / "old_sessions" / "before-840d117"

F_SAID = (
    "read by an older minseg-tui (before 27 Nov 2026 02:04 UTC) as 0.00186 mN m s/rad: a bare "
    "number was read in mN m s/rad, the field's unit, where this one refuses it ('0.00186' is "
    "ambiguous: "
)
T_SAID = (
    "read by an older minseg-tui (before 27 Nov 2026 17:30 UTC) as 57 ms: a bare number was "
    "read in s, the field's unit then, where this one refuses it ('0.057' is ambiguous: "
)
KEPT = "; kept as it was read then, until the field is typed again"


def _copy(tmp_path: Path) -> Path:
    folder = tmp_path / "sessions" / OLD.name
    shutil.copytree(OLD, folder)
    return folder


def _entry(folder: Path, key: str) -> dict[str, Any]:
    return dict(json.loads((folder / "session.json").read_text(encoding="utf-8"))["entries"][key])


def _edit(folder: Path, key: str, **change: Any) -> None:
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"][key].update(change)
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


def test_the_old_file_holds_what_the_old_program_read():
    assert _entry(OLD, "own.f")["text"] == "0.00186" and _entry(OLD, "own.f")["value"] == 1.86e-06
    assert _entry(OLD, "own.T")["text"] == "0.057" and _entry(OLD, "own.T")["value"] == 0.057


@pytest.mark.parametrize("readonly", [True, False])
def test_bare_f_and_T_count_as_the_older_program_read_them(tmp_path, readonly):
    folder = _copy(tmp_path)
    with Session.open(folder, readonly=readonly) as s:
        f, T = s.entry("own.f"), s.entry("own.T")
        assert f is not None and f.ok and f.value == 1.86e-06 and not f.edited
        assert T is not None and T.ok and T.value == 0.057 and not T.edited
        assert f.older.startswith(F_SAID) and f.older.endswith(KEPT)
        assert T.older.startswith(T_SAID) and T.older.endswith(KEPT)
        # judged with the value the group saw judged: f a thousand times off
        (judged,) = [c for c in s.comparisons("table") if c.key == "own.f"]
        assert judged.own == 1.86e-06 and not judged.right
        shown = views.entry(s, "own.f")
        assert shown is not None and shown.ok and shown.message == f.older
        if not readonly:
            s.enter("own.K", "1.94")  # another change saves: the old entries stay as held
    assert _entry(folder, "own.f") == _entry(OLD, "own.f")
    assert _entry(folder, "own.T") == _entry(OLD, "own.T")


def test_typing_the_field_again_reads_it_this_way(tmp_path):
    folder = _copy(tmp_path)
    with Session.open(folder) as s:
        e = s.enter("own.f", "1.86")
        assert e.ok and e.value == pytest.approx(1.86e-3) and not e.older
    with Session.open(folder, readonly=True) as s:
        e = s.entry("own.f")
        assert e is not None and not e.older and e.value == pytest.approx(1.86e-3)


@pytest.mark.parametrize(
    "change",
    [
        {"value": 0.00186},  # the text read in N m s/rad: no older program stored that
        {"at": "2026-11-27T09:00:00+00:00"},  # typed after the rule changed
        {"at": ""},
    ],
)
def test_a_value_no_older_rule_gives_then_is_still_a_hand_edit(tmp_path, change):
    folder = _copy(tmp_path)
    _edit(folder, "own.f", **change)
    with Session.open(folder, readonly=True) as s:
        e = s.entry("own.f")
        assert e is not None and not e.ok and e.value is None and not e.older
        assert e.edited.startswith(f"{HAND_EDITED}: it holds the text '0.00186'")


def test_the_report_and_the_class_view_say_it(tmp_path):
    folder = _copy(tmp_path)
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8").replace("\u00a0", " ")
    assert F_SAID in report and T_SAID in report
    group = classread.read(folder)
    notes = " ".join(group.notes)
    assert "0.00186 mN m s/rad" in notes and "as 57 ms" in notes
    assert not any("older" in flag for flag in group.flags)  # a note, not counted in its !
