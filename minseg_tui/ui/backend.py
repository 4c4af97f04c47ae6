"""Adapters from the real layers to the UI's ports: the lab session and store, the device.

No arithmetic here: every number comes from :mod:`minseg_tui.lab.session` (which uses
:mod:`minseg_tui.model.identify`) or :mod:`minseg_tui.signals`; formatting only.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from minseg_tui import signals
from minseg_tui.errors import DeviceError, MinsegError
from minseg_tui.lab import capture as lab_capture
from minseg_tui.lab import store as lab_store
from minseg_tui.lab.entry import format_quantity
from minseg_tui.lab.session import Entry, Session
from minseg_tui.lab.steps import FIELDS, STEPS, Step, step
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.ports import Cell, Device, EntryResult, SessionSummary, Steady, TableView

_FORMULAS = dict(step("table").formulas)


def _fmt(v: float | None, unit: str) -> str:
    return "—" if v is None or not math.isfinite(v) else format_quantity(v, unit, 4)


def _result(e: Entry | None, feedback: str = "") -> EntryResult | None:
    if e is None:
        return None
    return EntryResult(e.ok, e.message, tuple(e.warnings), feedback)


class SessionLab:
    """The :class:`~minseg_tui.ui.ports.Lab` port on a real :class:`Session`."""

    def __init__(self, session: Session) -> None:
        self.session = session
        self.steps: Sequence[Step] = STEPS

    def _feedback(self, key: str) -> str:
        for fb in self.session.feedback():
            if fb.key == key and fb.status != "missing":
                return fb.message
        return ""

    def text(self, key: str) -> str:
        e = self.session.entry(key)
        return e.text if e else ""

    def result(self, key: str) -> EntryResult | None:
        return _result(self.session.entry(key), self._feedback(key))

    def enter(self, key: str, text: str) -> EntryResult:
        e = self.session.enter(key, text)
        return _result(e, self._feedback(key)) or EntryResult(True)

    @property
    def current(self) -> str:
        return self.session.current_step

    def go(self, step_id: str) -> None:
        self.session.go_to(step_id)

    def steady(self, t: Sequence[float], count: Sequence[int]) -> Steady:
        w = signals.timestamp_velocity(t, count, window=0.1)
        s = lab_capture.steadiness(t, w)
        note = "" if s.ready else "(window filling)"
        return Steady(s.settled, s.mean, s.spread, lab_capture.DEFAULT_WINDOW, note)

    def capture_live(self, level: float, t: Sequence[float], count: Sequence[int]) -> EntryResult:
        """Task 4: omega_ss at ``level`` from the live samples (board time s, counts)."""
        w = signals.timestamp_velocity(t, count, window=0.1)
        s = lab_capture.steadiness(t, w)
        if not s.settled:
            return EntryResult(False, "not settled yet: wait until the indicator says SETTLED")
        try:
            e = self.session.capture_omega(level, t, w)
        except ValueError as exc:
            return EntryResult(False, str(exc))
        return _result(e) or EntryResult(True)

    def table(self) -> TableView:
        rows = []
        for r in self.session.table():
            spread = "" if r.spread is None else f" ±{r.spread:.2f}"
            rows.append((
                Cell(f"{r.level:g} V"),
                Cell(_fmt(r.u_ss, "V")),
                Cell(_fmt(r.omega_ss, "rad/s") + spread, "captured: mean over the settled window" if r.spread is not None else ""),
                Cell(_fmt(r.i_ss, "mA")),
                Cell(_fmt(r.k_v, "V s/rad"), _FORMULAS["k_v"]),
                Cell(_fmt(r.f, "N m s/rad"), _FORMULAS["f"]),
            ))
        res = self.session.results()
        ident = res.identification
        results: tuple[tuple[str, Cell], ...] = ()
        if ident is not None:
            results = (("k_v", Cell(_fmt(ident.k_v, "V s/rad"), _FORMULAS["k_v"])),
                       ("k_a", Cell(_fmt(ident.k_a, "N m/A"), _FORMULAS["k_a"])),
                       ("f", Cell(_fmt(ident.f, "N m s/rad"), _FORMULAS["f"])))
        warnings = tuple(n.message for n in self.session.warnings("table")) + tuple(res.problems)
        return TableView(("u", "u_ss", "omega_ss", "i_ss", "k_v", "f"), tuple(rows), results, warnings)

    def store_run(self, name: str, t: Sequence[float], count: Sequence[int], u_req: Sequence[float],
                  complete: bool) -> None:
        plan = dict(step("task10").plans)[name]
        rec = self.session.start_run("steps" if name == "manual" else "fast", plan)
        for k, (tt, c, u) in enumerate(zip(t, count, u_req, strict=True)):
            rec.append(k, round(tt * 1e6), int(c), round(u * 1000))
        self.session.finish_run(rec)

    def run(self, name: str) -> tuple[Sequence[float], Sequence[float]] | None:
        kind = "steps" if name == "manual" else "fast"
        runs = [r for r in self.session.runs if r.kind == kind]
        if not runs:
            return None
        log = self.session.load_run(runs[-1].name)
        return np.asarray(log.t), np.asarray(log.omega)

    def run_status(self) -> str:
        runs = self.session.runs
        return "runs: " + ", ".join(r.name for r in runs) if runs else "no runs recorded yet"

    def results_text(self) -> str:
        res = self.session.results()
        lines = list(res.problems)
        ident = res.identification
        if ident is not None and ident.step is not None:
            st = ident.step
            lines.append(f"K = {st.K:.3g} rad/s/V   T (LS) = {st.T:.3g} s  95 % CI {st.T_ci[0]:.3g}..{st.T_ci[1]:.3g} s")
            lines.append(f"J = {st.J:.3g} kg m^2   omega at 5 V = {5 * st.K:.3g} rad/s")
        for c in self.session.comparisons(self.session.current_step):
            own = "—" if c.own is None else (c.own if isinstance(c.own, str) else _fmt(c.own, c.unit))
            comp = "—" if c.computed is None else (c.computed if isinstance(c.computed, str) else _fmt(c.computed, c.unit))
            lines.append(f"{c.label}: yours {own} · computed {comp}")
        return "\n".join(lines) or "no results yet"

    def model_check_text(self) -> str:
        try:
            check = importlib.import_module("minseg_tui.model.check")
        except ImportError:
            return "the model check is not available in this build"
        run = self.session.step_run()
        if run is None:
            return "record the step experiment (Task 10) first"
        return f"model check module found ({check.__name__}); its API is not wired into the UI yet"

    def export(self) -> Sequence[str]:
        try:
            report = importlib.import_module("minseg_tui.report")
            write = report.write_report  # type: ignore[attr-defined]
        except (ImportError, AttributeError) as exc:
            raise MinsegError("the report module is not available in this build") from exc
        return [str(p) for p in write(self.session)]


class SessionStore:
    """The :class:`~minseg_tui.ui.ports.Store` port on the sessions folder."""

    def __init__(self, root: Path) -> None:
        self.root = root

    def list(self) -> list[SessionSummary]:
        return [SessionSummary(str(s.path), ", ".join(s.members), s.date, s.last_step,
                               s.damaged or (f"open in process {s.locked_by}" if s.locked_by else ""))
                for s in lab_store.list_sessions(self.root)]

    def new(self, members: str, date: str) -> SessionLab:
        names = [m.strip() for m in members.split(",") if m.strip()]
        return SessionLab(Session.create(self.root, names, date or None))

    def open(self, path: str) -> SessionLab:
        return SessionLab(Session.open(Path(path)))


def open_store(config: UiConfig) -> SessionStore:
    """The sessions folder of ``config``."""
    return SessionStore(Path(config.sessions))


def open_device(spec: str, config: UiConfig) -> Device:
    """The board or the virtual MinSeg for ``spec`` (auto, sim, a port or URL)."""
    # The Link -> Device adapter is not written yet (device.factory/link landed late).
    raise DeviceError(f"device {spec!r}: the UI's adapter to minseg_tui.device.link is not wired yet")


__all__ = ["FIELDS", "SessionLab", "SessionStore", "open_device", "open_store"]
