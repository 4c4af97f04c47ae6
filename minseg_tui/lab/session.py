"""A lab session: who, when, where the group is, everything typed, captured and recorded.

The UI holds one :class:`Session`, renders its state and calls its methods; it does no
arithmetic and no file I/O of its own. Every change is saved at once (atomically, see
:mod:`minseg_tui.lab.store`); reopening a session restores it exactly, current step
included. Derived numbers (Tasks 6-15) are never stored: :meth:`Session.results`
computes them from the entries and the chosen run with :mod:`minseg_tui.model.identify`,
so changing an earlier entry changes every later result.

Units: entries are stored as typed (``text``) and as parsed SI values (``value``: V, A,
ohm, rad/s, s, ...); the form unit of each field is in :mod:`minseg_tui.lab.steps`.

Typical use::

    s = Session.create(Path("sessions"), ["Ada", "Bo"])     # or Session.open(folder)
    s.enter("R", "5,2 Ω")                                   # -> Entry (ok, value 5.2, warnings)
    s.capture_omega(2.5, t, omega)                          # Task 4, from live samples
    rec = s.start_run("steps", plan)                        # Task 10
    rec.append(seq, t_us, count, u_mV) ...
    s.finish_run(rec)
    s.results().identification.k_v                          # Tasks 6-15
    s.close()
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from minseg_tui.errors import InputError
from minseg_tui.lab import steps as lab_steps
from minseg_tui.lab.capture import DEFAULT_WINDOW, Capture, capture
from minseg_tui.lab.entry import parse_quantity
from minseg_tui.lab.expr import Formula
from minseg_tui.lab.files import read_step_log
from minseg_tui.lab.runs import (
    PARTIAL_SUFFIX,
    Recorder,
    RunInfo,
    build_log,
    read_partial,
    remap_log,
    write_log_atomic,
)
from minseg_tui.lab.steps import FIELDS, LEVELS, STEP_INDEX, STEPS, Feedback, RunPlan, Step
from minseg_tui.lab.store import (
    KIND,
    RUNS_DIR,
    SCHEMA,
    SESSION_FILE,
    Lock,
    SessionDamaged,
    atomic_write_text,
    read_session_file,
)
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.identify import Identification, Reading, identify
from minseg_tui.model.steplog import StepLog

Clock = Callable[[], datetime]


def _now() -> datetime:
    return datetime.now(UTC)


@dataclass(frozen=True)
class Entry:
    """What was typed in one field, and what it was read as.

    key: the field's key; text: exactly as typed; ok: accepted; value: SI float for a
    quantity (or a formula without names), tuple of option indices for a choice, None
    otherwise; unit: the unit it was typed in; message: why it was refused, or a note on
    how it was read (``read as 47 mA``); warnings: plausibility warnings; source: ``typed``,
    ``capture`` or ``meter``; at: ISO time; history: earlier (text, at) pairs, oldest first.

    A refused text never displaces an accepted one: the accepted entry stays in effect and
    carries the refused attempt in ``refused`` (text, message, at) until something is
    accepted again, so neither what was typed last nor what was entered before is lost.
    """

    key: str
    text: str
    ok: bool
    value: float | tuple[int, ...] | None = None
    unit: str = ""
    message: str = ""
    warnings: tuple[str, ...] = ()
    source: str = "typed"
    at: str = ""
    history: tuple[tuple[str, str], ...] = ()
    refused: tuple[str, str, str] | None = None

    @property
    def typed(self) -> str:
        """What the field shows: the refused attempt if there is one, else the text in effect."""
        return self.refused[0] if self.refused else self.text

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict (the session file's form)."""
        out = {
            "text": self.text,
            "ok": self.ok,
            "value": list(self.value) if isinstance(self.value, tuple) else self.value,
            "unit": self.unit,
            "message": self.message,
            "warnings": list(self.warnings),
            "source": self.source,
            "at": self.at,
            "history": [list(h) for h in self.history],
        }
        if self.refused:
            out["refused"] = list(self.refused)
        return out

    @classmethod
    def from_json(cls, key: str, d: Mapping[str, Any]) -> Entry:
        """Inverse of :meth:`to_json`."""
        v = d.get("value")
        value: float | tuple[int, ...] | None = (
            tuple(int(x) for x in v)
            if isinstance(v, list)
            else (float(v) if isinstance(v, int | float) else None)
        )
        return cls(
            key=key,
            text=str(d["text"]),
            ok=bool(d["ok"]),
            value=value,
            unit=str(d.get("unit", "")),
            message=str(d.get("message", "")),
            warnings=tuple(str(w) for w in d.get("warnings", [])),
            source=str(d.get("source", "typed")),
            at=str(d.get("at", "")),
            history=tuple((str(h[0]), str(h[1])) for h in d.get("history", [])),
            refused=(str(d["refused"][0]), str(d["refused"][1]), str(d["refused"][2]))
            if d.get("refused")
            else None,
        )


