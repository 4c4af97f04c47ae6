"""The class view's legend of what it marks '!' named an entry "edited by hand in
session.json", where the rule behind it (:func:`~minseg_tui.lab.state.entries.check_stored`)
also covers a value an older program read from its text otherwise (commits 5cadbd4,
daaee7e): it says both causes now, in the entry's own words, from one place."""

from __future__ import annotations

from textual.widgets import Static

from minseg_tui.lab.state.entries import HAND_EDITED, NOT_AS_READ_WHY
from tests.ui.conftest import quiet_app
from tests.ui.helpers import class_view

from .build import group


async def test_the_legend_names_both_causes_as_the_entry_does(tmp_path):
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        detail = " ".join(str(screen.query_one("#class-group", Static).render()).split())
    assert "Nothing marked '!' (" in detail, detail
    assert "edited by hand in session.json" not in detail
    assert f"({NOT_AS_READ_WHY})" in detail
    assert f"({NOT_AS_READ_WHY})" in HAND_EDITED  # the entry's line, in the same words
