"""A one-line text box whose editing keys act in the order typed."""

from __future__ import annotations

from textual import events
from textual.binding import BindingsMap
from textual.widgets import Input


class TextBox(Input):
    """Textual's Input, with its own keys (Backspace, the arrows, Ctrl+U, ...) run as it
    reads them.

    Input inserts a printable character in its key handler, but leaves a bound key to bubble
    up to the app, which then looks it up in the bindings of the focused widget: one hop per
    container, each through a queue. Keys typed in a burst after a Backspace were inserted
    before it ran ('Abcd' Backspace Backspace 'x' gave 'Abc'; walk 7 created a session of
    'Omrr Haddad'; Textual issue 6605). The box's own bindings are the first the app would
    find for such a key (priority bindings aside, which the app runs before the box sees the
    key), so running them here changes nothing but the order."""

    async def on_key(self, event: events.Key) -> None:
        # Textual calls a subclass's handler before Input's; prevent_default() keeps Input's
        # own from seeing the key, and otherwise it handles it next (public API only)
        if not event.is_printable:
            for binding in BindingsMap(self.BINDINGS).key_to_bindings.get(event.key, ()):
                if not binding.priority and await self.app.run_action(binding.action, self):
                    event.stop()
                    event.prevent_default()
                    return
