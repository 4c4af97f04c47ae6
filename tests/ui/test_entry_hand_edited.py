"""Task 2 on a session whose session.json was edited by hand: R's text "5.22 Ω" with a stored
value of -5.22 (s38 attack, left). The field says in one line that the file was edited by
hand and what it holds, the step is not marked ✓, and typing R again clears it. A real
session folder, resumed in the real TUI through Pilot."""

from __future__ import annotations

import json

from minseg_tui.lab.state.entries import HAND_EDITED
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, nav_mark, resume, settle, type_in


async def test_task2_says_R_was_edited_by_hand_until_it_is_typed_again(quiet, tmp_path):
    with Session.create(tmp_path / "sessions", ["Ada", "Bo"], date="2024-04-16") as s:
        s.enter("R", "5.22 Ω")
        path = s.folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["R"]["value"] = -5.22
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False), encoding="utf-8")
    async with quiet().run_test(size=(100, 40)) as pilot:
        await resume(pilot)
        await goto(pilot, "task2", focus=None)
        row = pilot.app.screen.query_one(f"#{field_id('R')}", FieldRow)
        await settle(pilot, lambda: bool(row.message))
        said = " ".join(row.message.split())
        assert said == (
            f"✗ {HAND_EDITED}: it holds the text '5.22 Ω' with the value -5.22 Ω, but "
            "'5.22 Ω' reads as 5.22 Ω; it counts for nothing until the field is typed again"
        )
        assert row.input.value == "5.22 Ω" and nav_mark(pilot.app, "task2") != "✓"
        await type_in(pilot, "R", "5.22")
        await settle(pilot, lambda: HAND_EDITED not in row.message)
        assert HAND_EDITED not in row.message
        assert nav_mark(pilot.app, "task2") == "✓"
        with pilot.app.session as s:
            assert s.value("R") == 5.22
