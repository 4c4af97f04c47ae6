"""The base of the panels that show a view built from the session (the table, the runs, the
results, the model check)."""

from __future__ import annotations

from typing import Generic, TypeVar

from textual.containers import Vertical
from textual.message import Message
from textual.widget import Widget

from minseg_tui.lab.state.session import Session

V = TypeVar("V")


class ViewPanel(Vertical, Generic[V]):
    """A panel showing a view of type ``V``. The lab screen builds it with :meth:`build` in a
    worker (when the panel is shown and whenever the lab changes) and hands it over with
    :meth:`receive`; the panel draws it in :meth:`show_view`."""

    class Drawn(Message):
        """The panel drew its view: its height may have changed (the step it is in brings
        the entry it landed in back into view). ``reveal``: what the view newly shows that
        the group should see with the entry they are in (an answer's comparison), or None."""

        def __init__(self, reveal: Widget | None = None) -> None:
            super().__init__()
            self.reveal = reveal

    def __init__(self, classes: str = "") -> None:
        super().__init__(classes=f"panel {classes}".rstrip())
        self.view: V | None = None

    def build(self, session: Session) -> V:
        """The view from ``session`` (worker thread: a pure builder of
        :mod:`minseg_tui.lab.views.session`, no widget)."""
        raise NotImplementedError

    def sketch(self, session: Session) -> V | None:
        """A view quick to build, drawn while :meth:`build` works (worker thread), or None:
        none (the view is quick to build)."""
        return None

    def receive(self, view: V) -> None:
        """Keep ``view`` and draw it once the panel is composed."""
        self.view = view
        self.call_later(self._draw)

    def _draw(self) -> None:
        self.show_view()
        self.post_message(self.Drawn(self.revealed()))

    def after_rows(self) -> Widget | None:
        """What the panel shows under the step's entries (the step's form puts it there), or
        None: nothing."""
        return None

    def revealed(self) -> Widget | None:
        """What the view just drawn newly shows for the group to see (None: nothing)."""
        return None

    def show_view(self) -> None:
        """Draw :attr:`view`."""
        raise NotImplementedError
