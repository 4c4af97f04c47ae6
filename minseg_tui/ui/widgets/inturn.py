"""Keys that act in the order typed on a list or a table whose Enter is a priority binding.

Textual runs a widget's own bindings (Down on an OptionList, a DataTable's arrows) only once
the key has bubbled up from the widget to the app's queue (textual/app.py, ``_on_key``), while
a priority binding (the start screen's and the class view's Enter) runs the moment the app
reads its key. In one burst ('Down Enter', as tmux send-keys or a quick hand gives it) Enter
therefore acted on the row the cursor was leaving: the start screen resumed the group above
the one picked, writable, and the class view opened the group above (walk 15, D1). A widget
that runs its own bindings in its own key handler, as it reads each key, has moved before the
Enter behind it looks (:func:`minseg_tui.ui.widgets.fields.after_typed_keys` waits for the
focused widget's queue)."""

from __future__ import annotations

from textual import events
from textual.binding import Binding
from textual.dom import DOMNode
from textual.widget import Widget

NOT_HERE: frozenset[str] = frozenset({"enter"})
"""Keys left to Textual's way: Enter is the screen's (or the app's) priority binding."""


def own_bindings(widget: DOMNode, key: str) -> list[Binding]:
    """The bindings of ``key`` in ``widget``'s class that are not priority bindings, as
    Textual merges its classes' ``BINDINGS``: a class's own in place of its bases'."""
    for cls in type(widget).__mro__:
        bindings = Binding.make_bindings(cls.__dict__.get("BINDINGS", []))
        got = [b for b in bindings if b.key == key and not b.priority]
        if got:
            return got
    return []


async def run_in_turn(widget: Widget, event: events.Key) -> None:
    """Run ``widget``'s own binding of ``event``'s key now, in ``widget``'s queue, and stop the
    key there (it does not go on up to the app, which would run the binding a second time).
    A key it does not bind, and Enter, go on as Textual sends them."""
    if event.key in NOT_HERE:
        return
    for binding in own_bindings(widget, event.key):
        if await widget.app.run_action(binding.action, widget):
            event.stop()
            event.prevent_default()
            return
