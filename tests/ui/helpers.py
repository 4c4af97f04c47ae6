"""Shared steps of the UI tests: wait for the app, start a session, move, type, and a
recorded step run.

Waiting is exact, never on the clock: :func:`settle` lets the app process its messages
(``pilot.pause()``) and waits for its workers (all but the device stream, which runs for
the app's life) until a condition holds; :class:`Heard` waits for messages the app receives
(``run_test(message_hook=...)``), for the tests on the real-time virtual board.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from contextlib import suppress
from pathlib import Path

from textual import events
from textual.color import Color
from textual.message import Message
from textual.pilot import Pilot
from textual.widget import Widget
from textual.widgets import Input, OptionList
from textual.worker import WorkerCancelled

from minseg_tui.device.samples import SampleBatch
from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.messages import LinkEventArrived, LogImportRequested
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.lab import LabScreen, StepPane
from minseg_tui.ui.screens.quit import RECORDING_CHOICES, QuitScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.fields import AnswerList, EntryBox, FieldForm, FieldRow, field_id
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.textual_internals import all_idle, key_name, marking_idle_nodes, wait_for_screen

TABLE = {
    "R": "5.3",
    "u_ss@2.5": "2.05",
    "omega_ss@2.5": "3.1",
    "i_ss@2.5": "28 mA",
    "u_ss@3.5": "3.04",
    "omega_ss@3.5": "4.9",
    "i_ss@3.5": "32 mA",
    "u_ss@4.5": "4.02",
    "omega_ss@4.5": "6.7",
    "i_ss@4.5": "36 mA",
}
"""A filled Task 4-9 table as a group would type it (R in ohm, the rest per row)."""

HOPS = 4
"""Rounds of message processing :func:`settle` always waits: a handler may post a message
whose handler posts another (Enter in an entry: the lab-changed signal, the view's
worker); four rounds carry such a chain."""

ROUNDS = 1000
"""Most rounds :func:`settle` waits for a condition: a guard against a hang (a condition
that never holds), not a measure of time."""

GUARD = 6000
"""Most 10 ms pauses :func:`taken` waits for the stream worker: a guard against a hang (a
minute), never a threshold a busy machine could cross."""


async def settle(pilot: Pilot[None], until: Callable[[], bool] = lambda: True) -> None:
    """Let the app finish what it was asked, exactly: rounds that each return once every
    message queued on the screen is processed, and waits for the workers that build views
    or write the report (all but the device stream), until ``until()`` holds. A round
    begun while every node of the app is idle (``textual_internals.idle``: nothing queued,
    no handler under way) is ``pilot.pause(0)``, which also lays the screen out and runs
    what waits for its refresh; one begun while some node is busy only waits for the busy
    nodes (Textual's update timer lays out meanwhile, as it does in a terminal).
    ``until()`` is asked, and settle returns, only after a ``pilot.pause(0)`` round that
    began and ended with every node idle (so what waited for the screen's refresh has run
    too), :data:`HOPS` rounds at least. In a process without the tests' fixtures (a
    script a test starts) every round is ``pilot.pause(0)``."""
    app = pilot.app
    marked = marking_idle_nodes()
    for k in range(ROUNDS):
        quiet = not marked or all_idle(app)
        if quiet:
            await pilot.pause(0)
        else:
            await wait_for_screen(pilot)
        busy = [w for w in app.workers if w.group != "stream" and not w.is_finished]
        if busy:
            with suppress(WorkerCancelled):
                await app.workers.wait_for_complete(busy)
            continue
        if k >= HOPS and quiet and (not marked or all_idle(app)) and until():
            return
    raise AssertionError("the app never got there")


class Heard:
    """The messages the app hears (pass :meth:`hook` as ``run_test``'s ``message_hook``);
    :meth:`until` waits, message by message, for a condition. For the real-time board,
    whose stream brings about 25 messages a second. ``kinds``: the kind of every link
    event heard, in order (a status text may be replaced before a test reads it; the
    events stay).

    The hang guards count only the app's own messages (minseg_tui's: the stream's samples,
    the link's events, the procedure's moves), never Textual's (its timers and repaints
    come many times a second whether or not the lab moves on, so a wait counted in them
    could last an hour). The stream posts one message per read, so a busy machine, which
    reads less often, brings fewer of them per second of board time: a guard counted in
    them gives a slow machine more board time, never less."""

    SILENCE: float = 120.0
    """A hang guard, s: the app heard none of its own messages for this long (never reached
    by a test that works, however busy the machine: the stream alone brings one every
    40 ms), so the wait fails instead of blocking the suite."""

    MOST: int = 6000
    """A hang guard: most of the app's own messages one :meth:`until` waits through (about
    four minutes of the stream on a quiet machine; the longest wait of the suite took 105 of
    them on a quiet machine, fewer on a busy one)."""

    def __init__(self) -> None:
        self._new = asyncio.Event()
        self.count = 0
        self.own = 0
        self.kinds: list[str] = []

    def hook(self, message: Message) -> None:
        self.count += 1
        if type(message).__module__.startswith("minseg_tui."):
            self.own += 1
        if isinstance(message, LinkEventArrived):
            self.kinds.append(message.event.kind)
        self._new.set()

    async def until(
        self, pilot: Pilot[None], cond: Callable[[], bool], most: int | None = None
    ) -> None:
        """Wait until ``cond()`` holds, checking it whenever the app hears a message; fail
        after ``most`` (default :attr:`MOST`) of the app's own messages, or after
        :attr:`SILENCE` without one (hang guards). A board watchdog heard meanwhile fails at
        once: the motor is off, and a wait for a speed or a run would only end at the
        guard."""
        loop = asyncio.get_running_loop()
        watchdogs = self.kinds.count("watchdog")
        budget = self.MOST if most is None else most
        last = self.own + budget
        own, heard_at = self.own, loop.time()
        while not cond():
            if self.kinds.count("watchdog") > watchdogs:
                raise AssertionError("the board's watchdog stopped the motor during the wait")
            if self.own >= last:
                raise AssertionError(f"not after {budget} of the app's own messages")
            if self.own != own:
                own, heard_at = self.own, loop.time()
            self._new.clear()
            left = heard_at + self.SILENCE - loop.time()
            if left <= 0:
                raise AssertionError(
                    f"the app heard none of its own messages for {self.SILENCE:g} s"
                )
            with suppress(TimeoutError):
                await asyncio.wait_for(self._new.wait(), left)


def lab_screen(app: LabApp) -> LabScreen:
    screen = app.screen
    assert isinstance(screen, LabScreen)
    return screen


def enter_all(app: LabApp, entries: dict[str, str]) -> None:
    """Store every (field key, typed text) in the app's session, as typed."""
    assert app.session is not None
    with app.session as s:
        for key, text in entries.items():
            s.enter(key, text)


