"""The step form and its entry rows: label, text box or list of answers, and the message the
lab gave back."""

from __future__ import annotations

import asyncio
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager, nullcontext
from functools import partial
from inspect import isawaitable
from typing import Literal

from rich.text import Text
from textual import events, on
from textual.actions import SkipAction
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, ScrollableContainer, Vertical, VerticalScroll
from textual.content import Content
from textual.message import Message
from textual.reactive import reactive
from textual.strip import Strip
from textual.style import Style as VisualStyle
from textual.widget import Widget
from textual.widgets import Label
from textual.widgets.input import Selection

from minseg_tui.lab.content.steps import Field
from minseg_tui.lab.views.session import EntryView
from minseg_tui.ui.widgets.prose import Prose


def field_id(key: str) -> str:
    """A DOM id for a session key (ids take letters, digits, '-' and '_')."""
    return "f-" + re.sub(r"[^A-Za-z0-9_-]", "_", key)


CURSOR_MARK = "▶"
"""In the place of a focused list's left button edge, the answer Space (or Enter) would tick:
Textual shows it by colour alone."""


class AnswerList(Widget, can_focus=False):
    """A question's answers, one line each (wrapped if long) behind its mark: ● picked in a
    list of one answer, X ticked in a list of several, blank not. Drawn and keyed here, as
    :class:`EntryBox` is: it never takes the focus. Its step's form (:class:`FieldForm`)
    does, and hands it the keys typed while its row is the form's current one
    (:meth:`press`), in the order typed, in the form's one queue; it then shows as focused
    (:meth:`show_current`), with :data:`CURSOR_MARK` before the answer Space would tick.
    A pick goes to the lab at once, by a plain call (:meth:`FieldRow.pick`).

    Keys: Up/Left and Down/Right move the cursor (round from the last answer to the first),
    Home/End to the first/last; Space picks the answer under it, clearing the others at
    once in a list of one (walk 6: Textual's RadioSet cleared the answer picked before only
    when it read its button's message, after the keys of the burst still queued, and showed
    two dots), and ticks or unticks it in a list of several. Enter picks or ticks the answer
    under it too, but never unticks it: on an answer already picked or ticked the form takes
    Enter to go on to the next question (:attr:`on_chosen`; walk 13: 'Space Enter' unticked
    the answer just ticked).

    It looks as Textual's RadioSet of RadioButtons does (the snapshots are unchanged), the
    answers wrapping instead of cut with an ellipsis."""

    DEFAULT_CSS = """
    AnswerList {
        border: tall $border-blurred;
        background: $surface;
        padding: 0 1;
        height: auto;
        width: 1fr;
        text-wrap: wrap;
        pointer: pointer;
        &>.answer-list--button {
            color: $panel-darken-2;
            background: $panel;
        }
        &>.answer-list--button-on {
            color: $text-success;
            background: $panel;
        }
        &>.answer-list--cursor {
            background: $block-cursor-blurred-background;
        }
        &.-current {
            border: tall $border;
            background-tint: $foreground 5%;
            &>.answer-list--cursor {
                background: $block-cursor-background;
                color: $block-cursor-foreground;
                text-style: $block-cursor-text-style;
            }
        }
    }
    """
    COMPONENT_CLASSES = {
        "answer-list--button",
        "answer-list--button-on",
        "answer-list--label",
        "answer-list--cursor",
    }

    def __init__(
        self,
        answers: Sequence[str],
        chosen: Iterable[int] = (),
        multiple: bool = False,
        classes: str = "",
    ) -> None:
        super().__init__(classes=classes)
        self.answers = tuple(answers)
        """The answers, in order (0-based indices name them)."""
        self.multiple = multiple
        """Several answers may be ticked (False: one is picked)."""
        self._chosen = tuple(sorted(set(chosen)))
        if not multiple:
            self._chosen = self._chosen[:1]
        self._cursor = 0

    @property
    def chosen(self) -> tuple[int, ...]:
        """The answers ticked or picked, 0-based, in order."""
        return self._chosen

    @property
    def cursor(self) -> int:
        """The answer under the cursor (0-based): Space or Enter picks it."""
        return self._cursor

    @property
    def on_chosen(self) -> bool:
        """The cursor is on an answer picked or ticked (Enter then goes on)."""
        return self._cursor in self._chosen

    @property
    def mark(self) -> str:
        """The mark of a chosen answer: ● (one answer) or X (several)."""
        return "X" if self.multiple else "●"

    @property
    def is_current(self) -> bool:
        """The keys go to this list (its row is the focused form's current one)."""
        return self.has_class("-current")

    def show_current(self, current: bool) -> None:
        """Shown as the list the keys go to, or not: the focused look, and the cursor's
        mark."""
        self.set_class(current, "-current")
        self.refresh()

    def move(self, index: int) -> None:
        """The cursor on answer ``index`` (round from the last to the first and back)."""
        if self.answers:
            self._cursor = index % len(self.answers)
            self.refresh()

    def choose(self, index: int) -> bool:
        """Answer ``index`` picked (one answer: every other cleared at once) or ticked and
        unticked (several); False: nothing changed (the answer picked already)."""
        if self.multiple:
            ticked = set(self._chosen) ^ {index}
        else:
            ticked = {index}
        chosen = tuple(sorted(ticked))
        if chosen == self._chosen:
            return False
        self._chosen = chosen
        self.refresh()
        return True

    def show_chosen(self, indices: Iterable[int]) -> None:
        """Show ``indices`` (0-based) as the answers picked or ticked, the cursor left where
        it is: what the lab holds, put back after a pick it refused."""
        chosen = tuple(sorted(set(indices)))
        self._chosen = chosen if self.multiple else chosen[:1]
        self.refresh()

    KEYS: tuple[str, ...] = ("down", "right", "up", "left", "home", "end", "space", "enter")
    """The keys :meth:`press` takes."""

    def press(self, key: str) -> bool:
        """Key ``key`` acts on the list (see the class); False: not one of its keys."""
        if key in ("down", "right"):
            self.move(self._cursor + 1)
        elif key in ("up", "left"):
            self.move(self._cursor - 1)
        elif key == "home":
            self.move(0)
        elif key == "end":
            self.move(-1)
        elif key == "space" or (key == "enter" and not self.on_chosen):
            self._pick(self._cursor)
        elif key == "enter":
            return False  # never unticks: the form goes on (FieldForm._enter)
        else:
            return False
        return True

    def _pick(self, index: int) -> None:
        if self.answers and self.choose(index):
            row = self.parent
            if isinstance(row, FieldRow):
                row.pick(self._chosen)

    def _lines(self) -> list[Content]:
        """Each answer's line, unwrapped: its mark and its text."""
        button = self.get_visual_style("answer-list--button")
        on = self.get_visual_style("answer-list--button-on")
        label = self.get_visual_style("answer-list--label")
        cursor = self.get_visual_style("answer-list--cursor")
        back = self.background_colors[1]
        current = self.is_current
        lines = []
        for k, answer in enumerate(self.answers):
            chosen = k in self._chosen
            style = on if chosen else button
            side = VisualStyle(foreground=style.background, background=back)
            left = (CURSOR_MARK, "bold") if current and k == self._cursor else ("▐", side)
            text = Content(answer).first_line.rstrip().pad(1, 1)
            lines.append(
                Content.assemble(
                    left,
                    (self.mark if chosen else " ", style),
                    ("▌", side),
                    text.stylize_before(cursor if k == self._cursor else label),
                )
            )
        return lines

    def render(self) -> Content:
        return Content("\n").join(self._lines())

    def on_click(self, event: events.Click) -> None:
        """A click on an answer focuses the list's row and picks the answer (ticks or
        unticks it in a list of several)."""
        offset = event.get_content_offset(self)
        row = self.parent
        if isinstance(row, FieldRow):
            row.focus_input()
        if offset is None:
            return
        width = self.content_size.width
        top = 0
        for k, line in enumerate(self._lines()):
            top += len(line.wrap(width))  # as Textual wraps it (text-wrap: wrap)
            if offset.y < top:
                self.move(k)
                self._pick(k)
                return

    def focus(self, scroll_visible: bool = True) -> AnswerList:
        """Focusing the list focuses its form at its row."""
        row = self.parent
        if isinstance(row, FieldRow):
            row.focus_input()
        return self


