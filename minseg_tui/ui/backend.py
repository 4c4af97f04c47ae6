"""Adapters from the real layers to the UI's ports: the device link, the lab session and store.

No arithmetic of the lab here: every number comes from :mod:`minseg_tui.lab.session` (which
uses :mod:`minseg_tui.model.identify`), :mod:`minseg_tui.model.check` or
:mod:`minseg_tui.signals`; this module picks, formats and hands over arrays.

The session is meant to be used from one thread. The UI reads it from the event loop and
from workers (results, model check, report), so every call goes through one lock here.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Protocol

import numpy as np

from minseg_tui import signals
from minseg_tui.device import factory
from minseg_tui.device.link import Link
from minseg_tui.errors import DeviceError, InputError, MinsegError
from minseg_tui.lab import capture as lab_capture
from minseg_tui.lab import store as lab_store
from minseg_tui.lab.entry import format_quantity
from minseg_tui.lab.runs import Recorder
from minseg_tui.lab.session import Entry, Session, TableRow
from minseg_tui.lab.steps import FIELDS, STEPS, RunPlan, Step, step
from minseg_tui.model import identify as model_identify
from minseg_tui.model.check import text as check_text
from minseg_tui.model.steplog import StepLog
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.ports import (
    Batch,
    Cell,
    CheckView,
    DeviceInfo,
    EntryResult,
    Event,
    LinkHealth,
    Meter,
    ResultsView,
    RunView,
    SessionSummary,
    Steady,
    StepWindow,
    TableView,
)


class Written(Protocol):
    """What a report writer returns: the Markdown and HTML files and the runs' CSV."""

    markdown: Path
    html: Path
    runs: tuple[Path, ...]


ReportWriter = Callable[[Session], Written]
"""Writes a session's report into its folder."""

CAPTURE_VELOCITY_WINDOW: float = 0.1
"""Speed used for the steady-state indicator and the capture of omega_ss: the mean speed over
the last 0.1 s from the board's timestamps (:func:`signals.timestamp_velocity`), s. Four 25 ms
samples: quiet enough to judge steadiness, and without the manual's 0.5 s lag."""

RUN_KIND = {"manual": "steps", "fast": "fast"}
"""Task 10's plans (lab.steps) to the session's run kinds."""

_FORMULAS = dict(step("table").formulas)


def _fmt(v: float | None, unit: str, digits: int = 4) -> str:
    return "—" if v is None or not math.isfinite(v) else format_quantity(v, unit, digits)


def _fmt_milli(v: float | None, unit: str, digits: int = 4) -> str:
    """``v`` in thousandths of ``unit`` (f in mN m s/rad, as the table's column shows it)."""
    return "—" if v is None or not math.isfinite(v) else f"{v * 1e3:.{digits}g} m{unit}"


TABLE_COLUMNS = ("u\nV", "u_ss\nV", "omega_ss\nrad/s", "i_ss\nmA", "k_v\nV s/rad", "f\nmN m s/rad")
"""The table's headers: name over unit (the cells hold bare numbers in these units)."""


def _num(v: float | None, digits: int) -> str:
    return "—" if v is None or not math.isfinite(v) else f"{v:.{digits}g}"


def _row_formula(name: str, r: TableRow, R: float | None, k_a: float | None) -> str:
    """The formula of a computed cell of row ``r`` with the row's numbers in it (R in ohm,
    k_a in N m/A, the final one)."""
    if name == "k_v" and None not in (r.k_v, r.u_ss, r.i_ss, r.omega_ss, R):
        return (
            f"k_v = (u_ss - R i_ss) / omega_ss = ({r.u_ss:.3g} V - {R:.3g} Ω × {r.i_ss:.3g} A)"
            f" / {r.omega_ss:.3g} rad/s = {r.k_v:.4g} V s/rad"
        )
    if name == "f" and None not in (r.f, r.i_ss, r.omega_ss, k_a):
        return (
            f"f = k_a i_ss / omega_ss = {k_a:.4g} N m/A × {r.i_ss:.3g} A / {r.omega_ss:.3g} rad/s"
            f" = {r.f * 1e3:.4g} mN m s/rad (k_a = 0.65 × median k_v)"
        )
    return _FORMULAS[name]


