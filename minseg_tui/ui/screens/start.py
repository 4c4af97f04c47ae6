"""Start screen: a new session (group members, date) or one to resume from the sessions folder."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

from textual import events, on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.content import Content
from textual.message import Message
from textual.widgets import Input, OptionList, Static
from textual.widgets.option_list import Option

from minseg_tui.lab.content.keys import key_name
from minseg_tui.lab.content.steps import STEP_INDEX, step
from minseg_tui.lab.saving.store import SessionInfo, names_key, same_names
from minseg_tui.ui.screens.status import StatusScreen
from minseg_tui.ui.widgets.footer import KeyFooter
from minseg_tui.ui.widgets.inturn import run_in_turn
from minseg_tui.ui.widgets.textbox import TextBox


def step_name(step_id: str) -> str:
    """The step's name as the lab calls it: its title up to the colon ("Task 13",
    "Preparation 12"); the id itself for a step this program does not know."""
    return step(step_id).title.split(":")[0] if step_id in STEP_INDEX else step_id


def split_names(members: str) -> list[str]:
    """The group's names as typed in one box, split at commas ("Ada L, Alan T")."""
    return [m.strip() for m in members.split(",") if m.strip()]


def why_closed(s: SessionInfo) -> str:
    """Why a saved session cannot be opened ("damaged — ...", "in use by ..."), or ''."""
    if s.damaged:
        return f"damaged — {s.damaged}"
    if s.locked_by:
        return f"in use by another minseg-tui (pid {s.locked_by})"
    return ""


class SessionList(OptionList):
    """The saved sessions: its arrows (Home, End, PgUp, PgDn) move the cursor as each key is
    read, so an Enter typed right after them opens the session they moved to
    (:mod:`minseg_tui.ui.widgets.inturn`; walk 15's D1)."""

    async def on_key(self, event: events.Key) -> None:
        await run_in_turn(self, event)