async def start(pilot: Pilot[None], names: str = "Ada, Bo") -> None:
    """Put the group's names in the start screen's box at once, as a paste does, press
    Enter and wait for the lab screen. (Typed key by key, the names cost each test some
    50,000 Python calls of the 1.1 million of an app's start, start screen and step change;
    the names typed on the start screen are tested on their own: tests/ui/test_flow.py,
    test_bursts.py, test_walk7_keys.py.)"""
    await settle(pilot, lambda: bool(pilot.app.screen.query("#members")))
    pilot.app.screen.query_one("#members", Input).insert_text_at_cursor(names)
    await pilot.press("enter")
    await settle(pilot, lambda: isinstance(pilot.app.screen, LabScreen) and shown(pilot.app))


def typing_box(app: LabApp) -> EntryBox | None:
    """The text box the keys typed now go into: that of the step form's current row while
    the form has the focus (None: none)."""
    focused = app.focused
    if not isinstance(focused, FieldForm):
        return None
    row = focused.typing
    return row.input if row is not None else None


def answering(app: LabApp) -> AnswerList | None:
    """The list of answers the keys typed now go to: that of the step form's current row
    while the form has the focus (None: none)."""
    focused = app.focused
    if not isinstance(focused, FieldForm):
        return None
    return focused.answering


