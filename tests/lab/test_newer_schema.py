"""A session file written by a newer program (schema 2; s38 attack): it was called damaged and
the line said to repair session.json by hand, which would break the newer program's file.
Now it says which program to open it with; the file is left untouched either way."""

from __future__ import annotations

import json

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.saving.store import SessionDamaged, list_sessions
from minseg_tui.lab.state.session import Session
from tests.classview.build import group


def _newer(tmp_path):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=1, run=False)
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["schema"] = 2
    path.write_text(json.dumps(data), encoding="utf-8")
    return folder, path.read_bytes()


@pytest.mark.parametrize("readonly", [False, True])
def test_a_newer_session_file_says_which_program_opens_it(tmp_path, readonly):
    folder, before = _newer(tmp_path)
    with pytest.raises(SessionDamaged) as got:
        Session.open(folder, readonly=readonly)
    said = str(got.value)
    assert "was written by a newer minseg-tui (schema 2; this one reads schema 1)" in said
    assert "open it with the newer program" in said and "repair" not in said
    assert (folder / "session.json").read_bytes() == before


def test_the_start_screen_and_the_class_view_say_the_same(tmp_path, capsys, monkeypatch):
    folder, _ = _newer(tmp_path)
    (info,) = list_sessions(folder.parent)
    assert info.damaged is not None and "newer minseg-tui" in info.damaged
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    assert main(["class", "--sessions", str(folder.parent), "--workers", "1"]) == 2
    err = capsys.readouterr().err
    assert "newer minseg-tui" in err and "repair" not in err
