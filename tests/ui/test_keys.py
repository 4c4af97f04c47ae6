"""The keys' one table (ui/keys.py): every binding has its action on the class that binds it
(where Textual runs it), every key of the table is bound, F1 lists each key once, and the
step panels' keys keep a lab assistant's key last in the footer."""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys

from textual.actions import parse as parse_action
from textual.app import App
from textual.binding import Binding
from textual.dom import DOMNode

from minseg_tui import ui
from minseg_tui.ui.keys import KEYMAP, PanelKeys, app_bindings, help_lines, panel_keys


def ui_classes() -> list[type]:
    """Every class the UI defines (the app, its screens, the step's form, the panels and
    the widgets), each of ui/'s modules imported."""
    for module in pkgutil.walk_packages(ui.__path__, f"{ui.__name__}."):
        importlib.import_module(module.name)
    return [
        cls
        for name, module in sorted(sys.modules.items())
        if name == ui.__name__ or name.startswith(f"{ui.__name__}.")
        for _, cls in inspect.getmembers(module, inspect.isclass)
        if cls.__module__ == name
    ]


def has_action(node: type, action: str) -> bool:
    """Whether ``node`` has ``action``'s method, as Textual looks for it: ``action_<name>``,
    or ``_action_<name>`` (Textual's palette's Escape, whose binding our Palette keeps)."""
    return any(callable(getattr(node, f"{p}action_{action}", None)) for p in ("", "_"))


def test_every_binding_has_its_action_on_the_class_that_binds_it():
    # Textual runs a binding's action on the node whose BINDINGS hold it: a key bound by a
    # class that lacks the action's method does nothing (a mixin's, on each class it is in)
    classes = ui_classes()
    apps = [c for c in classes if issubclass(c, App)]
    bound: set[str] = set()
    for cls in (c for c in classes if "BINDINGS" in c.__dict__):
        nodes = [c for c in classes if issubclass(c, DOMNode) and issubclass(c, cls)]
        for binding in Binding.make_bindings(cls.__dict__["BINDINGS"]):
            namespace, action, parameters = parse_action(binding.action)
            assert namespace in ("", "app"), (cls, binding)
            # 'app.<name>': the app's action, whatever binds it
            runs_on = apps if namespace == "app" else nodes
            assert runs_on, (cls, binding)
            for node in runs_on:
                assert has_action(node, action), (node, binding)
            bound.add(action if action != "panel_key" else str(parameters[0]))
    # and every key of the table is bound, a panel key's action on a panel that has it
    panels = [c for c in classes if issubclass(c, PanelKeys)]
    for k in KEYMAP:
        if k.action:
            assert k.action in bound, k
        if k.panel:
            assert any(callable(getattr(p, f"action_{k.action}", None)) for p in panels), k


def test_help_lists_each_key_once_and_every_binding_is_described():
    names = [name for name, _ in help_lines()]
    assert len(names) == len(set(names)) and all(help_ for _, help_ in help_lines())
    bound = {b.key for b in app_bindings()} | {keys for keys, *_ in panel_keys()}
    described = {k.keys for k in KEYMAP if k.keys and (k.name or k.panel)}
    assert bound == described


def test_a_lab_assistants_key_is_last_among_the_panel_keys():
    actions = [action for _, action, _, _ in panel_keys()]
    assert actions[-1] == "reveal" and actions.index("set_voltage") == 0