def _result(e: Entry | None, feedback: str = "") -> EntryResult | None:
    if e is None:
        return None
    if e.refused:  # a refused attempt over an accepted entry: say so, and what still counts
        return EntryResult(
            False, f"{e.refused[1]} (still using {e.text.strip()!r})", tuple(e.warnings), feedback
        )
    return EntryResult(e.ok, e.message, tuple(e.warnings), feedback)


# -- the device ---------------------------------------------------------------------------
_STATES = {
    "connected": "ok",
    "alive": "ok",
    "disconnected": "lost",
    "silent": "silent",
    "error": "lost",
}


class LinkDevice:
    """The :class:`~minseg_tui.ui.ports.Device` port on a real :class:`Link` (board or virtual)."""

    def __init__(self, link: Link, fallback: bool = False) -> None:
        self.link = link
        ident = link.ident
        self.info = DeviceInfo(
            name=ident.board if ident else "?",
            firmware=ident.fw if ident else "?",
            virtual=link.board is not None,
            port=link.port,
            fallback=fallback,
        )
        self._state = "ok" if link.connected else "lost"

    def health(self) -> LinkHealth:
        s = self.link.stats
        return LinkHealth(self._state, s.dropped, s.corrupt, s.reconnects)

    def read(self, timeout: float) -> Batch:
        """Wait ``timeout`` s, then take every sample and event the link holds."""
        time.sleep(timeout)
        b = self.link.samples()
        events = tuple(Event(e.kind, e.message) for e in self.link.events())
        for e in events:
            self._state = _STATES.get(e.kind, self._state)
        return Batch(b.seq, b.t_us, b.count, np.round(b.u_req * 1000).astype(np.int64), events)

    def set_voltage(self, u: float) -> None:
        self.link.set_voltage(u)

    def stop(self) -> None:
        self.link.stop()

    def set_period(self, period: float) -> None:
        self.link.set_period(period)

    def run_steps(self, low: float, high: float, half: float, n: int) -> None:
        self.link.step(low, high, half, n)

    def meter(self) -> Meter | None:
        m = self.link.meter()
        return None if m is None else Meter(m.u_A, m.i, m.R)

    def close(self) -> None:
        self.link.close()


def device_spec(spec: str) -> str:
    """The factory's spec for the UI's: ``sim`` is the virtual MinSeg in real time."""
    return "virtual" if spec == "sim" else spec


def open_device(spec: str, config: UiConfig) -> LinkDevice:
    """The board or the virtual MinSeg for ``spec`` (auto, sim, a port or URL); DeviceError
    with one line when it cannot be opened."""
    virtual = f"{factory.VIRTUAL}&seed={config.seed}"
    link = factory.open_device(device_spec(spec), virtual=virtual)
    return LinkDevice(link, fallback=spec == "auto" and link.board is not None)


