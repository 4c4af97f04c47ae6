"""Tasks 2-5: the live plots, the steady-state indicator, the requested voltage, the meter."""

from __future__ import annotations

from collections.abc import Callable, Mapping

import numpy as np
from numpy.typing import NDArray
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.reactive import reactive
from textual.widget import Widget

from minseg_tui.lab.content.keys import key_name
from minseg_tui.lab.content.steps import LEVELS, Step
from minseg_tui.lab.views import session as views
from minseg_tui.model.plant import MeterReading
from minseg_tui.quantities import (
    MISSING,
    SPEED_AXIS,
    TIME_AXIS,
    axis_label,
    format_fixed,
    format_spread,
)
from minseg_tui.ui.device import DeviceInfo
from minseg_tui.ui.keys import PanelKeys, key_hint
from minseg_tui.ui.live import LiveBuffer, at_level
from minseg_tui.ui.messages import CaptureRequested, VoltageRequested
from minseg_tui.ui.panels.meter import MODES as METER_MODES
from minseg_tui.ui.panels.meter import MeterPanel
from minseg_tui.ui.widgets.fields import FieldForm, FieldRow
from minseg_tui.ui.widgets.plots import Trace, TracePlot
from minseg_tui.ui.widgets.prose import Prose


class LivePanel(Vertical, PanelKeys):
    """Angle and speed of the last seconds from the ``live`` buffer (redrawn every
    ``refresh`` s; never per sample), the manual's speed beside the timestamp one; the
    steady-state indicator (Task 4); F3 asks for the next voltage, F4 for a capture; the
    multimeter. Shows the app's ``requested`` voltage, ``meter`` reading and ``device``."""

    requested: reactive[float | None] = reactive(None)
    meter: reactive[MeterReading | None] = reactive(None)
    device: reactive[DeviceInfo | None] = reactive(None)

    def __init__(
        self, step: Step, live: LiveBuffer, refresh: float, readonly: bool = False
    ) -> None:
        super().__init__(classes="panel live")
        self.step = step
        self.readonly = readonly
        """A read-only session: F3 and F4 refuse there, so its lines do not offer them."""
        self._live = live
        self._refresh = refresh
        acts = set(step.actions)
        self.levels = tuple(dict.fromkeys(f.level for f in step.fields if f.level is not None))
        if not self.levels and {"capture_omega", "live_velocity"} & acts:
            self.levels = LEVELS  # Task 3 says "set a voltage": F3 steps through the lab's
        self.plots = bool({"live_velocity", "capture_omega"} & acts)
        self._steady = Prose("", id="steady") if self.levels or "capture_omega" in acts else None
        read = {f.unit for f in step.fields if f.unit in METER_MODES}  # what the meter is set to
        self._meter = MeterPanel(read.pop() if len(read) == 1 else "") if "meter" in acts else None

    def compose(self) -> ComposeResult:
        if self.plots:
            with Horizontal(classes="plots"):
                yield TracePlot("angle", TIME_AXIS, axis_label("theta", "rad"), id="plot-angle")
                yield TracePlot("speed", TIME_AXIS, SPEED_AXIS, id="plot-speed")

    def readout(self) -> Widget | None:
        """The lines to keep in sight while typing (the steady-state indicator, the requested
        voltage and keys, the multimeter): the step pane docks them at its bottom."""
        parts = [w for w in (self._steady, self._meter) if w is not None]
        return Readout(*parts) if parts else None

    def on_mount(self) -> None:
        self.redraw()
        if self._refresh > 0:
            self.set_interval(self._refresh, self.redraw)

    def watch_requested(self) -> None:
        t, count, u = self._live.snapshot()
        self._show_steady(t, count, u)

    def watch_meter(self, reading: MeterReading | None) -> None:
        if self._meter is not None:
            self._meter.reading = reading

    def watch_device(self, device: DeviceInfo | None) -> None:
        if self._meter is not None:
            self._meter.device = device

    def redraw(self) -> None:
        """Replot from the buffer and update the indicator (a few times a second)."""
        t, count, u = self._live.snapshot()
        if self.plots:
            v = views.live(t, count)
            if v.x.size:
                self.query_one("#plot-angle", TracePlot).show([Trace(v.x, v.theta, "theta")])
                self.query_one("#plot-speed", TracePlot).show(
                    [Trace(v.x, v.omega, "board time"), Trace(v.x, v.omega_lab, "manual", "dot")]
                )
        self._show_steady(t, count, u)

    def _show_steady(
        self, t: NDArray[np.float64], count: NDArray[np.int64], u: NDArray[np.float64]
    ) -> None:
        if self._steady is None:
            return
        level = "0 V (motor off)" if self.requested is None else f"{self.requested:g} V"
        keys = key_hint("stop_motor")
        if not self.readonly:
            keys = f"{key_hint('set_voltage')} · {keys}"
        if "capture_omega" in self.step.actions:
            s = views.steady(*at_level(t, count, u, self.requested))
            state = "SETTLED" if s.settled else "not settled"
            mean = (
                MISSING
                if s.mean != s.mean
                else f"{format_fixed(s.mean, 2)} {format_spread(s.spread, 'rad/s')}"
            )
            note = "" if s.ready else "(window filling)"
            text = (
                f"steady: {state} · {mean} over {views.CAPTURE_WINDOW:g} s {note}".rstrip()
                + f"\nrequested {level} · {keys}"
                + ("" if self.readonly else f" · {key_hint('capture')}")
            )
        else:
            text = f"requested {level} · {keys}"
        if t.size == 0:
            text = "waiting for samples…\n" + text
        self._steady.update(text)

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """F3 only where there are voltages to set, F4 only on Task 4 (elsewhere the key says
        that it is not part of this step)."""
        if action == "set_voltage":
            return bool(self.levels)
        if action == "capture":
            return "capture_omega" in self.step.actions
        return True

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        return {"set_voltage": self.action_set_voltage, "capture": self.action_capture}

    async def action_set_voltage(self) -> None:
        """F3: ask the lab screen for the next of this step's voltages, and wait until the app
        has set it: the keys typed after F3 see the new level (F4 captures at it)."""
        if not self.levels:
            self.notify("no voltage to set on this step (Tasks 4-5)")
            return
        if self.requested in self.levels:
            level = self.levels[(self.levels.index(self.requested) + 1) % len(self.levels)]
        else:  # motor off: the first voltage whose entries are all empty (walk 14, D8)
            level = self._first_open_level()
        request = VoltageRequested(level)
        if self.screen.post_message(request):
            await request.done.wait()

    def _first_open_level(self) -> float:
        """The first of this step's voltages whose entries on the screen are all empty, else
        the first voltage (walk 14, D8: resumed on Task 4 with 2.5 and 3.5 V done, F3 set
        2.5 V, and F4 there captured the 2.5 V row again)."""
        rows = [r for r in self.screen.query(FieldRow) if r.field.level is not None]
        for level in self.levels:
            mine = [r for r in rows if r.field.level == level]
            if mine and all(r.is_empty for r in mine):
                return level
        return self.levels[0]

    async def action_capture(self) -> None:
        """F4: ask the lab screen to take omega_ss from the settled window (refused while not
        settled), and wait until it did: the keys typed after F4 act on the result."""
        if "capture_omega" not in self.step.actions:
            self.notify("capturing omega_ss is part of Task 4")
            return
        if self.requested is None:
            self.notify(f"set a voltage first ({key_name('set_voltage')})", severity="warning")
            return
        request = CaptureRequested(self.requested)
        if self.screen.post_message(request):
            await request.done.wait()


