"""The Textual app: start screen, the lab screen, keys, command palette, the device worker.

:func:`make_app` is the one way to build it (the CLI and the tests share it). Widgets only
render; this module moves data between the device/lab layers (through
:mod:`minseg_tui.ui.ports`) and the screens. The device is opened in a worker; a second
worker drains it into the bounded live buffer (and into the run being recorded) and posts
coalesced messages, so the event loop never waits on the board.
"""

from __future__ import annotations

import datetime as _dt
import threading
import time
from collections.abc import Callable, Iterable

from textual import on, work
from textual.app import App, SystemCommand
from textual.binding import Binding
from textual.screen import Screen
from textual.widget import Widget
from textual.worker import get_current_worker

from minseg_tui.errors import MinsegError
from minseg_tui.lab.steps import step as lab_step
from minseg_tui.ui.backend import ReportWriter
from minseg_tui.ui.commands import StepCommands
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.live import LiveBuffer
from minseg_tui.ui.messages import DeviceOpened, LinkEvent, SamplesArrived
from minseg_tui.ui.ports import Device, Event, Lab, Meter, Recording, Store
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.status import DeviceStatus

KEYS: list[tuple[str, str]] = [
    ("F1", "this help"),
    ("F2", "STOP the motor (works everywhere, always)"),
    ("F3", "set the next voltage 2.5/3.5/4.5 V (Task 4/5)"),
    ("F4", "capture omega_ss over the settled window"),
    ("F5", "run the step sequence (Task 10)"),
    ("F6", "run it fast: 5 ms board-timed samples"),
    ("F7", "the formula behind the table cell"),
    ("F8", "export the report (Markdown, HTML, CSV)"),
    ("F9", "zoom the step log: next step, whole log (Tasks 11-15)"),
    ("Alt+← →", "previous / next step of the log (Tasks 11-15)"),
    ("Ctrl+← →", "the same, outside a text entry"),
    ("[ ] z", "the same on the focused plot; z zooms"),
    ("PgDn/PgUp", "next / previous lab step (Ctrl+N / Ctrl+B)"),
    ("Ctrl+L", "the list of steps (Ctrl+T hides it)"),
    ("Tab", "next field; Enter stores what you typed"),
    ("Space", "tick an answer (summary questions)"),
    ("Ctrl+P", "command palette (go to a step, pick the run, stop...)"),
    ("Ctrl+Q", "quit (the session is already saved)"),
]

EVENT_TEXT: dict[str, str] = {
    "disconnected": "board disconnected — everything recorded is kept",
    "connected": "board reconnected",
    "silent": "board silent — no data",
    "alive": "board answers again",
    "watchdog": "watchdog stopped the motor",
    "boot": "board restarted — motor off",
}
"""What the status line says at once for a link event (``error`` shows the link's own line)."""

PANEL_KEYS: tuple[tuple[str, str, str, str], ...] = (
    ("f3", "set_voltage", "Set V", "setting a voltage"),
    ("f4", "capture", "Capture", "capturing omega_ss"),
    ("f5", "run_steps", "Run", "the step experiment"),
    ("f6", "run_fast", "Run 5 ms", "the fast step experiment"),
    ("f7", "formula", "Formula", "a table formula"),
    ("f9", "zoom_next", "Zoom", "zooming the step log"),
    ("alt+left,ctrl+left", "pick_prev", "", "moving through the step log"),
    ("alt+right,ctrl+right", "pick_next", "Step", "moving through the step log"),
)
"""Keys that act on the current step's panel: (keys, the panel's method, footer label, what it
is; no label: not in the footer). The footer shows a key on the steps whose panel offers the
method; elsewhere the key says that it is not part of this step. None is printable, so no key
is taken from typing in an entry (Ctrl+arrows stay the entry's word moves)."""

RUN_ENDS = frozenset({"stepdone", "disconnected", "watchdog", "boot", "error"})
"""Link events after which a run being recorded takes no more samples."""

