"""The Textual app: start screen, the lab screen, keys, command palette, the device workers.

:func:`make_app` is the one way to build it (the CLI and the tests share it). The app owns
the device, the open session and the state the screens show, as reactive attributes it
binds into each screen it makes: ``device`` (who we talk to), ``link`` (its state and
counters), ``motor``, ``requested`` (the voltage set with F3), ``meter`` (the virtual
multimeter), ``run_progress`` (the Task 10 run being recorded) and ``written`` (where the
report's files are); and ``lab_changed``, a signal published whenever the session changed. It answers
the requests that need the device (:class:`RunRequested`, F2, F3 through the lab screen, F8).

The device is opened in a worker; a second worker drains it every 50 ms into the bounded
live buffer (and into the Task 10 procedure, :class:`~minseg_tui.lab.state.task10.Task10`, which
drives the run and keeps it) and posts coalesced messages, so the event loop never waits on
the board; the app shows the run's progress. Workers that only read the session (views,
the report) get a frozen snapshot of it.
"""

from __future__ import annotations

import asyncio
import datetime as _dt
import queue
import signal
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable, Sequence
from dataclasses import replace
from functools import partial
from pathlib import Path
from typing import Any

from textual import on, work
from textual.actions import SkipAction
from textual.app import App, SystemCommand
from textual.binding import Binding
from textual.command import CommandPalette
from textual.notifications import Notification, Notify, SeverityLevel
from textual.reactive import reactive
from textual.screen import Screen
from textual.signal import Signal
from textual.worker import get_current_worker

from minseg_tui.device.boardcheck import CHECK_U, NoCountWatch, check_board, count_revolution
from minseg_tui.device.samples import SampleBatch
from minseg_tui.device.standstill import timeout_message
from minseg_tui.errors import MinsegError
from minseg_tui.lab.content.keys import PALETTE, in_palette, key_name
from minseg_tui.lab.saving.store import (
    SessionInfo,
    SessionsUnreadable,
    list_sessions,
    lock_owner,
    os_reason,
)
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.state.task10 import ActiveRun, Outcome, RunProgress, Task10
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as lab_views
from minseg_tui.model.plant import MeterReading
from minseg_tui.quantities import format_fixed
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.device import Device, DeviceInfo, LinkState, open_device
from minseg_tui.ui.keys import FOOTER_ON, IN_FOOTER, app_bindings, bound_keys, help_lines
from minseg_tui.ui.live import LEVEL_TOL, LiveBuffer
from minseg_tui.ui.messages import (
    BoardChecked,
    CommandFailed,
    DeviceOpened,
    LinkEventArrived,
    MeterRead,
    MotorKnown,
    NoCounts,
    NoticesCrowd,
    RevolutionCounted,
    RunRequested,
    SamplesArrived,
    StepShown,
    Task10Moved,
)
from minseg_tui.ui.panels.report import written_in
from minseg_tui.ui.screens.boardcheck import (
    REVOLUTION,
    BoardCheckScreen,
    RevolutionScreen,
    WheelQuestionScreen,
)
from minseg_tui.ui.screens.classview import NO_WRITER, ClassScreen, ClassWriter
from minseg_tui.ui.screens.dialog import close_dialog
from minseg_tui.ui.screens.help import CLASS_NOW, START_NOW, HelpScreen, lab_now
from minseg_tui.ui.screens.lab import PANEL_KEYS, RUN_REFUSED, LabScreen
from minseg_tui.ui.screens.names import NamesScreen
from minseg_tui.ui.screens.palette import Palette
from minseg_tui.ui.screens.quit import (
    RECORDING_CHOICES,
    RUN_ENDED_CHOICES,
    QuitScreen,
    SaveElsewhereScreen,
    recording_question,
    run_ended_question,
)
from minseg_tui.ui.screens.start import StartScreen, split_names
from minseg_tui.ui.shared import Shared
from minseg_tui.ui.widgets.fields import after_typed_keys

ReportWriter = Callable[[Session], Sequence[Path]]
"""Writes a session's report into its folder; the files written (the CLI hands in
:func:`minseg_tui.report.write.write_report`: the report layer sits beside the UI)."""

KEYS: list[tuple[str, str]] = help_lines()
"""F1's list of keys (:data:`minseg_tui.ui.keys.KEYMAP`)."""

EVENT_TEXT: dict[str, str] = {
    "disconnected": "board disconnected — everything recorded is kept",
    "connected": "board reconnected",
    "silent": "board silent — no data",
    "alive": "board answers again",
    "watchdog": "watchdog stopped the motor",
    "boot": "board restarted — motor off",
    "motor": "motor off after the restart: nothing restored",
}
"""What the status line says at once for a link event (``error`` shows the link's own line)."""


def alive_text(silent_s: float | None, virtual: bool) -> str:
    """What the status line says when the board answers after a silence: the silence it ends
    with its length (s, host clock), so that the line is true even when the silence was too
    short to be seen (the PC busy: the two link events handled in one pass). The virtual
    MinSeg runs on the PC, so its silence can only be the PC being busy, and is said so
    ("paused 0.6 s (PC busy)"; a board: "silent 0.6 s, answers again"), short enough for the
    status line at 80 columns."""
    if silent_s is None:
        return EVENT_TEXT["alive"]
    lasted = format_fixed(silent_s, 1, "s")
    if virtual:
        return f"paused {lasted} (PC busy)"
    return f"silent {lasted}, answers again"


PASSING_EVENTS = frozenset({"alive", "connected", "square_wave_done"})
"""Link events whose words are news, not a lasting state: shown for :data:`TRANSIENT_SHOWN`,
then the link's counters again ("board answers again" stayed on the line for the rest of a
session; so did "square wave done", through later runs: walk 10, D2)."""

TRANSIENT_SHOWN = 3.0
"""How long the status line shows news about the link, s of board time (the samples'
clock: the line never changes while nothing comes)."""


STREAM_PERIOD = 0.05
"""How often the stream worker drains the device, s."""

METER_PERIOD = 0.25
"""How often the virtual multimeter is read while a step shows it, s."""

NOTICE_S = 5.0
"""How long a notice that something was done stays, s (F8's list of files stayed 10 s over
the last field of the summary: issue 20, walk 5). Textual's default is 5 s."""

SAVE_RETRY = 3.0
"""While the session cannot be saved, it is tried again this often, s."""

TERMINATING: tuple[int, ...] = tuple(
    sig for sig in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)) if sig
)
"""The signals that end the app as Ctrl+Q does (what stands in the entries stored first)."""

REVOLUTION_TIMEOUT = 300.0
"""Longest the hand check counts without an Enter, s."""

ENDED_WORDS: dict[str, str] = {
    "stopped": "stopped",
    "quit": "app closed",
    "not started": "could not start",
}
"""What ended a run (:attr:`minseg_tui.lab.state.task10.Outcome.why`) in the words of the run's
last line, where a link event's words (:data:`EVENT_TEXT`) do not say it."""


def _kind(notice: Notification) -> str:
    """What a notice is about, as one that replaces it is (:meth:`LabApp.notify`): its title
    (the report, the board check, an answer replaced); an untitled notice, its words (the
    same notice again)."""
    return notice.title or notice.message


