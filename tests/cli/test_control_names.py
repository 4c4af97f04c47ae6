"""A file or folder name holding a newline or a terminal escape (s36 attack): every refusal
stays one line on stderr, and no control character reaches the terminal."""

from __future__ import annotations

import os

from minseg_tui.cli import main
from tests.classview.build import group

EVIL = "evil\nname\x1b[2J"


def _clean(text: str) -> bool:
    return not any(ord(c) < 0x20 and c != "\n" or 0x7F <= ord(c) < 0xA0 for c in text)


def test_a_refusal_naming_such_a_path_is_one_line(tmp_path, capsys):
    code = main(["report", EVIL, "--sessions", str(tmp_path)])
    _, err = capsys.readouterr()
    assert code == 2 and err.count("\n") == 1 and _clean(err)
    assert "evil\\nname\\x1b[2J: no session found" in err


def test_the_class_lists_such_a_folder_on_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    root = tmp_path / "s"
    group(root, ["Ada"], seed=1, run=False)
    os.mkdir(root / EVIL)
    (root / EVIL / "session.json").write_text("{", encoding="utf-8")
    code = main(["class", "--sessions", str(root), "--workers", "1"])
    out, err = capsys.readouterr()
    assert code == 2 and err.count("\n") == 1 and _clean(err) and _clean(out)
    rows = [line for line in out.splitlines() if "evil" in line]
    assert rows and all("evil\\nname\\x1b[2J" in line for line in rows)