# -- recording a run ------------------------------------------------------------------------
class Recording:
    """A run being recorded: the session's Recorder behind a lock, so the stream worker can
    append samples as they arrive while a timer calls :meth:`tick` (flush to disk)."""

    def __init__(self, name: str, recorder: Recorder, plan: RunPlan) -> None:
        self.name = name
        self.recorder = recorder
        self.plan = plan
        self._lock = threading.Lock()
        self.samples = 0
        self.first_us: int | None = None
        self.last_us: int | None = None
        self.ended = False

    def end(self) -> None:
        """Take no more samples (the sequence ended or the board went); the file stays open
        until :meth:`close`."""
        with self._lock:
            self.ended = True

    def append(self, batch: Batch) -> None:
        """Every sample of ``batch``, with the board's own seq, t_us, count and u_mV."""
        with self._lock:
            if self.recorder.closed or self.ended:
                return
            for s, t, c, u in zip(batch.seq, batch.t_us, batch.count, batch.u_mV, strict=True):
                self.recorder.append(int(s), int(t), int(c), int(u))
            if len(batch):
                if self.first_us is None:
                    self.first_us = int(batch.t_us[0])
                self.last_us = int(batch.t_us[-1])
                self.samples += len(batch)

    def tick(self) -> None:
        """Flush what is older than the Recorder's flush interval (call a few times a second)."""
        with self._lock:
            if not self.recorder.closed:
                self.recorder.tick()

    def close(self) -> None:
        """No more samples."""
        with self._lock:
            self.recorder.close()

    @property
    def elapsed(self) -> float:
        """Board time covered so far, s."""
        if self.first_us is None or self.last_us is None:
            return 0.0
        return (self.last_us - self.first_us) / 1e6


def _median(values: Sequence[float | None]) -> float | None:
    vs = [v for v in values if v is not None]
    return float(np.median(vs)) if vs else None


def _t63(log: StepLog) -> float | None:
    """The manual's 63 % reading of the log's speed: the median over its rising steps, s."""
    try:
        return _median([s.T_63 for s in model_identify.rising_steps(log)])
    except (InputError, ValueError):
        return None


