"""s38-fix left: with a log imported, 'Ctrl+P import Enter' typed quickly sometimes picked
"Use run imported-1 for Tasks 11-15" in place of "Import a run log", and Tasks 11-15 were
then judged on the import. Textual's matcher gives both entries the same score for
"import" (21.0), the palette sorts its hits by score alone, and the two come from two
providers (Textual's system commands, the lab screen's StepCommands) whose hits arrive in
an order that changes from process to process. A run's entry changes what the group is
judged on: on a tie it comes after the command the query names."""

from __future__ import annotations

from textual.command import CommandList
from textual.fuzzy import Matcher

from minseg_tui.lab.content.keys import PALETTE
from minseg_tui.ui.screens.lab import StepCommands
from minseg_tui.ui.widgets.textbox import TextBox
from tests.ui.conftest import quiet_app
from tests.ui.helpers import import_a_copy, settle, start_with_a_run


async def test_a_runs_entry_ranks_under_a_command_of_the_same_score(tmp_path):
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await import_a_copy(pilot, tmp_path)
        use = "Use run imported-1 for Tasks 11-15"
        # the tie this is about: Textual's matcher scores both alike
        m = Matcher("import")
        assert m.match(use) == m.match(PALETTE["import_log"]) > 0
        hits = [h async for h in StepCommands(app.screen).search("import")]
        (run_hit,) = (h for h in hits if h.text == use)
        assert run_hit.score < m.match(PALETTE["import_log"])
        # typed as a group types it: the palette's list and its Enter
        with app.session as s:
            given_on = s.response_run().name
        await pilot.press("ctrl+p")
        await settle(pilot)
        for c in "import":
            await pilot.press(c)
        await settle(pilot)
        listing = app.screen.query_one(CommandList)
        shown = [str(listing.get_option_at_index(i).hit.text) for i in range(listing.option_count)]
        assert shown.index(PALETTE["import_log"]) < shown.index(use), shown
        await pilot.press("enter")
        await settle(pilot)
        assert app.focused is app.screen.query_one("#import-path", TextBox)
        with app.session as s:
            assert s.response_run().name == given_on
        # the run's own name still finds its entry first
        hits = [h async for h in StepCommands(app.screen).search("imported-1")]
        assert max(hits, key=lambda h: h.score).text == use
        assert max(h.score for h in hits) > Matcher("imported-1").match(PALETTE["import_log"])
