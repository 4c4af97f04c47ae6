"""The Textual app: start screen, the lab screen, keys, command palette, the device worker.

:func:`make_app` is the one way to build it (the CLI and the tests share it). Widgets only
render; this module moves data between the device/lab layers (through
:mod:`minseg_tui.ui.ports`) and the screens.
"""

from __future__ import annotations

import datetime as _dt
import threading
from collections.abc import Callable, Iterable

from textual import on, work
from textual.app import App, SystemCommand
from textual.binding import Binding
from textual.screen import Screen
from textual.widget import Widget
from textual.worker import get_current_worker

from minseg_tui.errors import MinsegError
from minseg_tui.ui.commands import StepCommands
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.live import LiveBuffer
from minseg_tui.ui.messages import LinkEvent, SamplesArrived
from minseg_tui.ui.ports import Device, Lab, Store
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.status import DeviceStatus

KEYS: list[tuple[str, str]] = [
    ("F1", "this help"),
    ("F2", "STOP the motor (works everywhere, always)"),
    ("F3", "set the step's voltage on the board"),
    ("F4", "capture omega_ss over the settled window"),
    ("F5", "run the step sequence (Task 10)"),
    ("F6", "run it fast: 5 ms board-timed samples"),
    ("F7", "show the formula behind the table cell"),
    ("F8", "export the report"),
    ("PgDn/PgUp", "next / previous step (also Ctrl+N / Ctrl+B)"),
    ("Ctrl+L", "jump to the list of steps"),
    ("Tab", "next field; Enter stores what you typed"),
    ("Ctrl+P", "command palette (go to step, capture, stop...)"),
    ("Ctrl+Q", "quit (the session is already saved)"),
]


