"""An entry row: label, input, and the one-line message the lab gave back."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

from rich.segment import Segment
from textual import events, on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, ScrollableContainer, Vertical
from textual.geometry import Size
from textual.message import Message
from textual.strip import Strip
from textual.widget import Widget
from textual.widgets import Input, Label, RadioButton, RadioSet, SelectionList

from minseg_tui.lab.content.steps import Field
from minseg_tui.lab.views.session import EntryView
from minseg_tui.ui.widgets.prose import Prose


def field_id(key: str) -> str:
    """A DOM id for a session key (ids take letters, digits, '-' and '_')."""
    return "f-" + re.sub(r"[^A-Za-z0-9_-]", "_", key)


class Choice(RadioButton):
    """A radio button whose mark says whether it is chosen without colour (NO_COLOR, a
    monochrome terminal): ● chosen, blank not."""

    def __init__(self, label: str, value: bool = False) -> None:
        super().__init__(label, value=value)
        self._mark()

    def watch_value(self) -> None:
        self._mark()
        super().watch_value()

    def _mark(self) -> None:
        self.BUTTON_INNER = "●" if self.value else " "

    def get_content_height(self, container: Size, viewport: Size, width: int) -> int:
        """As many lines as the answer wraps to (Textual's toggle buttons take one)."""
        return Widget.get_content_height(self, container, viewport, width)


class Ticks(SelectionList[int]):
    """A list to tick whose marks say which are ticked without colour: X ticked, blank not."""

    def render_line(self, y: int) -> Strip:
        strip = super().render_line(y)
        segments = list(strip)
        meta = segments[1].style.meta if len(segments) > 1 and segments[1].style else {}
        if "option" not in meta:
            return strip
        ticked = self.get_option_at_index(meta["option"]).value in self.selected
        segments[1] = Segment("X" if ticked else " ", segments[1].style)
        return Strip(segments, strip.cell_length)


EDITING_KEYS: dict[str, str] = {
    b.key: b.action for b in Binding.make_bindings(Input.BINDINGS) if b.key != "enter"
}
"""The text box's own keys (Textual's Input bindings) -> their actions; Enter is the lab
screen's (it stores the entry and moves on)."""


DESELECTING_KEYS = frozenset({"backspace", "delete", "left", "right", "home", "end"})
"""Keys that edit a refused text by one character (or move in it) rather than replace it."""

Restoring = Literal["held", "undo", "redo"]
"""What a key in an entry brings back: the text the lab holds (Escape), the answer stored
before it (Ctrl+Z), the answer Ctrl+Z took back (Ctrl+Y)."""

RESTORING_KEYS: dict[str, Restoring] = {"escape": "held", "ctrl+z": "undo", "ctrl+y": "redo"}


class EntryBox(Input):
    """The text box of an entry: focusing it selects what it holds (typing replaces it),
    except right after :meth:`start_with`, which begins it with a typed character.

    A refused text stays selected (:meth:`hold_refused`): the next value typed replaces it,
    while Backspace, Delete, the arrows and Home/End edit it one character at a time. Escape
    brings back the text the lab holds for the row and drops a refused text over it; Ctrl+Z
    the answer stored before it, Ctrl+Y the one Ctrl+Z took back (:class:`FieldRow.Restore`)."""

    def __init__(self, value: str, placeholder: str, disabled: bool) -> None:
        super().__init__(
            value=value,
            classes="field-input",
            select_on_focus=True,
            placeholder=placeholder,
            disabled=disabled,
        )
        self._starting = False
        """Set by :meth:`start_with` until the box has the focus."""
        self._refused = False
        """The whole refused text is selected (:meth:`hold_refused`) and no key acted since."""

    def hold_refused(self) -> None:
        """The text was refused: select it whole, so that the next value typed replaces it
        (not appended to it), while an editing key edits it by one character."""
        self.select_all()
        self._refused = True

    def start_with(self, character: str) -> None:
        """Replace the text with ``character`` (typed somewhere else, e.g. on the list of
        steps), focus the box and go on typing after it (this focus selects nothing). Keys
        of the same burst that arrive before the focus has moved here go on after it."""
        self.value = self.value + character if self._starting else character
        self.cursor_position = len(self.value)
        self.select_on_focus = False
        self._starting = True
        self.focus()

    @property
    def starting(self) -> bool:
        """Keys typed elsewhere are on their way here (:meth:`start_with`; not focused yet)."""
        return self._starting

    # Textual calls the handler of every class in the MRO: these run before Input's own.
    async def on_key(self, event: events.Key) -> None:
        """An editing key (Backspace, Ctrl+U, End, ...) acts here, in the order it was typed.
        Left to Textual, it would go up to the app to find its binding while the characters
        typed after it in the same burst went into the box first ('Ctrl+U 0,63' left the box
        empty)."""
        self.select_on_focus = True  # the next focus selects again
        if self._refused:
            self._refused = False
            if event.key in DESELECTING_KEYS:  # edit the refused text, from its end
                self.cursor_position = len(self.value)
        how = RESTORING_KEYS.get(event.key)
        if how is not None:
            row = next((a for a in self.ancestors if isinstance(a, FieldRow)), None)
            if row is not None:
                event.stop()
                event.prevent_default()
                row.restore(how)
            return
        action = EDITING_KEYS.get(event.key)
        if action is not None:
            event.stop()
            event.prevent_default()
            await self.run_action(action)

    def on_focus(self, event: events.Focus) -> None:
        self._starting = False

    def on_blur(self, event: events.Blur) -> None:
        self.select_on_focus = True
        self._starting = False
        self._refused = False


class FieldRow(Vertical):
    """One entry. Enter or leaving the field posts :class:`FieldRow.Typed` (and the screen
    takes what stands in it with :meth:`pending` before any key that leaves the step); a
    choice field is a list to tick with the keys (arrows, Space or Enter) and posts
    :class:`FieldRow.Chosen`. The screen answers with :meth:`show_result`.

    Typing never lands on the end of a value the group comes back to: focusing the box
    selects what it holds, so the next keys replace it (an arrow key or Home/End keeps it to
    edit). After Enter the cursor stands at the end of an accepted value, nothing selected
    (a digit typed next is appended); a refused text stays selected."""

    class Reflowed(Message):
        """The row grew or shrank once laid out (its hint moved under the box or back): the
        step keeps its focused entry in view."""

    @dataclass
    class Chosen(Message):
        """The group ticked options ``indices`` (0-based) of choice field ``key``."""

        row: FieldRow
        key: str
        indices: tuple[int, ...]

    @dataclass
    class Restore(Message):
        """Escape, Ctrl+Z or Ctrl+Y in the row (``how``). Escape has put back in the box the
        text the lab holds: the screen drops a refused text the lab keeps over it, and its
        refusal. Ctrl+Z: the group wants back the answer stored before the one in effect;
        Ctrl+Y: the answer the last Ctrl+Z took back."""

        row: FieldRow
        key: str
        how: Restoring = "undo"

    @dataclass
    class Typed(Message):
        """The group typed ``text`` for ``key`` (``submitted``: with Enter, not by leaving)."""

        row: FieldRow
        key: str
        text: str
        submitted: bool = False

    def __init__(
        self,
        field: Field,
        text: str,
        result: EntryView | None = None,
        chosen: tuple[int, ...] = (),
        readonly: bool = False,
        held: str | None = None,
    ) -> None:
        super().__init__(
            id=field_id(field.key), classes="field choice" if field.options else "field"
        )
        self.field = field
        self._text = text
        self.held = text if held is None else held
        """The text the lab holds in effect for this row (an accepted answer, not a refused
        attempt over it): what Escape brings back. The screen keeps it up to date."""
        self._result = result
        self._sent: str | None = text
        self._chosen = tuple(chosen)
        self._readonly = readonly

    def compose(self) -> ComposeResult:
        unit = f" [{self.field.unit}]" if self.field.unit else ""
        if self.field.options:
            yield Label(
                self.field.label + (" (tick all that apply)" if self.field.multiple else ""),
                classes="choice-label",
            )
            if self.field.multiple:
                yield Ticks(
                    *[(o, k, k in self._chosen) for k, o in enumerate(self.field.options)],
                    classes="field-choice",
                )
            else:
                yield RadioSet(
                    *[Choice(o, value=k in self._chosen) for k, o in enumerate(self.field.options)],
                    classes="field-choice",
                )
        else:
            with Horizontal(classes="field-line"):
                # as text, not markup: '[V]' would be read as a style and vanish
                yield Label(f"{self.field.label}{unit}", classes="field-label", markup=False)
                yield EntryBox(self._text, self.field.hint, self._readonly)
            yield Prose(self.field.hint, classes="field-hint")
        yield Prose("", classes="field-msg")

    def on_mount(self) -> None:
        if self._result is not None:
            self.show_result(self._result)
        self._place_hint()

    def on_resize(self) -> None:
        self._place_hint()

    @on(Input.Changed)
    def _place_hint(self) -> None:
        """The hint in the empty box if it fits there; if not (at 80 columns, 'multimeter on
        V=, between M1A and M1B' was cut to 'multimeter on V=, between M1A an'), in full on
        the line under the box while the box is empty."""
        hints = self.query(".field-hint")
        if not hints or not self.field.hint:
            return
        box = self.input
        fits = box.content_size.width == 0 or len(self.field.hint) < box.content_size.width
        box.placeholder = self.field.hint if fits else ""
        hint, under = hints.first(), not fits and not box.value
        if hint.display != under:
            hint.display = under
            self.post_message(self.Reflowed())

    @property
    def input(self) -> EntryBox:
        """The text box."""
        return self.query_one(EntryBox)

    @property
    def is_empty(self) -> bool:
        """Nothing typed or ticked here yet (nor stored)."""
        if self.field.options:
            return not self._chosen
        boxes = self.query(EntryBox)  # none yet while the row is being composed
        typed = boxes.first().value if boxes else self._text
        return not typed.strip() and not (self._sent or "").strip()

    def focus_input(self, landing: bool = False) -> None:
        """Focus the text box (what it holds selected: typing replaces it) or the list of
        options at once, not after the messages already queued (keys of the same burst go
        here), and scroll it into view once the layout has settled (``landing``: the step
        was just shown, see :meth:`bring_into_view`)."""
        for w in self.query(".field-input, .field-choice"):
            self.screen.set_focus(w, scroll_visible=False)
            if isinstance(w, Input):
                w.select_all()
            self.call_after_refresh(self.bring_into_view, landing)
            return

    def bring_into_view(self, landing: bool = False) -> None:
        """The row in view now, and once more when the layout has settled (wrapped answers
        change height on their first layout): its box centred if it is cut off, then the
        whole row. ``landing`` (the step just shown, or its view just drawn): from the top of
        the step each time, so the row ends up where the layout alone puts it, not where the
        step happened to be scrolled when the view came. At once, never animated. Nothing
        once the row has left (a call deferred to after a refresh: the group moved on)."""
        if not self.is_attached:
            return
        screen = self.screen
        boxes = self.query(".field-input, .field-choice")
        box = boxes.first() if boxes else None

        def place() -> None:
            if not self.is_attached:
                return
            if landing:
                step = next((a for a in self.ancestors if isinstance(a, ScrollableContainer)), None)
                if step is not None:
                    step.scroll_to(y=0, animate=False, immediate=True)
            if box is not None and screen.focused is box and not screen.can_view_entire(box):
                screen.scroll_to_center(box, animate=False, origin_visible=True, immediate=True)
            screen.scroll_to_widget(self, animate=False, immediate=True)

        place()
        self.call_after_refresh(place)

    def pending(self) -> str | None:
        """The text standing in the box that the lab does not hold yet (None when there is
        none); from now on it counts as sent."""
        if self.field.options or self._readonly:
            return None
        text = self.input.value
        if text == self._sent:
            return None
        self._sent = text
        return text

    def submitted(self) -> str | None:
        """Enter (the screen handles it): the text to store, sent again even if unchanged;
        the cursor at its end, nothing selected, so a key typed if the focus stays here goes
        on after it (a refused text is selected again by :meth:`show_result`). None on a
        list of answers."""
        if self.field.options:
            return None
        text = self.input.value
        self._sent = text
        self.input.cursor_position = len(text)
        return text

    def restore(self, how: Restoring = "held") -> None:
        """Escape (``held``): the box shows again the text the lab holds (:attr:`held`),
        whatever was typed over it and not confirmed, and the screen drops a refused text
        (:class:`Restore`). Ctrl+Z (``undo``) / Ctrl+Y (``redo``): ask the screen for the
        answer stored before the one in effect / the one Ctrl+Z took back."""
        if self.field.options or self._readonly:
            return
        if how == "held":
            box = self.input
            box.value = self.held
            box.cursor_position = len(box.value)
        self.post_message(self.Restore(self, self.field.key, how))

    def _choose(self, indices: tuple[int, ...]) -> None:
        if indices != self._chosen:
            self._chosen = indices
            self.post_message(self.Chosen(self, self.field.key, indices))

    @on(RadioSet.Changed)
    def _radio(self, event: RadioSet.Changed) -> None:
        event.stop()
        self._choose((event.index,))

    @on(SelectionList.SelectedChanged)
    def _ticked(self, event: SelectionList.SelectedChanged[int]) -> None:
        event.stop()
        self._choose(tuple(sorted(event.selection_list.selected)))

    @property
    def message(self) -> str:
        """The message shown under the box (plain text)."""
        return self.query_one(".field-msg", Prose).text

    @property
    def sent(self) -> str | None:
        """The text the lab holds for this row as far as the row knows (what it was given or
        last sent; None right after Enter)."""
        return self._sent

    def refresh_from_lab(self, text: str, result: EntryView | None) -> None:
        """Show what the lab now holds for this field (after a capture, say)."""
        if self.field.options:
            return
        self._sent = text
        self.input.value = text
        if result is not None:
            self.show_result(result)

    def show_result(self, result: EntryView) -> None:
        """Show the lab's verdict: a refusal, the warnings, or a checker's feedback."""
        parts = [("✗ " if not result.ok else "") + result.message] if result.message else []
        parts += [f"! {w}" for w in result.warnings]
        if result.feedback:
            parts.append(result.feedback)
        msgs = self.query(".field-msg")
        if not msgs:
            return
        msgs.first(Prose).update("\n".join(parts))
        self.set_class(not result.ok, "refused")
        self.set_class(bool(result.warnings), "warned")
        if not result.ok and self.query(EntryBox):
            # a refused text stays selected: a new value typed replaces it, while Backspace
            # and the arrows edit it by one character; and the whole refusal in view
            box = self.input
            box.hold_refused()
            if self.screen.focused is box:
                self.call_after_refresh(self.bring_into_view)

    def _send(self, submitted: bool = False) -> None:
        text = self.input.value
        if text == self._sent:
            return
        self._sent = text
        self.post_message(self.Typed(self, self.field.key, text, submitted))

    @on(Input.Submitted)
    def _submitted(self, event: Input.Submitted) -> None:
        event.stop()
        self._sent = None  # Enter always re-sends
        self._send(submitted=True)
        self.input.cursor_position = len(self.input.value)  # a digit typed next goes on after

    @on(Input.Blurred)
    def _blurred(self, event: Input.Blurred) -> None:
        event.stop()
        self._send()
