"""The app's keys in one table: what each is called, what F1 says it does, and the binding
behind it (its action, its footer label, and for a step panel's key what it is when a step
has no such panel). F1's list (:func:`help_lines`), the app's bindings (:func:`app_bindings`)
and the step panels' keys (:func:`panel_keys`) are made from it, so a key's words are written
once."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from textual.binding import Binding
from textual.widget import Widget

from minseg_tui.lab.content.keys import KEY_NAMES


@dataclass(frozen=True)
class Key:
    """One key (or the keys of one line of help).

    ``name``/``help``: the key as F1 writes it and what it does there (no name: no line of
    its own). ``keys``: Textual's key names of its binding ('': bound elsewhere, by the
    screen or the widget that owns it, or Textual's own); ``action``: the app's action (a
    panel key's: the panel's, which the step's form runs);
    ``label``: in the footer ('': not there); ``shown``: whether the footer shows it;
    ``priority``: the app's before any widget's. ``panel``: a key that acts on the shown
    step's panel, and what it is, for the line saying it is not part of this step;
    ``assistant``: a lab assistant's key (last in the footer, the first left out where its
    line cannot hold every key); ``footer_on``: the steps whose footer shows a key that is
    not shown elsewhere but works on every step (F10 on Task 1, which asks for it); the
    app has an action of its name with :data:`IN_FOOTER` after it, which runs it.
    ``written``: the key as a note under a plot writes it (:func:`key_hint`; '': its first
    Textual key name, 'f9').

    ``label`` is the key's one name: the footer shows it, F1's line starts with it (a line
    of two keys, Alt+← →, with that of the one the footer shows) and a note names the key
    with it (:func:`key_hint`), so a key reads the same wherever it is named."""

    name: str
    help: str
    keys: str = ""
    action: str = ""
    label: str = ""
    shown: bool = True
    priority: bool = False
    panel: str = ""
    assistant: bool = False
    footer_on: tuple[str, ...] = ()
    written: str = ""


QUIT_SAVED = "quit (the session is already saved)"
"""Ctrl+Q's line in F1 in the lab; outside it, with no session open, F1 says "quit"."""

KEYMAP: tuple[Key, ...] = (
    Key(KEY_NAMES["help"], "this list of keys", "f1", "help", "Help", priority=True),
    Key(
        KEY_NAMES["stop_motor"],
        "the motor stops (works everywhere, always)",
        "f2",
        "stop_motor",
        "STOP",
        priority=True,
    ),
    Key(
        KEY_NAMES["set_voltage"],
        "the next voltage, 2.5/3.5/4.5 V (Tasks 3-5)",
        "f3",
        "set_voltage",
        "Set V",
        panel="setting a voltage",
    ),
    Key(
        KEY_NAMES["capture"],
        "omega_ss over the settled window (Task 4)",
        "f4",
        "capture",
        "Capture",
        panel="capturing omega_ss",
    ),
    Key(
        KEY_NAMES["run_square_wave"],
        "the square wave on the board (Task 10)",
        "f5",
        "run_square_wave",
        "Run",
        panel="the step experiment",
    ),
    Key(
        KEY_NAMES["run_fast"],
        "the square wave with 5 ms board-timed samples",
        "f6",
        "run_fast",
        "Run 5 ms",
        panel="the fast step experiment",
    ),
    Key(
        KEY_NAMES["formula"],
        "how the table cell is worked out",
        "f7",
        "formula",
        "Formula",
        panel="a table formula",
    ),
    Key(
        KEY_NAMES["export"],
        "the report as Markdown, HTML and CSV files",
        "f8",
        "export",
        "Export",
        priority=True,
    ),
    Key(
        KEY_NAMES["zoom_next"],
        "the next rise, after the last the whole log (Tasks 11-15); the close-up or the "
        "whole log (model check)",
        "f9",
        "zoom_next",
        "Zoom",
        panel="zooming the run log",
    ),
    Key(
        KEY_NAMES["board_check"],
        "does the wheel turn, does the count follow?",
        "f10",
        "board_check",
        "Board check",
        shown=False,
        priority=True,
        footer_on=("task1",),
    ),
    Key(
        KEY_NAMES["reveal"],
        "a lab assistant shows the computed values before the group answers",
        "ctrl+r",
        "reveal",
        "Reveal",
        panel="revealing computed values",
        assistant=True,
    ),
    Key(
        "Alt+← →",
        "the previous / next rise: the speed after a voltage step up (Tasks 11-15)",
        "alt+left,ctrl+left",
        "pick_prev",
        panel="moving through the run log",
    ),
    Key(
        "",
        "",
        "alt+right,ctrl+right",
        "pick_next",
        "Rise",
        panel="moving through the run log",
        written="alt+←/→",
    ),
    Key("Ctrl+← →", "the same, outside a text entry"),
    Key("[ ] z", "the same on the focused plot; z zooms"),
    Key(
        "← → on a rise",
        "the focused plot's cursor: t and omega at its column (Shift: 5; Home/End: the ends)",
    ),
    Key("PgDn/PgUp", "the next lab step; PgUp the one before (Ctrl+N / Ctrl+B)", label="Next step"),
    Key("Ctrl+L", "the list of steps (Ctrl+T hides it)"),
    Key(
        KEY_NAMES["whole_todo"],
        "the whole of the step's What to do, over its top (again: folds it)",
    ),
    Key("Tab", "next field; Enter stores and goes on to the next field"),
    Key(
        "Esc",
        "in a field: back to the answer stored, dropping what was typed over it; in a group "
        "opened from the class view: back to the class view",
    ),
    Key(KEY_NAMES["undo"], "in a field: back to the answer stored before (again: further back)"),
    Key(
        KEY_NAMES["redo"],
        f"in a field: forward again to the answer {KEY_NAMES['undo']} took back",
    ),
    Key("Space", "tick an answer (summary questions)"),
    # Textual's own binding and footer word ('palette'), written here as the footer shows it
    Key(
        KEY_NAMES["palette"],
        "the command palette: go to a step, pick the run, stop...",
        label="palette",
    ),
    Key(KEY_NAMES["quit"], QUIT_SAVED),
)
"""Every key F1 lists, in its order, with the bindings the app makes for them."""


