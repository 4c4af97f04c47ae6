"""The keys' one table (ui/keys.py): every binding it makes has its action, F1 lists each
key once, and the step panels' keys keep a lab assistant's key last in the footer."""

from __future__ import annotations

from minseg_tui.ui.app import LabApp
from minseg_tui.ui.keys import KEYMAP, app_bindings, help_lines, panel_keys


def test_every_bound_key_has_its_action_on_the_app():
    for k in KEYMAP:
        if k.action:
            assert callable(getattr(LabApp, f"action_{k.action}", None)), k


def test_help_lists_each_key_once_and_every_binding_is_described():
    names = [name for name, _ in help_lines()]
    assert len(names) == len(set(names)) and all(help_ for _, help_ in help_lines())
    bound = {b.key for b in app_bindings()} | {keys for keys, *_ in panel_keys()}
    described = {k.keys for k in KEYMAP if k.keys and (k.name or k.panel)}
    assert bound == described


def test_a_lab_assistants_key_is_last_among_the_panel_keys():
    actions = [action for _, action, _, _ in panel_keys()]
    assert actions[-1] == "reveal" and actions.index("set_voltage") == 0
