"""Text that wraps at the widget's width without tearing a number from its unit.

Textual breaks a line at any space, "2.216 mN m s/rad" included. :class:`Prose` breaks
only where :func:`minseg_tui.quantities.join_units` allows: never between a number and its unit,
never inside a unit of several words.
"""

from __future__ import annotations

import textwrap
from functools import lru_cache

from textual.content import Content
from textual.css.styles import RulesMap
from textual.strip import Strip
from textual.style import Style
from textual.visual import RenderOptions, Visual
from textual.widgets import Static

from minseg_tui.quantities import NO_BREAK, join_units

CONTINUED = ("! ", "✗ ")
"""Starts of a line whose wrapped lines are indented under its text."""


def wrap(text: str, width: int) -> list[str]:
    """``text`` broken into lines of at most ``width`` characters, at plain spaces only
    (never inside a number with its unit); each line of the text starts a new line."""
    return list(_wrapped(text, max(width, 1)))


@lru_cache(maxsize=1024)
def _wrapped(text: str, width: int) -> tuple[str, ...]:
    """:func:`wrap`, kept for the texts last wrapped: a Prose's text is wrapped again at
    each layout (its height) and each render, the same text at the same width (0.3 ms for
    a step's "What to do", some 50 times a step change)."""
    out: list[str] = []
    for para in join_units(text).split("\n"):
        lead = para[: len(para) - len(para.lstrip(" "))]
        indent = lead + ("  " if para.lstrip(" ").startswith(CONTINUED) else "")
        lines = textwrap.wrap(
            para,
            width,
            subsequent_indent=indent if len(indent) < width // 2 else "",
            break_on_hyphens=False,
            replace_whitespace=False,
        )
        out += [line.replace(NO_BREAK, " ") for line in lines] or [""]
    return tuple(out)


class Wrapped(Visual):
    """The visual of :class:`Prose`: ``text`` laid out by :func:`wrap` at the width given."""

    def __init__(self, text: str) -> None:
        self.text = text

    def __str__(self) -> str:
        return self.text

    def _content(self, width: int) -> Content:
        return Content("\n".join(wrap(self.text, width)))

    def render_strips(
        self, width: int, height: int | None, style: Style, options: RenderOptions
    ) -> list[Strip]:
        return self._content(width).render_strips(width, height, style, options)

    def get_optimal_width(self, rules: RulesMap, container_width: int) -> int:
        return max((len(line) for line in self.text.split("\n")), default=0)

    def get_height(self, rules: RulesMap, width: int) -> int:
        return len(_wrapped(self.text, max(width, 1)))


class Prose(Static):
    """A Static for sentences with numbers in them: :meth:`update` takes plain text (no
    markup), which wraps at the width without breaking a quantity."""

    def __init__(self, text: str = "", *, id: str | None = None, classes: str = "") -> None:
        super().__init__(Wrapped(text), id=id, classes=classes, markup=False)

    def update(self, content: object = "", *, layout: bool = True) -> None:
        """Show ``content`` (plain text); the same text again changes nothing (no layout of
        the screen: panels show their whole view again whenever the lab changes)."""
        text = str(content)
        if isinstance(self.content, Wrapped) and self.content.text == text:
            return
        super().update(Wrapped(text), layout=layout)

    @property
    def text(self) -> str:
        """The text shown, unwrapped."""
        return str(self.content)
