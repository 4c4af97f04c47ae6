"""The two questions a failed save brings: quit anyway? and: save where instead?"""

from __future__ import annotations

from collections.abc import Callable

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.reactive import reactive
from textual.screen import ModalScreen
from textual.widgets import Input, OptionList
from textual.widgets.option_list import Option

from minseg_tui.lab.content.keys import PALETTE
from minseg_tui.lab.state.task10 import ActiveRun
from minseg_tui.ui.screens.dialog import (
    answer_bindings,
    close_dialog,
    close_with_highlighted,
    move_highlight,
)
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox

QUIT_CHOICES: tuple[tuple[str, str], ...] = (
    ("keep", "Keep working (it keeps trying to save)"),
    ("move", f"{PALETTE['save_elsewhere']}…"),
    ("quit", "Quit anyway: what is not saved is lost"),
)
"""What the group can do when quitting with something not on disk: (answer, words)."""

RECORDING_CHOICES: tuple[tuple[str, str], ...] = (
    ("keep", "Keep recording"),
    ("quit", "Stop the run and quit: what is recorded is kept, marked as ended by a quit"),
)
"""What the group can do when quitting while Task 10 records a run: (answer, words)."""

RUN_ENDED_CHOICES: tuple[tuple[str, str], ...] = (
    ("keep", "Keep working"),
    ("quit_now", "Quit"),
)
"""What the group can do once the run it was asked about has ended while the question was
up (walk 15, D2: the question went on saying the run was being recorded): (answer, words)."""


def run_ended_question(ended: str) -> str:
    """The question of Ctrl+Q once the run has ended while it was asked; ``ended``: how it
    ended and what was kept, as Task 10's notice says it ("square wave done; run steps-1: 489
    samples kept")."""
    return f"The run ended while this was asked: {ended}. Quitting now cuts nothing."


def recording_question(run: ActiveRun) -> str:
    """The question of Ctrl+Q while ``run`` is being recorded, with the samples it holds
    now (the app says it again as they come in)."""
    return (
        f"Run {run.name} is being recorded ({run.samples} samples so far). "
        "Quitting stops it before its plan ends."
    )


class QuitScreen(ModalScreen[str]):
    """Asks before quitting while the session is not all on disk (or, with ``title`` and
    ``choices`` :data:`RECORDING_CHOICES`, while a run is being recorded); dismissed with
    the key of a choice (Escape: keep). Enter and Escape close it before the app reads the
    next key (:mod:`~minseg_tui.ui.screens.dialog`). ``problem``: the question's words, which
    the app may set again while the dialog is up (the samples a run has so far)."""

    BINDINGS = [
        Binding("escape", "keep", "Keep working", priority=True),
        Binding("enter", "answer", show=False, priority=True),
        *answer_bindings(),
    ]
    AUTO_FOCUS = "#answers"

    problem: reactive[str] = reactive("", init=False)

    def __init__(
        self,
        problem: str,
        title: str = "Not everything is saved",
        choices: tuple[tuple[str, str], ...] = QUIT_CHOICES,
    ) -> None:
        super().__init__()
        self.set_reactive(QuitScreen.problem, problem)
        self._title = title
        self._choices = choices

    def compose(self) -> ComposeResult:
        with Vertical(id="ask", classes="dialog"):
            yield Prose(self._title, id="title", classes="title")
            yield Prose(self.problem, id="problem", classes="para")
            yield OptionList(*[Option(text, id=key) for key, text in self._choices], id="answers")

    @property
    def choices(self) -> tuple[tuple[str, str], ...]:
        """The choices it offers (:data:`QUIT_CHOICES` or :data:`RECORDING_CHOICES`)."""
        return self._choices

    def watch_problem(self, problem: str) -> None:
        self.query_one("#problem", Prose).update(problem)

    def ask(self, title: str, problem: str, choices: tuple[tuple[str, str], ...]) -> None:
        """Ask another question in place of the one up (its title, words and choices), the
        first choice highlighted: the app's way to keep the question true when what it was
        about has changed (the run ended while Ctrl+Q's question was up)."""
        self._title = title
        self._choices = choices
        self.query_one("#title", Prose).update(title)
        self.problem = problem
        answers = self.query_one("#answers", OptionList)
        answers.clear_options()
        answers.add_options([Option(text, id=key) for key, text in choices])
        answers.highlighted = 0

    @on(OptionList.OptionSelected, "#answers")
    def _answer(self, event: OptionList.OptionSelected) -> None:
        if self.is_current:  # not an answer handed on after the first one closed it
            self.dismiss(event.option.id or "keep")

    def action_move(self, action: str) -> None:
        move_highlight(self.query_one("#answers", OptionList), action)

    async def action_answer(self) -> None:
        await close_with_highlighted(self, self.query_one("#answers", OptionList), "keep")

    async def action_keep(self) -> None:
        await close_dialog(self, "keep")


class SaveElsewhereScreen(ModalScreen[None]):
    """Asks for a folder and saves the session there with ``save`` (it returns the one line
    to show); stays open on a refusal so another folder can be typed. Escape closes, before
    the app reads the next key."""

    BINDINGS = [Binding("escape", "close", "Close", priority=True)]
    AUTO_FOCUS = "#folder"

    def __init__(self, suggestion: str, save: Callable[[str], str]) -> None:
        super().__init__()
        self._suggestion = suggestion
        self._save = save

    def compose(self) -> ComposeResult:
        with Vertical(id="ask", classes="dialog"):
            yield Prose(PALETTE["save_elsewhere"], classes="title")
            yield Prose(
                "Type a folder that can be written (a home folder, another stick) and press "
                "Enter; the session is saved in a new folder inside it and goes on there.",
                classes="para",
            )
            yield TextBox(value=self._suggestion, id="folder", select_on_focus=True)
            yield Prose("", id="saved")

    @on(Input.Submitted, "#folder")
    def _submitted(self, event: Input.Submitted) -> None:
        event.stop()
        folder = event.value.strip()
        if not self.is_current:  # saved and closed by an Enter before this one
            return
        if not folder:
            self.query_one("#saved", Prose).update("✗ type a folder first")
            return
        said = self._save(folder)
        if said.startswith("✗"):
            self.query_one("#saved", Prose).update(said)
            return
        self.app.notify(said, title="session", timeout=10)
        self.dismiss(None)

    async def action_close(self) -> None:
        await close_dialog(self, None)
