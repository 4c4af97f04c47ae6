"""Walk 7, D10 on the screen: a session saved by an older version held T '85 ms' with the
echo 'read as 0.085 s', and Task 12 showed it above '✗ wrong: +49 % from 56.90 ms'. The
echo is said in this program's words, T in ms (Pilot, real session folder)."""

from __future__ import annotations

import json

from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, resume, settle, start, type_in


async def test_a_resumed_sessions_T_echo_reads_in_ms(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task12")
        row = await type_in(pilot, "own.T", "0,085 s")
        assert row.message.startswith("read as 85 ms"), row.message
    (saved,) = list_sessions(tmp_path / "sessions")
    path = saved.path / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["entries"]["own.T"]["text"] = "85 ms"  # as the walk's session holds it
    data["entries"]["own.T"]["message"] = "read as 0.085 s"
    path.write_text(json.dumps(data), encoding="utf-8")
    app2 = quiet()
    async with app2.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        await settle(pilot)
        row = app2.screen.query_one(f"#{field_id('own.T')}", FieldRow)
        assert row.input.value == "85 ms"
        assert "0.085 s" not in row.message, row.message
        assert not row.message.startswith("read as"), row.message  # typed the lab's way