class SessionLab:
    """The :class:`~minseg_tui.ui.ports.Lab` port on a real :class:`Session`."""

    def __init__(self, session: Session, writer: ReportWriter | None = None) -> None:
        self.session = session
        self.writer = writer
        self.steps: Sequence[Step] = STEPS
        self.lock = threading.RLock()

    # -- entries ------------------------------------------------------------------------
    def _feedback(self, key: str) -> str:
        for fb in self.session.feedback("*"):
            if fb.key == key and fb.status != "missing":
                return fb.message
        return ""

    def text(self, key: str) -> str:
        with self.lock:
            e = self.session.entry(key)
            return e.typed if e else ""

    def result(self, key: str) -> EntryResult | None:
        with self.lock:
            return _result(self.session.entry(key), self._feedback(key))

    def enter(self, key: str, text: str) -> EntryResult:
        with self.lock:
            e = self.session.enter(key, text)
            return _result(e, self._feedback(key)) or EntryResult(True)

    def choose(self, key: str, indices: Sequence[int]) -> EntryResult:
        """Pick options (0-based) of a choice field; saved."""
        with self.lock:
            e = self.session.choose(key, list(indices))
            return _result(e, self._feedback(key)) or EntryResult(True)

    def chosen(self, key: str) -> tuple[int, ...]:
        """The options (0-based) stored for a choice field."""
        with self.lock:
            e = self.session.entry(key)
            return e.value if e is not None and e.ok and isinstance(e.value, tuple) else ()

    @property
    def current(self) -> str:
        with self.lock:
            return self.session.current_step

    def go(self, step_id: str) -> None:
        with self.lock:
            self.session.go_to(step_id)

    def status(self, step_id: str) -> str:
        """done, started, todo or info."""
        with self.lock:
            return self.session.step_status(step_id)

    @property
    def title(self) -> str:
        """The group and date, for the header."""
        return f"{', '.join(self.session.members)} · {self.session.date}"

    @property
    def recovered(self) -> list[str]:
        """Runs rebuilt after a crash when the session was opened."""
        return list(self.session.recovered)

    # -- Task 4 ---------------------------------------------------------------------------
    def steady(self, t: Sequence[float], count: Sequence[int]) -> Steady:
        w = signals.timestamp_velocity(t, count, window=CAPTURE_VELOCITY_WINDOW)
        s = lab_capture.steadiness(t, w)
        note = "" if s.ready else "(window filling)"
        return Steady(s.settled, s.mean, s.spread, lab_capture.DEFAULT_WINDOW, note)

    def capture_live(self, level: float, t: Sequence[float], count: Sequence[int]) -> EntryResult:
        """Task 4: omega_ss at ``level`` from the live samples (board time s, counts)."""
        w = signals.timestamp_velocity(t, count, window=CAPTURE_VELOCITY_WINDOW)
        s = lab_capture.steadiness(t, w)
        if not s.settled:
            return EntryResult(False, "not settled yet: wait until the indicator says SETTLED")
        with self.lock:
            try:
                e = self.session.capture_omega(level, t, w)
            except ValueError as exc:
                return EntryResult(False, str(exc))
            return _result(e) or EntryResult(True)

    # -- Tasks 6-9 ---------------------------------------------------------------------------
    def table(self) -> TableView:
        """The table with its units in the headers and short cells (it fits the pane at 80
        columns); each computed cell's formula carries the row's own numbers."""
        with self.lock:
            R = self.session.value("R")
            res = self.session.results()
            ident = res.identification
            k_a = None if ident is None else ident.k_a
            rows = []
            for r in self.session.table():
                spread = "" if r.spread is None else f" ±{r.spread:.2f}"
                rows.append(
                    (
                        Cell(
                            f"{r.level:g}", f"u = {r.level:g} V: the voltage requested on the board"
                        ),
                        Cell(
                            _num(r.u_ss, 3),
                            "u_ss: read on the multimeter (V)" if r.u_ss is not None else "",
                        ),
                        Cell(
                            _num(r.omega_ss, 3) + spread,
                            "omega_ss: captured, the mean over the settled window ± its spread (rad/s)"
                            if r.spread is not None
                            else "omega_ss: typed in (rad/s)"
                            if r.omega_ss is not None
                            else "",
                        ),
                        Cell(
                            _num(None if r.i_ss is None else r.i_ss * 1e3, 3),
                            "i_ss: read on the multimeter (mA)" if r.i_ss is not None else "",
                        ),
                        Cell(_num(r.k_v, 4), _row_formula("k_v", r, R, k_a)),
                        Cell(
                            _num(None if r.f is None else r.f * 1e3, 4),
                            _row_formula("f", r, R, k_a),
                        ),
                    )
                )
            results: tuple[tuple[str, Cell], ...] = ()
            if ident is not None:
                results = (
                    ("k_v", Cell(_fmt(ident.k_v, "V s/rad"), _FORMULAS["k_v"])),
                    ("k_a", Cell(_fmt(ident.k_a, "N m/A"), _FORMULAS["k_a"])),
                    ("f", Cell(_fmt_milli(ident.f, "N m s/rad"), _FORMULAS["f"])),
                )
            warnings = tuple(n.message for n in self.session.warnings("table")) + tuple(
                res.problems
            )
            return TableView(
                TABLE_COLUMNS,
                tuple(rows),
                results,
                tuple(dict.fromkeys(warnings)),
                self._compare("table"),
            )

    def _compare(self, step_id: str) -> tuple[tuple[str, str, str], ...]:
        out = []
        for c in self.session.comparisons(step_id):
            own = (
                "—" if c.own is None else (c.own if isinstance(c.own, str) else _fmt(c.own, c.unit))
            )
            comp = (
                "—"
                if c.computed is None
                else (c.computed if isinstance(c.computed, str) else _fmt(c.computed, c.unit))
            )
            if c.rel_diff is not None:
                comp += f" ({c.rel_diff:+.0%})"
            out.append((c.label, own, comp))
        return tuple(out)

    # -- Task 10 -----------------------------------------------------------------------------
    def start_recording(self, name: str) -> Recording:
        """Start recording Task 10's plan ``name`` (manual or fast)."""
        plan = dict(step("task10").plans)[name]
        with self.lock:
            rec = self.session.start_run(RUN_KIND[name], plan)
        return Recording(rec.name, rec, plan)

    def finish_recording(self, rec: Recording) -> str:
        """Keep the run (or nothing, under 2 samples); one line saying what was kept."""
        rec.close()
        with self.lock:
            info = self.session.finish_run(rec.recorder)
            if (
                info is not None
            ):  # the new run is the one Tasks 11-15 use (an import or a pick is dropped)
                self.session.select_run(None)
        if info is None:
            return f"run {rec.name}: too few samples, nothing kept"
        return f"run {info.name}: {info.samples} samples kept" + (
            f", {info.dropped} lost on the link" if info.dropped else ""
        )

    def runs(self) -> tuple[str, ...]:
        """Names of the recorded runs, oldest first."""
        with self.lock:
            return tuple(r.name for r in self.session.runs)

    def use_run(self, name: str | None) -> str:
        with self.lock:
            self.session.select_run(name)
            run = self.session.step_run()
        return f"Tasks 11-15 and the model check use run {run.name if run else '— (none yet)'}"

    def run_views(self) -> tuple[RunView, ...]:
        """The latest 25 ms run and the latest fast run, with their T readings (worker)."""
        with self.lock:
            latest = {}
            for r in self.session.runs:
                if r.kind in ("steps", "fast"):
                    latest[r.kind] = r
            loaded = []
            for kind in ("steps", "fast"):
                r = latest.get(kind)
                if r is None:
                    continue
                try:
                    loaded.append((r, self.session.load_run(r.name)))
                except InputError:
                    continue
        out = []
        for r, log in loaded:
            lab = np.asarray(log.extra.get("omega_lab", log.omega), dtype=float)
            fit = None
            try:
                fit = model_identify.fit_time_constant(log)
            except (InputError, ValueError):
                fit = None
            out.append(
                RunView(
                    r.name,
                    r.kind,
                    r.ts,
                    r.samples,
                    r.interrupted,
                    np.asarray(log.t),
                    np.asarray(log.omega),
                    lab,
                    _t63(log),
                    _t63(replace(log, omega=lab)),
                    fit.T if fit else None,
                    fit.ci if fit else None,
                )
            )
        return tuple(out)

    # -- Tasks 11-15 ---------------------------------------------------------------------------
    def results_view(self, step_id: str) -> ResultsView:
        """Tasks 11-15 from the session (run it in a worker: 0.4-0.5 s on long runs)."""
        with self.lock:
            res = self.session.results()
            compare = self._compare(step_id) if any(f.compare for f in step(step_id).fields) else ()
            log = None
            if res.run is not None:
                try:
                    log = self.session.load_run(res.run)
                except InputError:
                    log = None
        ident = res.identification
        lines: list[str] = []
        steps: tuple[StepWindow, ...] = ()
        if ident is not None and ident.step is not None:
            st = ident.step
            t63 = _fmt(st.T_63, "s", 3)
            lines += [
                f"omega_ss in the steps = {_fmt(st.omega_ss, 'rad/s', 3)}   u_ss = {_fmt(st.u_ss, 'V', 3)} ({st.u_ss_how})",
                f"K = {_fmt(st.K, 'rad/s/V', 3)}",
                f"T (63 %) = {t63}   T (least squares) = {_fmt(st.T, 's', 3)}, "
                f"95 % CI {st.T_ci[0]:.3g}..{st.T_ci[1]:.3g} s",
                f"J = {_fmt(st.J, 'kg m^2', 3)}",
                f"model: {st.T:.3g} omega' = -omega + {st.K:.3g} u_A",
                f"omega at 5 V = {_fmt(ident.omega_at_5V, 'rad/s', 3)}",
            ]
            steps = tuple(StepWindow(s.t, s.t + s.duration, s.T_63) for s in st.steps)
        empty = np.zeros(0)
        return ResultsView(
            res.run,
            np.asarray(log.t) if log else empty,
            np.asarray(log.omega) if log else empty,
            np.asarray(log.u) if log else empty,
            steps,
            tuple(lines),
            compare,
            tuple(res.problems),
        )

    # -- the model check ---------------------------------------------------------------------------
    def check_view(self) -> CheckView:
        """The model check of the run Tasks 11-15 use (worker: up to 0.5 s)."""
        with self.lock:
            mc = self.session.model_check()
        r = mc.result
        if r is None:
            return CheckView(mc.run, problem=mc.problem or "no result")
        f, e = r.finding, r.extended
        ext = (
            "none needed (the baseline is enough)"
            if f.cause == "none"
            else (f"{e.model}: " + ", ".join(f"{k} = {v:.3g}" for k, v in e.params.items()))
        )
        gain = (
            f"rmse {r.baseline.rmse:.3f} → {e.rmse:.3f} rad/s ({r.gain.get('rmse_reduction_percent', 0.0):.0f} % lower), "
            f"fit {r.baseline.fit_percent:.1f} → {e.fit_percent:.1f} %"
        )
        return CheckView(
            mc.run,
            np.asarray(r.t),
            np.asarray(r.omega),
            np.asarray(r.baseline_pred),
            np.asarray(r.extended_pred),
            np.asarray(r.omega) - np.asarray(r.baseline_pred),
            f.cause,
            f.evidence,
            ext,
            gain,
            check_text(r),
        )

    def import_run(self, path: str) -> str:
        """Load a step log recorded elsewhere; it becomes the run Tasks 11-15 and the check use."""
        with self.lock:
            info = self.session.import_run(Path(path).expanduser())
            self.session.select_run(info.name)
        return f"imported {path} as {info.name} ({info.samples} rows); Tasks 11-15 and the model check use it"

    def export(self) -> tuple[str, ...]:
        """Write report.md and report.html into the session folder (worker); the files."""
        if self.writer is None:
            raise MinsegError("this program was started without the report writer")
        with self.lock:
            w = self.writer(self.session)
        return (str(w.markdown), str(w.html), *(str(p) for p in w.runs))

    def close(self) -> None:
        """Release the session's lock file."""
        with self.lock:
            self.session.close()