def keys_box(app: LabApp) -> EntryBox | AnswerList | None:
    """The text box or list of answers the keys typed now go to: that of the step form's
    current row while the form has the focus (None: none)."""
    focused = app.focused
    if not isinstance(focused, FieldForm):
        return None
    return focused.keys_box


def on_the_list(app: LabApp) -> bool:
    """The group is on the list of steps (Ctrl+L), as they see it and as the keys act: the
    list shows, its highlighted step drawn in the cursor's colours, as a list holding the
    keys draws it (a list without them draws it in the blurred cursor's); the step's form
    has the keys and browses the list with them (↑/↓ show the step before or after, a
    character goes into the first empty entry); and no entry of the step is current, so no
    box takes the keys."""
    screen = app.screen
    if not isinstance(screen, LabScreen) or not screen.query("#nav"):
        return False
    nav = screen.query_one("#nav", OptionList)
    pane = screen.pane
    cursor = nav.get_visual_style("option-list--option", "option-list--option-highlighted")
    keys_colour = Color.parse(app.theme_variables["block-cursor-background"])
    return (
        nav.display
        and cursor.background == keys_colour
        and app.focused is pane
        and pane.browsing
        and pane.current is None
    )


def shown(app: LabApp, step_id: str | None = None) -> bool:
    """The lab screen shows ``step_id`` (any step if None), its pane mounted."""
    screen = app.screen
    if not isinstance(screen, LabScreen):
        return False
    panes = screen.query(StepPane)
    pane = panes.first() if panes else None
    return (
        pane is not None
        and pane.is_mounted
        and pane.step is not None
        and step_id in (None, pane.step.id)
    )


async def resume(pilot: Pilot[None]) -> None:
    """Pick the first saved session on the start screen and wait for the lab screen."""
    await settle(pilot, lambda: bool(pilot.app.screen.query("#sessions")))
    pilot.app.screen.query_one("#sessions").focus()
    await pilot.press("enter")
    await settle(pilot, lambda: shown(pilot.app))


async def goto(pilot: Pilot[None], step_id: str, focus: str | None = "entry") -> None:
    """Jump to ``step_id`` as the palette does and wait until it is shown, its view drawn and
    the focus where ``focus`` says (``entry``: the step's first empty entry)."""
    app = pilot.app
    lab_screen(app).go_to(step_id, focus)

    def there() -> bool:
        if not shown(app, step_id):
            return False
        pane = app.screen.query_one(StepPane)
        if focus != "entry":
            return True
        row = pane.landing_row()  # the first empty entry (the step itself without entries)
        return app.focused is pane and pane.current is row

    await settle(pilot, there)


async def start_with_a_run(pilot: Pilot[None], step_id: str) -> None:
    """A new session with the table's entries (:data:`TABLE`) and the seeded step run of
    :func:`record_response_run`, then ``step_id`` shown and its entry focused (:func:`goto`)."""
    app = pilot.app
    await start(pilot)
    enter_all(app, TABLE)
    with app.session as s:
        record_response_run(s)
    await goto(pilot, step_id)


def stored_text(app: LabApp, key: str) -> str:
    """What the session holds as typed for entry ``key`` ("" when nothing is stored)."""
    with app.session as s:
        entry = s.entry(key)
    return entry.typed if entry is not None else ""


def box_text(app: LabApp, key: str) -> str:
    """What the text box of entry ``key`` on the lab screen shows."""
    return app.screen.query_one(f"#{field_id(key)}", FieldRow).input.value


async def type_in(pilot: Pilot[None], key: str, text: str) -> FieldRow:
    """Type ``text`` into field ``key`` and press Enter; the row, once the lab answered."""
    row = pilot.app.screen.query_one(f"#{field_id(key)}", FieldRow)
    row.input.focus()
    row.input.value = ""
    if text:
        await pilot.press(*text)
    await pilot.press("enter")
    await settle(pilot)
    return row


