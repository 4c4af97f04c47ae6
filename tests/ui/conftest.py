"""Fixtures: the app on a real session folder (tmp_path) with a deterministic device double."""

from __future__ import annotations

from pathlib import Path

import pytest

from minseg_tui.ui.app import LabApp
from minseg_tui.ui.backend import SessionStore
from minseg_tui.ui.config import UiConfig
from tests.ui.fakes import FakeDevice

DATE = "2024-04-16"


def build_app(root: Path, device: FakeDevice | None = None) -> LabApp:
    dev = device or FakeDevice(seed=1)
    cfg = UiConfig(device="sim", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, SessionStore(root), lambda spec: dev)


@pytest.fixture
def make(tmp_path: Path):
    def _make(device: FakeDevice | None = None) -> LabApp:
        return build_app(tmp_path / "sessions", device)
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
