"""A group's names of any length and script make a session (s39 attack: 300 characters of
names were refused with 'cannot make a session folder here (File name too long (<the whole
path>))', which blamed the folder and lost nothing but was no way on). The folder's name is
cut to SLUG_MAX characters; the names are kept whole. Real folders."""

from __future__ import annotations

import json

import pytest

from minseg_tui.lab.state.session import SLUG_MAX, Session
from tests.seeded import Clock


@pytest.mark.parametrize(
    "members",
    [
        ["A" * 300],
        ["Bo " * 1700],
        ["Ærøskøbing Ünïcødé", "李小龙 🚀", 'O\'Brien "x"'],
        [f"Student {k}" for k in range(60)],
    ],
)
def test_long_or_foreign_names_make_a_session_keeping_every_name(tmp_path, members):
    with Session.create(tmp_path, members, date="2026-11-28", clock=Clock()) as s:
        folder = s.folder
        s.enter("R", "5.2 Ω")
    assert len(folder.name) <= SLUG_MAX and folder.name.startswith("2026-11-28")
    data = json.loads((folder / "session.json").read_text(encoding="utf-8"))
    assert data["members"] == members and data["id"] == folder.name
    with Session.create(tmp_path, members, date="2026-11-28", clock=Clock()) as again:
        assert again.folder != folder and len(again.folder.name) <= SLUG_MAX + 4
