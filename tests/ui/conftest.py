"""Fixtures: the app on a real session folder (tmp_path), on the real virtual MinSeg (real
factory, link and URL board) or, for pinned screens, on a device double that sends nothing."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp, make_app
from minseg_tui.ui.backend import SessionStore
from minseg_tui.ui.config import UiConfig
from tests.ui.fakes import QuietDevice

DATE = "2024-04-16"
_names = itertools.count()


def board_url(seed: int = 1) -> str:
    """A fresh named virtual MinSeg in real time (named: tests can unplug it)."""
    return f"minseg://ui-{next(_names)}?clock=real&seed={seed}"


def quiet_app(root: Path, device: QuietDevice | None = None) -> LabApp:
    dev = device or QuietDevice(seed=1)
    cfg = UiConfig(device="sim", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, SessionStore(root), lambda spec: dev)


def real_app(root: Path, url: str) -> LabApp:
    return make_app(
        UiConfig(device=url, sessions=root, today=DATE, animations=False, refresh=0.25),
        write_report,
    )


async def settle(pilot, timeout: float = 20.0) -> None:
    """Wait until every worker but the device stream has finished, then let the screen update."""
    import time

    end = time.monotonic() + timeout
    while time.monotonic() < end:
        await pilot.pause(0.05)
        if all(w.group == "stream" or w.is_finished for w in pilot.app.workers):
            break
    await pilot.pause(0.05)


@pytest.fixture
def quiet(tmp_path: Path):
    def _make(device: QuietDevice | None = None) -> LabApp:
        return quiet_app(tmp_path / "sessions", device)

    return _make


@pytest.hookimpl(tryfirst=True)
def pytest_pyfunc_call(pyfuncitem: pytest.Function) -> bool | None:
    """Run ``async def`` tests here with asyncio (no async plugin is installed)."""
    import asyncio
    import inspect

    if not inspect.iscoroutinefunction(pyfuncitem.obj):
        return None
    names = pyfuncitem._fixtureinfo.argnames
    asyncio.run(pyfuncitem.obj(**{n: pyfuncitem.funcargs[n] for n in names}))
    return True
