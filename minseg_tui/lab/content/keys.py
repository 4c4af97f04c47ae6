"""The keys and palette commands the lab's sentences send a group to, by name.

The lab's words (a step's What to do, a notice, a line of the report) name keys: "F2
stops", "press F10", "Ctrl+P 'Use run steps-1'". They sit below the UI, which binds the
keys, so the names are written here once: the UI's table of keys
(:data:`minseg_tui.ui.keys.KEYMAP`) takes each key's name from :data:`KEY_NAMES`, and its
palette titles its commands with :data:`USE_RUN` and :data:`COUNT_BY_HAND`. A test checks
that each name is the one its binding answers to.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Final

KEY_NAMES: Final = MappingProxyType(
    {
        "help": "F1",
        "stop_motor": "F2",
        "set_voltage": "F3",
        "capture": "F4",
        "run_square_wave": "F5",
        "run_fast": "F6",
        "formula": "F7",
        "export": "F8",
        "zoom_next": "F9",
        "board_check": "F10",
        "reveal": "Ctrl+R",
        "palette": "Ctrl+P",
        "quit": "Ctrl+Q",
        "whole_todo": "Ctrl+O",
        "new_anyway": "Ctrl+N",
        "undo": "Ctrl+Z",
        "redo": "Ctrl+Y",
    }
)
"""Each key by the action it does, as a person writes it ('F10', 'Ctrl+R'): the app's
action names where the app binds it, else what it does ('palette', 'undo')."""

USE_RUN: Final = "Use run"
"""The start of the palette's command that picks the run Tasks 11-15 use ('Use run steps-1
for Tasks 11-15')."""

COUNT_BY_HAND: Final = "Count one revolution by hand"
"""The palette's command for Task 3's count of one turn of the wheel by hand."""


def key_name(action: str) -> str:
    """The key that does ``action`` (a key of :data:`KEY_NAMES`), as the lab's words write
    it: 'F2' for 'stop_motor'."""
    return KEY_NAMES[action]


def in_palette(command: str) -> str:
    """Where the palette's ``command`` is, as a step's words send a group there:
    'Ctrl+P → Count one revolution by hand'."""
    return f"{KEY_NAMES['palette']} → {command}"


__all__ = ["COUNT_BY_HAND", "KEY_NAMES", "USE_RUN", "in_palette", "key_name"]
