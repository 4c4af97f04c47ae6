"""Issue 19 item 3: a key's name is written once. The lab's and the report's sentences name
keys ('F2 stops', "Ctrl+P 'Use run steps-1'") from lab/content/keys.py, below the UI; the
UI's table of keys takes the same names, and each name is the key its binding answers to."""

from __future__ import annotations

import ast
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


def _app_bindings() -> dict[str, str]:
    """Every binding the app class and its bases declare: {key: action}."""
    out: dict[str, str] = {}
    for cls in reversed(LabApp.__mro__):
        for b in Binding.make_bindings(cls.__dict__.get("BINDINGS", [])):
            out[b.key] = b.action
    return out


def test_each_key_name_is_the_key_its_binding_answers_to():
    rows = {k.action: k for k in KEYMAP if k.action}
    bindings = _app_bindings()
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
            assert bindings.get(key) == action, (action, key, bindings.get(key))
    # and F1's list writes each of them as the lab's words do
    assert {n for n in KEY_NAMES.values()} <= {k.name for k in KEYMAP}


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


def test_no_sentence_below_the_ui_writes_a_key_by_hand():
    written: list[str] = []
    for folder in ("lab", "report"):
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            if path == PACKAGE / "lab" / "content" / "keys.py":
                continue
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in _strings_outside_docstrings(tree):
                for m in KEY_WORD.finditer(node.value):
                    written.append(f"{path.relative_to(PACKAGE)}:{node.lineno}: {m.group(0)}")
    assert not written, "\n".join(written)
