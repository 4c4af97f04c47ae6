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
from minseg_tui.lab.content.keys import KEY_NAMES, PALETTE
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
        else:  # bound to the action, on the screen or on the app ('app.class_view')
            assert bindings & {(key, action), (key, f"app.{action}")}, (action, key)
    # and F1's list writes each of the lab screen's keys as the sentences do (the start
    # screen's Ctrl+N and F12, before any lab step, are not in it)
    lab_keys = {n for a, n in KEY_NAMES.items() if a not in ("new_anyway", "class_view")}
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


def _call(node: ast.AST, name: str) -> ast.Call | None:
    """``node`` when it is a call of the function ``name`` (by its bare name), else None."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == name:
        return node
    return None


def _palette_key(node: ast.expr) -> bool:
    """Whether ``node`` is ``key_name('palette')`` or ``KEY_NAMES['palette']``."""
    call = _call(node, "key_name")
    if call is not None:
        return isinstance(call.args[0], ast.Constant) and call.args[0].value == "palette"
    return (
        isinstance(node, ast.Subscript)
        and isinstance(node.value, ast.Name)
        and node.value.id == "KEY_NAMES"
        and isinstance(node.slice, ast.Constant)
        and node.slice.value == "palette"
    )


BY_HAND = re.compile(r"^\s*(?:→\s*|['‘\"]\s*)\w")
"""Text after the palette's key that names a command written by hand: "Ctrl+P 'Frobnicate'",
"Ctrl+P → Frobnicate" (a command's name comes from PALETTE: in_palette, USE_RUN)."""

NAME_FOLLOWS = re.compile(r"^\s*(?:→\s*|['‘\"])?$")
"""Text after the palette's key before the command's name, from the table: "Ctrl+P '" then
USE_RUN."""

KEY_ALONE = re.compile(r"^\s*(?:[).,;:!?]|$)|^\s+\w+ the (?:command )?palette\b")
"""Text after the palette's key that names no command: the key alone ("press Ctrl+P."), or
the palette itself ("Ctrl+P opens the palette")."""


def _named_from_table(node: ast.expr | None) -> bool:
    """Whether ``node`` (a formatted value's expression) is a command's title from the table:
    USE_RUN or PALETTE[...]."""
    if isinstance(node, ast.Name):
        return node.id == "USE_RUN"
    return (
        isinstance(node, ast.Subscript)
        and isinstance(node.value, ast.Name)
        and node.value.id == "PALETTE"
    )


def _after_palette_key(parts: list[ast.expr], k: int) -> str | None:
    """What is wrong with the words after the palette's key at ``parts[k]`` of an f-string,
    or None: a command written by hand ("Ctrl+P 'Frobnicate'"), or one told in other words
    ("Ctrl+P counts one revolution by hand") where in_palette or USE_RUN names it."""
    after = parts[k + 1] if k + 1 < len(parts) else None
    if after is None:
        return None
    if not isinstance(after, ast.Constant):
        return f"{ast.unparse(after)} after the palette's key"
    text = str(after.value)
    if BY_HAND.match(text):
        return repr(text)
    if NAME_FOLLOWS.match(text):
        name = parts[k + 2] if k + 2 < len(parts) else None
        if isinstance(name, ast.FormattedValue) and _named_from_table(name.value):
            return None
        return f"{text!r} then no command of the table"
    if KEY_ALONE.match(text):
        return None
    return f"a command in other words: {text!r}"


def test_a_sentence_names_only_the_palette_commands_of_the_table():
    """Issue 19 item 3: a palette command's title is written once, in PALETTE (lab/content/
    keys.py), which the palette (ui/app.py) titles its commands from. A sentence names a
    command through in_palette('export') or USE_RUN; it fails here when it writes a title by
    hand, names a command after the palette's key by hand or in other words ("Ctrl+P counts
    one revolution by hand"), or asks in_palette for a command the table does not hold."""
    titles = {t for t in PALETTE.values() if " " in t}  # 'Keys' alone is any heading's word
    written: list[str] = []
    for folder in ("lab", "report", "ui", "cli"):
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            if path in EXEMPT:
                continue
            where = path.relative_to(PACKAGE)
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in _strings_outside_docstrings(tree):
                written += [f"{where}:{node.lineno}: {t}" for t in titles if t in node.value]
            for node in ast.walk(tree):
                call = _call(node, "in_palette")
                if call is not None:
                    command = call.args[0]
                    if not (isinstance(command, ast.Constant) and command.value in PALETTE):
                        written.append(f"{where}:{call.lineno}: in_palette({ast.unparse(command)})")
                if isinstance(node, ast.JoinedStr):
                    parts = node.values
                    for k, part in enumerate(parts):
                        if isinstance(part, ast.FormattedValue) and _palette_key(part.value):
                            wrong = _after_palette_key(parts, k)
                            if wrong is not None:
                                written.append(f"{where}:{node.lineno}: {wrong}")
    assert not written, "\n".join(written)


def _lab_entries() -> list[str]:
    """The table's keys that title the lab screen's own palette entries (StepCommands.entries
    in ui/screens/lab.py: a step to go to, a run to use), or 'by hand: ...' for a title
    written there."""
    tree = ast.parse((PACKAGE / "ui" / "screens" / "lab.py").read_text(encoding="utf-8"))
    (entries,) = [
        f
        for c in ast.walk(tree)
        if isinstance(c, ast.ClassDef) and c.name == "StepCommands"
        for f in c.body
        if isinstance(f, ast.FunctionDef) and f.name == "entries"
    ]
    keys: list[str] = []
    body = [node for statement in entries.body for node in ast.walk(statement)]
    for node in body:
        if isinstance(node, ast.Tuple) and len(node.elts) == 3:  # (title, action, help)
            title = node.elts[0]
            first = title.values[0] if isinstance(title, ast.JoinedStr) else title
            named = first.value if isinstance(first, ast.FormattedValue) else first
            if isinstance(named, ast.Subscript) and _named_from_table(named):
                keys.append(ast.unparse(named.slice).strip("'\""))
            elif isinstance(named, ast.Name) and _named_from_table(named):
                keys.append("use_run")
            else:
                keys.append(f"by hand: {ast.unparse(title)}")
    return keys


def test_the_palette_titles_its_commands_from_the_table():
    """Every command the app puts in the palette is titled by PALETTE, and so is each of the
    lab screen's own entries (a step to go to, a run to use); each of the table's commands
    is one the palette offers."""
    tree = ast.parse((PACKAGE / "ui" / "app.py").read_text(encoding="utf-8"))
    keys: list[str] = []
    for node in ast.walk(tree):
        call = _call(node, "SystemCommand")
        if call is not None:
            title = call.args[0]
            if (
                isinstance(title, ast.Subscript)
                and isinstance(title.value, ast.Name)
                and title.value.id == "PALETTE"
            ):
                keys.append(ast.unparse(title.slice))
            else:
                keys.append(f"by hand: {ast.unparse(title)}")
    # the step panels' commands are titled in one loop, PALETTE[action] over their actions
    looped = [k for k in keys if k == "action"]
    assert len(looped) == 1, keys
    panel = {"set_voltage", "capture", "run_square_wave", "run_fast", "reveal"}
    named = {k.strip("'\"") for k in keys if k != "action"}
    lab = _lab_entries()
    assert not [k for k in lab if k.startswith("by hand")], lab
    assert named | panel | set(lab) == set(PALETTE), (keys, lab)
