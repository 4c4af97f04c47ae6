"""The keys and palette commands the lab's sentences send a group to, by name.

The lab's words (a step's What to do, a notice, a line of the report) name keys: "F2
stops", "press F10", "Ctrl+P 'Use run steps-1'". They sit below the UI, which binds the
keys, so the names are written here once: the UI's table of keys
(:data:`minseg_tui.ui.keys.KEYMAP`) takes each key's name from :data:`KEY_NAMES`, and its
palette titles its commands from :data:`PALETTE`. Tests check that each name is the one its
binding answers to, and that the palette offers each command a sentence names.
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
        "class_view": "F12",
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

PALETTE: Final = MappingProxyType(
    {
        "stop_motor": "Stop motor",
        "set_voltage": "Set step voltage",
        "capture": "Capture omega_ss",
        "run_square_wave": "Run the square wave",
        "run_fast": "Run the square wave fast",
        "reveal": "Reveal computed values",
        "board_check": "Board check",
        "count_revolution": "Count one revolution by hand",
        "export": "Export report",
        "save_elsewhere": "Save the session to another folder",
        "correct_names": "Correct the group's names",
        "import_log": "Import a run log",
        "switch_to_virtual": "Switch to virtual board",
        "back_to_class": "Back to the class view",
        "use_run": "Use run",
        "use_newest_run": "Use the newest complete 25 ms run for Tasks 11-15",
        "go_to": "Go to:",
        "help": "Keys",
    }
)
"""Each of our palette commands by what it does (the app's action where it has one), with
its title as the palette lists it and a sentence names it ('use_run' is the start of 'Use
run steps-1 for Tasks 11-15', 'go_to' of 'Go to: Task 10: the step experiment'; 'help'
replaces Textual's own 'Keys'). The palette (ui/app.py, and the lab screen's entries in
ui/screens/lab.py) titles its commands from here, and a test fails on a sentence that names
one by hand."""

USE_RUN: Final = PALETTE["use_run"]
"""The start of the palette's command that picks the run Tasks 11-15 use ('Use run steps-1
for Tasks 11-15')."""


def key_name(action: str) -> str:
    """The key that does ``action`` (a key of :data:`KEY_NAMES`), as the lab's words write
    it: 'F2' for 'stop_motor'."""
    return KEY_NAMES[action]


def in_palette(command: str) -> str:
    """Where the palette's ``command`` (a key of :data:`PALETTE`) is, as a step's words send a
    group there: 'Ctrl+P → Count one revolution by hand' for 'count_revolution'."""
    return f"{KEY_NAMES['palette']} → {PALETTE[command]}"


__all__ = ["KEY_NAMES", "PALETTE", "USE_RUN", "in_palette", "key_name"]
