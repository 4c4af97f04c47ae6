"""An entry whose text and stored value disagree after session.json was edited by hand (s38
attack, left: R's text "5.22 Ω" with a stored value of -5.22, own.k_v's text "NaN" with 0.5,
which the report judged right). Opening reads each entry's text again with the field's own
reading (:func:`~minseg_tui.lab.state.entries.read_entry`); one that disagrees opens, is
kept as the file holds it, counts for nothing and says so in one line, until the field is
typed again. Real session folders, session.json edited as a person would (a text editor:
the JSON changed and written back)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest

from minseg_tui.lab.state.entries import HAND_EDITED, Entry
from minseg_tui.lab.state.session import EDITED_R, Session
from tests.seeded import Clock

OLD = Path(__file__).parent / "old_sessions" / "schema1"

TABLE = {
    "R": "5.22 Ω",
    "u_ss@2.5": "2.05",
    "omega_ss@2.5": "3.8",
    "i_ss@2.5": "29.8 mA",
    "own.k_v": "0.5",
    "summary.1": "b",
}


def _session(tmp_path: Path, entries: dict[str, str] = TABLE) -> Path:
    with Session.create(
        tmp_path / "sessions", ["Ada", "Bo"], date="2026-11-28", clock=Clock()
    ) as s:
        for key, text in entries.items():
            s.enter(key, text)
        return s.folder


def _edit(folder: Path, key: str, **change: Any) -> dict[str, Any]:
    """Change entry ``key`` of session.json as a person would; the entry as now written."""
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"][key].update(change)
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return dict(data["entries"][key])


def _on_disk(folder: Path, key: str) -> dict[str, Any]:
    return dict(json.loads((folder / "session.json").read_text(encoding="utf-8"))["entries"][key])


def test_a_negative_R_under_its_text_opens_said_and_out_of_effect(tmp_path):
    folder = _session(tmp_path)
    held = _edit(folder, "R", value=-5.22)
    with Session.open(folder) as s:
        e = s.entry("R")
        assert e is not None and not e.ok and e.value is None
        assert e.edited == (
            f"{HAND_EDITED}: it holds the text '5.22 Ω' with the value -5.22 Ω, but '5.22 Ω' "
            "reads as 5.22 Ω; it counts for nothing until the field is typed again"
        )
        assert e.text == "5.22 Ω" and s.value("R") is None and s.reading("R") is None
        assert s.step_status("task2") != "done"
        assert EDITED_R in s.results().problems
        s.enter("u_ss@3.5", "3.05")  # another change saves: the edited entry stays as held
    assert _on_disk(folder, "R") == held


def test_a_NaN_text_over_a_stored_value_is_not_judged_right(tmp_path):
    folder = _session(tmp_path)
    with Session.open(folder, readonly=True) as s:  # as typed: k_v 0.5 is judged right
        assert any(c.key == "own.k_v" and c.right for c in s.comparisons("table"))
    _edit(folder, "own.k_v", text="NaN")
    with Session.open(folder, readonly=True) as s:
        e = s.entry("own.k_v")
        assert e is not None and not e.ok and e.value is None
        assert e.edited.startswith(
            f"{HAND_EDITED}: it holds the text 'NaN' with the value 0.5 V s/rad, but 'NaN' "
            "does not read as a value (your k_v: 'NaN' is not a number"
        )
        assert not any(c.key == "own.k_v" and c.right for c in s.comparisons("table"))
        assert s.step_status("table") != "done"


def test_typing_the_field_again_clears_it_and_keeps_the_old_text(tmp_path):
    folder = _session(tmp_path)
    _edit(folder, "R", value=-5.22)
    with Session.open(folder) as s:
        assert not s.withdraw_refused("R")  # Escape drops nothing of it
        assert s.entry("R") is not None and s.entry("R").edited  # type: ignore[union-attr]
        e = s.enter("R", "5.3")
        assert e.ok and not e.edited and e.value == pytest.approx(5.3)
        assert ("5.22 Ω",) == tuple(t for t, _ in e.history)
        assert EDITED_R not in s.results().problems
    assert _on_disk(folder, "R")["value"] == pytest.approx(5.3)
    with Session.open(folder, readonly=True) as again:
        assert again.value("R") == pytest.approx(5.3) and not again.entry("R").edited  # type: ignore[union-attr]


def test_a_choice_edited_to_another_option_is_said_in_the_answers_words(tmp_path):
    folder = _session(tmp_path)
    with Session.open(folder, readonly=True) as s:  # as typed: 'a system' is right
        assert any(fb.key == "summary.1" and fb.status == "right" for fb in s.feedback("*"))
    _edit(folder, "summary.1", value=[0])
    with Session.open(folder, readonly=True) as s:
        e = s.entry("summary.1")
        assert e is not None and not e.ok
        assert e.edited == (
            f"{HAND_EDITED}: it holds the text 'b' with the value 'a model', but 'b' reads as "
            "'a system'; it counts for nothing until the field is typed again"
        )
        assert not any(fb.key == "summary.1" and fb.status == "right" for fb in s.feedback("*"))


@pytest.mark.parametrize(
    ("stored", "edited"),
    [(5.22 * (1 + 1e-12), False), (5.22 * (1 + 1e-6), True), (None, True)],
    ids=["float-rounding", "a-digit-changed", "value-removed"],
)
def test_what_counts_as_a_disagreement(tmp_path, stored, edited):
    folder = _session(tmp_path, {"R": "5.22 Ω"})
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    if stored is None:
        del data["entries"]["R"]["value"]
    else:
        data["entries"]["R"]["value"] = stored
    path.write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder, readonly=True) as s:
        e = s.entry("R")
        assert e is not None and e.ok is not edited and e.text == "5.22 Ω"
        assert (s.value("R") is None) is edited


def test_an_old_schema_1_session_whose_entries_agree_opens_as_before(tmp_path):
    """A pin: it passes on the program before this change too."""
    folder = tmp_path / "schema1"
    shutil.copytree(OLD, folder)
    raw = json.loads((OLD / "session.json").read_text(encoding="utf-8"))["entries"]
    with Session.open(folder) as s:
        assert s.entries == {k: Entry.from_json(k, v) for k, v in raw.items()}
        assert s.value("R") == 5.26 and s.step_status("task2") == "done"
        assert not any("by hand" in p for p in s.results().problems)
        s.enter("own.k_v", "0.5")  # a save: every entry the file held is written as it was
    saved = json.loads((folder / "session.json").read_text(encoding="utf-8"))["entries"]
    assert {k: v for k, v in saved.items() if k != "own.k_v"} == raw