def help_lines() -> list[tuple[str, str]]:
    """F1's list: (the key as written, what it does), what it does after the key's footer
    label ('Zoom: the next rise, ...'), the words the footer and the notes name it with."""
    out: list[tuple[str, str]] = []
    for i, k in enumerate(KEYMAP):
        if not k.name:
            continue
        label = k.label or _partner(i).label
        out.append((k.name, f"{label}: {k.help}" if label else k.help))
    return out


def key_label(name: str) -> str:
    """The footer label of the key F1 lists as ``name``, for a binding made elsewhere (the
    lab screen's PgDn: 'Next step')."""
    return next(k.label for k in KEYMAP if k.name == name)


def _partner(i: int) -> Key:
    """The row after F1's line ``i`` with no line of its own, the other key of that line
    (Alt+→ after Alt+←), or the row itself."""
    after = KEYMAP[i + 1] if i + 1 < len(KEYMAP) else None
    return after if after is not None and not after.name else KEYMAP[i]


def key_hint(action: str, what: str = "") -> str:
    """The key of the app's ``action`` as a note under a plot names it, with its footer
    label: 'f9 Zoom', 'alt+←/→ Rise'; ``what``: what it does there, after it in brackets
    ('f9 Zoom (rise 2)')."""
    k = next(k for k in KEYMAP if k.action == action)
    hint = f"{k.written or k.keys.split(',')[0]} {k.label}"
    return f"{hint} ({what})" if what else hint


def bound_keys(action: str) -> str:
    """The Textual key names of the binding of the app's ``action`` ('f8'), for a second
    binding of the same key."""
    return next(k.keys for k in KEYMAP if k.action == action)


def panel_keys() -> tuple[tuple[str, str, str, str], ...]:
    """The keys that act on the shown step's panel: (keys, the panel's action, footer label,
    what it is), a lab assistant's keys last."""
    panel = sorted((k for k in KEYMAP if k.panel), key=lambda k: k.assistant)
    return tuple((k.keys, k.action, k.label, k.panel) for k in panel)


class PanelKeys(Widget):
    """A step panel with keys (:func:`panel_keys`): :meth:`key_actions`, the actions of those
    it has, each with the method that does it; its ``check_action`` says on which steps one
    does nothing. The step's form binds the keys
    (:class:`~minseg_tui.ui.screens.lab.StepPane`), and the lab screen calls the method
    (:meth:`~minseg_tui.ui.screens.lab.LabScreen.run_panel_key`)."""

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        """The panel keys' actions it has (:func:`panel_keys`), each with its method (awaited
        when it returns an awaitable)."""
        return {}


FOOTER_ON: dict[str, tuple[str, ...]] = {k.action: k.footer_on for k in KEYMAP if k.footer_on}
"""The app's actions shown in the footer on some steps only (:attr:`Key.footer_on`)."""

IN_FOOTER = "_in_footer"
"""What the action of the binding the footer shows of a :data:`FOOTER_ON` key has after the
key's own action's name ('board_check_in_footer')."""


def app_bindings() -> list[Binding]:
    """The app's own keys' bindings (those of the step panels are :func:`panel_keys`). A key
    with :attr:`Key.footer_on` has two: first one shown in the footer, whose action (its
    own with :data:`IN_FOOTER` after it) the app's ``check_action`` leaves out (not live,
    not shown) on the other steps, then its own, which runs wherever the first is not live
    (Textual tries a key's bindings in turn until one's action runs)."""
    out: list[Binding] = []
    for k in KEYMAP:
        if not k.keys or k.panel:
            continue
        if k.footer_on:
            action = f"{k.action}{IN_FOOTER}"
            out.append(Binding(k.keys, action, k.label, priority=k.priority))
        out.append(Binding(k.keys, k.action, k.label, show=k.shown, priority=k.priority))
    return out
