"""Snapshot tests of every screen at 80x24 and 120x40: a device double that streams nothing,
a frozen buffer for the live plots, a seeded recorded run, a fixed date, no animations."""

from __future__ import annotations

import pytest

from tests.ui.conftest import quiet_app
from tests.ui.fakes import METER, frozen_stream
from tests.ui.helpers import TABLE, enter_all, goto, record_step_run, settle, start

SIZES = [(80, 24), (120, 40)]


def _to(
    step_id: str,
    entries: dict[str, str] | None = None,
    run: bool = False,
    live: bool = False,
    focus: str | None = "entry",
):
    async def run_before(pilot) -> None:
        app = pilot.app
        await start(pilot)
        enter_all(app, entries or {})
        if run:
            with app.session as s:
                record_step_run(s)
        if live:
            app.live.extend(frozen_stream())
        app.meter = METER
        await goto(pilot, step_id, focus)

    return run_before


def _entry(size: tuple[int, int]) -> str | None:
    """Where these pinned screens have the focus: in the step's first entry at 80x24, on the
    list of steps at 120x40 (as they were pinned)."""
    return "entry" if size == (80, 24) else None


def _app(tmp_path):
    return quiet_app(tmp_path / "sessions")


@pytest.mark.parametrize("size", SIZES)
def test_start_screen(snap_compare, tmp_path, size):
    async def run_before(pilot) -> None:
        await settle(pilot, lambda: pilot.app.device is not None)

    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=run_before)


@pytest.mark.parametrize("size", SIZES)
def test_prep_question_with_feedback(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("prep8", {"prep8.T": "b/a", "prep8.K": "c/b"}, focus=None),
    )


@pytest.mark.parametrize("size", SIZES)
def test_resistance_step_with_a_refused_entry(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("task2", {"R": "abc"}, focus=None)
    )


@pytest.mark.parametrize("size", SIZES)
def test_live_measurement_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("task4", {"u_ss@2.5": "2,05 V"}, live=True, focus=None),
    )


@pytest.mark.parametrize("size", SIZES)
def test_table_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("table", TABLE, focus=None)
    )


@pytest.mark.parametrize("size", SIZES)
def test_step_run(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("task10", TABLE, run=True)
    )


@pytest.mark.parametrize("size", SIZES)
def test_results_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("task12", {**TABLE, "own.T": "0.05 s"}, run=True, focus=_entry(size)),
    )


@pytest.mark.parametrize("size", SIZES)
def test_model_check(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("model_check", TABLE, run=True, focus=_entry(size)),
    )


@pytest.mark.parametrize("size", SIZES)
def test_summary_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("summary", {"summary.1": "b", "summary.5": "b, c"}, focus=_entry(size)),
    )


@pytest.mark.parametrize("size", SIZES)
def test_help_screen(snap_compare, tmp_path, size):
    async def run_before(pilot) -> None:
        await _to("prep1")(pilot)
        await pilot.press("f1")
        await settle(pilot, lambda: bool(pilot.app.screen.query("#help-keys")))

    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=run_before)
