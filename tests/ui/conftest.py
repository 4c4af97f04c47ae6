"""Fixtures: the app on a real session folder (tmp_path), on the real virtual MinSeg (real
factory, link and URL board) or, for pinned screens, on a device double that sends nothing;
every Input's cursor kept still. The async tests run under pytest-asyncio (auto mode)."""

from __future__ import annotations

import itertools
from collections.abc import Callable
from pathlib import Path

import pytest
from textual.widgets import Input

from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp, make_app
from minseg_tui.ui.config import UiConfig
from tests.ui.fakes import QuietDevice

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
    """The app as the CLI makes it, on the board at ``url``, with the report writer."""
    return make_app(
        UiConfig(device=url, sessions=root, today=DATE, animations=False, refresh=0.25),
        lambda session: write_report(session).paths,
    )


@pytest.fixture(autouse=True)
def no_cursor_blink(monkeypatch: pytest.MonkeyPatch) -> None:
    """Keep every Input's cursor shown: a blinking cursor would make a screen depend on when
    it was taken (harlequin's tests do the same)."""
    monkeypatch.setattr(Input, "_toggle_cursor", lambda _self: None)


@pytest.fixture
def quiet(tmp_path: Path) -> Callable[..., LabApp]:
    def _make(device: QuietDevice | None = None) -> LabApp:
        return quiet_app(tmp_path / "sessions", device)

    return _make
