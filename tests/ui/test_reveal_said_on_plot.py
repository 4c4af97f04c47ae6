"""Stop 37 left (issue 20): on Tasks 11-12 at 80x24, Ctrl+R leaves the plot being read in view
(s37-fix's decision, be4ed38: the reveal does not scroll the plot away) and shows the
revealed reading on the plot's caption; but "revealed before answering", the words that say
the report records it, stood only in the comparisons under the entry, below the screen until
the group answered. The caption says it beside the reading it shows, where the reveal
happens, the plot's frame still in view."""

from __future__ import annotations

import pytest

from minseg_tui.lab.state.compare import REVEALED_EARLY
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import burst, lab_screen, settle, start_with_a_run


def _in_view(app, widget, title_rows: int = 0) -> bool:
    """``widget`` wholly on screen in the step, below its heading and above the footer, but
    for its first ``title_rows``."""
    pane = lab_screen(app).pane
    view = pane.scrollable_content_region
    r = widget.region
    return bool(r) and r.y + title_rows >= view.y + pane.heading_rows and r.bottom <= view.bottom


@pytest.mark.parametrize(
    ("step_id", "shown"),
    [("task12", "ms after the edge"), ("task11", "63 % of the change is")],
)
async def test_a_reveal_on_tasks_11_12_is_said_where_it_is_seen(quiet, step_id, shown):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, step_id)
        screen = lab_screen(app)
        note = screen.query_one("#zoom-note", Prose)
        assert REVEALED_EARLY not in note.text
        await burst(pilot, "ctrl+r")
        await settle(pilot, lambda: shown in note.text)
        await settle(pilot)
        said = " ".join(note.text.split())
        assert f"({REVEALED_EARLY}, Ctrl+R)" in said, said
        assert _in_view(app, note), (note.region, screen.pane.scroll_y)
        # as s37-fix decided: the plot's data rows stay (its title and top border may go
        # under the heading), the entry too
        assert _in_view(app, screen.query_one("#plot-log"), title_rows=2)
        row = screen.pane.typing
        assert row is not None and _in_view(app, row.input)
