"""Issue 19 item 3: a key's name is written once. The lab's, the report's and the UI's
sentences name keys ('F2 stops', "Ctrl+P 'Use run steps-1'") from lab/content/keys.py, below
the UI; the UI's table of keys (F1's list) takes the same names, and each name is the key its
binding answers to."""

from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

from textual.binding import Binding

import minseg_tui
from minseg_tui.lab.content.keys import KEY_NAMES
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.keys import KEYMAP
from minseg_tui.ui.widgets.fields import RESTORING_KEYS

KEY_WORD = re.compile(r"\b(F[1-9][0-9]?|Ctrl\+[A-Z]|Alt\+\S+)(?![\w])")
"""A key as a person writes it, inside a sentence."""

PACKAGE = Path(minseg_tui.__file__).parent


def _textual(name: str) -> str:
    """'Ctrl+R' as Textual names the key: 'ctrl+r'."""
    return name.lower()


def _bindings() -> set[tuple[str, str]]:
    """Every (key, action) bound by the app, its bases and the UI's screens and widgets."""
    classes: set[type] = set(LabApp.__mro__)
    for path in sorted((PACKAGE / "ui").rglob("*.py")):
        name = ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        module = importlib.import_module(name)
        classes |= {c for c in vars(module).values() if isinstance(c, type)}
    return {
        (b.key, b.action)
        for cls in classes
        for b in Binding.make_bindings(cls.__dict__.get("BINDINGS", []))
    }


def test_each_key_name_is_the_key_its_binding_answers_to():
    rows = {k.action: k for k in KEYMAP if k.action}
    bindings = _bindings()
    for action, name in KEY_NAMES.items():
        key = _textual(name)
        if action in rows:
            assert rows[action].name == name, (action, rows[action].name)
            assert key in rows[action].keys.split(","), (action, rows[action].keys)
        elif action == "palette":
            assert LabApp.COMMAND_PALETTE_BINDING == key
        elif action in ("undo", "redo"):
            assert RESTORING_KEYS[key] == action
        else:
            assert (key, action) in bindings, (action, key)
    # and F1's list writes each of the lab screen's keys as the sentences do (the start
    # screen's Ctrl+N, before any lab step, is not in it)
    lab_keys = {n for a, n in KEY_NAMES.items() if a != "new_anyway"}
    assert lab_keys <= {k.name for k in KEYMAP}


def _strings_outside_docstrings(tree: ast.AST) -> list[ast.Constant]:
    docs = {
        id(node.body[0].value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)
        and node.body
        and isinstance(node.body[0], ast.Expr)
        and isinstance(node.body[0].value, ast.Constant)
    }
    # a string right after an assignment documents it (an attribute's docstring)
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list):
            for before, after in zip(body, body[1:], strict=False):
                if (
                    isinstance(before, ast.Assign | ast.AnnAssign)
                    and isinstance(after, ast.Expr)
                    and isinstance(after.value, ast.Constant)
                ):
                    docs.add(id(after.value))
    return [
        n
        for n in ast.walk(tree)
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docs
    ]


EXEMPT = (PACKAGE / "lab" / "content" / "keys.py", PACKAGE / "ui" / "keys.py")
"""Where keys are named: the names sentences use, and F1's table of every key."""


def test_no_sentence_writes_a_key_by_hand():
    written: list[str] = []
    for folder in ("lab", "report", "ui", "cli"):
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            if path in EXEMPT:
                continue
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in _strings_outside_docstrings(tree):
                for m in KEY_WORD.finditer(node.value):
                    written.append(f"{path.relative_to(PACKAGE)}:{node.lineno}: {m.group(0)}")
    assert not written, "\n".join(written)