class LabApp(App[None]):
    """minseg-tui: the DC-motor lab, step by step, on the board or the virtual MinSeg."""

    TITLE = "minseg-tui"
    CSS_PATH = "lab.tcss"
    COMMANDS = App.COMMANDS | {StepCommands}
    BINDINGS = [
        Binding("f1", "help", "Help"),
        Binding("f2", "stop_motor", "STOP", priority=True),
        Binding("f3", "set_voltage", "Set V"),
        Binding("f4", "capture", "Capture"),
        Binding("f5", "run_steps", "Steps", show=False),
        Binding("f6", "run_fast", "Fast", show=False),
        Binding("f7", "formula", "Formula", show=False),
        Binding("f8", "export", "Export", show=False),
    ]

    def __init__(self, config: UiConfig, store: Store, open_device: Callable[[str], Device]) -> None:
        super().__init__()
        self.config = config
        self.store = store
        self._open_device = open_device
        self.device: Device | None = None
        self.lab: Lab | None = None
        self.live = LiveBuffer()
        self.motor = "off"
        self.last_event = ""
        self._stop = threading.Event()
        self.run_name: str | None = None
        self.run_duration = 0.0
        self.run_period = 0.025
        if not config.animations:
            self.animation_level = "none"

    # -- start-up ---------------------------------------------------------------------
    def on_mount(self) -> None:
        try:
            self.device = self._open_device(self.config.device)
        except MinsegError as exc:
            self.notify(str(exc), title="device", severity="error")
        today = self.config.today or _dt.date.today().isoformat()
        self.push_screen(StartScreen(self.store.list(), today))
        if self.device is not None:
            self._stream()

    def on_screen_resume(self) -> None:
        self.refresh_status()

    def refresh_status(self) -> None:
        """Copy device info, link health and motor state into every status line."""
        info = self.device.info if self.device else None
        health = self.device.health() if self.device else None
        for screen in self.screen_stack:
            for w in screen.query(DeviceStatus):
                w.info, w.health, w.motor = info, health, self.motor

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
            self.notify(str(exc), title="session", severity="error")
            return
        self.switch_screen(LabScreen(self.lab))
        self.call_after_refresh(self.refresh_status)

    # -- the stream ---------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="stream", name="device stream")
    def _stream(self) -> None:
        """Worker thread: drain the device into the bounded buffer and say so (coalesced)."""
        worker = get_current_worker()
        device = self.device
        assert device is not None
        while not worker.is_cancelled and not self._stop.is_set():
            try:
                batch = device.read(0.05)
            except MinsegError as exc:
                self.post_message(LinkEvent("LOST", str(exc)))
                return
            if len(batch.t):
                self.live.extend(batch)
                self.post_message(SamplesArrived(device.health(), self.live.total))
            for ev in batch.events:
                self.post_message(LinkEvent(ev))

    @on(SamplesArrived)
    def _samples(self, event: SamplesArrived) -> None:
        for w in self.screen.query(DeviceStatus):
            w.health = event.health
        if self.run_name is not None:
            self._show_progress()

    def _show_progress(self) -> None:
        from minseg_tui.ui.panels import StepRunPanel

        n = self.live.recorded
        period = self.run_period
        fraction = min(1.0, n * period / self.run_duration) if self.run_duration > 0 else 0.0
        for panel in self.screen.query(StepRunPanel):
            panel.progress(fraction, f"recording {self.run_name}: {n} samples, {n * period:.1f} of {self.run_duration:.1f} s")

    def start_run(self, name: str, period: float) -> None:
        """Task 10: start the board's step sequence for plan ``name`` and record it."""
        from minseg_tui.lab.steps import step

        if self.device is None or self.lab is None:
            self.notify("no device", severity="error")
            return
        if self.run_name is not None:
            self.notify("a run is in progress; F2 stops it", severity="warning")
            return
        plan = dict(step("task10").plans)[name]
        self.run_name, self.run_duration, self.run_period = name, plan.duration, plan.ts
        self.live.start_recording()
        self.device.run_steps(plan.low, plan.high, plan.half_period, plan.periods, plan.ts)
        self.motor = f"steps {plan.low:g}/{plan.high:g} V"
        self.refresh_status()

    def finish_run(self, complete: bool) -> None:
        """The run ended (STEPDONE) or was stopped: keep what was recorded."""
        if self.run_name is None:
            return
        name, self.run_name = self.run_name, None
        t, count, u = self.live.stop_recording()
        if self.lab is not None and t.size:
            try:
                self.lab.store_run(name, t, count, u, complete)
            except MinsegError as exc:
                self.notify(str(exc), title="run", severity="error")
        self.notify(f"run {name} {'done' if complete else 'stopped'}: {t.size} samples kept")
        self.entry_stored(name)

    @on(LinkEvent)
    def _link_event(self, event: LinkEvent) -> None:
        self.last_event = event.kind
        if event.kind in ("WDOG", "STEPDONE", "LOST"):
            self.motor = "off"
            self.finish_run(complete=event.kind == "STEPDONE")
        self.refresh_status()
        if event.kind in ("WDOG", "LOST"):
            self.notify(event.detail or "the board stopped the motor (watchdog)", severity="warning")

    # -- what a step shows besides its entries -------------------------------------------
    def step_panel(self, step: object) -> Widget | None:
        """The live/table/run panel of a step (None for steps that only take entries)."""
        from minseg_tui.ui.panels import panel_for

        return panel_for(self, step)  # type: ignore[arg-type]

    def entry_stored(self, key: str) -> None:
        """An entry was saved: panels that depend on entries recompute."""
        for screen in self.screen_stack:
            for w in screen.query(".recompute"):
                w.recompute()  # type: ignore[attr-defined]

    def refresh_fields(self) -> None:
        """Show in every entry row what the lab now holds (after a capture)."""
        from minseg_tui.ui.widgets.fields import FieldRow

        if self.lab is None:
            return
        for row in self.screen.query(FieldRow):
            row.refresh_from_lab(self.lab.text(row.field.key), self.lab.result(row.field.key))

    # -- actions -------------------------------------------------------------------------
    def action_help(self) -> None:
        if not isinstance(self.screen, HelpScreen):
            self.push_screen(HelpScreen(KEYS))

    def action_stop_motor(self) -> None:
        if self.device is not None:
            self.device.stop()
        self.motor = "off"
        self.finish_run(complete=False)
        self.refresh_status()

    def _lab_screen(self) -> LabScreen | None:
        return self.screen if isinstance(self.screen, LabScreen) else None

    def _panel_action(self, name: str) -> None:
        screen = self._lab_screen()
        if screen is None:
            return
        for w in screen.query(".panel"):
            handler = getattr(w, name, None)
            if handler is not None:
                handler()
                return
        self.notify("nothing to do for this key on this step", severity="information")

    def action_set_voltage(self) -> None:
        self._panel_action("set_voltage")

    def action_capture(self) -> None:
        self._panel_action("capture")

    def action_run_steps(self) -> None:
        self._panel_action("run_steps")

    def action_run_fast(self) -> None:
        self._panel_action("run_fast")

    def action_formula(self) -> None:
        self._panel_action("formula")

    def action_export(self) -> None:
        if self.lab is None:
            return
        try:
            paths = self.lab.export()
        except MinsegError as exc:
            self.notify(str(exc), title="report", severity="error")
            return
        self.notify("report written: " + ", ".join(str(p) for p in paths), title="report")

    def go_to_step(self, step_id: str) -> None:
        """Jump to a step (from the palette)."""
        screen = self._lab_screen()
        if screen is not None:
            screen.go_to(step_id)

    def switch_to_virtual(self) -> None:
        """Drop the board and use the virtual MinSeg."""
        self.action_stop_motor()
        self.workers.cancel_group(self, "stream")
        if self.device is not None:
            self.device.close()
        self.device = self._open_device("sim")
        self.live.clear()
        self._stream()
        self.refresh_status()

    def get_system_commands(self, screen: Screen) -> Iterable[SystemCommand]:
        yield from super().get_system_commands(screen)
        yield SystemCommand("Stop motor", "Motor off now (F2)", self.action_stop_motor)
        yield SystemCommand("Capture omega_ss", "Mean over the settled window (F4)", self.action_capture)
        yield SystemCommand("Set step voltage", "Request this step's voltage on the board (F3)", self.action_set_voltage)
        yield SystemCommand("Run step sequence", "Task 10 on the board (F5)", self.action_run_steps)
        yield SystemCommand("Run fast step sequence", "5 ms board-timed sampling (F6)", self.action_run_fast)
        yield SystemCommand("Export report", "Markdown, HTML and CSV into the session folder (F8)", self.action_export)
        yield SystemCommand("Switch to virtual board", "Use the virtual MinSeg instead of the board", self.switch_to_virtual)
        yield SystemCommand("Help", "The keys (F1)", self.action_help)

    def on_unmount(self) -> None:
        self._stop.set()
        if self.device is not None:
            try:
                self.device.stop()
                self.device.close()
            except MinsegError:
                pass


def make_app(config: UiConfig) -> LabApp:
    """The app for ``config``, wired to the real session store and device factory."""
    from minseg_tui.ui.backend import open_device, open_store

    return LabApp(config, open_store(config), lambda spec: open_device(spec, config))