Restoring = Literal["held", "undo", "redo"]
"""What a key in an entry brings back: the text the lab holds (Escape), the answer stored
before it (Ctrl+Z), the answer Ctrl+Z took back (Ctrl+Y)."""

RESTORING_KEYS: dict[str, Restoring] = {"escape": "held", "ctrl+z": "undo", "ctrl+y": "redo"}

NOT_ENTERED = "not entered"
"""An empty entry's box in a read-only session (its hint would ask for what it refuses)."""

FOCUS_MARK = "▶ "
"""Before the label of the row the keys go to: the focus seen without colour."""


_WORD_START = re.compile(r"(?<=\W)\w")
"""Where a word starts (Ctrl+arrows move to one, Ctrl+W deletes back to one)."""


class EntryBox(Widget, can_focus=False):
    """The text box of an entry: one line of text with a cursor and a selection, drawn and
    edited here (:meth:`edit`, :meth:`type_text`). It never takes the focus: its form
    (:class:`FieldForm`) does, and hands it the keys typed while its row is the form's
    current one, in the order typed; it then shows as focused (:meth:`show_current`),
    cursor and selection included. It looks as Textual's Input does, and its keys are
    Input's: the arrows (with Shift: select; with Ctrl: by word), Home/End (Ctrl+A/E),
    Backspace, Delete (Ctrl+D), Ctrl+W, Ctrl+U, Ctrl+K, Ctrl+X/C/V. The cursor does not
    blink.

    A refused text stays as typed, nothing selected, the cursor at its end
    (:meth:`hold_refused`): the missing ')' typed next goes on after it, Backspace deletes
    one character (walk 4: a refused text left selected was replaced by the ')' typed to
    mend it). Escape brings back the text the lab holds for the row and drops a refused text
    over it; Ctrl+Z the answer stored before it, Ctrl+Y the one Ctrl+Z took back (the form
    asks the lab)."""

    DEFAULT_CSS = """
    EntryBox {
        background: $surface;
        color: $foreground;
        padding: 0 2;
        border: tall $border-blurred;
        width: 100%;
        height: 3;
        pointer: text;
        &.-current {
            border: tall $border;
            background-tint: $foreground 5%;
        }
        &>.entry-box--cursor {
            background: $input-cursor-background;
            color: $input-cursor-foreground;
            text-style: $input-cursor-text-style;
        }
        &>.entry-box--selection {
            background: $input-selection-background;
            color: $input-selection-foreground;
        }
        &>.entry-box--placeholder {
            color: $text-disabled;
        }
        &:ansi {
            background: ansi_default;
            color: ansi_default;
            &>.entry-box--cursor {
                background: ansi_white;
                color: ansi_black;
            }
            &>.entry-box--placeholder {
                text-style: dim;
                color: ansi_default;
            }
        }
    }
    """
    COMPONENT_CLASSES = {"entry-box--cursor", "entry-box--selection", "entry-box--placeholder"}

    class Changed(Message):
        """The text changed (typed, or set by the lab)."""

    def __init__(self, value: str, placeholder: str, disabled: bool) -> None:
        super().__init__(classes="field-input", disabled=disabled)
        self._value = value
        self._cursor = len(value)
        self._anchor = self._cursor
        """The other end of the selection (the cursor's place: nothing selected)."""
        self._scroll_x = 0
        """The first column of the text shown (a text longer than the box scrolls)."""
        self.placeholder = placeholder
        """Shown in the box while it is empty."""

    # -- what it holds --------------------------------------------------------------------
    @property
    def value(self) -> str:
        return self._value

    @value.setter
    def value(self, text: str) -> None:
        if text == self._value:
            return
        self._value = text
        self._cursor = min(self._cursor, len(text))
        self._anchor = min(self._anchor, len(text))
        self._changed()

    @property
    def cursor_position(self) -> int:
        return self._cursor

    @cursor_position.setter
    def cursor_position(self, position: int) -> None:
        """The cursor at ``position`` (clamped to the text), nothing selected."""
        self._select(position, position)

    @property
    def selection(self) -> Selection:
        """(anchor, cursor): the selected text lies between them (none if equal)."""
        return Selection(self._anchor, self._cursor)

    def select_all(self) -> None:
        self._select(0, len(self._value))

    def _select(self, anchor: int, cursor: int) -> None:
        size = len(self._value)
        self._anchor = max(0, min(anchor, size))
        self._cursor = max(0, min(cursor, size))
        self._scroll_to_cursor()
        self.refresh()

    def _changed(self) -> None:
        self._scroll_to_cursor()
        self.refresh()
        self.post_message(self.Changed())

    def _scroll_to_cursor(self) -> None:
        width = self.content_size.width
        if width == 0:  # not laid out yet (a step opening): scrolled when its size comes
            self._scroll_x = 0
            return
        if len(self._value) < width:  # the text fits, the cursor's cell after it too
            self._scroll_x = 0
        elif self._cursor < self._scroll_x:
            self._scroll_x = self._cursor
        elif self._cursor >= self._scroll_x + width:
            self._scroll_x = self._cursor - width + 1
        self._scroll_x = max(0, min(self._scroll_x, len(self._value)))

    def on_resize(self) -> None:
        # the line may already be drawn at the new size before this message comes: draw it
        # again with the text scrolled for that size
        self._scroll_x = 0
        self._scroll_to_cursor()
        self.refresh()

    # -- shown -----------------------------------------------------------------------------
    def show_current(self, current: bool) -> None:
        """Shown as the box typing goes into (its row is the focused form's current one), or
        not: the focused look, the cursor and the selection show only then."""
        self.set_class(current, "-current")
        self.refresh()

    def render_line(self, y: int) -> Strip:
        width = self.content_size.width
        if y != 0:
            return Strip.blank(width, self.rich_style)
        current = self.has_class("-current")
        console = self.app.console
        options = self.app.console_options
        # drawn as Textual's Input draws its line, one cell wider than the box (the cursor's
        # cell after a text as wide as the box)
        if not self._value:
            text = Text(self.placeholder, justify="left", end="")
            text.stylize(self.get_component_rich_style("entry-box--placeholder"))
            if current:
                if not text:
                    text = Text(" ", end="")
                text.stylize(self.get_component_rich_style("entry-box--cursor"), 0, 1)
            strip = Strip(console.render(text, options.update_width(width + 1)))
            return strip.apply_style(self.rich_style)
        text = Text(self._value, no_wrap=True, overflow="ignore", end="")
        cells = text.cell_len + 1  # the cursor's cell after the text
        if current:
            start, end = sorted((self._anchor, self._cursor))
            if start != end:
                selected = self.get_component_rich_style("entry-box--selection")
                text.stylize_before(selected, start, end)
            if self._cursor == len(self._value):
                text.pad_right(1)
            cursor = self.get_component_rich_style("entry-box--cursor")
            text.stylize(cursor, self._cursor, self._cursor + 1)
        strip = Strip(console.render(text, options.update_width(cells)))
        strip = strip.crop(self._scroll_x, self._scroll_x + width + 1)
        return strip.extend_cell_length(width + 1).apply_style(self.rich_style)

    def on_click(self, event: events.Click) -> None:
        """A click focuses the box's row and puts the cursor where it was."""
        row = self.parent.parent if self.parent is not None else None
        if isinstance(row, FieldRow):
            row.focus_input()
        offset = event.get_content_offset(self)
        if offset is not None:
            self.cursor_position = self._scroll_x + offset.x

    def focus(self, scroll_visible: bool = True) -> EntryBox:
        """Focusing the box focuses its form at its row (what it holds selected)."""
        row = self.parent.parent if self.parent is not None else None
        if isinstance(row, FieldRow):
            row.focus_input()
        return self

    # -- editing ---------------------------------------------------------------------------
    def hold_refused(self) -> None:
        """The text was refused: it stays to be mended, nothing selected, the cursor at its
        end (where a missing ')' or operand goes)."""
        self.cursor_position = len(self.value)

    def replace(self, text: str, start: int, end: int) -> None:
        """``text`` in place of the characters from ``start`` to ``end``, the cursor after it."""
        start, end = sorted((max(0, start), min(end, len(self._value))))
        self._value = self._value[:start] + text + self._value[end:]
        self._cursor = self._anchor = start + len(text)
        self._changed()

    def insert_text_at_cursor(self, text: str) -> None:
        self.type_text(text)

    def type_text(self, text: str) -> None:
        """Text typed (a character) or pasted: it replaces what is selected, else goes in at
        the cursor."""
        self.replace(text, self._anchor, self._cursor)

    def _word_left(self) -> int:
        hits = list(_WORD_START.finditer(self._value[: self._cursor]))
        return hits[-1].start() if hits else 0

    def _word_right(self) -> int:
        hit = _WORD_START.search(self._value, self._cursor + 1)
        return hit.start() if hit is not None else len(self._value)

    def _cut(self, start: int, end: int) -> None:
        """Delete from ``start`` to ``end``, or what is selected if anything is."""
        if self._anchor != self._cursor:
            self.replace("", self._anchor, self._cursor)
        elif start != end:
            self.replace("", start, end)

    KEYS: tuple[str, ...] = (
        "left", "right", "ctrl+left", "ctrl+right", "home", "ctrl+a", "end", "ctrl+e",
        "shift+left", "shift+right", "ctrl+shift+left", "ctrl+shift+right", "shift+home",
        "shift+end", "ctrl+shift+a", "backspace", "delete", "ctrl+d", "ctrl+w", "ctrl+u",
        "super+backspace", "ctrl+backspace", "alt+backspace", "ctrl+k", "ctrl+x", "ctrl+c",
        "super+c", "ctrl+v",
    )  # fmt: skip
    """The editing keys :meth:`edit` takes."""

    def edit(self, key: str) -> bool:
        """An editing key (Backspace, Ctrl+U, End, ...: see the class; not Enter) acts here;
        False: not one of them."""
        at, size, selected = self._cursor, len(self._value), self._anchor != self._cursor
        low, high = sorted((self._anchor, self._cursor))
        moves = {
            "left": (low if selected else at - 1),
            "right": (high if selected else at + 1),
            "ctrl+left": self._word_left(),
            "ctrl+right": self._word_right(),
            "home": 0,
            "ctrl+a": 0,
            "end": size,
            "ctrl+e": size,
        }
        selects = {
            "shift+left": at - 1,
            "shift+right": at + 1,
            "ctrl+shift+left": self._word_left(),
            "ctrl+shift+right": self._word_right(),
            "shift+home": 0,
            "shift+end": size,
        }
        if key in moves:
            self.cursor_position = moves[key]
        elif key in selects:
            self._select(self._anchor, selects[key])
        elif key == "ctrl+shift+a":
            self.select_all()
        elif key == "backspace":
            self._cut(at - 1, at)
        elif key in ("delete", "ctrl+d"):
            self._cut(at, at + 1)
        elif key == "ctrl+w":
            self._cut(self._word_left(), at)
        elif key in ("ctrl+u", "super+backspace"):
            self._cut(0, at)
        elif key in ("ctrl+backspace", "alt+backspace"):
            self._cut(at, self._word_right())
        elif key == "ctrl+k":
            self._cut(at, size)
        elif key in ("ctrl+x", "ctrl+c", "super+c"):
            if selected:
                self.app.copy_to_clipboard(self._value[low:high])
                if key == "ctrl+x":
                    self._cut(low, high)
        elif key == "ctrl+v":
            self.type_text(self.app.clipboard)
        else:
            return False
        return True


