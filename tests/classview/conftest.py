"""Every test reads the class cold: its own empty cache folder (MINSEG_TUI_CACHE). The
Pilot tests of the class screen wait as the UI tests do (tests/ui/conftest.py's autouse
fixtures: exact waits instead of Pilot's wait for an idle CPU, which lasts up to a second
per key and is cut short on a busy machine; no frame painted for the headless terminal,
Inputs' cursors still)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.ui.conftest import exact_pilot_waits, no_cursor_blink, no_headless_frames

__all__ = ["exact_pilot_waits", "no_cursor_blink", "no_headless_frames", "own_cache"]


@pytest.fixture(autouse=True)
def own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    cache = tmp_path / "class-cache"
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(cache))
    return cache