@dataclass(frozen=True)
class Notice:
    """A warning to show: ``source`` is a field key or a finding code; ``message`` one line."""

    source: str
    message: str


@dataclass(frozen=True)
class TableRow:
    """One row of the table of Tasks 4-9 (None where not known yet).

    level: requested u_req (V); u_ss (V); omega_ss (rad/s); spread (rad/s, of the capture);
    window: (t0, t1) s of the capture; i_ss (A); k_v (V s/rad); f (N m s/rad).
    """

    level: float
    u_ss: float | None = None
    omega_ss: float | None = None
    spread: float | None = None
    window: tuple[float, float] | None = None
    i_ss: float | None = None
    k_v: float | None = None
    f: float | None = None


@dataclass(frozen=True)
class Results:
    """Tasks 6-15 computed now from the entries: ``identification`` (None when the table is
    not far enough), the run used for Tasks 11-15 (None without one), and ``problems``:
    one line each for what keeps a result from being computed."""

    identification: Identification | None
    run: str | None
    problems: tuple[str, ...] = ()

    def to_json(self) -> dict[str, object] | None:
        """The --json dict of ``minseg-tui identify`` for these results, or None."""
        return self.identification.to_json() if self.identification else None

    def lookup(self, path: str) -> float | str | None:
        """A computed value by path (``k_v``, ``step.K``, ``step.T_63``, ``omega_at_5V``,
        ``model`` as a sentence); None when not computed."""
        d = self.to_json()
        if d is None:
            return None
        if path == "model":
            m = d.get("model")
            if not isinstance(m, dict):
                return None
            return f"{m['T']:.3g} omega' = -omega + {m['K']:.3g} u_A"
        node: object = d
        for part in path.split("."):
            if not isinstance(node, dict) or part not in node:
                return None
            node = node[part]
        return float(node) if isinstance(node, int | float) else None


@dataclass(frozen=True)
class Comparison:
    """A student's own reading beside the computed value (same SI unit; ``unit`` is the
    form unit for display); rel_diff = own / computed - 1 when both are numbers."""

    key: str
    label: str
    unit: str
    own: float | str | None
    computed: float | str | None
    rel_diff: float | None


@dataclass(frozen=True)
class ModelCheck:
    """The model check of one run: its name, the result (None when it could not run) and,
    then, why in one line (``problem``)."""

    run: str | None
    result: CheckResult | None
    problem: str = ""


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def _parse_choice(text: str, n: int) -> tuple[int, ...]:
    """'b', 'B, c', '2', '2 3' -> option indices; ValueError if unreadable."""
    parts = [p for p in re.split(r"[\s,;]+", text.strip()) if p]
    out = []
    for p in parts:
        if len(p) == 1 and p.isalpha():
            k = ord(p.lower()) - ord("a")
        elif p.isdigit():
            k = int(p) - 1
        else:
            raise ValueError(p)
        if not 0 <= k < n:
            raise ValueError(p)
        out.append(k)
    if not out:
        raise ValueError(text)
    return tuple(sorted(set(out)))