class Readout(Vertical):
    """The lines docked at the bottom of a step (:meth:`LivePanel.readout`). An entry of the
    step that takes the focus under them (Tab: Textual scrolls a widget into view only when
    it is outside the step, and these lines lie inside it) is scrolled up above them: its
    whole row when it fits, else its box.

    The lift is made on the screen's layouts (:meth:`_laid_out`, called as each is made, the
    regions fresh), never from a callback deferred to after a refresh: such a callback may
    run before a layout still to come, and on Task 5 '30,1 Enter' typed in one burst lifted
    the 3.5 V entry from where it lay before the 2.5 V row's hint went (by 4 rows where 2
    show it whole). A layout that moves the entry places it again: from the scroll the step
    had before the lift while the step is still where the last lift left it (a lift read
    from a layout that a later one replaced is undone down to that), else from where the
    step is (another placing or the group moved it: never lowered)."""

    def __init__(self, *parts: Widget) -> None:
        super().__init__(*parts, classes="readout")
        self._lifting: Widget | None = None
        """The box (or focused widget) the lift is for (None: no lift asked yet)."""
        self._lift_from = 0
        """The step's scroll before the lift for :attr:`_lifting` began."""
        self._lifted: int | None = None
        """The scroll the last lift left the step at (None: none made for it yet)."""

    def on_mount(self) -> None:
        self.watch(self.screen, "focused", self._moved, init=False)
        if isinstance(self.parent, FieldForm):
            self.watch(self.parent, "current", self._moved, init=False)
        self.screen.screen_layout_refresh_signal.subscribe(self, self._laid_out, immediate=True)

    def on_resize(self) -> None:
        """The lines changed height (a line wrapped, or the "waiting for samples" line went):
        lift the focused entry again, out from under them."""
        self._moved()

    def _moved(self) -> None:
        """The focus moved, or these lines changed height: the lift comes with the next
        layout, which is asked for (a move of the focus alone lays nothing out)."""
        target = self._target()
        if target is None:
            return
        if target is not self._lifting:
            self._lifting, self._lifted = target, None
        self.screen.refresh(layout=True)

    def _laid_out(self, _: object) -> None:
        step = self.parent
        target = self._target()
        if target is None or target is not self._lifting or not isinstance(step, FieldForm):
            return
        if not step.follows_keys:  # the group scrolled away: the step stays where they put it
            self._lifting = None
            return
        now = round(step.scroll_y)
        if self._lifted != now:  # no lift of ours made yet, or the step was moved since
            self._lift_from = now
        y = self._lift_to(step, target, self._lift_from)
        if y is not None and y != now:
            with step.placing():  # a placing of the step's entry (the step's own follow it)
                step.scroll_to(y=y, animate=False, immediate=True)
        self._lifted = round(step.scroll_y)

    def _target(self) -> Widget | None:
        """Where the focus is in the step: the box of its form's current row, or a focused
        widget in it (None: elsewhere, or these lines left with their step: a lift deferred
        to after a refresh comes after PgDn PgDn in one burst took the step away)."""
        if not self.is_attached:
            return None
        step = self.parent
        focused = self.screen.focused
        if isinstance(step, FieldForm) and focused is step:
            return step.keys_box
        if focused is None or step is None or step not in focused.ancestors:
            return None
        return focused

    def _lift_to(self, step: FieldForm, focused: Widget, base: int) -> int | None:
        """The scroll that shows ``focused``'s whole row above these lines, else its box, and
        below the step's heading, at least ``base`` (None: the layout does not show them)."""
        if not (focused.is_attached and self.is_attached):
            return None
        row = next(
            (
                a
                for a in focused.ancestors_with_self
                if isinstance(a, Widget) and a.has_class("field")
            ),
            focused,
        )
        # Worked out in the step's content (the row's place in it does not change as the
        # step scrolls), from the layout just made.
        view = step.scrollable_content_region
        drawn = row.region
        if not (drawn and self.region) or row.parent is not step:
            return None
        room = self.region.y - view.y  # the step's rows above these lines
        for shown in (row, focused):
            top = row.virtual_region.y + shown.region.y - drawn.y
            y = top + shown.region.height - room  # the least scroll that shows it whole
            if y <= base:
                return base
            # below the step's heading, which covers its top while it is scrolled down
            if top - y >= step.heading_rows:
                return y
        return base