class FieldRow(Vertical):
    """One entry. A text field is typed into through its form (:class:`FieldForm`), which
    hands what stands in it to the lab on Enter or when it is left (:meth:`pending`,
    :meth:`submitted`); a choice field is a list to tick with the keys (arrows, Space or
    Enter), through its form too, which hands a tick to the lab at once (:meth:`pick`).
    The lab's verdict shows with :meth:`show_result`.

    Typing never lands on the end of a value the group comes back to: focusing the box
    selects what it holds, so the next keys replace it (an arrow key or Home/End keeps it to
    edit). After Enter the cursor stands at the end of the value, accepted or refused,
    nothing selected (a digit or a missing ')' typed next is appended)."""

    class Reflowed(Message):
        """The row grew or shrank once laid out (its hint moved under the box or back): the
        step keeps its focused entry in view."""

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
        self._shown: EntryView | None = None
        self._sent: str | None = text
        self._chosen = tuple(chosen)
        self._readonly = readonly

    @property
    def hint(self) -> str:
        """What the empty box says: the field's hint (what to type, '0.0335 A' or '33.5 mA'),
        or in a read-only session, where nothing can be typed, that nothing was entered."""
        return NOT_ENTERED if self._readonly else self.field.hint

    @property
    def label_text(self) -> str:
        """The row's label as written beside its box or above its answers (its unit, or that
        several answers may be ticked), without the focus mark."""
        if self.field.options:
            return self.field.label + (" (tick all that apply)" if self.field.multiple else "")
        return self.field.label + (f" [{self.field.unit}]" if self.field.unit else "")

    def show_focus(self, focused: bool) -> None:
        """Mark the row as the one the keys go to (:data:`FOCUS_MARK` before its label, the
        label bold), or not. Without colour (a plain or monochrome terminal) the focused
        box looked like the others: Space went into the notes instead of the done? choice."""
        if focused == self.has_class("-focus"):
            return
        # the row's class without a style pass over the row (its six widgets, the box's
        # component classes): only the label's look changes, and it has the class too
        self.set_class(focused, "-focus", update=False)
        labels = self.query(".field-label, .choice-label")
        if labels:
            label = labels.first(Label)
            label.set_class(focused, "-focus")
            label.update((FOCUS_MARK if focused else "") + self.label_text)

    @property
    def is_current(self) -> bool:
        """The keys go to this row (the focused form's current one)."""
        return self.has_class("-focus")

    def show_current(self, current: bool) -> None:
        """The row is the focused form's current one (the keys go to it), or not: its label
        marked, its box or list shown as focused."""
        box = self.box
        if box is not None:
            box.show_current(current)
        self.show_focus(current)

    def compose(self) -> ComposeResult:
        if self.field.options:
            yield Label(self.label_text, classes="choice-label", markup=False)
            yield AnswerList(
                self.field.options, self._chosen, self.field.multiple, classes="field-choice"
            )
        else:
            with Horizontal(classes="field-line"):
                # as text, not markup: '[V]' would be read as a style and vanish
                yield Label(self.label_text, classes="field-label", markup=False)
                yield EntryBox(self._text, self.hint, self._readonly)
            yield Prose(self.hint, classes="field-hint")
        yield Prose("", classes="field-msg")

    def on_mount(self) -> None:
        if self._result is not None:
            self.show_result(self._result)
        self._place_hint()

    def on_resize(self) -> None:
        self._place_hint()

    @on(EntryBox.Changed)
    def _place_hint(self) -> None:
        """The hint in the empty box if it fits there; if not (at 80 columns, 'multimeter on
        V=, between M1A and M1B' was cut to 'multimeter on V=, between M1A an'), in full on
        the line under the box while the box is empty."""
        hints = self.query(".field-hint")
        if not hints or not self.hint:
            return
        box = self.input
        fits = box.content_size.width == 0 or len(self.hint) < box.content_size.width
        box.placeholder = self.hint if fits else ""
        hint, under = hints.first(), not fits and not box.value
        if hint.display != under:
            hint.display = under
            self.post_message(self.Reflowed())

    @property
    def input(self) -> EntryBox:
        """The text box."""
        return self.query_one(EntryBox)

    @property
    def answers(self) -> AnswerList | None:
        """The list of answers of a choice row (None: a text row, or not composed yet)."""
        lists = self.query(AnswerList)
        return lists.first() if lists else None

    @property
    def box(self) -> EntryBox | AnswerList | None:
        """Where the row's keys go: its text box or its list of answers (None: not composed
        yet)."""
        if self.field.options:
            return self.answers
        boxes = self.query(EntryBox)
        return boxes.first() if boxes else None

    @property
    def is_empty(self) -> bool:
        """Nothing typed or ticked here yet (nor stored)."""
        if self.field.options:
            return not self._chosen
        boxes = self.query(EntryBox)  # none yet while the row is being composed
        typed = boxes.first().value if boxes else self._text
        return not typed.strip() and not (self._sent or "").strip()

    def focus_input(self, landing: bool = False) -> None:
        """Make this row the one the keys go to (its text box: what it holds selected, so
        typing replaces it; or its list of answers), at once, not after the messages
        already queued (keys of the same burst go here); scrolled into view once the layout
        has settled (``landing``: the step was just shown, see :meth:`bring_into_view`)."""
        form = next((a for a in self.ancestors if isinstance(a, FieldForm)), None)
        if form is not None:
            form.focus_row(self, landing)

    def bring_into_view(self, landing: bool = False) -> None:
        """The row in view now, and once more when the layout has settled (wrapped answers
        change height on their first layout): its box centred if it is cut off, then the
        whole row. ``landing`` (the step just shown, or its view just drawn): from the top of
        the step each time, the least scroll that shows the whole row, so the row ends up
        where the layout alone puts it, not where the step happened to be scrolled when the
        view came (and the step's form places it again after each layout that moves it,
        :meth:`~minseg_tui.ui.screens.lab.StepPane.laid_out`). At once, never animated. Nothing
        once the row has left (a call deferred to after a refresh: the group moved on)."""
        if not self.is_attached:
            return
        scrollers = [a for a in self.ancestors_with_self if isinstance(a, Widget)]
        before = [w.scroll_offset for w in scrollers]
        self.place_now(landing, settled=False)
        if [w.scroll_offset for w in scrollers] != before:
            # the second placing must see this scroll: a container tells the screen of its
            # scroll only when it is next idle, and the screen's refresh may come first and
            # lay nothing out (the second placing then measured the layout from before the
            # scroll: the box read as cut off and was centred again, lower)
            self.screen.refresh(layout=True)
        self.call_after_refresh(self.place_now, landing, True)

    def place_now(self, landing: bool = False, settled: bool = True) -> None:
        """One placing of :meth:`bring_into_view`, at once (``settled``: the layout has
        settled since the row was shown, a list of answers may be centred)."""
        if not self.is_attached:
            return
        screen = self.screen
        boxes = self.query(".field-input, .field-choice")
        box = boxes.first() if boxes else None
        form = next((a for a in self.ancestors if isinstance(a, FieldForm)), None)
        focused = screen.focused
        if form is not None and focused is not None and focused is not form:
            if form in focused.ancestors:
                # a placing deferred to after a refresh, come after another widget of the
                # step took the keys (F7's table): it stays where that widget scrolled the
                # step ('Ctrl+P task 6 Enter F7' in one burst: the landing's second placing
                # put the table and its formula above the screen)
                return
        with nullcontext() if form is None else form.placing():
            if landing:
                step = next((a for a in self.ancestors if isinstance(a, ScrollableContainer)), None)
                if step is not None:
                    step.scroll_to(y=0, animate=False, immediate=True)
            # a list of answers is centred only once laid out (its answers wrap then); a
            # landing is not: the least scroll from the top that shows the whole row
            centre = (settled or not self.field.options) and not landing
            if box is not None and centre and self.is_current and self._cut_off(box):
                screen.scroll_to_center(box, animate=False, origin_visible=True, immediate=True)
            screen.scroll_to_widget(self, animate=False, immediate=True)

    def layout_key(self) -> tuple[object, ...]:
        """What a landing's placing depends on in the layout: where the row lies in the
        step and how tall it is, where its box lies in it, the view's size and the rows the
        docked lines take (:meth:`~minseg_tui.ui.screens.lab.StepPane.laid_out`)."""
        boxes = self.query(".field-input, .field-choice")
        box = boxes.first().region if boxes else None
        row = self.region
        inside = None if box is None else (box.y - row.y, box.height)
        parent = self.parent
        view = parent.scrollable_content_region.size if isinstance(parent, Widget) else None
        return (self.virtual_region, inside, view, self.dock_gutter)

    def _cut_off(self, box: Widget) -> bool:
        """Whether a row of ``box`` (this row's box or list of answers) lies outside the view
        of the step, at the scroll the step has now: its rows only (Textual's
        ``can_view_entire`` read the columns too), worked out from the layout, not from where
        the screen last drew the step (a scroll just made is drawn only at the next
        refresh). Read from where the screen drew it, a box came out cut off or not by the
        timing alone, and the step was centred on it or not: Task 5 landed scrolled by 3
        rows or by none (drawn before the step's scrollbar came, its box reached under the
        scrollbar's columns); a landing's placing from the top read the box where the last
        placing had scrolled it."""
        step = self.parent
        row, drawn = self.region, box.region
        if not (isinstance(step, ScrollableContainer) and row and drawn):
            return True
        top = self.virtual_region.y + drawn.y - row.y  # in the step's content
        return top < step.scroll_y or top + drawn.height > step.scroll_y + (
            step.scrollable_content_region.height
        )

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
        on after it. None on a list of answers."""
        if self.field.options:
            return None
        text = self.input.value
        self._sent = text
        self.input.cursor_position = len(text)
        return text

    def restore(self) -> None:
        """Escape: the box shows again the text the lab holds (:attr:`held`), whatever was
        typed over it and not confirmed; nothing is stored."""
        if self.field.options or self._readonly:
            return
        box = self.input
        box.value = self.held
        box.cursor_position = len(box.value)

    def pick(self, indices: tuple[int, ...]) -> None:
        """The group ticked options ``indices`` (0-based): handed to the lab at once, by a
        plain call of the form (:meth:`FieldForm.chose`), so that it is stored before a key
        typed after it acts."""
        if indices != self._chosen:
            self._chosen = indices
            form = next((a for a in self.ancestors if isinstance(a, FieldForm)), None)
            if form is not None:
                form.chose(self, indices)

    def show_chosen(self, indices: tuple[int, ...]) -> None:
        """Show ``indices`` (0-based) as the answers the lab holds for this row, without
        handing them to the lab: a pick the lab refused (a session opened read-only) is put
        back on screen."""
        self._chosen = indices
        answers = self.answers
        if answers is not None:
            answers.show_chosen(indices)

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

    def lab_changed(self, text: str, result: EntryView | None) -> None:
        """The lab now holds ``text`` for this field, changed by something other than the
        group's keys in this row (a capture). Shown, unless the group has typed in the box
        since the row last sent its text: what they typed stays, never overwritten by a
        change of the lab (Enter, or leaving the row, stores it over the lab's text). A box
        that was empty or wholly selected (F3 made it ready for the next reading) has the
        new text selected, so that the next reading replaces it, not mixes with it."""
        if self.field.options or self._readonly:
            return
        box = self.input
        if box.value != self._sent:  # typed and not sent: the group's text stays
            self._sent = text
            return
        whole = sorted(box.selection) == [0, len(box.value)]  # all of it, or empty
        self.refresh_from_lab(text, result)
        if whole:
            box.select_all()

    def update_result(self, result: EntryView) -> None:
        """The lab's verdict on this row after a change elsewhere (a reading in another row
        of Task 5 makes a current fall as the voltage rises): shown if it is not the one
        shown already."""
        if result != self._shown:
            self.show_result(result)

    def show_result(self, result: EntryView) -> None:
        """Show the lab's verdict: a refusal, the warnings, or a checker's feedback."""
        self._shown = result
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
        if (not result.ok or result.warnings) and self.query(EntryBox):
            # a refused text stays to be mended, the cursor at its end, nothing selected;
            # and the whole refusal or warning in view
            box = self.input
            if not result.ok:
                box.hold_refused()
            if self.is_current:
                self.call_after_refresh(self.bring_into_view)


Store = Callable[[FieldRow, str, bool], EntryView]
"""Hands the lab what was typed in a row (``submitted``: with Enter, not by leaving it) and
returns its verdict, at once (the lab screen's)."""


ROW_KEYS: tuple[str, ...] = tuple(
    dict.fromkeys(k for k in (*EntryBox.KEYS, *AnswerList.KEYS) if k != "enter")
)
"""The keys that act on the form's current row: a text box's editing keys, a list's keys."""


class FieldForm(VerticalScroll, can_focus=True, inherit_bindings=False):
    """A step's text, its panel and its entry rows, as one focus target that owns the keys
    typed into the rows. It outlives the step (:meth:`~minseg_tui.ui.screens.lab.StepPane.show`
    puts the next step's widgets in it), so every key of a burst is handled here, in the
    order typed, whatever it does: a character or an editing key goes into the current row,
    Enter hands the row to the lab (``store``, a plain call: the verdict is there before the
    next key) and moves on if it was accepted; on a list of answers the arrows, Space and
    Enter act on the list and a tick goes to the lab at once (``choose``, a plain call too);
    Tab and Shift+Tab move between the rows and the step's other focusable widgets. The rows'
    boxes and lists never take the focus.

    These keys are the form's bindings, bound with priority so that Textual runs them as the
    app reads the key; each action first waits until the form has handled the keys ahead of
    it (:func:`after_typed_keys`), and one that does nothing then is skipped, so Textual
    hands its key on to the widget focused now. The characters typed go into the rows from
    the form's key handler, as Textual's Input takes them in its own. Any other key goes on
    up to the app, which runs its binding as Textual does; the app's and the screen's keys
    that must act between the keys typed before and after them (PgDn, the F-keys, Ctrl+P)
    are bound with priority too, and their actions wait the same way and store what stands
    in the rows first.

    ``current`` is the row the keys go to (None: the step itself, at its top; the arrows
    scroll it). Keys a focused widget of the step (a plot, a table) passes up, and
    characters typed while the group browses the list of steps or on a list of answers
    (:meth:`take`), go into the first empty entry."""

    BINDINGS = [
        Binding("up", "scroll_up", show=False),
        Binding("down", "scroll_down", show=False),
        Binding("home", "scroll_home", show=False),
        Binding("end", "scroll_end", show=False),
        *(Binding(key, f"row_key('{key}')", show=False, priority=True) for key in ROW_KEYS),
        Binding("enter", "enter", show=False, priority=True),
        *(
            Binding(key, f"bring_back('{how}')", show=False, priority=True)
            for key, how in RESTORING_KEYS.items()
        ),
        Binding("tab", "tab(1)", show=False, priority=True),
        Binding("shift+tab", "tab(-1)", show=False, priority=True),
    ]

    current: reactive[FieldRow | None] = reactive(None, init=False)

    def __init__(
        self,
        store: Store,
        restore: Callable[[FieldRow, Restoring], None],
        choose: Callable[[FieldRow, tuple[int, ...]], None],
        readonly: bool = False,
        classes: str = "",
    ) -> None:
        super().__init__(classes=classes)
        self._store = store
        self._restore = restore
        self._choose = choose
        self.readonly = readonly
        self._taking = False
        """Set by :meth:`take` until the form handles a key of its own: characters typed
        elsewhere are on their way into the current row."""
        self._placing = 0
        """How deep in :meth:`placing` (0: not in it)."""

    @property
    def heading_rows(self) -> int:
        """Rows a heading kept over the form's top covers (none here; the lab's step form
        has one): a widget scrolled into view goes below them."""
        return 0

    def covered_rows(self, y: int) -> int:
        """Rows a heading covers at the form's top while it is scrolled to ``y`` (none here;
        the lab's step form has one once it scrolls)."""
        return 0

    def show_whole(self, first: Widget, last: Widget) -> None:
        """Scroll the least that shows the form's widgets ``first`` down to ``last`` whole,
        below the rows a heading covers, read from the layout the screen has now; nothing
        when they show already. Where they do not fit, their top shows."""
        view = self.scrollable_content_region
        now = round(self.scroll_y)
        if not (first.region and last.region):
            return
        top = first.region.y - view.y + now
        bottom = last.region.bottom - view.y + now
        if top >= now + self.covered_rows(now) and bottom <= now + view.height:
            return
        under = max(top - self.covered_rows(1), 0)  # their top just under the heading
        if top >= now + self.covered_rows(now):  # they reach below the view: up from there
            y = bottom - view.height
            under = y if top >= y + self.covered_rows(y) else under
        self.scroll_to(y=under, animate=False, immediate=True)

    @property
    def follows_keys(self) -> bool:
        """Whether what keeps the row with the keys in view may scroll the form (always here;
        the lab's step form stops once the group scrolled it since the keys last moved)."""
        return True

    @contextmanager
    def placing(self) -> Iterator[None]:
        """Scrolls made in one go to place an entry (landing: the step's top, then the
        entry): :meth:`placed` follows once, on where they left the form, and what watches
        the scrolling in between may wait for it (:attr:`is_placing`)."""
        self._placing += 1
        try:
            yield
        finally:
            self._placing -= 1
            if not self._placing:
                self.placed()

    @property
    def is_placing(self) -> bool:
        """Within :meth:`placing`."""
        return self._placing > 0

    def placed(self) -> None:
        """The form's scrolls of one :meth:`placing` are done (nothing to do here; the lab's
        step form shows or hides its heading)."""

    # -- rows ------------------------------------------------------------------------------
    def rows(self) -> list[FieldRow]:
        return list(self.query(FieldRow))

    @property
    def typing(self) -> FieldRow | None:
        """The current row if the form has the focus and it is a text row (None: keys go to
        the step, not into a box)."""
        row = self.current
        if row is None or not row.is_attached or row.field.options:
            return None
        return row if self.screen.focused is self else None

    @property
    def keyed(self) -> FieldRow | None:
        """The current row if the form has the focus, a text row or a list of answers (None:
        keys go to the step)."""
        row = self.current
        if row is None or not row.is_attached or self.screen.focused is not self:
            return None
        return row

    @property
    def answering(self) -> AnswerList | None:
        """The list of answers of the current row if the form has the focus and it is a
        choice row (None: the keys do not go to a list)."""
        row = self.current
        if row is None or not row.is_attached or not row.field.options:
            return None
        return row.answers if self.screen.focused is self else None

    @property
    def keys_box(self) -> EntryBox | AnswerList | None:
        """The box or list of answers the keys go to (the current row's, while the form has
        the focus; None: none)."""
        row = self.current
        if row is None or not row.is_attached or self.screen.focused is not self:
            return None
        return row.box

    def chose(self, row: FieldRow, indices: tuple[int, ...]) -> None:
        """``row``'s list was ticked: the lab stores it now (``choose``)."""
        self._choose(row, indices)

    def watch_has_focus(self, _has_focus: bool) -> None:
        """Restyle the form alone when it takes or loses the focus. Textual restyles the
        focused widget and everything in it (``Widget.watch_has_focus``), here the whole step,
        though no rule of the app's CSS styles a widget by the focus of a widget it is in
        (tests/ui/test_restyles.py checks that): each Tab out of the step, Ctrl+L, a dialog
        or the palette restyled every widget of the step twice."""
        self.app.stylesheet.update_nodes([self], animate=True)

    def watch_current(self, old: FieldRow | None, new: FieldRow | None) -> None:
        for row, shown in ((old, False), (new, self.screen.focused is self)):
            if row is not None and row.is_attached:
                row.show_current(shown)

    def on_focus(self) -> None:
        if self.current is not None and self.current.is_attached:
            self.watch_current(None, self.current)

    def on_blur(self) -> None:
        """Leaving the form stores what stands in its current row (as leaving a field does)."""
        self.store_pending()
        if self.current is not None and self.current.is_attached:
            self.watch_current(self.current, None)

    def store_pending(self) -> None:
        """Hand the lab what stands in the current row and was not handed yet."""
        row = self.current
        if row is None or not row.is_attached or row.field.options:
            return
        text = row.pending()
        if text is not None:
            self._store(row, text, False)

    def focus_row(self, row: FieldRow, landing: bool = False) -> None:
        """Focus ``row``: the keys go to it, into its box (what it holds selected, so typing
        replaces it) or to its list of answers. At once, not after the messages already
        queued: keys of the same burst go here."""
        if row is not self.current:
            self.store_pending()
        self.current = row
        if self.screen.focused is not self:
            self.screen.set_focus(self, scroll_visible=False)
        self.watch_current(None, row)
        if not row.field.options:
            row.input.select_all()
        row.call_after_refresh(row.bring_into_view, landing)

    def focus_after(self, key: str) -> None:
        """Focus the entry after field ``key`` (stays put on the last one)."""
        rows = self.rows()
        keys = [r.field.key for r in rows]
        if key in keys and keys.index(key) + 1 < len(rows):
            self.focus_row(rows[keys.index(key) + 1])

    def typing_row(self) -> FieldRow | None:
        """The entry keys typed outside the rows go into: the first empty text entry, else
        the first (None: the step has none)."""
        rows = [r for r in self.rows() if not r.field.options]
        return next((r for r in rows if r.is_empty), rows[0] if rows else None)

    def take(self, character: str) -> None:
        """A character typed outside the rows (browsing the list of steps, on a list of
        answers, the step's text): it goes into :meth:`typing_row`, replacing what that
        holds (a reading typed off a plot), and the keys after it go on there. Into free
        text (notes, what is still unclear) it goes on after what is there: a letter typed
        on "done?" replaced a group's notes, and PgDn stored the letter alone (walk 16's
        D2)."""
        if self.readonly:
            return
        row = self.current if self._taking else None
        if row is None or not row.is_attached:
            row = self.typing_row()
            if row is None:
                return
            self.focus_row(row)
            self._taking = True
            if row.field.kind == "text" and not row.field.compare:
                row.input.cursor_position = len(row.input.value)
        row.input.type_text(character)
        self.screen.scroll_to_widget(row, animate=False)

    # -- focus moves ---------------------------------------------------------------------
    def _targets(self) -> list[Widget]:
        """Where Tab goes in the step, in order: its focusable widgets and its rows."""
        chain = set(self.screen.focus_chain)
        return [w for w in self.walk_children(Widget) if isinstance(w, FieldRow) or w in chain]

    def move_focus(self, delta: int, here: Widget | None = None) -> None:
        """Tab (``delta`` 1) or Shift+Tab (-1) from ``here`` (None: the current row, or the
        top of the step): the next target in the step, else the widget outside it that the
        screen's order puts next."""
        targets = self._targets()
        if here is None:
            here = self.current if self.current in targets else None
        if here in targets:
            k = targets.index(here) + delta
        else:
            k = 0 if delta > 0 else len(targets) - 1
        if 0 <= k < len(targets):
            target = targets[k]
            if isinstance(target, FieldRow):
                self.focus_row(target)
            else:
                self.store_pending()
                self.screen.set_focus(target)
            return
        if self.leave(delta):
            return
        chain = self.screen.focus_chain
        outside = [w for w in chain if w is not self and self not in w.ancestors]
        if not outside:
            if targets:
                self.move_focus(delta, None)
            return
        mine = [k for k, w in enumerate(chain) if w is self or self in w.ancestors]
        if delta > 0:
            after = [w for w in outside if chain.index(w) > max(mine, default=-1)]
            self.screen.set_focus((after or outside)[0])
        else:
            before = [w for w in outside if chain.index(w) < min(mine, default=len(chain))]
            self.screen.set_focus((before or outside)[-1])

    def enter(self, delta: int) -> None:
        """The focus comes in from outside: the first target of the step (the last with
        Shift+Tab)."""
        self.current = None
        self.move_focus(delta, None)

    # -- keys ------------------------------------------------------------------------------
    # The keys that act on the rows (the editing keys, Enter, Escape, Ctrl+Z/Y, Tab) are the
    # form's bindings, bound with priority: Textual runs a widget's other bindings only once
    # its key has bubbled up to the app (textual/app.py:4341-4343), behind the keys typed
    # after it, which the form has handled by then (pinned by test_bursts's
    # test_editing_keys_in_a_burst_act_before_the_text_typed_after_them). The app runs a
    # priority binding as it reads the key (textual/app.py:4136), so each action first
    # waits until the keys typed before it are handled (after_typed_keys); a key that does
    # nothing in the row then (the focus left the form, the row is a list, ...) is skipped
    # (SkipAction), and Textual hands it on to the widget focused now. The characters stay
    # in the form's key handler, as Textual's Input takes its characters in its own
    # (textual/widgets/_input.py:743-754).

    async def _in_turn(self, act: Callable[[], bool]) -> None:
        """Run ``act`` once the keys typed before its key are handled; it returns False
        where the key does nothing: Textual then hands it on (SkipAction)."""
        if not await after_typed_keys(self.app, lambda: self._on_form() and act()):
            raise SkipAction()

    def _on_form(self) -> bool:
        """The keys go to the form: its screen is shown and it has the focus."""
        if self.app.screen is not self.screen or self.screen.focused is not self:
            return False
        self._taking = False
        return True

    async def action_row_key(self, key: str) -> None:
        """An editing key of the current text box, or a key of its list of answers."""
        await self._in_turn(partial(self._row_key, key))

    async def action_enter(self) -> None:
        """Enter: the current entry to the lab, on to the next if it was accepted; on a list
        of answers, picks the one under the cursor."""
        await self._in_turn(self._enter)

    async def action_bring_back(self, how: Restoring) -> None:
        """Escape, Ctrl+Z, Ctrl+Y: what the lab holds for the current entry, or held
        before."""
        await self._in_turn(partial(self._bring_back, how))

    async def action_tab(self, delta: int) -> None:
        """Tab (``delta`` 1) or Shift+Tab (-1): the next target of the step, from the current
        row or from the widget of the step that has the focus (a plot, a table)."""
        if not await after_typed_keys(self.app, partial(self._tab, delta)):
            raise SkipAction()

    def _row_key(self, key: str) -> bool:
        row = self.typing
        if row is not None:
            return not row.input.disabled and row.input.edit(key)
        answers = self.answering
        if answers is not None:
            return answers.press(key)
        return self.current is None and self.off_rows_key(key)

    def off_rows_key(self, key: str) -> bool:
        """A row key (an arrow, Home/End, Space, Enter) with no current row, the form
        focused: nothing here (False: Textual hands it on). The lab's step form drives its
        list of steps with them while the group browses it."""
        return False

    def leave(self, delta: int) -> bool:
        """Tab past the step's last target (``delta`` 1) or Shift+Tab before its first (-1):
        nothing here (False: the focus goes to the widget outside the form that the screen's
        order puts next). The lab's step form goes to its list of steps."""
        return False

    def _enter(self) -> bool:
        row = self.typing
        if row is None:
            answers = self.answering
            if answers is not None and answers.on_chosen and self.current is not None:
                self.focus_after(self.current.field.key)  # answered: on to the next
                return True
            return self._row_key("enter")
        text = row.submitted()
        if text is not None:
            result = self._store(row, text, True)
            if result.ok:  # accepted: on to the next entry at once
                self.focus_after(row.field.key)
        return True

    def _bring_back(self, how: Restoring) -> bool:
        row = self.typing
        if row is None:
            return False
        if how == "held":
            row.restore()
        self._restore(row, how)
        return True

    def _tab(self, delta: int) -> bool:
        if self.app.screen is not self.screen:
            return False
        focused = self.screen.focused
        if focused is self:
            self._taking = False
            self.move_focus(delta)
            return True
        if focused is not None and self in focused.ancestors:
            self.move_focus(delta, focused)
            return True
        return False

    def on_key(self, event: events.Key) -> None:
        """A character typed into the form (see the keys' note above), or a key a focused
        widget of the step passes up (:meth:`_passed_on`). Also with another screen over the
        lab: the app read the key while the lab had the keys (one read later goes to that
        screen), so it was typed for the row; dropped, the Enter after it stored the row
        empty once the screen had gone (walk 11's D2: a board check's result, say, coming
        while the reading waited in the form's queue)."""
        focused = self.screen.focused
        if focused is not self:
            self._passed_on(event, focused)
            return
        self._taking = False
        self._character(event)

    def _character(self, event: events.Key) -> None:
        """A printable key with the form focused: into the current text box, or (on a list
        of answers, or at the step's top) into the first empty entry."""
        if not (event.is_printable and event.character):
            return
        row = self.typing
        if row is not None:
            if not row.input.disabled:
                self._own(event)
                row.input.type_text(event.character)
                if row._cut_off(row.input):
                    # typed into an entry out of view (F9 or Alt+→ scrolled the step to
                    # its plot, walk 17's D4): the entry comes back into view
                    self.screen.scroll_to_widget(row, animate=False)
            return
        if self.typing_row() is not None:
            self._own(event)
            self.take(event.character)

    def _passed_on(self, event: events.Key, focused: Widget | None) -> None:
        """A key the form did not get as the focused widget: passed up by a widget of the
        step that has the focus (a plot, a table: Tab moves on from it; a character it
        takes itself, as it answers Textual's ``check_consume_key`` (z or [ on the run log),
        goes on to its binding; any other character goes into the first empty entry, Space
        only mid-word), or handed to the form before a key ahead of it moved the focus
        away (Tab onto a plot of the step): a character goes into the entry as well, any
        other key goes on up to the app, which runs the binding of the widget focused now, as
        Textual runs a key's binding. No key is posted again."""
        inside = focused is not None and self in focused.ancestors
        key = event.key
        if inside and focused is not None and focused.check_consume_key(key, event.character):
            return  # Textual runs its binding once the key has bubbled up to the app
        if event.is_printable and event.character and (event.character != " " or self._taking):
            if self.typing_row() is not None and not self.readonly:
                self._own(event)
                self.take(event.character)

    def on_paste(self, event: events.Paste) -> None:
        """Text pasted (its first line, as a text box takes it) goes where typing goes."""
        text = event.text.splitlines()[0] if event.text else ""
        row = self.typing
        if row is None:
            row = self.typing_row()
            if row is None or self.readonly:
                return
            self.focus_row(row)
        event.stop()
        if text and not row.input.disabled:
            row.input.type_text(text)

    @staticmethod
    def _own(event: events.Key) -> None:
        event.stop()
        event.prevent_default()


async def after_typed_keys(app: App[None], work: Callable[[], object]) -> object:
    """Run ``work``, the action of a key bound with priority (F2, Ctrl+P, Ctrl+Q, PgDn, the
    panel keys: keys that act on every screen, over any widget), after the keys typed before
    it.

    Textual runs a priority binding on the app's queue the moment the app reads its key,
    while each key read before it was handed to the queue of the widget focused then, where
    it may still wait ('5,3 F2' stopped the motor before 5,3 was in its box). So the app
    waits until that widget has handled what it was handed (a key that moved the focus on:
    the widget focused now, too), then runs ``work``. The app reads no key while it waits,
    so the keys typed after it go where ``work`` left the focus (the palette's box, the next
    step's entry). The widgets' key handlers never wait for the app, so this cannot wait
    for itself. Returns what ``work`` returns."""
    waited: set[int] = set()
    focused = app.focused
    while focused is not None and id(focused) not in waited:
        waited.add(id(focused))
        handled = asyncio.Event()
        if not focused.call_later(handled.set):  # it is being removed, its keys with it
            break
        await handled.wait()
        focused = app.focused
    return await _done(work())


async def _done(result: object) -> object:
    """``result``, awaited if it is awaitable (an action may be async or not)."""
    if isawaitable(result):
        return await result
    return result