async def burst(pilot: Pilot[None], *keys: str) -> None:
    """Send ``keys`` the way a terminal hands over a burst (several keys in one read, as a
    quick typist or ``tmux send-keys`` gives them): all queued on the app at once, without
    waiting for the app between them (``pilot.press`` waits after every key); then wait
    until the app has processed them all."""
    app = pilot.app
    for key in keys:
        event = events.Key(key_name(key), key if len(key) == 1 else None)
        event.set_sender(app)
        app.post_message(event)
    await settle(pilot)


async def paste_in(pilot: Pilot[None], key: str, text: str) -> FieldRow:
    """Put ``text`` into field ``key`` at once, as a paste does, and press Enter; the row,
    once the lab answered. (Typing key by key waits for the app to idle after every key,
    which takes long while the board streams; the quiet tests type.)"""
    row = pilot.app.screen.query_one(f"#{field_id(key)}", FieldRow)
    row.input.focus()
    row.input.value = ""
    row.input.insert_text_at_cursor(text)
    await pilot.press("enter")
    await settle(pilot)
    return row


def standing(n: int, first_seq: int = 0, period_us: int = 25_000) -> SampleBatch:
    """``n`` samples of a wheel standing still (count 0, motor off), as the link hands them
    over, from sequence number ``first_seq`` on."""
    return SampleBatch.from_rows(
        [(k, (k + 1) * period_us, 0, 0, 0, 0.0) for k in range(first_seq, first_seq + n)]
    )


async def start_run_on(pilot: Pilot[None], device: QuietDevice, key: str = "f5") -> int:
    """Press ``key`` on Task 10 and let the double's wheel stand (samples fed to the app, as
    the board would send them) until the run is recorded and the board asked for its
    sequence: the app stops the motor, waits for the wheel to stand, records a few samples
    of it, then sends STEP. The sequence number the board's next sample has."""
    await pilot.press(key)
    await settle(pilot)
    seq = 0
    for _ in range(ROUNDS):
        if device.commands and device.commands[-1].startswith("STEP"):
            return seq
        device.feed(standing(4, seq))
        seq += 4
        await taken(pilot, seq)
    raise AssertionError("the run never started")


async def answer_T_on_a_run(pilot: Pilot[None]) -> str:
    """:func:`start_with_a_run` on Task 12, and the group's T typed there (the run's T_63 in
    ms, three digits): the run's name. Task 12 stays shown."""
    app = pilot.app
    await start_with_a_run(pilot, "task12")
    with app.session as s:
        run, T_63 = s.response_run().name, s.results().step.T_63
    await type_in(pilot, "own.T", f"{T_63 * 1e3:.3g} ms")
    return run


async def record_a_square_wave(pilot: Pilot[None], device: QuietDevice) -> str:
    """F5 on Task 10 (shown), the double's 12 s square wave (seed 9) taken as the run, and the
    run finished; the name of the run Tasks 11-15 use then."""
    app = pilot.app
    seq = await start_run_on(pilot, device)
    app.recording.append(square_wave_stream(seq, (seq + 1) * 25_000, 12.0, seed=9))
    app.finish_run("done")
    await settle(pilot)
    with app.session as s:
        return s.response_run().name


async def quit_asked_mid_run(pilot: Pilot[None], device: QuietDevice) -> int:
    """On Task 10: F5's run started on the double, 2 s of its square wave taken (80 samples),
    then Ctrl+Q while it records: the quit question is up, its choices the recording's. The
    run's first sequence number (feed the rest of the run from ``seq + 80``)."""
    app = pilot.app
    seq = await start_run_on(pilot, device)
    device.feed(square_wave_stream(seq, (seq + 1) * 25_000, 2.0))
    await taken(pilot, seq + 80)
    await pilot.press("ctrl+q")
    await settle(pilot, lambda: isinstance(app.screen, QuitScreen))
    asking = app.screen
    assert isinstance(asking, QuitScreen) and asking.choices is RECORDING_CHOICES
    return seq


