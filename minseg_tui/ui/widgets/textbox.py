"""A one-line text box whose editing keys act in the order typed."""

from __future__ import annotations

from dataclasses import replace
from typing import ClassVar

from textual.binding import Binding, BindingType
from textual.widgets import Input


class TextBox(Input):
    """Textual's Input, with its own keys (Backspace, the arrows, Ctrl+U, ...) acting in the
    order typed.

    Input inserts a printable character in its key handler, in its own queue, but leaves a
    bound key to bubble up to the app, which then runs the binding: one hop per container,
    each through a queue. Keys typed in a burst after a Backspace were inserted before it ran
    ('Abcd' Backspace Backspace 'x' gave 'Abc'; walk 7 created a session of 'Omrr Haddad';
    Textual issue 6605). So the box binds Input's keys with priority, which the app runs as
    it reads the key, before it hands on the keys after it; and each action joins the box's
    own queue (``call_later``), behind the characters read before its key and ahead of those
    read after it. The app's and the screen's priority bindings still come first."""

    BINDINGS: ClassVar[list[BindingType]] = [
        replace(b, priority=True) for b in Input.BINDINGS if isinstance(b, Binding)
    ]

    def action_cursor_left(self, select: bool = False) -> None:
        self.call_later(super().action_cursor_left, select)

    def action_cursor_right(self, select: bool = False) -> None:
        self.call_later(super().action_cursor_right, select)

    def action_cursor_left_word(self, select: bool = False) -> None:
        self.call_later(super().action_cursor_left_word, select)

    def action_cursor_right_word(self, select: bool = False) -> None:
        self.call_later(super().action_cursor_right_word, select)

    def action_home(self, select: bool = False) -> None:
        self.call_later(super().action_home, select)

    def action_end(self, select: bool = False) -> None:
        self.call_later(super().action_end, select)

    def action_select_all(self) -> None:
        self.call_later(super().action_select_all)

    def action_delete_left(self) -> None:
        self.call_later(super().action_delete_left)

    def action_delete_right(self) -> None:
        self.call_later(super().action_delete_right)

    def action_delete_left_word(self) -> None:
        self.call_later(super().action_delete_left_word)

    def action_delete_right_word(self) -> None:
        self.call_later(super().action_delete_right_word)

    def action_delete_left_all(self) -> None:
        self.call_later(super().action_delete_left_all)

    def action_delete_right_all(self) -> None:
        self.call_later(super().action_delete_right_all)

    async def action_submit(self) -> None:
        self.call_later(super().action_submit)

    def action_cut(self) -> None:
        self.call_later(super().action_cut)

    def action_copy(self) -> None:
        self.call_later(super().action_copy)

    def action_paste(self) -> None:
        self.call_later(super().action_paste)