LAB_PERIOD = 0.025
"""Sample period restored after a fast run, s (the manual's)."""


class LabApp(App[None]):
    """minseg-tui: the DC-motor lab, step by step, on the board or the virtual MinSeg."""

    TITLE = "minseg-tui"
    CSS_PATH = "lab.tcss"
    COMMANDS = App.COMMANDS | {StepCommands}
    BINDINGS = [
        Binding("f1", "help", "Help"),
        Binding("f2", "stop_motor", "STOP", priority=True),
        Binding("f8", "export", "Export"),
        *[
            Binding(keys, f"panel('{method}')", label, show=bool(label))
            for keys, method, label, _ in PANEL_KEYS
        ],
        *[Binding(keys, f"not_here('{what}')", show=False) for keys, _, _, what in PANEL_KEYS],
    ]

    def __init__(
        self, config: UiConfig, store: Store, open_device: Callable[[str], Device]
    ) -> None:
        super().__init__()
        self.config = config
        self.store = store
        self._open_device = open_device
        self.device: Device | None = None
        self.lab: Lab | None = None
        self.live = LiveBuffer()
        self.motor = "off"
        self.requested: float | None = None
        """The voltage last set with F3 (V; None: none, or the motor is off or runs steps)."""
        self.event_text = "connecting…"
        self.recording: Recording | None = None
        self.meter_reading: Meter | None = None
        self.meter_wanted = 0
        self.exported: tuple[str, ...] = ()
        self._stop = threading.Event()
        if not config.animations:
            self.animation_level = "none"

    # -- start-up ---------------------------------------------------------------------
    def on_mount(self) -> None:
        today = self.config.today or _dt.date.today().isoformat()
        self.push_screen(StartScreen(self.store.list(), today))
        self._connect(self.config.device)

    @work(thread=True, exclusive=True, group="connect", name="open device")
    def _connect(self, spec: str) -> None:
        """Worker: open (and handshake) the device; a real board takes up to 2.5 s."""
        try:
            device = self._open_device(spec)
        except MinsegError as exc:
            self.post_message(DeviceOpened(None, str(exc)))
            return
        self.post_message(DeviceOpened(device, ""))

    @on(DeviceOpened)
    def _opened(self, event: DeviceOpened) -> None:
        if event.device is None:
            self.event_text = "no device: " + event.error
            self.notify(event.error, title="device", severity="error", timeout=10)
        else:
            self.device = event.device
            self.event_text = ""
            self._stream()
        self.refresh_status()

    def on_screen_resume(self) -> None:
        self.refresh_status()

    def refresh_status(self) -> None:
        """Copy device info, link health, the last event and the motor into every status line."""
        info = self.device.info if self.device else None
        health = self.device.health() if self.device else None
        for screen in self.screen_stack:
            for w in screen.query(DeviceStatus):
                w.info, w.health, w.motor, w.event = info, health, self.motor, self.event_text

    @on(StartScreen.NewSession)
    def _new(self, event: StartScreen.NewSession) -> None:
        self._enter_lab(lambda: self.store.new(event.members, event.date))

    @on(StartScreen.Resume)
    def _resume(self, event: StartScreen.Resume) -> None:
        self._enter_lab(lambda: self.store.open(event.path))

    def _enter_lab(self, get: Callable[[], Lab]) -> None:
        try:
            self.lab = get()
        except MinsegError as exc:
            self.notify(str(exc), title="session", severity="error", timeout=10)
            return
        self.switch_screen(LabScreen(self.lab))
        self.call_after_refresh(self.refresh_status)
        recovered = getattr(self.lab, "recovered", [])
        if recovered:
            self.notify("kept after a crash: " + ", ".join(recovered), title="session")

    # -- the stream ---------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="stream", name="device stream")
    def _stream(self) -> None:
        """Worker thread: drain the device into the live buffer and the run being recorded (and
        flush the run to disk); say so with one coalesced message per read; poll the virtual
        multimeter."""
        worker = get_current_worker()
        device = self.device
        assert device is not None
        next_meter = 0.0
        while not worker.is_cancelled and not self._stop.is_set():
            try:
                batch = device.read(0.05)
            except MinsegError as exc:
                self.post_message(LinkEvent(Event("error", str(exc))))
                return
            if len(batch):
                self.live.extend(batch)
                rec = self.recording
                if rec is not None:
                    rec.append(batch)
                    if any(ev.kind in RUN_ENDS for ev in batch.events):
                        rec.end()
                self.post_message(SamplesArrived(device.health(), self.live.total))
            rec = self.recording
            if rec is not None:  # the run's samples reach the disk within a second (the flush
                rec.tick()  # fsyncs: here, never on the UI thread)
            for ev in batch.events:
                self.post_message(LinkEvent(ev))
            now = time.monotonic()
            if self.meter_wanted and device.info.virtual and now >= next_meter:
                next_meter = now + 0.25
                try:
                    self.meter_reading = device.meter()
                except MinsegError:
                    self.meter_reading = None

    @on(SamplesArrived)
    def _samples(self, event: SamplesArrived) -> None:
        for w in self.screen.query(DeviceStatus):
            w.health = event.health
        if self.recording is not None:
            self._show_progress()

    def _show_progress(self) -> None:
        from minseg_tui.ui.panels import StepRunPanel

        rec = self.recording
        if rec is None:
            return
        duration = rec.plan.duration  # type: ignore[attr-defined]
        fraction = min(1.0, rec.elapsed / duration) if duration > 0 else 0.0
        for panel in self.screen.query(StepRunPanel):
            panel.progress(
                fraction,
                f"recording {rec.name}: {rec.samples} samples, "
                f"{rec.elapsed:.1f} of {duration:.1f} s · F2 stops",
            )

    def start_run(self, name: str) -> None:
        """Task 10: start the board's step sequence for plan ``name`` and record it."""
        if self.device is None or self.lab is None:
            self.notify(
                "no device: the run needs the board or the virtual MinSeg", severity="error"
            )
            return
        if self.recording is not None:
            self.notify("a run is in progress; F2 stops it", severity="warning")
            return
        plan = dict(lab_step("task10").plans)[name]
        try:
            self.device.stop()
            self.device.set_period(plan.ts)
            self.recording = self.lab.start_recording(name)
            self.device.run_steps(plan.low, plan.high, plan.half_period, plan.periods)
        except MinsegError as exc:
            self.notify(str(exc), title="run", severity="error")
            self.finish_run("could not start")
            return
        self.motor = f"steps 0/{plan.high:g} V"
        self.requested = None
        self.refresh_status()
        self._show_progress()

    def finish_run(self, why: str) -> None:
        """The run ended (done, stopped, board lost): keep what was recorded."""
        rec, self.recording = self.recording, None
        if rec is None or self.lab is None:
            return
        try:
            kept = self.lab.finish_recording(rec)
        except MinsegError as exc:
            kept = str(exc)
        self.notify(f"{why}: {kept}", title="Task 10")
        from minseg_tui.ui.panels import StepRunPanel

        for panel in self.screen.query(StepRunPanel):
            panel.progress(1.0 if why == "done" else 0.0, f"{why}: {kept}")
        if self.device is not None and rec.plan.ts != LAB_PERIOD:  # type: ignore[attr-defined]
            try:
                self.device.set_period(LAB_PERIOD)
            except MinsegError:
                pass
        self.entry_stored("run")

    @on(LinkEvent)
    def _link_event(self, event: LinkEvent) -> None:
        kind = event.event.kind
        if kind == "step":
            return
        if kind == "stepdone":
            self.motor = "off"
            self.requested = None
            self.finish_run("done")
        elif kind in ("disconnected", "watchdog", "boot", "error"):
            self.motor = "off"
            self.requested = None
            if self.recording is not None:
                self.finish_run(EVENT_TEXT.get(kind, "stopped"))
        if kind == "connected" and self.event_text == "":
            return
        self.event_text = EVENT_TEXT.get(kind, event.event.message)
        self.refresh_status()
        if kind in ("disconnected", "watchdog", "error"):
            self.notify(
                self.event_text if kind != "error" else event.event.message,
                severity="warning",
                timeout=8,
            )

    # -- what a step shows besides its entries -------------------------------------------
    def step_panel(self, step: object) -> Widget | None:
        """The live/table/run panel of a step (None for steps that only take entries)."""
        from minseg_tui.ui.panels import panel_for

        return panel_for(self, step)  # type: ignore[arg-type]

    def entry_stored(self, key: str) -> None:
        """An entry was saved: panels that depend on entries recompute; the navigator marks."""
        for screen in self.screen_stack:
            for w in screen.query(".recompute"):
                w.recompute()  # type: ignore[attr-defined]
            if isinstance(screen, LabScreen):
                screen.refresh_marks()

    def focus_after(self, key: str) -> None:
        """Put the cursor in the entry that follows field ``key`` on the step (a form's flow)."""
        if isinstance(self.screen, LabScreen):
            self.screen.focus_after(key)

    def refresh_fields(self) -> None:
        """Show in every entry row what the lab now holds (after a capture)."""
        from minseg_tui.ui.widgets.fields import FieldRow

        if self.lab is None:
            return
        for row in self.screen.query(FieldRow):
            row.refresh_from_lab(self.lab.text(row.field.key), self.lab.result(row.field.key))
        self.entry_stored("capture")

    # -- actions -------------------------------------------------------------------------
    def action_help(self) -> None:
        if not isinstance(self.screen, HelpScreen):
            self.push_screen(HelpScreen(KEYS))

    def action_stop_motor(self) -> None:
        """F2: motor off now; a run in progress keeps what it recorded."""
        self.motor = "off"
        self.requested = None
        if self.device is not None:
            try:
                self.device.stop()
            except MinsegError as exc:
                self.notify(
                    f"{exc} (a board without USB power stops by itself)", severity="warning"
                )
        if self.recording is not None:
            self.finish_run("stopped")
        self.refresh_status()

    def _lab_screen(self) -> LabScreen | None:
        return self.screen if isinstance(self.screen, LabScreen) else None

    def _panel_method(self, name: str) -> Callable[[], None] | None:
        """The current step panel's method ``name``, or None (no lab screen, or not this step)."""
        screen = self._lab_screen()
        panel = None if screen is None else screen.panel
        handler = getattr(panel, name, None)
        offers = getattr(panel, "offers", None)
        return None if handler is None or (offers is not None and not offers(name)) else handler

    def _panel_action(self, name: str, what: str) -> None:
        handler = self._panel_method(name)
        if handler is not None:
            handler()
        elif self._lab_screen() is not None:
            self.action_not_here(what)

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """A panel key is live (and in the footer) only on the steps whose panel has it."""
        if action == "panel":
            return self._panel_method(str(parameters[0])) is not None
        return True

    def action_panel(self, name: str) -> None:
        handler = self._panel_method(name)
        if handler is not None:
            handler()

    def action_not_here(self, what: str) -> None:
        if self._lab_screen() is not None:
            self.notify(f"{what} is not part of this step", severity="information")

    def action_set_voltage(self) -> None:
        self._panel_action("set_voltage", "setting a voltage")

    def action_capture(self) -> None:
        self._panel_action("capture", "capturing omega_ss")

    def action_run_steps(self) -> None:
        self._panel_action("run_steps", "the step experiment")

    def action_run_fast(self) -> None:
        self._panel_action("run_fast", "the fast step experiment")

    def action_formula(self) -> None:
        self._panel_action("formula", "a table formula")

    def action_zoom_next(self) -> None:
        self._panel_action("zoom_next", "zooming the step log")

    def action_export(self) -> None:
        if self.lab is None:
            self.notify("start or resume a session first", severity="warning")
            return
        self._export()

    @work(thread=True, exclusive=True, group="export", name="report")
    def _export(self) -> None:
        """Worker: write the report (it computes every result and figure)."""
        lab = self.lab
        assert lab is not None
        try:
            paths = lab.export()
        except (MinsegError, OSError) as exc:
            self.call_from_thread(self.notify, str(exc), title="report", severity="error")
            return
        self.call_from_thread(self._exported, paths)

    def _exported(self, paths: tuple[str, ...]) -> None:
        self.exported = paths
        self.notify(
            "written: "
            + ", ".join(paths[:2])
            + (f" and {len(paths) - 2} run CSV" if len(paths) > 2 else ""),
            title="report",
            timeout=10,
        )
        self.entry_stored("export")

    def go_to_step(self, step_id: str) -> None:
        """Jump to a step (from the palette)."""
        screen = self._lab_screen()
        if screen is not None:
            screen.go_to(step_id)

    def use_run(self, name: str | None) -> None:
        """Palette: the run Tasks 11-15 and the model check use (None: the latest)."""
        if self.lab is None:
            return
        try:
            said = self.lab.use_run(name)
        except MinsegError as exc:
            self.notify(str(exc), severity="error")
            return
        self.notify(said, title="runs")
        self.entry_stored("run")

    def import_log(self) -> None:
        """Palette: go to the model check, where a log recorded elsewhere can be loaded."""
        self.go_to_step("model_check")
        self.call_after_refresh(self._focus_import)

    def _focus_import(self) -> None:
        for w in self.screen.query("#import-path"):
            w.focus()

    def switch_to_virtual(self) -> None:
        """Drop the board and use the virtual MinSeg."""
        self.action_stop_motor()
        self.workers.cancel_group(self, "stream")
        old, self.device = self.device, None
        if old is not None:
            try:
                old.close()
            except MinsegError:
                pass
        self.live.clear()
        self.event_text = "connecting…"
        self.refresh_status()
        self._connect("sim")

    def get_system_commands(self, screen: Screen) -> Iterable[SystemCommand]:
        yield from super().get_system_commands(screen)
        yield SystemCommand("Stop motor", "Motor off now (F2)", self.action_stop_motor)
        yield SystemCommand(
            "Set step voltage",
            "Request the next of 2.5/3.5/4.5 V on the board (F3)",
            self.action_set_voltage,
        )
        yield SystemCommand(
            "Capture omega_ss", "Mean over the settled window (F4)", self.action_capture
        )
        yield SystemCommand(
            "Run step sequence", "Task 10 on the board, 25 ms (F5)", self.action_run_steps
        )
        yield SystemCommand(
            "Run fast step sequence", "Task 10 at 5 ms, board-timed (F6)", self.action_run_fast
        )
        yield SystemCommand(
            "Export report",
            "Markdown, HTML and CSV into the session folder (F8)",
            self.action_export,
        )
        yield SystemCommand(
            "Import a step log",
            "Load a log recorded elsewhere into the model check",
            self.import_log,
        )
        yield SystemCommand(
            "Switch to virtual board",
            "Use the virtual MinSeg instead of the board",
            self.switch_to_virtual,
        )
        yield SystemCommand("Keys", "The help screen (F1)", self.action_help)

    def on_unmount(self) -> None:
        self._stop.set()
        if self.recording is not None:
            self.finish_run("app closed")
        if self.device is not None:
            try:
                self.device.stop()
            except MinsegError:
                pass
            try:
                self.device.close()
            except MinsegError:
                pass
        if self.lab is not None:  # saved already; this releases the session's lock
            self.lab.close()


def make_app(config: UiConfig, writer: ReportWriter | None = None) -> LabApp:
    """The app for ``config``, wired to the real session store and device factory; ``writer``
    writes the report (the CLI hands in :func:`minseg_tui.report.write.write_report`)."""
    from minseg_tui.ui.backend import open_device, open_store

    return LabApp(config, open_store(config, writer), lambda spec: open_device(spec, config))