def motor_words(u_req: float | None, plan_high: float | None = None) -> str:
    """The motor in words for the status line: off, 2.5 V, steps 0/4.5 V."""
    if u_req is None:
        return f"steps 0/{plan_high:g} V" if plan_high is not None else "steps"
    return "off" if u_req == 0 else f"{u_req:g} V"


class LabApp(App[None]):
    """minseg-tui: the DC-motor lab, step by step, on the board or the virtual MinSeg.

    ``open_device`` opens the device for a spec (see :func:`~minseg_tui.ui.device.open_device`);
    ``writer`` writes the report (None: F8 says it cannot)."""

    TITLE = "minseg-tui"
    CSS_PATH = "lab.tcss"
    BINDINGS = [
        *app_bindings(),
        # a panel key the step's form does not run (its panel does not have it here): said
        # (the form binds the panel keys, StepPane)
        *[Binding(keys, f"not_here('{what}')", show=False) for keys, _, _, what in PANEL_KEYS],
        # F8 in a read-only session: not in its footer (the binding above is not live there),
        # still saying why when pressed
        Binding(bound_keys("export"), "export(True)", show=False, priority=True),
    ]

    device: reactive[DeviceInfo | None] = reactive(None)
    """Who the app talks to (None: no device yet, or none could be opened)."""
    link: reactive[LinkState] = reactive(LinkState(event="connecting…"))
    """The link's state, counters and the last event's words."""
    motor: reactive[str] = reactive("off")
    """What the motor does, in words: off, 2.5 V, steps 0/4.5 V."""
    requested: reactive[float | None] = reactive(None)
    """The voltage last set with F3 (V; None: none, or the motor is off or runs steps)."""
    meter: reactive[MeterReading | None] = reactive(None)
    """The virtual multimeter's last reading (None: none yet)."""
    run_progress: reactive[RunProgress | None] = reactive(None)
    """The Task 10 run being recorded, or the last one's end (None: none yet)."""
    exported: reactive[tuple[str, ...]] = reactive(())
    """The files the report was last written to."""
    written: reactive[tuple[str, tuple[str, ...]]] = reactive(("", ()))
    """Where they are, as :func:`written_in` says it (worked out by the export's worker)."""
    saving: reactive[str] = reactive("")
    """Why the session is not all on disk, in one line ('' when it is)."""

    def __init__(
        self,
        config: UiConfig,
        open_device: Callable[[str], Device],
        writer: ReportWriter | None = None,
        class_writer: ClassWriter | None = None,
    ) -> None:
        super().__init__()
        self.config = config
        self._open_device = open_device
        self._writer = writer
        self._class_writer = class_writer
        self._device: Device | None = None
        self.session: Shared[Session] | None = None
        """The open session (None on the start screen)."""
        self.live = LiveBuffer()
        self.task10: Task10 | None = None
        """The Task 10 procedure under way (fed by the stream worker), or None."""
        self._run: ActiveRun | None = None
        self._used_before: str | None = None
        """The run Tasks 11-15 used when Task 10 began the run now under way."""
        self.lab_changed: Signal[None] = Signal(self, "lab-changed")
        """Published whenever the session changed (an entry, a capture, a run, an import)."""
        self._meter_wanted = False
        self._stop = threading.Event()
        self._commands: deque[tuple[str, Callable[[], object]]] = deque()
        """Board commands (F2, F3) not yet sent, oldest first: one worker sends them in order."""
        self._sending = False
        """The worker that sends :attr:`_commands` runs (set and read under :attr:`_lock`)."""
        self._exports_asked = 0
        """How many exports (F8) were asked for: only the last asked writes once it may."""
        self._export_lock = threading.Lock()
        """Held by the export writing the report (one at a time)."""
        self._motor_unread = False
        """The link's motor was passed over while the commands were sent: the worker asks
        for it again once the last is sent (set and read under :attr:`_lock`)."""
        self._lock = threading.Lock()
        self._signals: list[int] = []  # the terminating signals the app answers
        self._tap: queue.Queue[SampleBatch] | None = None
        """While the board check runs: the stream's samples, for the check (the stream
        worker is the one reader of the device)."""
        self._newest: SampleBatch | None = None
        """The newest sample the stream has read (set and read under :attr:`_lock`)."""
        self._watch = NoCountWatch()
        self._notices: list[Notification] = []
        """The notices shown (Textual drops one from the screen once its time is up), oldest
        first: one of a kind, the newest (:func:`_kind`)."""
        self._step_id = ""
        self._watching_speed = False
        """The shown step is done once the live speed is watched with the wheel turning."""
        if not config.animations:
            self.animation_level = "none"

    @property
    def recording(self) -> ActiveRun | None:
        """The Task 10 run being recorded, as the screen knows it: from the message that it
        started to the one that it ended (None: none, or the wheel is still awaited)."""
        return self._run

    @property
    def _run_busy(self) -> bool:
        """Task 10 waits for the wheel or records."""
        return self.task10 is not None and self.task10.active

    def notify(
        self,
        message: str,
        *,
        title: str = "",
        severity: SeverityLevel = "information",
        timeout: float | None = None,
        markup: bool = True,
    ) -> None:
        """Show a notification as plain text, whoever asks (a widget's ``notify`` asks with
        markup on): the messages hold what was typed, refused text and file names, which
        are shown as they are, never read as markup ('Cy [/]' was a MarkupError).

        An override, because Textual offers no app-wide setting for it: ``App.notify`` and
        ``Widget.notify`` default to ``markup=True``, and every widget's goes through this
        one. ``markup=False`` at each of the 43 calls (or a helper of another name) would
        hold only as long as every new call remembered it."""
        stack = self.screen_stack  # empty while the app closes (a run's notice at exit)
        lab = stack[-1] if stack and isinstance(stack[-1], LabScreen) else None
        if lab is not None:
            lab.place_notices()  # away from the entry typed in
        notice = Notification(
            message,
            title,
            severity,
            self.NOTIFICATION_TIMEOUT if timeout is None else timeout,
            markup=False,
        )
        shown = [n for n in self._notices if not n.has_expired]
        same = [n for n in shown if _kind(n) == _kind(notice)]
        self._notices = [n for n in shown if n not in same] + [notice]
        if same:  # the newest word on it replaces the older (a second F8's, say)
            self._show_notices()
        else:
            self.post_message(Notify(notice))  # as Textual's notify posts it
        if lab is not None:  # and from where it is once the keys before it have moved it
            lab.call_after_refresh(lab.place_notices)

    def _show_notices(self) -> None:
        """Show :attr:`_notices` in place of the notices on screen, each for the time it had
        left. Textual withdraws one notice only when its time is up or it is clicked; this
        clears them all and shows again the ones kept (its public calls)."""
        for screen in self.screen_stack:  # each screen shows the app's notices in its rack
            for rack in screen.query_children("ToastRack"):
                # the toasts with their holders: Textual's rack takes a toast out of a clear,
                # not its holder, and each holder left took a row over the next notices
                rack.remove_children()
        self.clear_notifications()
        kept = [n for n in self._notices if not n.has_expired]
        self._notices = [
            Notification(n.message, n.title, n.severity, n.time_left, markup=False) for n in kept
        ]
        for notice in self._notices:
            self.post_message(Notify(notice))

    @on(NoticesCrowd)
    def _notices_crowd(self, _: NoticesCrowd) -> None:
        """The lab screen's notices cover the entry typed in or the one judged last: the
        oldest goes, the newest always stays."""
        shown = [n for n in self._notices if not n.has_expired]
        if len(shown) > 1:
            self._notices = shown[1:]
            self._show_notices()

    # -- start-up ---------------------------------------------------------------------
    def on_mount(self) -> None:
        today = self.config.today or _dt.date.today().isoformat()
        sessions: list[SessionInfo] = []
        unreadable = ""
        try:
            sessions = list_sessions(Path(self.config.sessions))
        except SessionsUnreadable as exc:  # it was readable when the CLI looked; not now
            unreadable = str(exc)
        start = StartScreen(sessions, today, unreadable)
        self.push_screen(start.data_bind(LabApp.device, LabApp.link, LabApp.motor))
        self._connect(self.config.device)
        self.set_interval(SAVE_RETRY, self.retry_save)
        self._catch_signals()

    def _catch_signals(self) -> None:
        """SIGTERM and SIGHUP (a shutdown, a closed terminal window, ``kill``) end the app
        the way Ctrl+Q does: :meth:`terminated`. Where the loop cannot take them (not the
        main thread, another platform) they keep their default."""
        loop = asyncio.get_running_loop()
        for signum in TERMINATING:
            try:
                loop.add_signal_handler(signum, self.terminated, signum)
            except (NotImplementedError, RuntimeError, ValueError):
                continue
            self._signals.append(signum)

    def terminated(self, signum: int) -> None:
        """A terminating signal: store what stands in the entries, save the session (what
        cannot be saved is lost with the program, as with 'quit anyway'), then exit as Ctrl+Q
        does, with the terminal restored; the exit status is 128 + the signal's number, as
        the shell expects of a program that a signal ended (143 for SIGTERM)."""
        screen = self._lab_screen()
        if screen is not None:
            screen.store_typed()
        if self.session is not None:
            with self.session as s:
                if not s.readonly and s.unsaved:
                    s.save()
        self.exit(return_code=128 + signum)

    @work(thread=True, exclusive=True, group="connect", name="open device")
    def _connect(self, spec: str) -> None:
        """Worker: open (and handshake) the device; a real board takes up to 2.5 s."""
        try:
            device = self._open_device(spec)
        except MinsegError as exc:
            self.post_message(DeviceOpened(None, str(exc)))
            return
        self.post_message(
            DeviceOpened(device, fallback=spec == "auto" and device.board is not None)
        )

    @on(DeviceOpened)
    def _opened(self, event: DeviceOpened) -> None:
        if event.device is None:
            self.link = LinkState(event="no device: " + event.error)
            self.notify(event.error, title="device", severity="error", timeout=10)
            return
        with self._lock:
            self._device = event.device
            self._newest = None
        self.device = DeviceInfo.of(event.device, event.fallback)
        self.link = LinkState()
        self._stream(event.device)
        if event.device.board is None:  # a real board: worth checking before the lab
            self.notify(
                f"{self.device.name} connected. {key_name('board_check')} runs the board check: does the wheel "
                "turn when asked, and does the count follow it? (about a second)",
                title="board check",
                timeout=15,
            )

    async def action_command_palette(self) -> None:  # type: ignore[override]
        # (Textual's is not async; its actions may be, and this one waits for the keys)
        """Ctrl+P: the palette, closed once however many Enters it is handed; after the keys
        typed before it (what they typed stored first), before those typed after it (they
        go into the palette)."""
        await after_typed_keys(self, self._open_palette)

    async def _open_palette(self) -> None:
        self._store_typed()
        if isinstance(self.screen, (BoardCheckScreen, HelpScreen)):
            # a result the group reads closes first, as its Escape does: the palette is the
            # lab screen's, with its steps (over the board check's result 'task 2' found no
            # match, and the keys typed after it went into the search: walk 12's D3)
            await close_dialog(self.screen, None)
        if self.use_command_palette and not isinstance(self.screen, CommandPalette):
            await self.push_screen(Palette(id="--command-palette"))

    async def action_start_lab(self) -> None:
        """Enter on the start screen: open the lab it asks for, and return once the lab shows
        its step (the keys typed after Enter wait for it and land in the lab); what was typed
        in the boxes before it, in the same burst, is in them first."""
        await after_typed_keys(self, self._start_lab)

    async def _start_lab(self) -> None:
        screen = self.screen
        if not isinstance(screen, StartScreen):
            return
        wanted = screen.request()
        if isinstance(wanted, StartScreen.NewSession):
            await self._new(wanted)
        elif isinstance(wanted, StartScreen.Resume):
            await self._resume(wanted)

    def action_class_view(self) -> None:
        """F12 on the start screen: every group of the sessions folder, one row each."""
        if isinstance(self.screen, StartScreen):
            self.push_screen(
                ClassScreen(Path(self.config.sessions), self._class_writer, self.open_group)
            )

    @on(StartScreen.NewSession)
    async def _new(self, event: StartScreen.NewSession) -> None:
        names = split_names(event.members)
        root = Path(self.config.sessions)
        await self._enter_lab(lambda: Session.create(root, names, event.date or None))

    @on(StartScreen.Resume)
    async def _resume(self, event: StartScreen.Resume) -> None:
        path = Path(event.path)
        await self._enter_lab(lambda: Session.open(path, readonly=event.readonly))

    async def open_group(self, folder: Path) -> None:
        """Enter on the class view: the group's session in ``folder`` read-only, over the
        class view; returns once the lab shows its step."""
        await self._enter_lab(lambda: Session.open(folder, readonly=True), over_class=True)

    async def _enter_lab(self, get: Callable[[], Session], over_class: bool = False) -> None:
        """Open the session ``get`` returns in the lab screen: in place of the start screen,
        or pushed over the class view (``over_class``), which Escape there shows again."""
        if not isinstance(self.screen, ClassScreen if over_class else StartScreen):
            return  # a second Enter (or click) while the lab opens
        try:
            session = get()
        except MinsegError as exc:
            self.notify(str(exc), title="session", severity="error", timeout=10)
            return
        self.session = Shared(session)
        self.lab_changed.subscribe(self, lambda _: self._saved_or_not())
        screen = LabScreen(
            self.session,
            self.live,
            self.lab_changed,
            self.set_voltage,
            self.config.refresh,
            back=self.back_to_class if over_class else None,
        )
        bound = screen.data_bind(
            LabApp.device,
            LabApp.link,
            LabApp.motor,
            LabApp.requested,
            LabApp.meter,
            LabApp.run_progress,
            LabApp.written,
            LabApp.saving,
        )
        await (self.push_screen(bound) if over_class else self.switch_screen(bound))
        await screen.shown.wait()
        if session.readonly:
            self.notify(
                "opened read-only: "
                + (session.damaged or "to look, not to change")
                + "; nothing typed here is saved"
                + (_as_read(session) if over_class else "")
                + (
                    " (Escape: back to the class view)"
                    if over_class
                    else " (start a new session to go on)"
                ),
                title="damaged session" if session.damaged else "read-only session",
                severity="warning",
                timeout=20,
            )
        notes = list(session.recovery_notes)  # one notice: a second would replace the first
        if session.recovered:
            notes.insert(0, "kept after a crash: " + ", ".join(session.recovered))
        if notes:
            self.notify("\n".join(notes), title="session", timeout=10)
        self._saved_or_not()

    async def back_to_class(self) -> None:
        """Escape (or the palette) in a session opened read-only from the class view: the
        session closed (nothing of it is written: it is read-only) and the lab screen popped,
        which shows the class view under it as it was left, the cursor on that group."""
        screen = self._lab_screen()
        if screen is None or screen.back is None or self.session is None:
            return
        session, self.session = self.session, None
        self.lab_changed.unsubscribe(self)
        with session as s:
            s.close()
        self._meter_wanted = self._watching_speed = False
        self._step_id = ""
        self.written = ("", ())
        self.exported = ()
        self._saved_or_not()
        await self.pop_screen()

    # -- the stream ---------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="stream", name="device stream")
    def _stream(self, device: Device) -> None:
        """Worker thread: drain the device into the live buffer and the run being recorded (and
        flush the run to disk); say so with one coalesced message per read; pass the link's
        events on; read the virtual multimeter while a step shows it."""
        worker = get_current_worker()
        next_meter = 0.0
        u_req: float | None = 0.0
        since = time.monotonic()  # when the request u_req began
        while not worker.is_cancelled and not self._stop.wait(STREAM_PERIOD):
            batch = device.samples()
            events = device.events()
            task = self.task10
            # the procedure takes the samples first (it drives the board and keeps the run:
            # here, never on the UI thread); the screen hears that it went on before the
            # samples, and that it ended after the link's events (the event that ended it)
            moved = task is not None and task.active and task.feed(batch, events)
            if moved and task is not None and task.outcome is None:
                self.post_message(Task10Moved(task))
            with self._lock:  # not into the buffer of the device switched to meanwhile
                if self._device is not device:
                    return
                self.live.extend(batch)
                tap = self._tap  # a check's tap, opened under this lock (_open_tap)
                if len(batch):
                    self._newest = batch.newest()
                    if tap is not None:
                        tap.put(batch)
            if len(batch):
                if tap is None and (u := self._watch.feed(batch)) is not None:
                    self.post_message(NoCounts(u))
                self.post_message(SamplesArrived(replace(device.stats), self.live.total))
            if device.u_req != u_req:
                u_req = device.u_req
                since = time.monotonic()
                self.post_message(MotorKnown(u_req))
            for ev in events:
                self.post_message(LinkEventArrived(ev))
            if moved and task is not None and task.outcome is not None:
                self.post_message(Task10Moved(task))
            now = time.monotonic()
            if self._meter_wanted and device.board is not None and now >= next_meter:
                next_meter = now + METER_PERIOD
                try:
                    reading = device.meter()
                except MinsegError:
                    reading = None
                self.post_message(MeterRead(reading, u_req, now - since))

    @on(SamplesArrived)
    def _samples(self, event: SamplesArrived) -> None:
        self.link = self.link.counted(event.stats).aged(self.live.latest, TRANSIENT_SHOWN)
        if self.recording is not None:
            self.run_progress = self.recording.progress()
            asking = self.screen
            if isinstance(asking, QuitScreen) and asking.choices is RECORDING_CHOICES:
                asking.problem = recording_question(self.recording)
        if self._watching_speed and self.session is not None:
            t, count, _ = self.live.snapshot()
            with self.session as s:
                watched = s.watch_speed(t, count)
            if watched:  # Task 3 done: its mark in the list of steps
                self._watching_speed = False
                self.lab_changed.publish(None)

    def _record_check(self, key: str, ok: bool, text: str, counts: int | None) -> None:
        """Keep a board check's result in the session (its step's mark, the report)."""
        if self.session is None:
            return
        with self.session as s:
            if s.readonly:
                return
            s.record_check(key, ok, text, counts)
        self.lab_changed.publish(None)

    @on(MeterRead)
    def _meter_read(self, event: MeterRead) -> None:
        """Show the virtual multimeter's reading, and have the session note it for the step
        shown: a reading typed there is judged against what the meter showed."""
        self.meter = event.reading
        if event.reading is None or self.session is None or not self._meter_wanted:
            return
        with self.session as s:
            if not s.readonly:
                s.note_meter(self._step_id, event.requested, event.held, event.reading)

    @on(MotorKnown)
    def _motor_known(self, event: MotorKnown) -> None:
        """The link's own idea of the motor (after a reconnect: off, nothing restored)."""
        self._motor_from_link()

    def _motor_from_link(self) -> None:
        """The status line's motor and F3's level as the link has them now, when the message
        that asks is handled, never as a worker read them: a check, a command or a board
        event may have changed the motor since, and what the screen took would stand until
        the link changed again. Not while a run waits or records (its own words stand), nor
        while board commands are on their way (what they ask is shown; the worker that sends
        them asks again once the last is sent, :attr:`_motor_unread`); without a device, as it
        is."""
        device = self._device
        if device is None or self._run_busy:
            return
        with self._lock:
            if self._sending:
                self._motor_unread = True
                return
        u_req = device.u_req
        self.motor = motor_words(u_req)
        if u_req is not None and self.requested != u_req:
            self.requested = u_req or None

    @on(StepShown)
    def _step_shown(self, event: StepShown) -> None:
        self._meter_wanted = "meter" in event.step.actions
        self._step_id = event.step.id
        self._watching_speed = "speed_watched" in event.step.done_when

    @on(LinkEventArrived)
    def _link_event(self, event: LinkEventArrived) -> None:
        ev = event.event
        kind = ev.kind
        if kind == "edge":
            return
        if kind in ("disconnected", "error"):
            self.motor = "off"  # the board is gone (its watchdog stops it); the link keeps
            self.requested = None  # the voltage last asked, which is no longer on the motor
        elif kind in ("square_wave_done", "watchdog", "boot", "motor"):
            # the link has the motor off (or at the square wave's low level): as it has it
            # now, not "off" whatever happened since the stream read the event (an F3 handled
            # in between put a voltage on the motor again, and the screen said "off" while the
            # wheel turned); a run these end is ended by the Task 10 procedure
            self._motor_from_link()
        if (kind == "connected" and self.link.event == "") or (
            kind == "alive" and self.link.state != "silent"
        ):  # nothing was said that these would answer: "again" only after "silent"
            self.link = self.link.after(ev, "")
            return
        text = EVENT_TEXT.get(kind, ev.message)
        if kind == "alive":
            device = self._device
            text = alive_text(ev.silent_s, device is not None and device.board is not None)
        self.link = self.link.after(ev, text, kind in PASSING_EVENTS, self.live.latest)
        if kind in ("disconnected", "watchdog", "error", "motor"):
            self.notify(
                self.link.event if kind not in ("error", "motor") else ev.message,
                severity="warning",
                timeout=8,
            )

    # -- the board check ---------------------------------------------------------------------
    def _check_device(self) -> Device | None:
        """The device, if a board check may start now (else None, and why is said)."""
        device = self._device
        if device is None:
            self.notify(
                "no device: the board check needs the board or the virtual MinSeg",
                severity="warning",
            )
            return None
        if self._tap is not None:
            self.notify("the board check is running", severity="information")
            return None
        if self._run_busy:
            self.notify(
                f"a run is in progress: {key_name('stop_motor')} stops it, then {key_name('board_check')} checks",
                severity="warning",
            )
            return None
        if isinstance(self.screen, BoardCheckScreen):
            self.screen.dismiss(None)
        return device

    def _taker(self, tap: queue.Queue[SampleBatch]) -> Callable[[], SampleBatch]:
        """What the check reads samples with: everything the stream put in ``tap`` so far."""

        def take() -> SampleBatch:
            got: list[SampleBatch] = []
            while True:
                try:
                    got.append(tap.get_nowait())
                except queue.Empty:
                    return SampleBatch.concat(got)

        return take

    def action_board_check_in_footer(self) -> None:
        """F10 as Task 1's footer shows it (live there only: :meth:`check_action`)."""
        self.action_board_check()

    def action_board_check(self) -> None:
        """F10: drive the motor briefly and say whether the count follows (in a worker)."""
        device = self._check_device()
        if device is None:
            return
        self._tap = queue.Queue()
        self.requested = None
        self.notify(
            f"board check: {CHECK_U:g} V for half a second…", title="board check", timeout=3
        )
        self._board_check(device, self._tap, self._step_id == "task5")

    @work(thread=True, exclusive=True, group="check", name="board check")
    def _board_check(self, device: Device, tap: queue.Queue[SampleBatch], task5: bool) -> None:
        """Worker: the board check on the samples the stream hands over."""
        take = self._taker(tap)
        try:
            result = check_board(device, samples=take, task5=task5, wheel_turned=self._ask_turned)
        except MinsegError as exc:
            self.post_message(BoardChecked(None, str(exc)))
            return
        self.post_message(BoardChecked(result))

    def _ask_turned(self) -> bool | None:
        """In the check's worker: ask the group whether the wheel turned, wait for them."""
        answered = threading.Event()
        box: list[str] = []

        def got(answer: str | None) -> None:
            box.append(answer or "unsure")
            answered.set()

        self.call_from_thread(self.push_screen, WheelQuestionScreen(), got)
        worker = get_current_worker()
        while not answered.wait(0.1):
            if worker.is_cancelled or self._stop.is_set():
                return None
        return {"yes": True, "no": False}.get(box[0])

    @on(BoardChecked)
    def _board_checked(self, event: BoardChecked) -> None:
        self._tap = None
        self._watch = NoCountWatch()
        if self._device is not None:
            self.motor = motor_words(self._device.u_req)  # the check ends with the motor off
        if event.result is None:
            self.notify(event.error, title="board check", severity="error", timeout=10)
            return
        r = event.result
        self._record_check("board_check", r.ok, r.text, r.counts)
        self.push_screen(BoardCheckScreen(r.ok, r.text))

    def action_count_revolution(self) -> None:
        """Palette: count one revolution turned by hand (720 expected)."""
        device = self._check_device()
        if device is None:
            return
        # from the newest sample read when asked: the board samples every 25 ms and the
        # stream reads every 50 ms, so a hand that turns at once (the simulated one) can
        # turn before the board's next sample, and a tap holding only the samples read
        # after the ask would hold none from before the turn (it counted 0)
        with self._lock:
            self._tap = queue.Queue()
            if self._newest is not None:
                self._tap.put(self._newest)
        self.requested = None
        done, cancelled = threading.Event(), threading.Event()
        board = device.board  # the virtual MinSeg behind the link, or None at a real board
        hand = getattr(board, "hand_turn", None)  # the virtual MinSeg's simulated hand
        turned: list[float] = []  # board time of the simulated hand's turn, s

        def turn() -> None:
            if hand is not None:
                hand()
                turned.append(float(board.now))

        self.push_screen(RevolutionScreen(done, cancelled, None if hand is None else turn))
        self._revolution(device, self._tap, done, cancelled, lambda: turned[-1] if turned else None)

    @work(thread=True, exclusive=True, group="check", name="revolution")
    def _revolution(
        self,
        device: Device,
        tap: queue.Queue[SampleBatch],
        done: threading.Event,
        cancelled: threading.Event,
        turned_at: Callable[[], float | None],
    ) -> None:
        """Worker: count until the group says the wheel turned once (or closes the dialog);
        ``turned_at()``: board time (s) of the simulated hand's turn, once it has turned."""
        stop = self._stop

        def finished() -> bool:
            return done.is_set() or stop.is_set()

        try:
            result = count_revolution(
                device,
                finished,
                samples=self._taker(tap),
                timeout=REVOLUTION_TIMEOUT,
                turned_at=turned_at,
            )
        except MinsegError as exc:
            self.post_message(RevolutionCounted(None, str(exc)))
            return
        self.post_message(RevolutionCounted(None if cancelled.is_set() else result))

    @on(RevolutionCounted)
    def _revolution_counted(self, event: RevolutionCounted) -> None:
        self._tap = None
        self._watch = NoCountWatch()
        if isinstance(self.screen, RevolutionScreen):
            self.screen.dismiss(None)
        if event.result is None:
            if event.error:
                self.notify(event.error, title="counts per revolution", severity="error")
            return
        r = event.result
        self._record_check("revolution", r.ok, r.text, r.counts)
        self.push_screen(
            BoardCheckScreen(
                r.ok,
                r.text,
                REVOLUTION,
                f"{in_palette('count_revolution')} counts again",
            )
        )

    @on(NoCounts)
    def _no_counts(self, event: NoCounts) -> None:
        """The motor is driven and the count stands: say what to do (Task 5: the meter)."""
        if self._tap is not None:
            return
        device = self._device
        u_now = device.u_req if device is not None else None
        if u_now is None or abs(u_now - event.u) > LEVEL_TOL:
            return  # the motor was stopped or set anew since the stream read the samples
        if self._step_id == "task5":
            text = (
                f"The motor is driven at {event.u:g} V and the encoder counts nothing. If the "
                "wheel does not turn: is the meter on mA, in series across the jumper pins? "
                f"{key_name('board_check')} runs the board check."
            )
        else:
            text = (
                f"The motor is driven at {event.u:g} V and the encoder counts nothing: "
                f"{key_name('board_check')} runs the board check, which says what is wrong."
            )
        self.notify(text, title="no counts", severity="warning", timeout=15)

    # -- what the panels ask for ------------------------------------------------------------
    def set_voltage(self, level: float) -> None:
        """F3: ``level`` V on the motor (the lab screen asks, for its step's panel)."""
        device = self._device
        if device is None:
            self.notify("no device: setting a voltage needs the board or the virtual MinSeg")
            return
        self._command("voltage", partial(device.set_voltage, level))
        self.requested = level
        self.motor = f"{level:g} V"

    @on(RunRequested)
    def _run_requested(self, event: RunRequested) -> None:
        event.stop()
        self.start_run(event.plan)

    def start_run(self, name: str) -> None:
        """Task 10: the procedure (:class:`~minseg_tui.lab.state.task10.Task10`) for plan ``name``:
        motor off now; the stream worker feeds it, and it starts the board's sequence once
        the wheel stands and keeps the run when it ends. The app shows its progress."""
        if self._device is None or self.session is None:
            self.notify(
                "no device: the run needs the board or the virtual MinSeg", severity="error"
            )
            return
        self._ended_unheard()  # else never told: its message would find this run in place
        if self._run_busy:
            self.notify(
                f"a run is in progress; {key_name('stop_motor')} stops it", severity="warning"
            )
            return
        with self.session as s:
            read_only = lab_views.read_only(s) if s.readonly else ""
        if read_only:
            self.notify(
                f"{read_only}: {RUN_REFUSED}",
                severity="error",
            )
            return
        task = Task10.of(self.session, self._device, name)
        try:
            task.begin()
        except MinsegError as exc:
            self.notify(str(exc), title="run", severity="error")
            return
        with self.session as s:
            used = s.response_run()
        self._used_before = used.name if used is not None else None
        self.task10 = task
        self.motor = "off"
        self.requested = None
        self.run_progress = task.progress()

    @on(Task10Moved)
    def _task10_moved(self, event: Task10Moved) -> None:
        """The procedure went on: the board runs the sequence, or it ended."""
        task = event.task
        if task is not self.task10:
            return
        if task.outcome is not None:
            self._task10_ended(task.outcome)
            return
        self._run = task.run
        if task.phase == "square_wave":
            self.motor = motor_words(None, task.plan.high)
            self.requested = None
            self.link = self.link.news_over()  # the last run's "square wave done" (walk 10, D2)
        self.run_progress = task.progress()

    def finish_run(self, why: str = "done", ended_by: str = "") -> None:
        """End Task 10 now (F2, quit; ``why`` ``done`` keeps the run as complete): a wait ends
        without a run, a run being recorded is kept, interrupted by ``ended_by`` (a key of
        :data:`minseg_tui.lab.saving.runs.ENDED_BY`). A run the group chose stays in use; without a
        choice, Tasks 11-15 use the newest complete 25 ms run (:meth:`Session.response_run`)."""
        task = self.task10
        if task is None or not task.active:
            return
        # F2 has switched the motor off; on quit the app switches it off after
        outcome = task.stop("done" if why == "done" else ended_by or "stopped", motor_off=False)
        if outcome is not None:
            self._task10_ended(outcome)

    def _ended_unheard(self) -> None:
        """Task 10's procedure ended on the stream's thread before this thread heard it (on a
        busy machine it lags the board by a whole run): said now, before a key acts on a
        run still held as recording (F5/F6, Ctrl+Q); its message, when it comes, finds it
        told."""
        task = self.task10
        if task is not None and not task.active and task.outcome is not None:
            self._task10_ended(task.outcome)

    def _task10_ended(self, outcome: Outcome) -> None:
        """Say how Task 10 ended, once."""
        if self.task10 is None:
            return
        self.task10, self._run = None, None
        if outcome.problem and outcome.why in ("no run", "not started"):
            self.notify(outcome.problem, title="run", severity="error")
        if not outcome.started:
            if outcome.why == "no run":
                why = f"could not start: {outcome.problem}"
                self.run_progress = RunProgress(0.0, why, recording=False)
                return
            if outcome.why == "turning":
                why = timeout_message()
            elif outcome.event is not None:
                said = EVENT_TEXT.get(outcome.event.kind, outcome.event.message)
                why = f"{said}: the run did not start"
            else:
                why = f"run cancelled ({key_name('stop_motor')}): the motor is off"
            self.run_progress = RunProgress(0.0, why, recording=False)
            self.notify(why, title="Task 10", severity="warning")
            return
        if outcome.event is not None:
            said = EVENT_TEXT.get(outcome.event.kind, "stopped")
        else:
            said = ENDED_WORDS.get(outcome.why, outcome.why)
        info = outcome.info
        if outcome.problem and outcome.why != "not started":
            kept = outcome.problem
        elif info is None:
            kept = f"run {outcome.run}: too few samples, nothing kept"
        else:
            kept = f"run {info.name}: {info.samples} samples kept" + (
                f", {info.dropped} lost on the link" if info.dropped else ""
            )
        self.notify(f"{said}: {kept}", title="Task 10")
        asking = self.screen_stack[-1] if self.screen_stack else None  # none once quitting
        if isinstance(asking, QuitScreen) and asking.choices is RECORDING_CHOICES:
            # Ctrl+Q's question was about this run: it is no longer being recorded
            asking.ask(
                "The run has ended", run_ended_question(f"{said}; {kept}"), RUN_ENDED_CHOICES
            )
        changed = ""
        if self.session is not None:
            with self.session as s:
                changed = own_first.run_changed(s, self._used_before)
        if changed:
            self.notify(changed, title="Tasks 11-15", severity="warning", timeout=20)
        # a run cut short keeps its bar where it stopped (walk 18, D5: it fell to 0 % beside
        # "run steps-1: 95 samples kept")
        reached = self.run_progress.fraction if self.run_progress is not None else 0.0
        self.run_progress = RunProgress(
            1.0 if outcome.why == "done" else reached, f"{said}: {kept}", False
        )
        self.lab_changed.publish(None)

    # -- saving ----------------------------------------------------------------------------
    def _saved_or_not(self) -> None:
        """Show on the status line whether everything is on disk."""
        if self.session is None:
            self.saving = ""
            return
        with self.session as s:
            problem = s.save_problem
            restored = s.take_restored()
        self.saving = problem.line if problem is not None else ""
        if restored:  # a run file deleted by hand while the session is open (s37 attack)
            self.notify("\n".join(restored), title="session", severity="warning", timeout=20)

    def retry_save(self) -> None:
        """Every few seconds while a save fails: try again (a stick put back, space freed)."""
        if self.session is None:
            return
        with self.session as s:
            if s.readonly or s.save_problem is None:
                return
            runs = len(s.runs)
            saved = s.save()
            kept = len(s.runs) != runs  # a run that finished while nothing could be written
        self._saved_or_not()
        if saved:
            self.notify("saved: everything is on disk again", title="session")
        if kept:  # Task 10 and the results show it now, not once the group pages away
            self.lab_changed.publish(None)

    def save_elsewhere(self, folder: str) -> str:
        """Save the session under ``folder`` and go on there; the one line to show."""
        if self.session is None:
            return "no session is open"
        target = Path(folder).expanduser()
        try:
            with self.session as s:
                moved = s.move_to(target)
        except MinsegError as exc:
            return f"✗ {exc}"
        finally:
            self._saved_or_not()
        said = f"saved to {moved.folder}; every change goes there from now on"
        if moved.left_behind:
            said += "; not brought along: " + "; ".join(moved.left_behind)
        self.lab_changed.publish(None)
        return said

    def action_save_elsewhere(self) -> None:
        """Palette: save the session to another folder."""
        if self.session is None:
            self.notify("start or resume a session first", severity="warning")
            return
        with self.session as s:
            readonly, here = s.readonly, s.folder.parent
        if readonly:
            self.notify("this session is open read-only: nothing to save", severity="warning")
            return
        self.push_screen(SaveElsewhereScreen(str(here), self.save_elsewhere))

    def action_correct_names(self) -> None:
        """Palette: correct the group's names (walk 7, D1: a name misspelt at the start)."""
        if self.session is None:
            return
        with self.session as s:
            readonly, names = s.readonly, ", ".join(s.members)
        if readonly:
            self.notify("this session is open read-only: nothing to change", severity="warning")
            return
        self.push_screen(NamesScreen(names, self.correct_names))

    def correct_names(self, typed: str) -> str:
        """Make ``typed`` (names split at commas) the group's names; the one line to show."""
        names = split_names(typed)
        if not names:
            return "✗ type the group's names first, commas between them"
        if self.session is None:
            return "✗ no session is open"
        with self.session as s:
            s.set_members(names)
        self._names_changed()
        return f"the group's names are now {', '.join(names)}"

    def _names_changed(self) -> None:
        """Whatever shows the names is redrawn (the lab's panels rebuild on a change)."""
        self.lab_changed.publish(None)

    async def action_quit(self) -> None:
        """Ctrl+Q: quit, after the keys typed before it; everything typed is stored first.
        While a run is being recorded, ask first: keep recording, or stop it and quit (Ctrl+Q
        again quits). If something is not on disk (a failed save), ask: keep working, save to
        another folder, or quit anyway."""
        await after_typed_keys(self, self._quit)

    def _quit(self) -> None:
        screen = self._lab_screen()
        if screen is not None:
            screen.store_typed()
        self._ended_unheard()  # not asked about a run that has ended
        rec = self.recording
        if rec is not None and not isinstance(self.screen, QuitScreen):
            self.push_screen(
                QuitScreen(
                    recording_question(rec),
                    title="A run is being recorded",
                    choices=RECORDING_CHOICES,
                ),
                self._quit_answer,
            )
            return
        if self.session is not None:
            with self.session as s:
                unsaved = not s.readonly and s.unsaved and not s.save()
                problem = s.save_problem
            self._saved_or_not()
            if unsaved and not isinstance(self.screen, QuitScreen):
                self.push_screen(
                    QuitScreen(problem.line if problem else "not everything is saved"),
                    self._quit_answer,
                )
                return
        self.exit()

    def _quit_answer(self, answer: str | None) -> None:
        if answer == "quit":
            self.exit()
        elif answer == "quit_now":  # the run asked about has ended: quit as Ctrl+Q does
            self._quit()
        elif answer == "move":
            self.action_save_elsewhere()

    # -- actions -------------------------------------------------------------------------
    async def action_help(self) -> None:
        """F1: the keys, after the keys typed before it (those typed after it go to the help)."""
        self._not_past_a_modal()
        await after_typed_keys(self, self._help)

    def _not_past_a_modal(self) -> None:
        """F1 and F8 act behind no modal screen, as Textual keeps the app's other bindings:
        bound with priority, they would reach past it. Skipped, the key goes on to the modal
        screen (F1 on the help closes it, its own binding)."""
        if self.screen.is_modal:
            raise SkipAction()

    def _help(self) -> None:
        self._store_typed()
        screen = self.screen
        if isinstance(screen, HelpScreen):
            return
        if isinstance(screen, LabScreen):
            self.push_screen(HelpScreen(KEYS, lab_now(screen.step.title)))
        else:
            now = CLASS_NOW if isinstance(screen, ClassScreen) else START_NOW
            self.push_screen(HelpScreen(KEYS, now, lab=False))

    async def action_stop_motor(self) -> None:
        """F2: motor off, after the keys typed before it (:meth:`stop_motor`)."""
        await after_typed_keys(self, self.stop_motor)

    def stop_motor(self) -> None:
        """Motor off now; a run in progress keeps what it recorded, and what stands in the
        step's entries is stored."""
        self._store_typed()
        self.motor = "off"
        self.requested = None
        if self._device is not None:
            self._command("stop", self._device.stop)
        self.finish_run("stopped", "stopped")

    def _command(self, what: str, send: Callable[[], object]) -> None:
        """Send a board command (``what``: F2's ``stop`` or F3's ``voltage``) in a worker,
        after those asked before it: the board's answer takes a round trip (seconds on a
        loaded machine), and the keys typed after F2 or F3 must not wait for it (walk 7: a
        PgDn after F2 was applied seconds late, carrying the group past a step)."""
        with self._lock:
            self._commands.append((what, send))
            start, self._sending = not self._sending, True
        if start:
            self._send_commands()

    @work(thread=True, group="board", name="board commands")
    def _send_commands(self) -> None:
        """Worker: send the board commands queued, in order, until none is left."""
        while True:
            with self._lock:
                if not self._commands:
                    self._sending = False
                    unread, self._motor_unread = self._motor_unread, False
                    break
                what, send = self._commands.popleft()
            try:
                send()
            except MinsegError as exc:
                if what == "stop":  # F2's "off" stands (a board without power stops by
                    with self._lock:  # itself): what the link said before it is old news
                        self._motor_unread = False
                self.post_message(CommandFailed(what, str(exc)))
        if unread:
            # what the link said of the motor meanwhile (the stream's MotorKnown, a board
            # event, a failed command) was passed over, and the stream says nothing more until
            # the link changes again: the screen takes the link's motor now
            self.post_message(MotorKnown(None))

    @on(CommandFailed)
    def _command_failed(self, event: CommandFailed) -> None:
        """A board command went wrong: say so; the motor is as the link knows it."""
        if event.what == "stop":
            self.notify(
                f"{event.error} (a board without USB power stops by itself)", severity="warning"
            )
            return
        self.notify(event.error, severity="error")
        self._motor_from_link()  # (not while later commands are on their way)

    def _lab_screen(self) -> LabScreen | None:
        return self.screen if isinstance(self.screen, LabScreen) else None

    def _store_typed(self) -> None:
        """Store what stands in the lab screen's entries (if it is on screen)."""
        screen = self._lab_screen()
        if screen is not None:
            screen.store_typed()

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """A key shown in the footer on some steps only (its binding's action with
        ``IN_FOOTER`` after its name), only on those: elsewhere its own binding runs it, not
        shown. F8 on the class view is that screen's (the class's report), not the session's.
        (The panel keys are the step's form's, which answers for them:
        :meth:`~minseg_tui.ui.screens.lab.StepPane.check_action`.)"""
        if action == "export":
            if isinstance(self.screen, ClassScreen):
                return False  # the class view's F8 writes the class's report (its own binding)
            # a read-only session refuses it: the hidden binding, not the footer's, says why
            return bool(parameters) == self._read_only()
        own = action.removesuffix(IN_FOOTER)
        if own != action and own in FOOTER_ON:
            screen = self._lab_screen()
            shown = screen.step_id_shown if screen is not None else None
            return shown is not None and shown in FOOTER_ON[own]
        return True

    def action_not_here(self, what: str) -> None:
        """A panel key on a step whose panel does not have it (nothing off the lab screen)."""
        if self._lab_screen() is not None:
            self.notify(f"{what} is not part of this step", severity="information")

    def _read_only(self) -> bool:
        """The session open is read-only (nothing written into it, no report either)."""
        if self.session is None:
            return False
        with self.session as s:
            return s.readonly

    async def action_export(self, refused: bool = False) -> None:
        """F8: the report, after the keys typed before it (what they typed stored first).
        ``refused``: its binding in a read-only session, which says why it writes none."""
        self._not_past_a_modal()
        await after_typed_keys(self, self.export)

    def export(self) -> None:
        """Write the report of the session as it stands now (in a worker)."""
        self._store_typed()
        if self.session is None:
            self.notify("start or resume a session first", severity="warning")
            return
        with self.session as s:
            read_only = lab_views.read_only(s) if s.readonly else ""
            s.restore_runs()  # a run file deleted by hand since the last save: written back
            snapshot = s.snapshot()
        self._saved_or_not()
        if read_only:  # walk 15: F8 wrote report.md and report.html into a group's folder
            # opened from the class view ("to look, not to change")
            self.notify(f"{read_only}: no report is written into it", severity="warning")
            return
        self._exports_asked += 1
        self._export(snapshot, self._exports_asked)

    @work(thread=True, exclusive=True, group="export", name="report")
    def _export(self, session: Session, asked: int) -> None:
        """Worker: write the report of ``session``, a frozen snapshot (it computes every
        result and figure), the ``asked``-th export asked for.

        One export writes at a time, and one that a newer export follows writes nothing: a
        worker is cancelled only between its steps, so two F8s ran two writers on the same
        files at once, and the older snapshot, finishing last, could stand on disk (and on
        the screen, its notice last) after the newer one was said written."""
        with self._export_lock:
            if asked != self._exports_asked:
                return  # a newer export was asked for since: it writes the report
            try:
                if self._writer is None:
                    raise MinsegError(NO_WRITER)
                paths = tuple(str(p) for p in self._writer(session))
            except (MinsegError, OSError) as exc:
                said = (  # the system's words and the file, not Python's '[Errno 21] ...'
                    str(exc)
                    if isinstance(exc, MinsegError)
                    else f"cannot write the report ({os_reason(exc)})"
                )
                self.call_from_thread(self.notify, said, title="report", severity="error")
                return
            written = written_in(paths, Path(self.config.sessions))  # resolves: not on the UI
            self.call_from_thread(
                self._exported, paths, written, lab_views.unanswered_line(session)
            )

    def _exported(
        self, paths: tuple[str, ...], written: tuple[str, tuple[str, ...]], unanswered: str = ""
    ) -> None:
        """The report was written to ``paths`` (``written``: where, in words): say where, and
        what is still ``unanswered`` (a line of its own, the notice a warning: the report is
        written all the same). One notice: two stacked covered eleven rows at 80x24 (walk 12's
        D5), and the next F8's replaces it."""
        self.exported = paths
        self.written = written
        folder, names = written
        said = (
            "written: "
            + ", ".join(names[:2])
            + (f" and {len(names) - 2} run CSV" if len(names) > 2 else "")
            + (f", in {folder}" if folder else "")
        )
        self.notify(
            said + (f"\n{unanswered}" if unanswered else ""),
            title="report",
            severity="warning" if unanswered else "information",
            timeout=NOTICE_S,
        )
        self.lab_changed.publish(None)

    def import_log(self) -> None:
        """Palette: go to the model check, where a log recorded elsewhere can be loaded."""
        screen = self._lab_screen()
        if screen is not None:
            screen.go_to("model_check", focus="#import-path")

    def switch_to_virtual(self) -> None:
        """Drop the board and use the virtual MinSeg."""
        self.stop_motor()
        self.workers.cancel_group(self, "stream")
        with self._lock:  # the old stream, were it between a read and the buffer, stops there
            old, self._device = self._device, None
            self.live.clear()
            self._newest = None
        if old is not None:
            try:
                old.close()
            except MinsegError:
                pass
        self.device = None
        self.link = LinkState(event="connecting…")
        self._connect("sim")

    def get_system_commands(self, screen: Screen[Any]) -> Iterable[SystemCommand]:
        """The palette's actions on ``screen``; a step panel's (set a voltage, capture, run)
        only on the steps whose panel has it, as the footer shows its key. Textual's own
        "Keys" (its key panel) is left out: ours, the last, opens F1's list."""
        for command in super().get_system_commands(screen):
            if command.title != PALETTE["help"]:
                yield command
        yield SystemCommand(
            PALETTE["stop_motor"], f"Motor off now ({key_name('stop_motor')})", self.stop_motor
        )
        lab = screen if isinstance(screen, LabScreen) else None
        for action, help_text in (
            ("set_voltage", "Request the next of 2.5/3.5/4.5 V on the board"),
            ("capture", "Mean over the settled window"),
            ("run_square_wave", "Task 10 on the board, 25 ms"),
            ("run_fast", "Task 10 at 5 ms, board-timed"),
            (
                "reveal",
                "Lab assistant: show this step's values before the group answers; the report "
                "says so",
            ),
        ):
            if lab is not None and lab.offers(action):
                yield SystemCommand(
                    PALETTE[action],
                    f"{help_text} ({key_name(action)})",
                    partial(lab.run_panel_key, action),
                )
        yield SystemCommand(
            PALETTE["board_check"],
            "Does the wheel turn when asked, and does the count follow it? "
            f"({key_name('board_check')})",
            self.action_board_check,
        )
        yield SystemCommand(
            PALETTE["count_revolution"],
            "Turn the wheel once by hand: 720 counts expected",
            self.action_count_revolution,
        )
        # a read-only session refuses every change: what would change it is not offered
        if not self._read_only():
            yield SystemCommand(
                PALETTE["export"],
                f"Markdown, HTML and CSV into the session folder ({key_name('export')})",
                self.export,
            )
            yield SystemCommand(
                PALETTE["save_elsewhere"],
                "When it cannot be saved where it is (a full disk, a read-only folder, a "
                "stick pulled out): save it elsewhere and go on there",
                self.action_save_elsewhere,
            )
        if self.session is not None and not self._read_only():
            yield SystemCommand(
                PALETTE["correct_names"],
                "Mend a misspelt name; the report and the resume list show the new names",
                self.action_correct_names,
            )
        if not self._read_only():
            yield SystemCommand(
                PALETTE["import_log"],
                "Load a log recorded elsewhere into the model check (Tasks 11-15 keep their run)",
                self.import_log,
            )
        if self._device is None or self._device.board is None:  # not on the virtual one
            yield SystemCommand(
                PALETTE["switch_to_virtual"],
                "Use the virtual MinSeg instead of the board",
                self.switch_to_virtual,
            )
        if lab is not None and lab.back is not None:
            yield SystemCommand(
                PALETTE["back_to_class"],
                "Close this read-only session; the class view again, at its group (Escape)",
                self.back_to_class,
            )
        yield SystemCommand(PALETTE["help"], f"The help screen ({key_name('help')})", self._help)

    def on_unmount(self) -> None:
        self._stop.set()
        loop = asyncio.get_running_loop()
        for signum in self._signals:
            loop.remove_signal_handler(signum)
        self._signals.clear()
        self.finish_run("app closed", "quit")
        if self._device is not None:
            try:
                self._device.stop()
            except MinsegError:
                pass
            try:
                self._device.close()
            except MinsegError:
                pass
        if self.session is not None:  # saved already; this releases the session's lock
            with self.session as s:
                s.close()


def _as_read(session: Session) -> str:
    """What a session opened read-only from the class view shows: the session as saved at
    its last change, and, while the group has it open in another program, that what it
    does from now on is not shown here (walk 17's D3: the lab assistant looked at an empty
    Summary the group had answered since)."""
    try:
        at = _dt.datetime.fromisoformat(session.modified).astimezone(_dt.UTC)
        when = f" at {at:%Y-%m-%d %H:%M:%S} UTC"
    except ValueError:
        when = ""
    said = f"; as saved{when}"
    pid = lock_owner(session.folder)
    if pid is not None:
        said += (
            f"; the group has it open in another minseg-tui (pid {pid}): what it does from now "
            "on shows when you open it again"
        )
    return said


def make_app(
    config: UiConfig, writer: ReportWriter | None = None, class_writer: ClassWriter | None = None
) -> LabApp:
    """The app for ``config``, on the real device factory; ``writer`` writes the report and
    ``class_writer`` the class's (the CLI hands in
    :func:`minseg_tui.report.write.write_report`, returning its paths, and
    :func:`~minseg_tui.report.write.write_class`)."""
    return LabApp(config, lambda spec: open_device(spec, config.seed), writer, class_writer)