class Session:
    """One group's lab session, saved in its folder after every change.

    Create with :meth:`create` or :meth:`open`; close with :meth:`close` (or use ``with``).
    A session opened with ``readonly=True`` (for reports) takes no lock and never writes.
    """

    def __init__(
        self, folder: Path, data: dict[str, Any], *, lock: Lock | None, clock: Clock, readonly: bool
    ) -> None:
        self.folder = Path(folder)
        self._data = data
        self._lock = lock
        self._clock = clock
        self.readonly = readonly
        self._entries: dict[str, Entry] = {
            k: Entry.from_json(k, v) for k, v in data["entries"].items()
        }
        self._captures: dict[str, Capture] = {
            k: Capture.from_json(v) for k, v in data["captures"].items()
        }
        self._runs: list[RunInfo] = [RunInfo.from_json(r) for r in data["runs"]]
        self._results: tuple[object, Results] | None = None
        self._checks: dict[tuple[int, str], ModelCheck] = {}
        self._run_version = 0
        self.recovered: list[str] = []
        """Names of runs rebuilt at open from a recording a crash interrupted."""

    # -- life cycle ----------------------------------------------------------------------------

    @classmethod
    def create(
        cls,
        root: Path,
        members: Sequence[str],
        date: str | None = None,
        session_id: str | None = None,
        clock: Clock = _now,
    ) -> Session:
        """A new session folder under ``root`` (created if needed), locked and saved.

        ``date`` defaults to today (ISO); the id defaults to ``<date>-<members>``, made
        unique with ``-2``, ``-3``, ...
        """
        root = Path(root)
        root.mkdir(parents=True, exist_ok=True)
        now = clock()
        date = date or now.date().isoformat()
        base = session_id or _slug(f"{date} {' '.join(members)}") or "session"
        sid, k = base, 1
        while (root / sid).exists():
            if session_id:
                raise InputError(
                    str(root / sid),
                    None,
                    "a session with this id exists already; open it or pick another id",
                )
            k += 1
            sid = f"{base}-{k}"
        folder = root / sid
        (folder / RUNS_DIR).mkdir(parents=True)
        lock = Lock(folder)
        lock.acquire()
        stamp = now.isoformat(timespec="seconds")
        data: dict[str, Any] = {
            "kind": KIND,
            "schema": SCHEMA,
            "id": sid,
            "members": [str(m) for m in members],
            "date": date,
            "created": stamp,
            "modified": stamp,
            "current_step": STEPS[0].id,
            "selected_run": None,
            "entries": {},
            "captures": {},
            "runs": [],
        }
        s = cls(folder, data, lock=lock, clock=clock, readonly=False)
        s.save()
        return s

    @classmethod
    def open(cls, folder: Path, clock: Clock = _now, readonly: bool = False) -> Session:
        """Open the session in ``folder``: take its lock (SessionLocked if another live
        program has it), read it (SessionMissing / SessionDamaged with one line; a damaged
        file is never written over) and rebuild any run a crash interrupted."""
        folder = Path(folder)
        lock = None
        if not readonly:
            if not (folder / SESSION_FILE).exists():
                read_session_file(folder / SESSION_FILE)  # raises SessionMissing
            lock = Lock(folder)
            lock.acquire()
        try:
            data = read_session_file(folder / SESSION_FILE)
            if data["current_step"] not in STEP_INDEX:
                raise SessionDamaged(
                    str(folder / SESSION_FILE),
                    None,
                    f"names an unknown step {data['current_step']!r}; the file is left untouched",
                )
            s = cls(folder, data, lock=lock, clock=clock, readonly=readonly)
            if not readonly:
                (folder / RUNS_DIR).mkdir(exist_ok=True)
                s._recover_runs()
        except BaseException:
            if lock is not None:
                lock.release()
            raise
        return s

    def close(self) -> None:
        """Release the lock (everything is already saved)."""
        if self._lock is not None:
            self._lock.release()
            self._lock = None

    def __enter__(self) -> Session:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def save(self) -> None:
        """Write session.json atomically (done by every change; call it only after set-up)."""
        if self.readonly:
            raise InputError(str(self.folder), None, "this session was opened read-only")
        self._data["entries"] = {k: e.to_json() for k, e in self._entries.items()}
        self._data["captures"] = {k: c.to_json() for k, c in self._captures.items()}
        self._data["runs"] = [r.to_json() for r in self._runs]
        self._data["modified"] = self._clock().isoformat(timespec="seconds")
        atomic_write_text(
            self.folder / SESSION_FILE, json.dumps(self._data, indent=1, ensure_ascii=False) + "\n"
        )

    def _changed(self) -> None:
        self.save()

    # -- who, when, where ----------------------------------------------------------------------

    @property
    def id(self) -> str:
        """The session's id (its folder name)."""
        return str(self._data["id"])

    @property
    def members(self) -> tuple[str, ...]:
        """The group's members."""
        return tuple(self._data["members"])

    @property
    def date(self) -> str:
        """The lab's date (ISO)."""
        return str(self._data["date"])

    @property
    def modified(self) -> str:
        """ISO time of the last change."""
        return str(self._data["modified"])

    def set_members(self, members: Sequence[str]) -> None:
        """Change the group's members (saved)."""
        self._data["members"] = [str(m) for m in members]
        self._changed()

    def set_date(self, date: str) -> None:
        """Change the lab's date (saved)."""
        self._data["date"] = str(date)
        self._changed()

    @property
    def current_step(self) -> str:
        """Id of the step the group is at."""
        return str(self._data["current_step"])

    @property
    def step(self) -> Step:
        """The step the group is at."""
        return lab_steps.step(self.current_step)

    def go_to(self, step_id: str) -> Step:
        """Move to ``step_id`` (KeyError if unknown); saved, so resume comes back here."""
        new = lab_steps.step(step_id)
        self._data["current_step"] = new.id
        self.save()
        return new

    def next_step(self) -> Step:
        """Move one step on (stays at the last)."""
        return self.go_to(STEPS[min(STEP_INDEX[self.current_step] + 1, len(STEPS) - 1)].id)

    def previous_step(self) -> Step:
        """Move one step back (stays at the first)."""
        return self.go_to(STEPS[max(STEP_INDEX[self.current_step] - 1, 0)].id)

    # -- entries -------------------------------------------------------------------------------

    @property
    def entries(self) -> Mapping[str, Entry]:
        """Every entry by field key (read-only view)."""
        return dict(self._entries)

    def entry(self, key: str) -> Entry | None:
        """The entry of field ``key``, or None if nothing was typed there."""
        return self._entries.get(key)

    def value(self, key: str) -> float | None:
        """The accepted SI value of a quantity field, or None."""
        e = self._entries.get(key)
        return e.value if e is not None and e.ok and isinstance(e.value, float) else None

    def enter(self, key: str, text: str, source: str = "typed") -> Entry:
        """Store ``text`` typed in field ``key`` (KeyError for an unknown key) and return the
        entry: accepted with its value, note and warnings, or refused with a one-line message.
        The text is kept either way; the session is saved before this returns."""
        fld = FIELDS[key]
        entry = self._read(fld, text)
        old = self._entries.get(key)
        at = self._clock().isoformat(timespec="seconds")
        if not entry.ok and old is not None and old.ok:
            # keep the accepted entry in effect; remember the refused attempt beside it
            entry = replace(old, refused=(text, entry.message, at))
            self._entries[key] = entry
            self._changed()
            return entry
        history = (*old.history, (old.text, old.at)) if old is not None else ()
        if old is not None and old.refused:
            history = (*history, (old.refused[0], old.refused[2]))
        entry = Entry(
            key=key,
            text=text,
            ok=entry.ok,
            value=entry.value,
            unit=entry.unit,
            message=entry.message,
            warnings=entry.warnings,
            source=source,
            at=at,
            history=history,
        )
        self._entries[key] = entry
        if entry.ok and source != "capture" and key.startswith("omega_ss@"):
            self._captures.pop(key, None)
        self._changed()
        if key.startswith("u_ss@"):
            self._remap_runs()
        return entry

    def choose(self, key: str, options: Sequence[int]) -> Entry:
        """Pick option indices (0-based) of a choice field; saved. Same as typing letters."""
        return self.enter(key, ", ".join(chr(ord("a") + k) for k in options))

    def _read(self, fld: lab_steps.Field, text: str) -> Entry:
        if fld.kind == "text":
            return Entry(fld.key, text, ok=True)
        if not text.strip() and fld.optional:
            return Entry(fld.key, text, ok=True)
        try:
            if fld.kind == "quantity":
                p = parse_quantity(
                    text,
                    fld.unit,
                    label=fld.label,
                    allow_negative=fld.allow_negative,
                    allow_zero=fld.allow_zero,
                )
                warnings = tuple(w for rule in fld.plausible for w in rule.warnings(p.value))
                return Entry(
                    fld.key,
                    text,
                    ok=True,
                    value=p.value,
                    unit=p.unit,
                    message=p.note,
                    warnings=warnings,
                )
            if fld.kind == "formula":
                f = lab_steps.read_formula(fld, text)
                value = f.value({}) if not fld.names else None
                return Entry(fld.key, text, ok=True, value=value)
            try:
                chosen = _parse_choice(text, len(fld.options))
            except ValueError:
                letters = "/".join(chr(ord("a") + k) for k in range(len(fld.options)))
                raise InputError(
                    fld.label,
                    None,
                    f"expected {'one or more of' if fld.multiple else 'one of'} {letters}; got {text.strip()!r}",
                ) from None
            if len(chosen) > 1 and not fld.multiple:
                raise InputError(fld.label, None, f"expected one answer; got {len(chosen)}")
            return Entry(fld.key, text, ok=True, value=chosen)
        except InputError as exc:
            return Entry(fld.key, text, ok=False, message=str(exc))

    def parsed(self) -> dict[str, object]:
        """Accepted values by key, as checks use them (floats, Formulas, option tuples)."""
        out: dict[str, object] = {}
        for key, e in self._entries.items():
            if not e.ok or key not in FIELDS:
                continue
            fld = FIELDS[key]
            if fld.kind == "formula":
                try:
                    out[key] = lab_steps.read_formula(fld, e.text)
                except InputError:
                    continue
            elif e.value is not None:
                out[key] = e.value
        return out

    def feedback(self, step_id: str | None = None) -> list[Feedback]:
        """The verdict on every checked field of ``step_id`` (default: the current step), or of
        all steps with ``step_id="*"``."""
        ids = [s.id for s in STEPS] if step_id == "*" else [step_id or self.current_step]
        values = self.parsed()
        out = []
        for sid in ids:
            for chk in lab_steps.step(sid).checks:
                answer = values.get(chk.key)
                if isinstance(answer, Formula) and not FIELDS[chk.key].names:
                    answer = answer.value({})
                out.append(lab_steps.check_answer(chk, answer, values))
        return out

    def step_status(self, step_id: str) -> str:
        """``done`` (every required field accepted; for Task 10 a run recorded), ``started``
        (something entered), ``todo``, or ``info`` (nothing to enter)."""
        st = lab_steps.step(step_id)
        if "run_steps" in st.actions:
            return "done" if any(r.kind in ("steps", "fast") for r in self._runs) else "todo"
        required = [f for f in st.fields if not f.optional]
        if not st.fields:
            return "info"
        if required and all(
            self._entries.get(f.key) is not None and self._entries[f.key].ok for f in required
        ):
            return "done"
        if any(f.key in self._entries for f in st.fields):
            return "started" if required else "done"
        return "todo"

    # -- the table -----------------------------------------------------------------------------

    def capture_omega(
        self,
        level: float,
        t: Sequence[float],
        omega: Sequence[float],
        window: float = DEFAULT_WINDOW,
        velocity: str = "timestamps",
    ) -> Entry:
        """Task 4: capture omega_ss at requested ``level`` (V) as the mean of the last
        ``window`` s of ``omega`` (rad/s) at times ``t`` (s); stores the capture (spread,
        window) and enters omega_ss@level. ValueError with fewer than 3 samples."""
        key = f"omega_ss@{level:g}"
        if key not in FIELDS:
            raise KeyError(key)
        cap = capture(t, omega, window, velocity)
        self._captures[key] = cap
        return self.enter(key, f"{cap.omega_ss:.4g}", source="capture")

    def capture_of(self, level: float) -> Capture | None:
        """The capture behind omega_ss at ``level``, or None if it was typed or not taken."""
        return self._captures.get(f"omega_ss@{level:g}")

    def table_pairs(self) -> list[tuple[float, float]]:
        """(u_req, u_ss) in V for each row with an accepted u_ss: the driver's mapping."""
        return [(lv, v) for lv in LEVELS if (v := self.value(f"u_ss@{lv:g}")) is not None]

    def readings(self) -> list[Reading]:
        """The complete rows (u_ss, omega_ss and i_ss accepted) as identify's Readings (i_ss in mA)."""
        out = []
        for lv in LEVELS:
            u, w, i = (self.value(f"{n}@{lv:g}") for n in ("u_ss", "omega_ss", "i_ss"))
            if u is not None and w is not None and i is not None:
                out.append(Reading(u_req=lv, u_ss=u, omega_ss=w, i_ss=i * 1e3))
        return out

    def table(self) -> list[TableRow]:
        """The table of Tasks 4-9, one row per requested voltage, k_v and f filled when computable."""
        res = self.results()
        by_level = (
            {r.reading.u_req: r for r in res.identification.rows} if res.identification else {}
        )
        out = []
        for lv in LEVELS:
            cap = self.capture_of(lv)
            row = by_level.get(lv)
            out.append(
                TableRow(
                    level=lv,
                    u_ss=self.value(f"u_ss@{lv:g}"),
                    omega_ss=self.value(f"omega_ss@{lv:g}"),
                    spread=cap.spread if cap else None,
                    window=(cap.t0, cap.t1) if cap else None,
                    i_ss=self.value(f"i_ss@{lv:g}"),
                    k_v=row.k_v if row else None,
                    f=row.f if row else None,
                )
            )
        return out

    # -- results -------------------------------------------------------------------------------

    def results(self) -> Results:
        """Tasks 6-15 from the current entries and the chosen run (cached until R, a table
        value or the run changes)."""
        run = self.step_run()
        key = (
            self.value("R"),
            tuple(self.readings()),
            run.name if run else None,
            self._run_version,
        )
        if self._results is not None and self._results[0] == key:
            return self._results[1]
        res = self._compute()
        self._results = (key, res)
        return res

    def _compute(self) -> Results:
        problems: list[str] = []
        R = self.value("R")
        if R is None:
            problems.append("R is not entered yet (Task 2)")
        readings = []
        for r in self.readings():
            why = r.problem()
            if why:
                problems.append(f"row {r.u_req:g} V left out: {why}")
            else:
                readings.append(r)
        if not readings:
            problems.append("no complete row in the table yet (u_ss, omega_ss and i_ss; Tasks 4-5)")
        run = self.step_run()
        log: StepLog | None = None
        if run is not None:
            try:
                log = read_step_log(self.folder / run.file)
            except InputError as exc:
                problems.append(f"run {run.name} cannot be used: {exc}")
        if R is None or not readings:
            return Results(None, run.name if run and log else None, tuple(problems))
        try:
            ident = identify(readings, R, log, source="table")
        except InputError as exc:
            if log is None:
                return Results(None, None, (*problems, str(exc)))
            problems.append(f"run {run.name if run else ''} gives no step result: {exc}")
            try:
                ident = identify(readings, R, None, source="table")
            except InputError as exc2:
                return Results(None, None, (*problems, str(exc2)))
            return Results(ident, None, tuple(problems))
        return Results(ident, run.name if (run and log is not None) else None, tuple(problems))

    def model_check(self, name: str | None = None) -> ModelCheck:
        """The model check (:func:`minseg_tui.model.check.check`) of run ``name`` (default: the
        run Tasks 11-15 use): measured against the first-order model, the named cause, the
        extended model and the gain. Cached until something changes."""
        run = (
            self.step_run()
            if name is None
            else next((r for r in self._runs if r.name == name), None)
        )
        if run is None:
            return ModelCheck(
                None,
                None,
                "no step run recorded yet (Task 10)" if name is None else f"no run {name}",
            )
        key = (self._run_version, run.name)
        cached = self._checks.get(key)
        if cached is not None:
            return cached
        try:
            log = read_step_log(self.folder / run.file)
            result = ModelCheck(run.name, check(log.t, log.u, log.omega, ts=run.ts))
        except InputError as exc:
            result = ModelCheck(run.name, None, str(exc))
        except ValueError as exc:
            result = ModelCheck(run.name, None, f"run {run.name}: {exc}")
        self._checks = {key: result}
        return result

    def warnings(self, step_id: str | None = None) -> list[Notice]:
        """Plausibility warnings of the entries (of ``step_id``, or all) and, for all or the
        table and results steps, what the numbers show (identify's findings)."""
        keys = {f.key for f in lab_steps.step(step_id).fields} if step_id else None
        out = [
            Notice(k, w)
            for k, e in self._entries.items()
            if keys is None or k in keys
            for w in e.warnings
        ]
        if step_id is None or lab_steps.step(step_id).part in ("Table", "Results", "Step response"):
            res = self.results()
            if res.identification:
                out += [Notice(f.code, f.message) for f in res.identification.observations]
        return out

    def comparisons(self, step_id: str | None = None) -> list[Comparison]:
        """Each of the group's own readings (fields with ``compare``) beside the computed value."""
        res = self.results()
        fields = lab_steps.step(step_id).fields if step_id else [f for s in STEPS for f in s.fields]
        out = []
        for fld in fields:
            if not fld.compare:
                continue
            e = self._entries.get(fld.key)
            own: float | str | None
            if fld.kind == "text":
                own = e.text if e and e.text.strip() else None
            else:
                own = self.value(fld.key)
            computed = res.lookup(fld.compare)
            rel = None
            if isinstance(own, float) and isinstance(computed, float) and computed != 0:
                rel = own / computed - 1.0
            out.append(Comparison(fld.key, fld.label, fld.unit, own, computed, rel))
        return out

    # -- runs ----------------------------------------------------------------------------------

    @property
    def runs(self) -> list[RunInfo]:
        """Every recorded run, oldest first."""
        return list(self._runs)

    def run_path(self, name: str) -> Path:
        """The step-log CSV of run ``name``."""
        for r in self._runs:
            if r.name == name:
                return self.folder / r.file
        raise KeyError(name)

    def load_run(self, name: str) -> StepLog:
        """Run ``name`` read back as a StepLog (InputError if its file is damaged)."""
        return read_step_log(self.run_path(name), require_step=False)

    def step_run(self) -> RunInfo | None:
        """The run Tasks 11-15 use: the selected one, else the latest step run."""
        sel = self._data.get("selected_run")
        for r in self._runs:
            if r.name == sel:
                return r
        for r in reversed(self._runs):
            if r.kind in ("steps", "fast", "imported"):
                return r
        return None

    def select_run(self, name: str | None) -> None:
        """Use run ``name`` for Tasks 11-15 (None: the latest step run); saved."""
        if name is not None:
            self.run_path(name)
        self._data["selected_run"] = name
        self._run_version += 1
        self._changed()

    def _new_name(self, kind: str) -> str:
        taken = {r.name for r in self._runs} | {
            p.name.split(".")[0] for p in (self.folder / RUNS_DIR).iterdir()
        }
        k = 1
        while f"{kind}-{k}" in taken:
            k += 1
        return f"{kind}-{k}"

    def start_run(
        self,
        kind: str = "steps",
        plan: RunPlan | None = None,
        ts: float | None = None,
        flush_interval: float | None = None,
    ) -> Recorder:
        """Begin recording a run (``steps``/``fast`` for Task 10, ``free`` otherwise); returns
        the Recorder to append samples to. Nothing is lost to a crash beyond its flush interval."""
        if self.readonly:
            raise InputError(str(self.folder), None, "this session was opened read-only")
        name = self._new_name(kind)
        ts_ = ts if ts is not None else (plan.ts if plan else 0.025)
        header = {
            "name": name,
            "kind": kind,
            "ts": ts_,
            "started": self._clock().isoformat(timespec="seconds"),
            "plan": {
                k: float(getattr(plan, k)) for k in ("low", "high", "half_period", "periods", "ts")
            }
            if plan
            else {},
        }
        kwargs = {} if flush_interval is None else {"flush_interval": flush_interval}
        return Recorder(self.folder / RUNS_DIR / f"{name}{PARTIAL_SUFFIX}", header, **kwargs)

    def finish_run(self, recorder: Recorder) -> RunInfo | None:
        """End a recording: its samples become runs/<name>.csv (atomically), the session
        records the run (saved) and the partial file goes. None (and nothing kept) when it
        holds fewer than 2 samples."""
        recorder.close()
        return self._adopt(recorder.path, interrupted=False)

    def discard_run(self, recorder: Recorder) -> None:
        """Throw a recording away (the partial file is removed)."""
        recorder.close()
        recorder.path.unlink(missing_ok=True)

    def _adopt(self, partial: Path, interrupted: bool) -> RunInfo | None:
        raw = read_partial(partial)
        name = partial.name[: -len(PARTIAL_SUFFIX)]
        if any(r.name == name for r in self._runs):
            partial.unlink(missing_ok=True)
            return None
        if raw.seq.size < 2:
            partial.unlink(missing_ok=True)
            return None
        ts = float(raw.header.get("ts", 0.025))  # type: ignore[arg-type]
        log, dropped = build_log(raw, self.table_pairs(), ts)
        file = f"{RUNS_DIR}/{name}.csv"
        write_log_atomic(self.folder / file, log)
        plan = raw.header.get("plan") or {}
        info = RunInfo(
            name=name,
            file=file,
            kind=str(raw.header.get("kind", "free")),
            ts=ts,
            samples=len(log),
            dropped=dropped,
            started=str(raw.header.get("started", "")),
            interrupted=interrupted,
            plan={str(k): float(v) for k, v in dict(plan).items()},  # type: ignore[call-overload]
        )
        self._runs.append(info)
        self._run_version += 1
        self._changed()
        partial.unlink(missing_ok=True)
        return info

    def _recover_runs(self) -> None:
        for partial in sorted((self.folder / RUNS_DIR).glob(f"*{PARTIAL_SUFFIX}")):
            info = self._adopt(partial, interrupted=True)
            if info is not None:
                self.recovered.append(info.name)

    def import_run(self, path: Path) -> RunInfo:
        """Copy a step log recorded elsewhere into runs/ (checked by read_step_log; InputError
        with file and line if it is not one) for the model check and Tasks 11-15."""
        log = read_step_log(Path(path))
        name = self._new_name("imported")
        file = f"{RUNS_DIR}/{name}.csv"
        write_log_atomic(
            self.folder / file,
            StepLog(
                t=log.t,
                u=log.u,
                omega=log.omega,
                extra=log.extra,
                metadata={**log.metadata, "imported_from": str(path)},
            ),
        )
        info = RunInfo(
            name=name,
            file=file,
            kind="imported",
            ts=log.ts,
            samples=len(log),
            dropped=0,
            started=self._clock().isoformat(timespec="seconds"),
        )
        self._runs.append(info)
        self._run_version += 1
        self._changed()
        return info

    def _remap_runs(self) -> None:
        table = self.table_pairs()
        for r in self._runs:
            if r.kind == "imported":
                continue
            path = self.folder / r.file
            if path.exists():
                try:
                    remap_log(path, table)
                except InputError:
                    continue
        self._run_version += 1


__all__ = ["Comparison", "Entry", "ModelCheck", "Notice", "Results", "Session", "TableRow"]
