"""Walk 11's D2 lead (issue 20, /work/coord/WALK12.md): a change of the lab landing between
the group's typing and its Enter must not put the stored text back over what was typed.

LabScreen._on_lab_changed rewrites an entry with the session's text when that differs from
what the row last sent; these tests land such changes (a notice's, a stored entry of another
row, a capture's, the run in use) at that point, deterministically (called between two
bursts of keys), on Task 5 at 80x24, with the row holding nothing, an accepted reading, a
refused text, or a refused text over an accepted reading.

What they showed: the lab's own changes (a notice, another row's reading, the run in use)
leave the typed text alone: the row is rewritten only when the lab's text for that very row
changes under it, and the only change of that kind, F4's capture, stores what stands typed
first. Forced (``this-row``), the typed text was replaced by the lab's, and after F3 the
reading was mixed into the lab's text ('0.0372 A33'); the row now keeps what was typed."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from minseg_tui.ui.app import LabApp
from minseg_tui.ui.messages import RevealRequested
from tests.ui.helpers import (
    box_text,
    burst,
    goto,
    lab_screen,
    start,
    start_with_a_run,
    stored_text,
)


def _notice(app: LabApp) -> None:
    """What a board check kept, a run that ended, a save, the names do: the lab changed."""
    app.lab_changed.publish(None)


def _other_row(app: LabApp) -> None:
    """Another row's reading changed in the session (as a capture or a resumed store)."""
    assert app.session is not None
    with app.session as s:
        s.enter("i_ss@2.5", "14")
    app.lab_changed.publish(None)


def _this_row(app: LabApp) -> None:
    """The row's own stored text changed under it, not by the group's keys (the worst
    case of the lead: what the row last sent and what the lab holds now disagree)."""
    assert app.session is not None
    with app.session as s:
        s.enter("i_ss@4.5", "33")
    app.lab_changed.publish(None)


def _run_in_use(app: LabApp) -> None:
    """The group picked the run Tasks 11-15 use (a notice and a lab change)."""
    lab_screen(app).use_run(None)


CHANGES: dict[str, Callable[[LabApp], None]] = {
    "notice": _notice,
    "other-row": _other_row,
    "this-row": _this_row,
    "run-in-use": _run_in_use,
}

BEFORE: dict[str, tuple[str, ...]] = {
    "empty": (),
    "accepted": (*"37,1", "enter"),
    "refused": (*"37 x", "enter"),
    "refused-over-accepted": (*"37,1", "enter", "ctrl+u", *"37 x", "enter"),
}


@pytest.mark.parametrize("change", list(CHANGES))
@pytest.mark.parametrize("before", list(BEFORE))
async def test_a_lab_change_between_typing_and_enter_keeps_the_typed_text(quiet, before, change):
    """Task 5, the keys on the 4.5 V row (holding ``before``); '37.2' typed over what it
    holds; the lab changes (``change``); Enter stores '37.2'. Walk 11 saw the typed text
    vanish at Enter (once stored empty, once the old text kept)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        await burst(pilot, "tab", "tab")  # the 4.5 V row
        await burst(pilot, *BEFORE[before])
        assert lab_screen(app).pane.typing is not None
        assert lab_screen(app).pane.typing.field.key == "i_ss@4.5"
        await burst(pilot, "ctrl+u", *"37.2")
        assert box_text(app, "i_ss@4.5") == "37.2"
        CHANGES[change](app)
        await burst(pilot)
        assert box_text(app, "i_ss@4.5") == "37.2"
        await burst(pilot, "enter")
        assert stored_text(app, "i_ss@4.5") == "37.2"


@pytest.mark.parametrize("change", list(CHANGES))
async def test_a_lab_change_between_f3_and_the_reading_keeps_the_reading(quiet, change):
    """Walk 11's D2 as typed: the motor at 3.5 V, the keys on the empty 4.5 V row; 'F3',
    then the lab changes, then '0.0372 A Enter': stored as typed."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        await burst(pilot, "f3", "f3", "tab")  # 3.5 V, the keys on the 4.5 V row
        await burst(pilot, "f3")
        assert app.requested == 4.5
        CHANGES[change](app)
        await burst(pilot, *"0.0372 A", "enter")
        assert stored_text(app, "i_ss@4.5") == "0.0372 A"


@pytest.mark.parametrize("before", ["empty", "refused"])
@pytest.mark.parametrize("change", ["reveal", "run-in-use"])
async def test_a_change_of_the_results_between_typing_and_enter_keeps_the_typed_T(
    quiet, before, change
):
    """Task 12, on a recorded run: T typed ('57', over nothing or over the refused
    '0.057', ambiguous between s and ms) and not entered; then the step's computed values
    are revealed (the message Ctrl+R posts) or the run in use is chosen again, which judge
    the entries anew; Enter stores '57'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        screen = lab_screen(app)
        assert screen.pane.typing is not None and screen.pane.typing.field.key == "own.T"
        if before == "refused":
            await burst(pilot, *"0.057", "enter")
            assert stored_text(app, "own.T") == "0.057"
            assert box_text(app, "own.T") == "0.057"
        await burst(pilot, "ctrl+u", *"57")
        if change == "reveal":
            screen.post_message(RevealRequested("task12"))
        else:
            screen.use_run(None)
        await burst(pilot)
        if change == "reveal":
            with app.session as s:
                assert s.revealed() == {"own.T"}
        assert box_text(app, "own.T") == "57"
        await burst(pilot, "enter")
        assert stored_text(app, "own.T") == "57"
