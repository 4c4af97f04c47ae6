"""Fixtures: the app on a real session folder (tmp_path), on the real virtual MinSeg (real
factory, link and URL board) or, for pinned screens, on a device double that sends nothing;
every Input's cursor kept still; Pilot's waits exact instead of timed; no frame painted
for a headless terminal that throws it away. The async tests run
under pytest-asyncio (auto mode)."""

from __future__ import annotations

import asyncio
import itertools
from collections.abc import Callable
from pathlib import Path

import pytest
from textual.pilot import Pilot

from minseg_tui.report.write import write_class, write_report
from minseg_tui.ui.app import LabApp, make_app
from minseg_tui.ui.config import UiConfig
from tests.ui.fakes import QuietDevice
from tests.ui.textual_internals import (
    all_idle,
    keep_cursors_still,
    leave_headless_frames_unpainted,
    make_waits_exact,
    mark_idle_nodes,
    running_app,
    wait_for_screen,
)

DATE = "2024-04-16"
_names = itertools.count()


def board_url(seed: int = 1) -> str:
    """A fresh named virtual MinSeg in real time (named: tests can unplug it)."""
    return f"minseg://ui-{next(_names)}?clock=real&seed={seed}"


def quiet_app(root: Path, device: QuietDevice | None = None) -> LabApp:
    """The app on the device double (it looks like the virtual MinSeg found in place of a
    board); no redraw timer, no animation."""
    dev = device or QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: dev)


def real_app(root: Path, url: str) -> LabApp:
    """The app as the CLI makes it, on the board at ``url``, with the report writers."""
    return make_app(
        UiConfig(device=url, sessions=root, today=DATE, animations=False, refresh=0.25),
        lambda session: write_report(session).paths,
        write_class,
    )


@pytest.fixture(autouse=True)
def no_cursor_blink(monkeypatch: pytest.MonkeyPatch) -> None:
    """Keep every Input's cursor shown: a blinking cursor would make a screen depend on when
    it was taken (harlequin's tests do the same)."""
    keep_cursors_still(monkeypatch)


@pytest.fixture
def quiet(tmp_path: Path) -> Callable[..., LabApp]:
    def _make(device: QuietDevice | None = None) -> LabApp:
        return quiet_app(tmp_path / "sessions", device)

    return _make


DRAIN_ROUNDS = 8
"""Most rounds :func:`drained` waits for the app's queues to empty. An app on the real-time
board never empties them (its stream brings a message every 40 ms): there the key's own
chain of messages is handled within the first rounds (:func:`tests.ui.helpers.settle`
carries chains of four), and the rest is the stream's."""


async def drained(_min_sleep: float = 0.0, _max_sleep: float = 0.0) -> None:
    """Return once the app has processed every message: the key a Pilot just sent and all it
    led to, round by round (each round waits until every node of the app and of its screens
    has handled what was queued on it when the round began, a handler under way included),
    until a round ends with the app and every node of its screen idle (nothing queued, no
    handler under way: ``textual_internals.all_idle``) and nothing queued on the screens
    under it, or :data:`DRAIN_ROUNDS` rounds. Takes the arguments of Textual's
    ``wait_for_idle`` and ignores them."""
    for _ in range(3):  # the driver hands a key over through the loop (run_coroutine_threadsafe)
        await asyncio.sleep(0)
    app = running_app()
    if app is None:
        return
    pilot = Pilot(app)
    for _ in range(DRAIN_ROUNDS):
        if not app.is_running:
            return
        await wait_for_screen(pilot)
        under = [n for s in app.screen_stack[:-1] for n in s.walk_children(with_self=True)]
        if all_idle(app) and all(n.message_queue_size == 0 for n in under):
            return


@pytest.fixture(autouse=True)
def exact_pilot_waits(monkeypatch: pytest.MonkeyPatch) -> None:
    """Pilot waits after every key it presses (and in ``pause()``) until the process has used
    almost no CPU for 20 ms, at most 1 s: a guess on the clock, which the CPU that the app's
    threads use (the board, the stream) makes last up to the second, key after key, and a busy
    machine cuts short. :func:`drained` waits for exactly what the key set going, on the
    nodes that are not idle (``textual_internals.idle``)."""
    mark_idle_nodes(monkeypatch)
    make_waits_exact(monkeypatch, drained)


@pytest.fixture(autouse=True)
def no_headless_frames(monkeypatch: pytest.MonkeyPatch, request: pytest.FixtureRequest) -> None:
    """A headless app's frames are not painted (``textual_internals.unpainted_refresh``:
    painting frames its driver throws away was about 40 % of a UI test's CPU). The whole-lab
    walks (marked slow) paint every frame, as the app does in a terminal, so a widget that
    fails while it is drawn fails them."""
    if request.node.get_closest_marker("slow") is None:
        leave_headless_frames_unpainted(monkeypatch)
