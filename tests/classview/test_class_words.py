"""Issue 20, second walk, the class view read by an instructor at 80x24 (Pilot, real session
folders): one group is "1 group", '!' says what it counts and what it leaves to each
group's report, and nothing speaks to the group ("own your k_v", "if you mean it")."""

from __future__ import annotations

import re
from pathlib import Path

from textual.widgets import Static

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import classview
from minseg_tui.report import content, markdown
from tests.ui.conftest import quiet_app
from tests.ui.helpers import class_view

from .build import group

_SECOND_PERSON = re.compile(r"\b(you|your|yours)\b", re.I)


def _one_group(root: Path) -> Path:
    """One group as the second walk left it: the table, a step run, its own k_v and T, and
    a refused f (the program told the group "... if you mean it")."""
    folder = group(root, ["Ada", "Bo"], seed=4, own_T="57 ms")
    with Session.open(folder) as s:
        s.enter("own.k_v", "0.49")
        s.enter("own.f", "0.00186 V")
        assert not s.entry("own.f").ok
    return folder


async def test_one_group_is_counted_and_the_mark_says_what_it_counts(tmp_path):
    root = tmp_path / "sessions"
    folder = _one_group(root)
    with Session.open(folder, readonly=True) as s:  # the group's report warns of things
        warnings = markdown.render(content.build(s)).split("## Warnings")[1]
    assert warnings.count("\n- ") >= 2
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await class_view(pilot)
        screen = app.screen
        title = str(screen.query_one("#class-title", Static).render())
        detail = str(screen.query_one("#class-group", Static).render())
    flat = " ".join(title.split())
    assert "1 groups" not in flat and "stands out" not in flat
    assert "Class view for instructors (read-only)" in flat
    assert "1 group, 1 marked '!' (" in flat  # the refused entry
    assert " ".join(classview.MARKED.split()) in flat
    assert "own your" not in detail
    assert "the group's k_v: " in detail and "from the value computed the group's way" in detail
    assert "! a refused entry, the group's f: '0.00186 V' (the program told the group:" in detail
    # what the program told the group is quoted as such; the view's own words name the group
    own_words = re.sub(r"\(the program told the group: .*?\); nothing", "", detail, flags=re.S)
    assert not _SECOND_PERSON.findall(own_words), own_words
    assert " ".join(classview.NOT_MARKED.split()) in " ".join(detail.split())
