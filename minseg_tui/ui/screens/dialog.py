"""The keys that close a dialog close it before the app reads the next key, so the keys typed
after them act on the screen beneath (walk 11, D1)."""

from __future__ import annotations

from typing import TypeVar

from textual.binding import Binding
from textual.screen import ModalScreen
from textual.widgets import OptionList

from minseg_tui.ui.screens.palette import handled

R = TypeVar("R")


async def close_dialog(screen: ModalScreen[R], result: R) -> None:
    """Dismiss ``screen`` with ``result``, from a key bound with priority on it (the app runs
    such a key's action the moment it reads the key, and reads no other key until the action
    returns), and return once the screen beneath has handled what the dismissal asked of it.

    Bound as Textual binds a screen's keys, the closing key went to the dialog's focused
    widget's queue, and the app read the keys typed after it while the dialog was still its
    screen: they went to the dialog and were lost ('Enter PgDn' in one burst on the board
    check's answer closed it and left the step where it was). Nothing when ``screen`` has
    closed already (a second Enter of the burst)."""
    if not screen.is_current:
        return
    await screen.dismiss(result)
    await handled(screen.app.screen)


ANSWER_KEYS: tuple[tuple[str, str], ...] = (
    ("up", "cursor_up"),
    ("down", "cursor_down"),
    ("home", "first"),
    ("end", "last"),
)
"""The keys that move the highlight of a dialog's answers, and the list's action for each:
bound with priority on the dialog (:func:`answer_bindings`), so that they act in the order
typed with its Enter. Bound by the list as Textual binds them, each reached the app only
after the Enter typed behind it had closed the dialog with the answer highlighted before
('Down Enter' answered the first answer)."""


def answer_bindings() -> list[Binding]:
    """A dialog of answers' bindings of :data:`ANSWER_KEYS` (its action ``move``)."""
    return [
        Binding(key, f"move({action!r})", show=False, priority=True) for key, action in ANSWER_KEYS
    ]


def move_highlight(answers: OptionList, action: str) -> None:
    """Do the list's own ``action`` (one of :data:`ANSWER_KEYS`) on ``answers``."""
    getattr(answers, f"action_{action}")()


async def close_with_highlighted(
    screen: ModalScreen[str], answers: OptionList, missing: str
) -> None:
    """Enter on a dialog of answers: close ``screen`` with the highlighted answer's id
    (``missing``: none is highlighted), as :func:`close_dialog` closes it."""
    if not screen.is_current:
        return
    index = answers.highlighted
    answer = missing if index is None else answers.get_option_at_index(index).id or missing
    await close_dialog(screen, answer)