class StartScreen(StatusScreen):
    """Type the group's names and press Enter, or pick a session and press Enter."""

    BINDINGS = [
        # the app's before any widget's: the lab opens before the keys typed after Enter are
        # handed on, so they go into the lab (the app asks :meth:`request` what Enter wants)
        Binding("enter", "app.start_lab", show=False, priority=True),
        # the focus moves when the key arrives, so that the Enter after it reads the box or
        # the list it moved to
        Binding("tab", "app.focus_next", show=False, priority=True),
        Binding("shift+tab", "app.focus_previous", show=False, priority=True),
        # as it is read, as Enter is: 'F12 Enter' in one burst ran Enter on the start screen
        # before F12's binding, and the class view stayed up, the Enter lost (walk 16's D4)
        Binding("f12", "app.class_view", "Class view (instructors)", priority=True),
        Binding("ctrl+n", "new_anyway", "New anyway", show=False),
    ]

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
        self._offered: tuple[tuple[str, ...], str] | None = None
        """The names typed and the session of those names offered for them (Enter again
        opens it), once Enter found one."""

    def compose(self) -> ComposeResult:
        yield self.status_line()
        with Vertical(id="start"):
            yield Static("New session", classes="title")
            yield TextBox(placeholder="group members, e.g. Ada L, Alan T", id="members")
            yield TextBox(value=self._today, placeholder="date (YYYY-MM-DD)", id="date")
            yield Static(
                "Enter on the names starts the lab. Tab moves on.", id="start-msg", classes="hint"
            )
            yield Static("Resume a session", classes="title")
            # a label holds what was typed (names) and file names: shown as is, never as markup
            # sessions of one group on one date (a folder copied to another name, a second
            # session started anyway) read alike but for their step: each says its folder,
            # as the class view does (walk 16's D1: the group went on in the copy)
            alike = Counter(self._group(s) for s in self._sessions.values() if not why_closed(s))
            options = [
                Option(
                    Content(
                        self._label(s) + (f"  ({s.path.name})" if alike[self._group(s)] > 1 else "")
                    ),
                    id=key,
                    disabled=s.locked_by is not None,
                )
                for key, s in self._sessions.items()
            ]
            if self._unreadable:
                options = [Option(Content(f"✗ {self._unreadable}"), id="", disabled=True)]
            elif not options:
                options = [Option("no saved sessions yet", id="", disabled=True)]
            yield SessionList(*options, id="sessions")
        yield KeyFooter()

    @staticmethod
    def _group(s: SessionInfo) -> tuple[str, tuple[str, ...]]:
        """Who and when: a session's date and its group's names (:func:`names_key`)."""
        return s.date, names_key(s.members)

    @staticmethod
    def _label(s: SessionInfo) -> str:
        """A saved session's row: its date, names and step (why it cannot be opened, if so)."""
        why = why_closed(s)
        row = f"{s.date}  {', '.join(s.members) or '(no names)'}  at {step_name(s.last_step)}"
        if why and not s.damaged:
            # in use, not damaged: its names and step are read, so the row says them, as
            # every other row does (walk 18, D6: the folder's name, spelt as first typed)
            return f"{row}: {why}"
        if why:
            return f"{s.path}: {why}" + (
                " (Enter opens it read-only)" if s.damaged and s.runs_left is None else ""
            )
        return row

    def request(self) -> StartScreen.NewSession | StartScreen.Resume | None:
        """What Enter asks for where the focus is: a new session (in the names' or the date's
        box), the highlighted saved session (in the list), or None (with the reason shown
        when the names are missing)."""
        focused = self.focused
        if isinstance(focused, Input):
            members = self.query_one("#members", Input).value.strip()
            date = self.query_one("#date", Input).value.strip()
            if not members:
                self.query_one("#start-msg", Static).update("Type the group members' names first.")
                self.query_one("#members", Input).focus()
                return None
            names = split_names(members)
            if self._offered is not None and self._offered[0] == names_key(names):
                return self._resume(self._offered[1])  # Enter again: the session offered
            same = same_names(list(self._sessions.values()), names)
            if same:
                self._offer(names, same[0])
                return None
            return self.NewSession(members, date)
        if isinstance(focused, OptionList):
            if focused.highlighted is not None:
                return self._resume(focused.get_option_at_index(focused.highlighted).id)
            # no row to open: every one listed is in use (a row in use takes no cursor); Enter
            # did nothing and said nothing (walk 16's D5: a second group in another window)
            busy = next((s for s in self._sessions.values() if s.locked_by is not None), None)
            if busy is not None:
                self.query_one("#start-msg", Static).update(
                    Content(
                        f"{busy.path.name} is open in another minseg-tui (pid "
                        f"{busy.locked_by}): quit it there first, then resume it here; or "
                        "type the names for a new session."
                    )
                )
        return None

    def _offer(self, names: Sequence[str], info: SessionInfo) -> None:
        """Say that a session of these names exists, and what Enter and Ctrl+N do now."""
        self._offered = (names_key(names), str(info.path))
        self.query_one("#start-msg", Static).update(
            Content(
                f"A session of {', '.join(info.members)} exists ({info.date}, at "
                f"{step_name(info.last_step)}, session {info.id}): Enter resumes it; "
                f"{key_name('new_anyway')} "
                "starts a second one anyway, in a folder of its own."
            )
        )
        keys = list(self._sessions)
        self.query_one("#sessions", OptionList).highlighted = keys.index(str(info.path))

    def action_new_anyway(self) -> None:
        """Ctrl+N: a new session of the names typed, although one of them exists."""
        members = self.query_one("#members", Input).value.strip()
        if not members:
            self.query_one("#start-msg", Static).update("Type the group members' names first.")
            return
        self.post_message(self.NewSession(members, self.query_one("#date", Input).value.strip()))

    def _resume(self, key: str | None) -> StartScreen.Resume | None:
        info = self._sessions.get(key or "")
        if info is not None and info.runs_left is not None:  # no session.json: nothing to open
            self.query_one("#start-msg", Static).update(Content(f"{info.path}: {info.damaged}"))
            return None
        return None if info is None else self.Resume(str(info.path), bool(info.damaged))

    @on(OptionList.OptionSelected, "#sessions")
    def _picked(self, event: OptionList.OptionSelected) -> None:
        """A saved session clicked (Enter is the app's, see BINDINGS)."""
        wanted = self._resume(event.option.id)
        if wanted is not None:
            self.post_message(wanted)
