"""Start screen: a new session (group members, date) or one to resume from the sessions folder."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from textual import on
from textual.app import ComposeResult
from textual.containers import Vertical
from textual.message import Message
from textual.widgets import Footer, Input, OptionList, Static
from textual.widgets.option_list import Option

from minseg_tui.lab.store import SessionInfo
from minseg_tui.ui.screens.status import StatusScreen


def why_closed(s: SessionInfo) -> str:
    """Why a saved session cannot be opened ("damaged — ...", "in use by ..."), or ''."""
    if s.damaged:
        return f"damaged — {s.damaged}"
    if s.locked_by:
        return f"in use by another minseg-tui (pid {s.locked_by})"
    return ""


class StartScreen(StatusScreen):
    """Type the group's names and press Enter, or pick a session and press Enter."""

    @dataclass
    class NewSession(Message):
        """The group asked for a new session: ``members`` as typed, ``date`` (ISO or '')."""

        members: str
        date: str

    @dataclass
    class Resume(Message):
        """The group picked a saved session (its folder); ``readonly``: a damaged one, opened
        to be read only."""

        path: str
        readonly: bool = False

    def __init__(self, sessions: Sequence[SessionInfo], today: str, unreadable: str = "") -> None:
        super().__init__()
        self._sessions = {str(s.path): s for s in sessions}
        self._today = today
        self._unreadable = unreadable

    def compose(self) -> ComposeResult:
        yield self.status_line()
        with Vertical(id="start"):
            yield Static("New session", classes="title")
            yield Input(placeholder="group members, e.g. Ada L, Alan T", id="members")
            yield Input(value=self._today, placeholder="date (YYYY-MM-DD)", id="date")
            yield Static(
                "Enter on the names starts the lab. Tab moves on.", id="start-msg", classes="hint"
            )
            yield Static("Resume a session", classes="title")
            options = [
                Option(self._label(s), id=key, disabled=s.locked_by is not None)
                for key, s in self._sessions.items()
            ]
            if self._unreadable:
                options = [Option(f"✗ {self._unreadable}", id="", disabled=True)]
            elif not options:
                options = [Option("no saved sessions yet", id="", disabled=True)]
            yield OptionList(*options, id="sessions")
        yield Footer()

    @staticmethod
    def _label(s: SessionInfo) -> str:
        why = why_closed(s)
        if why:
            return f"{s.path}: {why}" + (" (Enter opens it read-only)" if s.damaged else "")
        return f"{s.date}  {', '.join(s.members) or '(no names)'}  at {s.last_step}"

    @on(Input.Submitted)
    def _submitted(self, event: Input.Submitted) -> None:
        members = self.query_one("#members", Input).value.strip()
        date = self.query_one("#date", Input).value.strip()
        if not members:
            self.query_one("#start-msg", Static).update("Type the group members' names first.")
            self.query_one("#members", Input).focus()
            return
        self.post_message(self.NewSession(members, date))

    @on(OptionList.OptionSelected, "#sessions")
    def _picked(self, event: OptionList.OptionSelected) -> None:
        info = self._sessions.get(event.option.id or "")
        if info is not None:
            self.post_message(self.Resume(str(info.path), readonly=bool(info.damaged)))
