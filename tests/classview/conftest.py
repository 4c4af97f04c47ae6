"""Every test reads the class cold: its own empty cache folder (MINSEG_TUI_CACHE)."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(autouse=True)
def own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    cache = tmp_path / "class-cache"
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(cache))
    return cache