class SessionStore:
    """The :class:`~minseg_tui.ui.ports.Store` port on the sessions folder; ``writer`` writes
    a session's report (:func:`minseg_tui.report.write.write_report`, handed in by the CLI:
    the report layer sits beside the UI, not below it)."""

    def __init__(self, root: Path, writer: ReportWriter | None = None) -> None:
        self.root = root
        self.writer = writer

    def list(self) -> list[SessionSummary]:
        return [
            SessionSummary(
                str(s.path),
                ", ".join(s.members),
                s.date,
                s.last_step,
                (
                    f"damaged — {s.damaged}"
                    if s.damaged
                    else f"in use by another minseg-tui (pid {s.locked_by})"
                    if s.locked_by
                    else ""
                ),
            )
            for s in lab_store.list_sessions(self.root)
        ]

    def new(self, members: str, date: str) -> SessionLab:
        names = [m.strip() for m in members.split(",") if m.strip()]
        return SessionLab(Session.create(self.root, names, date or None), self.writer)

    def open(self, path: str) -> SessionLab:
        return SessionLab(Session.open(Path(path)), self.writer)


def open_store(config: UiConfig, writer: ReportWriter | None = None) -> SessionStore:
    """The sessions folder of ``config``."""
    return SessionStore(Path(config.sessions), writer)


__all__ = [
    "CAPTURE_VELOCITY_WINDOW",
    "FIELDS",
    "CheckView",
    "DeviceError",
    "LinkDevice",
    "MinsegError",
    "Recording",
    "ResultsView",
    "RunView",
    "SessionLab",
    "SessionStore",
    "StepWindow",
    "open_device",
    "open_store",
]