async def taken(pilot: Pilot[None], total: int) -> None:
    """Wait until the app's stream worker has taken ``total`` samples from the device double
    (it reads every 50 ms on its own thread) and the app has handled what they brought.

    The live buffer has them before the worker posts what that read found (the samples'
    message, the link's events, the run's end come after the buffer), and the worker's
    thread may wait behind others on a busy machine: the samples are taken once the worker
    has read the double again, which it does only after posting everything of the read
    before; :func:`settle` then handles it."""
    app = pilot.app
    device = app._device
    assert isinstance(device, QuietDevice), "taken() counts the reads of the device double"
    for _ in range(GUARD):
        if app.live.total >= total:
            break
        await pilot.pause(0.01)
    else:
        raise AssertionError(f"the stream worker took {app.live.total} of {total} samples")
    reads = device.reads
    for _ in range(GUARD):
        if device.reads > reads:
            await settle(pilot)
            return
        await pilot.pause(0.01)
    raise AssertionError("the stream worker never read the device double again")


def record_response_run(session: Session, seed: int = 5) -> str:
    """Task 10's 25 ms plan on the seeded plant, appended to the session's Recorder as a board
    would send it; the run's name."""
    plan = dict(step("task10").plans)["manual"]
    plant = Plant(PlantParams(), seed=seed)
    rec = session.start_run("steps", plan)
    n = round(plan.duration / plan.ts)
    per_half = round(plan.half_period / plan.ts)
    for k in range(n):
        u = plan.high if (k // per_half) % 2 == 0 and k >= 4 else plan.low
        plant.set_command(u)
        rec.append(k, round(k * plan.ts * 1e6), plant.count, round(u * 1000))
        plant.advance(plan.ts)
    info = session.finish_run(rec)
    assert info is not None
    return info.name


def heard_notifications(app) -> list[str]:
    """Every notification the app shows from now on (its text), in a list."""
    said: list[str] = []
    notify = app.notify

    def keep(message, *args, **kwargs):
        said.append(str(message))
        return notify(message, *args, **kwargs)

    app.notify = keep
    return said


def nav_mark(app: LabApp, step_id: str) -> str:
    """The mark before step ``step_id`` in the list of steps (✓, ✗, ?, … or a blank)."""
    nav = app.screen.query_one("#nav", OptionList)
    return str(nav.get_option(step_id).prompt)[0]


async def class_view(pilot: Pilot[object]) -> ClassScreen:
    """F12 on the start screen: the class view, once every group in it is read."""
    app = pilot.app
    await settle(pilot, lambda: isinstance(app.screen, StartScreen))
    await pilot.press("f12")
    await settle(pilot, lambda: isinstance(app.screen, ClassScreen) and app.screen.done)
    screen = app.screen
    assert isinstance(screen, ClassScreen)
    return screen


def in_step_view(pane: StepPane, widget: Widget) -> bool:
    """``widget`` lies whole in the part of the step on screen below its heading."""
    view = pane.scrollable_content_region
    top = view.y + pane.heading_rows
    return (
        widget.region.height > 0 and top <= widget.region.y and widget.region.bottom <= view.bottom
    )


async def import_a_copy(pilot: Pilot[object], folder: Path) -> str:
    """Import a copy of the run in use, written to ``folder``/log.csv, as the palette's
    "Import a run log" does (the message its path box posts); the reply said."""
    app = pilot.app
    assert isinstance(app, LabApp)
    with app.session as s:
        log = s.run_path(s.response_run().name)
    elsewhere = folder / "log.csv"
    elsewhere.write_bytes(log.read_bytes())
    replies: list[str] = []
    app.screen.post_message(LogImportRequested(str(elsewhere), replies.append))
    await settle(pilot, lambda: bool(replies))
    return replies[0]
