"""Start screen: a new session (group members, date) or one to resume from the sessions folder."""

from __future__ import annotations

from collections.abc import Sequence

from textual import on
from textual.app import ComposeResult
from textual.containers import Vertical
from textual.message import Message
from textual.screen import Screen
from textual.widgets import Footer, Input, OptionList, Static
from textual.widgets.option_list import Option

from minseg_tui.ui.ports import SessionSummary
from minseg_tui.ui.widgets.fields import LabInput
from minseg_tui.ui.widgets.status import DeviceStatus


class StartScreen(Screen[None]):
    """Type the group's names and press Enter, or pick a session and press Enter."""

    class NewSession(Message):
        """The group asked for a new session."""

        def __init__(self, members: str, date: str) -> None:
            super().__init__()
            self.members = members
            self.date = date

    class Resume(Message):
        """The group picked a saved session (its folder)."""

        def __init__(self, path: str) -> None:
            super().__init__()
            self.path = path

    def __init__(self, sessions: Sequence[SessionSummary], today: str) -> None:
        super().__init__()
        self._sessions = list(sessions)
        self._today = today

    def compose(self) -> ComposeResult:
        yield DeviceStatus()
        with Vertical(id="start"):
            yield Static("New session", classes="title")
            yield LabInput(placeholder="group members, e.g. Ada L, Alan T", id="members")
            yield LabInput(value=self._today, placeholder="date (YYYY-MM-DD)", id="date")
            yield Static(
                "Enter on the names starts the lab. Tab moves on.", id="start-msg", classes="hint"
            )
            yield Static("Resume a session", classes="title")
            options = [
                Option(self._label(s), id=s.path, disabled=bool(s.damaged)) for s in self._sessions
            ]
            if not options:
                options = [Option("no saved sessions yet", id="", disabled=True)]
            yield OptionList(*options, id="sessions")
        yield Footer()

    @staticmethod
    def _label(s: SessionSummary) -> str:
        if s.damaged:
            return f"{s.path}: {s.damaged}"
        return f"{s.date}  {s.members or '(no names)'}  at {s.step}"

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
        if event.option.id:
            self.post_message(self.Resume(event.option.id))
