"""A walk at 80x24: Tasks 4, 6-9 and 11-15 opened scrolled past their title and instructions,
to show the entry the step lands in; a group arriving on the step did not see what it asks.
Every step, reached with PgDn as a group does, now shows its title and the start of what to
do (the step's own lines, or the heading kept over the top of a step scrolled down) and the
entry it landed in, neither under the heading nor under the readout kept at the bottom."""

from __future__ import annotations

import pytest
from textual.geometry import Region
from textual.widget import Widget
from textual.widgets import Static

from minseg_tui.lab.content.steps import STEPS, step
from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.fields import FieldRow
from tests.ui.helpers import (
    TABLE,
    burst,
    enter_all,
    goto,
    keys_box,
    record_response_run,
    settle,
    shown,
    start,
)


def _view(pane: StepPane) -> Region:
    """The rows of the step the group sees (screen coordinates): the pane's, less the
    heading over its top and the readout docked at its bottom."""
    view = pane.scrollable_content_region
    top = view.y
    heading = pane.query(".heading")
    if heading and heading.first().display and heading.first().region.height:
        top = heading.first().region.bottom
    bottom = view.bottom
    readout = pane.query(".readout")
    if readout and readout.first().region.height:
        bottom = readout.first().region.y
    return Region(view.x, top, view.width, max(bottom - top, 0))


def _seen(view: Region, widget: Widget, rows: int | None = None) -> bool:
    """``widget`` (its first ``rows`` rows; all if None) lies in ``view``."""
    r = widget.region
    if not r.height:
        return False
    if rows is not None:
        r = Region(r.x, r.y, r.width, min(rows, r.height))
    return view.contains_region(r)


def _what_is_missing(app, here) -> list[str]:
    """What of the step the group does not see at once: its title, the start of what to
    do, the entry (or the step) the focus landed in."""
    pane = app.screen.query(StepPane).last()
    view = _view(pane)
    found = pane.query(".heading")  # the step's title and what to do, over its top
    heading = found.first() if found else None
    shows = heading is not None and heading.display and heading.region.height == 2
    heads = [str(s.render()) for s in heading.query(Static)] if heading and shows else []
    title = _seen(view, pane.query_one(".title"), 1) or (bool(heads) and heads[0] == here.title)
    todo = _seen(view, pane.query_one(".todo"), 1) or (
        len(heads) == 2 and heads[1].startswith("What to do: ")
    )
    missing = [] if title else ["title"]
    missing += [] if todo else ["what to do"]
    focused = keys_box(app) or app.focused  # the box the form types into, else the focus
    row = next((a for a in focused.ancestors_with_self if isinstance(a, FieldRow)), None)
    if row is not None and not _seen(view, focused):
        missing.append(f"entry {row.field.key}")
    return missing


async def _walk(pilot, steps) -> dict[str, list[str]]:
    """PgDn from the first step through ``steps``: what each does not show on arrival."""
    app = pilot.app
    off: dict[str, list[str]] = {}
    for k, here in enumerate(steps):
        if k:
            await burst(pilot, "pagedown")
        await settle(pilot, lambda s=here: shown(app, s.id))
        await settle(pilot)
        missing = _what_is_missing(app, here)
        if missing:
            off[here.id] = missing
    return off


async def test_every_step_opens_with_its_title_instructions_and_entry_in_view(quiet):
    """The lab as a group walks it at 80x24 (the table typed, a run recorded): Task 4, Tasks
    6-9 and Tasks 11-15 showed neither their title nor what to do."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
        app.lab_changed.publish(None)
        await settle(pilot)
        assert await _walk(pilot, STEPS) == {}


@pytest.mark.parametrize(
    ("step_id", "landing"),
    [("task4", "omega_ss@3.5"), ("table", "own.k_a"), ("task11", "own.K")],
)
async def test_a_step_landing_on_a_later_entry_shows_its_title_and_that_entry(
    quiet, step_id, landing
):
    """Task 4 with its first voltage done lands on omega_ss at 3.5 V; Tasks 6-9 with k_v
    typed on k_a; Task 11 with omega_ss in the steps typed on K, four rows lower."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(
            app,
            {k: v for k, v in TABLE.items() if not k.endswith(("@3.5", "@4.5"))}
            | {"own.omega_step": "7.8", "own.k_v": "0.59"},
        )
        with app.session as s:
            record_response_run(s)
        await goto(pilot, step_id)
        await settle(pilot)
        box = keys_box(app) or app.focused
        row = next(a for a in box.ancestors_with_self if isinstance(a, FieldRow))
        assert row.field.key == landing
        assert _what_is_missing(app, step(step_id)) == []


async def test_an_entry_reached_upwards_is_never_under_the_heading(quiet):
    """Shift+Tab back up Task 4's entries: Textual scrolls an entry above the view to its top
    edge, where the heading lies; the entry is brought out from under it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        app.lab_changed.publish(None)
        app.screen.go_to("task4")
        await settle(pilot, lambda: shown(app, "task4"))
        await settle(pilot)
        rows = list(app.screen.query(FieldRow))
        rows[-1].focus_input()
        await settle(pilot)
        pane = app.screen.query(StepPane).last()
        for _ in range(len(rows) - 1):
            await pilot.press("shift+tab")
            await settle(pilot)
            box = keys_box(app) or app.focused
            row = next(a for a in box.ancestors_with_self if isinstance(a, FieldRow))
            assert _seen(_view(pane), box), (row.field.key, pane.scroll_y)
