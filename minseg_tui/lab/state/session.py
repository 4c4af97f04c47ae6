"""A lab session: who, when, where the group is, everything typed, captured and recorded.

The UI holds one :class:`Session`, renders its state and calls its methods; it does no
arithmetic and no file I/O of its own. Every change is saved at once (atomically, see
:mod:`minseg_tui.lab.saving.store`); reopening a session restores it exactly, current step
included. Derived numbers (Tasks 6-15) are never stored: :meth:`Session.results`
computes them from the entries and the chosen run with :mod:`minseg_tui.model.identify`,
so changing an earlier entry changes every later result.

The session holds the state and saves it; its parts are modules of their own:
:mod:`~minseg_tui.lab.state.entries` (what was typed, read and revised),
:mod:`~minseg_tui.lab.state.results` (Tasks 6-15, the table, the model check),
:mod:`~minseg_tui.lab.saving.runs` (recording and keeping runs), :mod:`~minseg_tui.lab.saving.store`
(the files on disk, the lock, what a failed save is), :mod:`~minseg_tui.lab.saving.schema`
(the session file's one schema) and :mod:`~minseg_tui.lab.content.answers` (checking answers).

A save that fails never raises: the session goes on in memory and says why in
:attr:`Session.save_problem` (see :class:`Session`).

Units: entries are stored as typed (``text``) and as parsed SI values (``value``: V, A,
ohm, rad/s, s, ...); the form unit of each field is in :mod:`minseg_tui.lab.content.steps`.

Typical use::

    s = Session.create(Path("sessions"), ["Ada", "Bo"])     # or Session.open(folder)
    s.enter("R", "5,2 Ω")                                   # -> Entry (ok, value 5.2, warnings)
    s.capture_omega(2.5, t, omega)                          # Task 4, from live samples
    rec = s.start_run("steps", plan)                        # Task 10
    rec.append(seq, t_us, count, u_mV) ...
    s.finish_run(rec)
    s.results().identification.k_v                          # Tasks 6-15
    if s.save_problem: print(s.save_problem.line)           # not on disk yet: s.save() retries
    s.close()
"""

from __future__ import annotations

import contextlib
import json
import re
import threading
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from minseg_tui.errors import InputError
from minseg_tui.lab.content import answers
from minseg_tui.lab.content import meter as lab_meter
from minseg_tui.lab.content import steps as lab_steps
from minseg_tui.lab.content.expr import Formula
from minseg_tui.lab.content.identify_says import sentence, u_ss_not_entered
from minseg_tui.lab.content.steps import (
    FIELDS,
    LEVELS,
    STEP_INDEX,
    STEPS,
    Feedback,
    Field,
    RunPlan,
    Step,
)
from minseg_tui.lab.saving import kept as kept_results
from minseg_tui.lab.saving.kept import Kept, ResponseFigures
from minseg_tui.lab.saving.runs import (
    FLUSH_INTERVAL,
    PARTIAL_SUFFIX,
    RESPONSE_KINDS,
    ChangedFile,
    LogCache,
    RawRun,
    Recorder,
    RunInfo,
    changed_file,
    import_log,
    keep_run,
    new_name,
    pasted_path,
    read_partial,
    read_run,
    run_header,
    ts_of,
)
from minseg_tui.lab.saving.schema import KIND, RUN_NAME, SCHEMA
from minseg_tui.lab.saving.store import (
    RUNS_DIR,
    SESSION_FILE,
    SaveProblem,
    SessionNotWritable,
    atomic_write_bytes,
    atomic_write_text,
    clean_leftovers,
    exists,
    new_session_folder,
    os_reason,
    read_regular,
    read_session_file,
    salvage_session_file,
    take_lock,
)
from minseg_tui.lab.state import shown as lab_shown
from minseg_tui.lab.state.capture import DEFAULT_WINDOW, Capture, capture
from minseg_tui.lab.state.compare import (
    ANSWERED_FIRST,
    STEP_LEVEL,
    Policy,
    compare_fields,
    read_policy,
    reveal_keys,
)
from minseg_tui.lab.state.entries import Entry, check_stored, parsed_values, read_entry, revise
from minseg_tui.lab.state.results import (
    Comparison,
    ModelCheck,
    Notice,
    Results,
    TableRow,
    check_figures,
    check_run,
    compute,
    falling_currents,
    response_figures,
)
from minseg_tui.lab.state.shown import PolicyRecord, Shown
from minseg_tui.lock import FileLock
from minseg_tui.model.identify import Reading
from minseg_tui.model.plant import MeterReading
from minseg_tui.model.runlog import RunLog
from minseg_tui.quantities import format_number, format_reading, shown_unit

Clock = Callable[[], datetime]


def _now() -> datetime:
    return datetime.now(UTC)


SLUG_MAX = 80
"""Most characters of a session folder's name made from the date and the names (a file
name may have 255 bytes: a group that typed 300 characters of names got 'cannot make a
session folder here (File name too long)', s39 attack); the names are kept whole in the
session file."""


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:SLUG_MAX].rstrip("-")


class _Cache:
    """What a session computed (Tasks 6-15, the model checks), each under the key of what it
    was computed from; shared by a session and its snapshots, so a view built from a snapshot
    is not computed again by the next one. Each attribute is replaced whole (never changed
    in place), so threads may share it."""

    def __init__(self) -> None:
        self.results: tuple[object, Results] | None = None
        self.checks: dict[tuple[int, str], ModelCheck] = {}
        self.kept: tuple[tuple[int, str], Kept] | None = None
        """What the session file is to keep of the run in use, stamped with the run version
        and the run's name it was computed at (:meth:`Session.save` writes it while they
        still hold)."""
        self.kept_lock = threading.Lock()
        """Held while a part is merged into :attr:`kept` (the results and the model check
        may be computed by two workers at once: neither part is lost)."""
        self.logs = LogCache()
        """The run logs read, each parsed once while its file stays as it was (an import's
        copy held as the import read it)."""


READ_ONLY = "this session was opened read-only"
"""Why a change of a session opened read-only is refused (the class view opens every
session so; the start screen a damaged one)."""

MAX_RUN_COPY = 64 * 2**20
"""Largest run file (bytes) a session holds a copy of in memory (a 12 s run at 5 ms is
about 0.3 MB; a log larger than this is not held: its file is all there is)."""

MAX_RUN_COPIES = 256 * 2**20
"""Most bytes of run files a session holds in all (the runs past it are not held)."""

NO_RUN_YET = "no run recorded yet (Task 10)"
"""What stands in for the model check and the class's figures before any run is recorded
(the square wave of Task 10 records one)."""


EDITED_R = (
    "R (Task 2) counts for nothing: session.json holds a value there that its text does not read as"
)
"""Why nothing is computed from R when its entry was edited by hand (said with the results'
other missing inputs; the entry's own line says what the file holds)."""


class SessionFrozen(RuntimeError):
    """A change asked of a snapshot (:meth:`Session.snapshot`): a program error."""


@dataclass(frozen=True)
class Moved:
    """Where :meth:`Session.move_to` put the session, and the run files it could not
    bring (one line each: the file and why; the run stays listed, its log missing)."""

    folder: Path
    left_behind: tuple[str, ...] = ()


class Session:
    """One group's lab session, saved in its folder after every change.

    Create with :meth:`create` or :meth:`open`; close with :meth:`close` (or use ``with``).
    A session opened with ``readonly=True`` (for reports) takes no lock and never writes;
    if its file breaks the schema, what is sound is shown and :attr:`damaged` says what
    is not.

    A save that fails (a full disk, a read-only folder, a drive pulled out) never raises
    and never loses anything: the session keeps working in memory, :attr:`save_problem`
    says in one line what is wrong and where it will save, every change (and every call
    of :meth:`save`) tries again, and :meth:`move_to` saves it in another folder.
    """

    def __init__(
        self,
        folder: Path,
        data: dict[str, Any],
        *,
        lock: FileLock | None,
        clock: Clock,
        readonly: bool,
    ) -> None:
        self.folder = Path(folder)
        self._data = data
        self._lock = lock
        self._clock = clock
        self.readonly = readonly
        self._entries: dict[str, Entry] = {
            k: check_stored(Entry.from_json(k, v)) for k, v in data["entries"].items()
        }
        # entries marked edited by hand, as the file holds them: saved as they are until the
        # field is typed again (nothing the file holds is thrown away by opening it)
        self._as_stored: dict[str, Any] = {
            k: data["entries"][k] for k, e in self._entries.items() if e.edited
        }
        self._captures: dict[str, Capture] = {
            k: Capture.from_json(v) for k, v in data["captures"].items()
        }
        self._runs: list[RunInfo] = [RunInfo.from_json(r) for r in data["runs"]]
        self._cache = _Cache()
        self._meter_seen: dict[str, tuple[float, ...]] = {}
        """What the virtual multimeter last showed for each reading field (SI, the newest
        :data:`~minseg_tui.lab.content.meter.KEPT`), while this program runs: it is saved
        with the entry typed (:attr:`Entry.meter`), never on its own."""
        self.frozen = False
        """A snapshot (:meth:`snapshot`): it reads as the session did, and changes nothing."""
        self._run_version = 0
        self._problem: SaveProblem | None = None
        self._unsaved = False
        # finished recordings whose log is not written yet, and whether each stopped early
        self._unkept: list[tuple[Recorder, bool, str]] = []
        self._copies: dict[str, bytes] = {}
        # the bytes of each run file as written (or found at open), by run name, held while
        # the session is open: a file deleted by hand is written back from them (s37 attack)
        self._lost: set[str] = set()  # runs said to be gone with no copy held (said once)
        self._unrestored = False  # a run file deleted by hand could not be written back yet
        self._restored: list[str] = []  # lines of restore_runs not yet taken
        self.recovered: list[str] = []
        """Names of runs rebuilt at open from a recording a crash interrupted."""
        self.recovery_notes: list[str] = []
        """One line for each thing opening had to mend: leftovers removed, a damaged run
        header (the run rebuilt without it), a recording that could not be kept yet."""
        self.damaged: str | None = None
        """For a read-only session whose file breaks the schema: what was left out, in one
        line (None when the file is sound)."""

    # -- life cycle and saving -----------------------------------------------------------------

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
        unique with ``-2``, ``-3``, ... SessionNotWritable (one line) when no session can
        be made under ``root``; a first save that fails is a :attr:`save_problem`.
        """
        root = Path(root)
        now = clock()
        date = date or now.date().isoformat()
        base = session_id or _slug(f"{date} {' '.join(members)}") or "session"
        if session_id and exists(root / session_id):
            raise InputError(
                str(root / session_id),
                None,
                "a session with this id exists already; open it or pick another id",
            )
        folder, lock = new_session_folder(root, base)
        stamp = now.isoformat(timespec="seconds")
        data: dict[str, Any] = {
            "kind": KIND,
            "schema": SCHEMA,
            "id": folder.name,
            "members": [str(m) for m in members],
            "date": date,
            "created": stamp,
            "modified": stamp,
            "current_step": STEPS[0].id,
            "selected_run": None,
            "entries": {},
            "captures": {},
            "runs": [],
            "shown": {},
            "shown_since": stamp,
        }
        s = cls(folder, data, lock=lock, clock=clock, readonly=False)
        s.note_policy(save=False)
        s.save()
        return s

    @classmethod
    def open(cls, folder: Path, clock: Clock = _now, readonly: bool = False) -> Session:
        """Open the session in ``folder``: take its lock (SessionLocked if another program
        has it; SessionNotWritable if the folder cannot be written), read it (SessionMissing
        / SessionDamaged with one line; a damaged file is never written over), remove what
        a killed program left and rebuild any run a crash interrupted.

        ``readonly=True`` takes no lock and writes nothing; a file that breaks the schema
        then opens with what is sound in it (:attr:`damaged` says what is not).
        """
        folder = Path(folder)
        if readonly:
            data, damaged = salvage_session_file(folder / SESSION_FILE)
            s = cls(folder, data, lock=None, clock=clock, readonly=True)
            s.damaged = damaged
            return s
        if not exists(folder / SESSION_FILE):
            read_session_file(folder / SESSION_FILE)  # raises SessionMissing
        try:
            lock = take_lock(folder)
        except OSError as exc:
            raise SessionNotWritable(
                str(folder),
                None,
                f"the session folder cannot be written ({os_reason(exc)}): open it read-only "
                "(minseg-tui report) or copy the folder where it can be written",
            ) from None
        try:
            data = read_session_file(folder / SESSION_FILE)
            s = cls(folder, data, lock=lock, clock=clock, readonly=False)
            s.recovery_notes += [
                f"removed {name}, left by a program that was killed"
                for name in clean_leftovers(folder)
            ]
            with contextlib.suppress(OSError):
                (folder / RUNS_DIR).mkdir(exist_ok=True)
            s._recover_runs()
            s._hold_copies()
            s._start_records()
        except BaseException:
            lock.release()
            raise
        return s

    def close(self) -> None:
        """Try a last save if something is not on disk, and release the lock. What could
        not be saved is lost with the program: ask :attr:`unsaved` (and offer
        :meth:`move_to`) before closing."""
        if self._lock is not None:
            if self.unsaved:
                self.save()
            elif self._take_kept():  # results computed since the last save: a memo, so
                with contextlib.suppress(OSError):  # its time stays that of the last change
                    self._write_file()
            self._lock.release()
            self._lock = None

    def __enter__(self) -> Session:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def snapshot(self) -> Session:
        """A frozen copy of the session as it stands now, for another thread (a worker that
        builds a view or writes the report): it reads as the session does (entries, runs,
        results, the model check, its folder), shares nothing the session changes, and
        refuses every change (:class:`SessionFrozen`). It holds no lock; what it computes
        is kept for the session too (the same inputs give the same results)."""
        data = {k: v for k, v in self._data.items() if k not in ("entries", "captures", "runs")}
        snap = Session(
            self.folder,
            {**json.loads(json.dumps(data)), "entries": {}, "captures": {}, "runs": []},
            lock=None,
            clock=self._clock,
            readonly=True,
        )
        snap._entries = dict(self._entries)  # Entry, Capture and RunInfo are frozen
        snap._as_stored = dict(self._as_stored)
        snap._captures = dict(self._captures)
        snap._runs = list(self._runs)
        snap._cache = self._cache
        snap._run_version = self._run_version
        snap._problem = self._problem
        snap._unsaved = self.unsaved
        snap.readonly = self.readonly
        snap.damaged = self.damaged
        snap.recovered = list(self.recovered)
        snap.recovery_notes = list(self.recovery_notes)
        snap.frozen = True
        return snap

    def _change(self) -> None:
        """Refuse a change of a snapshot (before anything is changed)."""
        if self.frozen:
            raise SessionFrozen(f"a snapshot of session {self.id} is not changed")

    def _writable(self) -> None:
        """Refuse a change of a snapshot or of a session opened read-only, before anything
        is changed (walk 14, D1: a read-only session took the change in memory, an imported
        log into its runs/ folder, and only its save refused, with an error nothing caught)."""
        self._change()
        if self.readonly:
            raise InputError(str(self.folder), None, READ_ONLY)

    @property
    def save_problem(self) -> SaveProblem | None:
        """Why the session is not all on disk (``.line``: one line for the status bar), or
        None when it is."""
        return self._problem

    @property
    def unsaved(self) -> bool:
        """True while a change or a finished run is only in memory."""
        return self._unsaved or bool(self._unkept) or self._unrestored

    def save(self, memo: bool = False) -> bool:
        """Write everything not yet on disk: runs kept since the last save that worked,
        session.json (atomically). True when all is on disk. A failed write never raises: it becomes :attr:`save_problem`, and the
        next change or call of :meth:`save` tries again (call it every few seconds while
        there is a problem). ``memo``: what is saved is a record, not a change of the group's
        (what they were shown, the lab's policy): the time of the last change stays."""
        self._change()
        if self.readonly:
            raise InputError(str(self.folder), None, READ_ONLY)
        ok = True
        try:
            self._keep_unkept()
        except OSError as exc:  # the file still lists what is on disk; the rest waits
            self._failed(exc)
            ok = False
        if not self.restore_runs():  # held in memory still; the next save tries again
            ok = False
        self._data["entries"] = {
            k: self._as_stored[k] if k in self._as_stored else e.to_json()
            for k, e in self._entries.items()
        }
        self._data["captures"] = {k: c.to_json() for k, c in self._captures.items()}
        self._data["runs"] = [r.to_json() for r in self._runs]
        if not memo:
            self._data["modified"] = self._clock().isoformat(timespec="seconds")
        self._take_kept()
        try:
            self._write_file()
        except OSError as exc:
            self._unsaved = True
            self._failed(exc)
            return False
        self._unsaved = False
        if ok:
            self._problem = None
        return ok

    def _write_file(self) -> None:
        """session.json from ``_data``, atomically (OSError when it cannot be written)."""
        atomic_write_text(
            self.folder / SESSION_FILE,
            json.dumps(self._data, indent=1, ensure_ascii=False) + "\n",
        )

    def _take_kept(self) -> bool:
        """Put into ``_data`` what the session computed of the run in use and the file does
        not keep yet (merged with the file's record of the same key); True when it did."""
        got = self._cache.kept
        run = self.response_run()
        if got is None or run is None or got[0] != (self._run_version, run.name):
            return False
        old = kept_results.from_json(self._data.get("kept"))
        new = got[1] if old is None else old.merged(got[1])
        as_json = new.to_json()
        if self._data.get("kept") == as_json:
            return False
        self._data["kept"] = as_json
        return True

    def _note_kept(
        self,
        run: RunInfo,
        table: Sequence[tuple[float, float]],
        step: ResponseFigures | None = None,
        check: ModelCheck | None = None,
    ) -> None:
        """Note what the session file is to keep of ``run`` (the run in use, read through
        ``table``): Tasks 11-13's numbers or the model check in brief. Shared with the
        session's snapshots, written by its next save (or its close); a read-only session
        notes nothing (it never writes)."""
        if self.readonly or run != self.response_run():
            return
        key = kept_results.run_key(self.folder, run, table)
        if key is None:
            return
        new = Kept(run.name, key, step, None if check is None else check_figures(check))
        stamp = (self._run_version, run.name)
        with self._cache.kept_lock:
            got = self._cache.kept
            self._cache.kept = (stamp, got[1].merged(new) if got and got[0] == stamp else new)

    def kept(self) -> Kept | None:
        """What the session file keeps of the run in use (its model check in brief and Tasks
        11-13's numbers), when it was computed from this very run and table; else None."""
        got = kept_results.read(
            self._data.get("kept"), self.folder, self.response_run(), self.table_pairs()
        )
        if got is not None and got.check is not None and self.check_run() != self.response_run():
            return replace(got, check=None)  # the model check is of another run (an import)
        return got

    def _failed(self, exc: OSError) -> None:
        old = self._problem
        self._problem = SaveProblem(
            folder=self.folder,
            reason=os_reason(exc),
            since=old.since if old else self._clock().isoformat(timespec="seconds"),
            attempts=(old.attempts if old else 0) + 1,
        )

    def _changed(self) -> None:
        self.save()

    def move_to(self, root: Path) -> Moved:
        """Save the session in a new folder under ``root`` (named by its id, made unique),
        lock it there and go on there; the old folder is left as it is (and unlocked). The
        run files come along where they can be read. SessionNotWritable (one line, nothing
        changed) when ``root`` cannot take it."""
        self._change()
        if self.readonly:
            raise InputError(str(self.folder), None, READ_ONLY)
        # the id as a folder name of its own: a file saying '../x' must not leave ``root``
        folder, lock = new_session_folder(Path(root), _slug(self.id) or "session")
        left: list[str] = []
        for r in self._runs:
            try:
                held = self._copies.get(r.name)
                atomic_write_bytes(
                    folder / r.file,
                    held if held is not None else (self.folder / r.file).read_bytes(),
                )
            except OSError as exc:
                left.append(f"{r.file}: {os_reason(exc)}")
        old_folder, old_lock, old_id = self.folder, self._lock, self._data["id"]
        self.folder, self._lock, self._data["id"] = folder, lock, folder.name
        if not self.save():
            why = self._problem.reason if self._problem else "unknown"
            self.folder, self._lock, self._data["id"] = old_folder, old_lock, old_id
            self._problem = replace(self._problem, folder=old_folder) if self._problem else None
            lock.release()
            raise SessionNotWritable(str(folder), None, f"cannot save the session here ({why})")
        if old_lock is not None:
            old_lock.release()
        self._run_version += 1
        return Moved(folder, tuple(left))

    # -- who, when, where ----------------------------------------------------------------------

    @property
    def id(self) -> str:
        """The session's id: its folder's name. A folder copied (or renamed) holds a file
        that still says the first folder's id; the copy is named by its own folder, as the
        class view names it, so its report does not name the session it was copied from
        (walk 16's D1)."""
        return self.folder.name

    @property
    def members(self) -> tuple[str, ...]:
        """The group's members."""
        return tuple(self._data["members"])

    @property
    def date(self) -> str:
        """The lab's date (ISO)."""
        return str(self._data["date"])

    @property
    def created(self) -> str:
        """When the session was created (ISO time)."""
        return str(self._data["created"])

    @property
    def modified(self) -> str:
        """ISO time of the last change."""
        return str(self._data["modified"])

    def set_members(self, members: Sequence[str]) -> None:
        """Change the group's members (saved); the names they replace are kept, in
        :attr:`former_members` (a misspelt name mended: the instructor can see it was)."""
        self._writable()
        old = [str(m) for m in self._data["members"]]
        new = [str(m) for m in members]
        if new != old:
            self._data.setdefault("former_members", []).append(", ".join(old))
        self._data["members"] = new
        self._changed()

    @property
    def former_members(self) -> tuple[str, ...]:
        """The names the group had before each :meth:`set_members`, oldest first (each the
        names joined by ', ')."""
        return tuple(str(m) for m in self._data.get("former_members", []))

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
        self._writable()
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

    def reading(self, key: str) -> str | None:
        """The group's accepted value of quantity field ``key`` wherever it is quoted back to
        them: the digits they gave, in the one unit its quantity is shown in (the field's,
        T and f in theirs: :func:`~minseg_tui.quantities.shown_unit`): "57ms" and "0,057" are
        "57 ms", never "57.00 ms" or "0.057 s"; "80 rpm" is "8.378 rad/s", "0.0372 A"
        "37.2 mA" (:func:`~minseg_tui.quantities.format_reading`); None when there is none."""
        e = self._entries.get(key)
        if e is None or not e.ok or not isinstance(e.value, float) or key not in FIELDS:
            return None
        return format_reading(e.value, shown_unit(FIELDS[key].unit), typed=e.text)

    def enter(self, key: str, text: str, source: str = "typed") -> Entry:
        """Store ``text`` typed in field ``key`` (KeyError for an unknown key) and return the
        entry: accepted with its value, note and warnings, or refused with a one-line message.
        The text is kept either way, and saved before this returns (or, when the save
        fails, kept in memory and said by :attr:`save_problem`). A blank text where nothing
        was entered (a Space meant for a 'done?' tick that went into a note) is no entry:
        nothing is stored, and the step stays as it was."""
        self._writable()
        read = read_entry(FIELDS[key], text)
        old = self._entries.get(key)
        if old is None and read.ok and not text.strip():
            return read
        entry = revise(old, read, source, self._clock().isoformat(timespec="seconds"))
        self._as_stored.pop(key, None)  # typed again: what the hand edit left is history
        seen = self._meter_seen.get(key)
        if seen and entry.ok and entry.refused is None and source == "typed":
            # what the virtual meter showed when the group typed it: the fact it is judged by
            entry = replace(entry, meter=tuple(sorted(set(seen))))
        if key in ANSWERED_FIRST and entry.ok and entry.refused is None and entry.text.strip():
            # the run it is given on: judged against another, it is said to be judged again
            run = self.response_run()
            entry = replace(entry, run=run.name if run is not None else "")
        self._entries[key] = entry
        if (
            entry.ok
            and entry.refused is None
            and source != "capture"
            and key.startswith("omega_ss@")
        ):
            self._captures.pop(key, None)
        if key.startswith("u_ss@") and entry.refused is None:
            self._run_version += 1  # the runs' applied voltage follows the table when read
        self._changed()
        return entry

    def note_meter(
        self, step_id: str, requested: float | None, held: float, reading: MeterReading
    ) -> None:
        """What the virtual multimeter shows now, while step ``step_id`` is shown, the request
        ``requested`` V (None: none, or the square wave) standing for ``held`` s: kept for the
        step's reading fields it is a reading of (R on Task 2; u_ss and i_ss of the voltage
        requested, once it has stood :data:`~minseg_tui.lab.content.meter.SETTLE_S`), so that
        a value typed there is judged against what the meter showed (:meth:`enter`). Kept in
        memory only; nothing is saved. On a real board it is never called: nothing changes."""
        if step_id not in STEP_INDEX:
            return
        for fld in lab_steps.step(step_id).fields:
            if fld.unit not in lab_meter.DISPLAYS:
                continue
            if fld.level is not None and (requested != fld.level or held < lab_meter.SETTLE_S):
                continue
            seen = (*self._meter_seen.get(fld.key, ()), lab_meter.shown(fld.unit, reading))
            self._meter_seen[fld.key] = seen[-lab_meter.KEPT :]

    def withdraw_refused(self, key: str) -> bool:
        """Escape in field ``key``: the refused text shown there is dropped (the group took
        it back), so the field holds what is in effect again: the accepted answer the refusal
        stood over, or nothing when no answer was ever accepted. Saved. Whether anything was
        dropped."""
        self._writable()
        e = self._entries.get(key)
        if e is None or (e.ok and e.refused is None) or e.edited:
            return False  # an entry edited by hand stays until the field is typed again
        if e.ok:
            self._entries[key] = replace(e, refused=None)
        else:
            del self._entries[key]
        self._changed()
        return True

    def choose(self, key: str, options: Sequence[int]) -> Entry | None:
        """Pick option indices (0-based) of a choice field; saved. Same as typing letters.
        No option (every box of a list to tick unticked): the question is not answered any
        more, as the list shows it (None); its earlier answer is not kept in effect."""
        if options:
            return self.enter(key, ", ".join(chr(ord("a") + k) for k in options))
        if key not in FIELDS:
            raise KeyError(key)
        self._writable()
        if self._entries.pop(key, None) is not None:
            self._as_stored.pop(key, None)
            self._changed()
        return None

    def parsed(self) -> dict[str, object]:
        """Accepted values by key, as checks use them (floats, Formulas, option tuples)."""
        return parsed_values(self._entries)

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
                out.append(answers.check_answer(chk, answer, values))
            out += self._meter_verdicts(lab_steps.step(sid))
        return out

    def _meter_verdicts(self, st: Step) -> list[Feedback]:
        """The readings of step ``st`` typed while the virtual multimeter was shown, each judged
        against what it showed (:attr:`Entry.meter`); none on a real board."""
        out = []
        for fld in st.fields:
            e = self._entries.get(fld.key)
            if e is not None and e.meter and e.ok and isinstance(e.value, float):
                out.append(lab_meter.judge(fld, e.value, e.text, e.meter))
        return out

    def step_status(self, step_id: str) -> str:
        """``done`` (every required field accepted; for Task 10 a complete run recorded, an
        interrupted one alone ``started``; for a step
        done by board checks, its ``done_when`` checks passed), ``wrong``
        (answered, but a checked answer is wrong), ``refused`` (a field shows a text that was
        refused, even over an accepted answer still in effect), ``warned`` (answered, but an
        entry stored with a warning the program itself gives, e.g. a u_ss above the requested
        voltage, which the driver cannot give, or a value right the group's way that rests on
        one of theirs marked wrong, Task 14's model with their wrong T: not done until the
        group looks again; a wrong answer stays ``wrong``; a reading of Tasks 2, 4 and 5 that
        is not what the virtual multimeter showed makes its step ``wrong`` at once, the
        others not yet typed), ``started`` also for a step of
        Tasks 11-15 with one of its own values given and another not (Task 11's K),
        ``unjudged`` (a step of the
        group's own values, Tasks 6-9 and 11-15, answered, one of them stored but not judged
        yet: nothing computed to compare it with), ``started`` (something entered), ``todo``,
        or ``info`` (nothing to enter)."""
        st = lab_steps.step(step_id)
        if "run_square_wave" in st.actions:  # an interrupted run alone: started (walk 14)
            runs = [r for r in self._runs if r.kind in ("steps", "fast")]
            return "done" if any(r.complete for r in runs) else "started" if runs else "todo"
        shown = [self._entries.get(f.key) for f in st.fields]
        if any(e is not None and (e.refused is not None or not e.ok) for e in shown):
            return "refused"
        required = [f for f in st.fields if not f.optional]
        if not st.fields and st.done_when:
            got = self.board_checks()
            if all(k in got and got[k]["ok"] for k in st.done_when):
                return "done"
            return "started" if any(k in got for k in st.done_when) else "todo"
        if not st.fields:
            return "info"
        if any(fb.status == "wrong" for fb in self._meter_verdicts(st)):
            return "wrong"  # a reading not what the virtual meter showed: said at once
        answered = bool(required) and all(
            self._entries.get(f.key) is not None and self._entries[f.key].ok for f in required
        )
        if not answered and any(self._given(f.key) for f in st.fields):
            answered = not required
            if required:
                return "started"
        if not answered:
            return "todo"
        wrong = any(fb.status == "wrong" for fb in self.feedback(step_id))
        mine = (
            [c for c in self.comparisons(step_id) if c.key in self.answered()]
            if any(f.compare for f in st.fields)
            else []
        )
        judged = [c.right for c in mine]
        if wrong or any(r is False for r in judged):
            return "wrong"
        if st.part == "Results" and any(
            f.compare and f.key not in self.answered() for f in st.fields
        ):
            return "started"  # Task 11: omega_ss given, K not yet (it read ✓)
        if self._warned(st.fields) or any(c.caveat for c in mine):
            return "warned"  # a value right the group's way, resting on one marked wrong
        return "unjudged" if any(r is None for r in judged) else "done"

    def _given(self, key: str) -> bool:
        """Whether something stands in field ``key``: an entry with a text that is not blank
        (a Space or a Tab through an empty entry stores a blank one, which starts nothing:
        walk 11, D6)."""
        e = self._entries.get(key)
        return e is not None and bool(e.text.strip())

    def _warned(self, fields: Sequence[Field]) -> bool:
        """Whether one of ``fields`` stands with a warning of its own (stored, but outside
        what the program calls possible or likely) or a Task 5 current falling as the voltage
        rises (:meth:`falling_currents`)."""
        keys = {f.key for f in fields}
        if any(self._entries[k].warnings for k in keys if k in self._entries):
            return True
        return any(n.source in keys for n in self.falling_currents())

    # -- the board checks ----------------------------------------------------------------------

    def board_checks(self) -> dict[str, dict[str, Any]]:
        """The newest result of each board check, by key of :data:`lab_steps.BOARD_CHECKS`:
        ``ok``, ``text`` (what it found, in sentences), ``at`` (ISO time) and, where it
        counted, ``counts``."""
        return {k: dict(v) for k, v in self._data.get("board_checks", {}).items()}

    def record_check(self, key: str, ok: bool, text: str, counts: int | None = None) -> None:
        """Keep the result of board check ``key`` (KeyError for an unknown key), replacing an
        earlier one of the same check; saved. ``counts``: the encoder counts it saw."""
        self._writable()
        if key not in lab_steps.BOARD_CHECKS:
            raise KeyError(key)
        result: dict[str, Any] = {
            "ok": bool(ok),
            "text": str(text),
            "at": self._clock().isoformat(timespec="seconds"),
        }
        if counts is not None:
            result["counts"] = int(counts)
        self._data["board_checks"] = {**self._data.get("board_checks", {}), key: result}
        self._changed()

    def watch_speed(self, t: ArrayLike, count: ArrayLike) -> bool:
        """Task 3: the live speed was shown over board times ``t`` (s) with encoder counts
        ``count``; when the wheel turned half a revolution within the last 2 s of them, record
        ``speed_watched`` (once). Whether it is recorded now."""
        if self.board_checks().get("speed_watched", {}).get("ok"):
            return True
        if self.readonly:  # nothing is recorded in it
            return False
        tt, cc = np.asarray(t, dtype=float), np.asarray(count, dtype=np.int64)
        if tt.size < 2:
            return False
        recent = tt >= tt[-1] - lab_steps.SPEED_WATCHED_S
        turned = int(np.ptp(cc[recent]))
        if turned < lab_steps.SPEED_WATCHED_COUNTS:
            return False
        self.record_check(
            "speed_watched",
            True,
            f"the live speed was watched while the wheel turned {turned} counts in "
            f"{lab_steps.SPEED_WATCHED_S:g} s",
            turned,
        )
        return True

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
        self._writable()
        key = f"omega_ss@{level:g}"
        if key not in FIELDS:
            raise KeyError(key)
        cap = capture(t, omega, window, velocity)
        self._captures[key] = cap
        # a measured value keeps its digits: 5.800, not "5.8" (walk 9, D8)
        return self.enter(key, format_number(cap.omega_ss), source="capture")

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

    def has_input(self, name: str, row: TableRow | None = None) -> bool:
        """Whether the session has input ``name`` of
        :data:`~minseg_tui.lab.content.needs.INPUTS`: R, a complete row of the table, the
        run in use, the group's own omega_ss in the steps, K, a T (theirs or the run's 63 %
        reading), a u_ss for the run's steps (any row's), and ``row``'s own u_ss, omega_ss
        and i_ss."""
        if name == "R":
            return self.value("R") is not None
        if name == "row":
            return any(
                x.u_ss is not None and x.omega_ss is not None and x.i_ss is not None
                for x in self.table()
            )
        if name == "run":
            return self.response_run() is not None
        if name == "u_ss@steps":
            return bool(self.table_pairs())
        if name == "own.T":
            st = self.results().step
            return self.value(name) is not None or (st is not None and st.T_63 is not None)
        if name.startswith("own."):
            return self.value(name) is not None
        return row is not None and getattr(row, name) is not None

    def results(self, kept: ResponseFigures | None = None) -> Results:
        """Tasks 6-15 from the current entries and the chosen run (cached until R, a table
        value or the run changes); the run's numbers of Tasks 11-13 are noted for the
        session file to keep (:meth:`kept`).

        ``kept``: those numbers as the file keeps them (``self.kept().step``): the run is
        then not fitted again (for the class view; ``identification.step`` is None, the
        numbers are in :attr:`Results.step`; not cached)."""
        run = self.response_run()
        if kept is not None:
            return compute(
                self.value("R"),
                self.readings(),
                run,
                self.folder,
                self.table_pairs(),
                kept=kept,
                R_missing=self._R_missing(),
                logs=self._cache.logs,
            )
        key = (
            self.value("R"),
            self._R_missing(),
            tuple(self.readings()),
            tuple(self.table_pairs()),
            run.name if run else None,
            self._run_version,
        )
        cached = self._cache.results
        if cached is not None and cached[0] == key:
            return cached[1]
        res = self._compute()
        self._cache.results = (key, res)
        ident = res.identification
        if run is not None and ident is not None and ident.step is not None:
            self._note_kept(run, self.table_pairs(), step=response_figures(ident.step))
        return res

    def _compute(self) -> Results:
        return compute(
            self.value("R"),
            self.readings(),
            self.response_run(),
            self.folder,
            self.table_pairs(),
            R_missing=self._R_missing(),
            logs=self._cache.logs,
        )

    def _R_missing(self) -> str:
        """Why R is not in effect when it was entered and then edited by hand in the session
        file (:func:`~minseg_tui.lab.state.entries.check_stored`); '' otherwise."""
        e = self._entries.get("R")
        return EDITED_R if e is not None and e.edited else ""

    def model_check(self, name: str | None = None) -> ModelCheck:
        """The model check (:func:`minseg_tui.model.check.check`) of run ``name`` (default: the
        run the model check uses, :meth:`check_run`): measured against the first-order model,
        the named cause, the extended model and the gain. Cached until something changes."""
        run = (
            self.check_run()
            if name is None
            else next((r for r in self._runs if r.name == name), None)
        )
        if run is None:
            return ModelCheck(
                None,
                None,
                NO_RUN_YET if name is None else f"no run {name}",
            )
        key = (self._run_version, run.name)
        cached = self._cache.checks.get(key)
        if cached is not None:
            return cached
        table = self.table_pairs()
        result = check_run(self.folder, run, table, logs=self._cache.logs)
        self._cache.checks = {key: result}
        self._note_kept(run, table, check=result)
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
        out += [
            n
            for n in self.falling_currents()
            if keys is None or n.source in keys or step_id == "table"
        ]
        if step_id is None or lab_steps.step(step_id).part in ("Table", "Results", "Step response"):
            res = self.results()
            if res.identification:
                out += [
                    Notice(f.code, self._u_ss_said(f.code, sentence(f)))
                    for f in res.identification.observations
                ]
        return out

    def _u_ss_said(self, code: str, message: str) -> str:
        """identify's sentence on a u_ss the table has no row for, as true of this table: the
        row at the step's level is there, its u_ss is not entered (walk 7: "No table row has
        u_req = 4.5 V" while the row held omega_ss and i_ss)."""
        if code not in ("u_ss_extrapolated", "u_ss_interpolated"):
            return message
        level = STEP_LEVEL
        if self.value(f"u_ss@{level:g}") is not None:
            return message
        st = self.results().step
        return u_ss_not_entered(
            level, code == "u_ss_extrapolated", st.u_ss if st is not None else None
        )

    def falling_currents(self) -> list[Notice]:
        """The Task 5 readings whose current falls as the voltage rises (a warning each, on
        the field of the higher voltage; :func:`~minseg_tui.lab.state.results.falling_currents`)."""
        rows = []
        for level in LEVELS:
            key = f"i_ss@{level:g}"
            i_ss, said = self.value(key), self.reading(key)
            if i_ss is not None and said is not None:  # in mA, with the digits typed
                rows.append((level, i_ss, said))
        return falling_currents(rows)

    def comparisons(
        self, step_id: str | None = None, results: Results | None = None, whose: str = "your"
    ) -> list[Comparison]:
        """Each of the group's own readings (fields with ``compare``) beside the value
        computed the group's way and the least-squares one (:func:`lab.compare.compare_fields`);
        ``results``: those to compare with (default: :meth:`results`); ``whose``: how the
        texts name the group's values ("your" on the screen, "the group's" in the report)."""
        fields = lab_steps.step(step_id).fields if step_id else [f for s in STEPS for f in s.fields]

        def text(key: str) -> str | None:
            e = self._entries.get(key)
            return e.text if e and e.text.strip() else None

        res = self.results() if results is None else results
        return compare_fields(
            fields, self.value, text, res, self.revealed(), self.reading, whose, self.has_input
        )

    def answered(self) -> set[str]:
        """The keys of the fields the group has answered (an accepted, non-empty entry)."""
        return {k for k, e in self._entries.items() if e.ok and e.text.strip()}

    def revealed(self) -> set[str]:
        """The fields of Tasks 11-15 a lab assistant revealed before the group answered."""
        return set(self._data.get("revealed", []))

    def reveal(self, step_id: str) -> list[str]:
        """Show the computed values of step ``step_id`` before the group answered them:
        the fields so marked (saved; the report says "revealed before answering"). Only
        those with a computed value now: one not computed yet cannot be shown, so it is
        neither marked nor recorded as shown (walk 10, D5: a reveal with no u_ss showed
        dashes, and the report said both values were revealed then). In a session opened
        read-only they are shown and nothing is recorded or saved (walk 14, D1)."""
        self._change()
        can = {
            c.key
            for c in self.comparisons(step_id)
            if c.computed is not None or c.least_squares is not None
        }
        keys = [k for k in reveal_keys(lab_steps.step(step_id).fields, self.answered()) if k in can]
        if keys:
            self._data["revealed"] = sorted(self.revealed() | set(keys))
            if not self.readonly:  # read-only: shown to whoever looks, recorded nowhere
                self._note(keys, lab_shown.REVEAL)
                self._changed()
        return keys

    # -- what the group was shown, and the lab's policy ----------------------------------------

    def shown(self) -> dict[str, Shown]:
        """The first time each computed value of Tasks 11-15 was on the group's screen, as
        recorded since :attr:`shown_since` (a value not in it was not shown since then)."""
        out: dict[str, Shown] = {}
        got = self._data.get("shown")
        for key, d in (got if isinstance(got, dict) else {}).items():
            with contextlib.suppress(KeyError, TypeError, AttributeError):
                out[key] = Shown.from_json(d)
        return out

    @property
    def shown_since(self) -> str | None:
        """Since when (ISO time) the session records what the group was shown and the lab's
        policy: its creation, or its first opening by a program that records them (None: a
        session of an older program, never opened since to be written)."""
        since = self._data.get("shown_since")
        return since if isinstance(since, str) and since else None

    def note_shown(self, keys: Iterable[str], by: str) -> list[str]:
        """The group's screen now shows the computed values of fields ``keys`` (of Tasks
        11-15): record the first showing of each, with the group's answer then, if any (saved
        at once; the time of the last change stays). ``by``: ``"results"`` (Tasks 11-15 drew
        it: after the answer, by the lab's policy or by a reveal, whichever let it be shown)
        or one of :data:`minseg_tui.lab.state.shown.BY`. The fields newly recorded; none on a
        read-only session or a snapshot."""
        if self.frozen or self.readonly:
            return []
        rule = self.note_policy()
        if by == "results":
            revealed = self.revealed()
            new = [k for k in keys if k not in self.shown()]
            for how, group in (
                (lab_shown.REVEAL, [k for k in new if k in revealed]),
                (
                    lab_shown.POLICY,
                    [k for k in new if k not in revealed and not rule.answers_first],
                ),
                (
                    lab_shown.AFTER_ANSWER,
                    [k for k in new if k not in revealed and rule.answers_first],
                ),
            ):
                if how == lab_shown.AFTER_ANSWER:  # only an answer lets it be shown so
                    group = [k for k in group if k in self.answered()]
                self._note(group, how)
            noted = [k for k in new if k in self.shown()]
        else:
            noted = self._note(keys, by)
        if noted:
            self.save(memo=True)
        return noted

    def _note(self, keys: Iterable[str], by: str) -> list[str]:
        """Record the first showing of ``keys`` by ``by`` in the session's data (not saved)."""
        got = self._data.get("shown")
        known: dict[str, Any] = got if isinstance(got, dict) else {}
        stamp = self._clock().isoformat(timespec="seconds")
        noted = []
        for key in keys:
            if key not in ANSWERED_FIRST or key in known:
                continue
            e = self._entries.get(key)
            answer = e.text.strip() if e is not None and e.ok and e.text.strip() else None
            known[key] = Shown(stamp, by, answer).to_json()
            noted.append(key)
        self._data["shown"] = known
        return noted

    def policies(self) -> list[PolicyRecord]:
        """The lab's policy as the session recorded it, oldest first: when it was opened, and
        each change since (empty: a session of an older program)."""
        out: list[PolicyRecord] = []
        got = self._data.get("policy")
        for d in got if isinstance(got, list) else []:
            with contextlib.suppress(KeyError, TypeError, AttributeError):
                out.append(PolicyRecord.from_json(d))
        return out

    def note_policy(self, save: bool = True) -> Policy:
        """The lab's policy now (``lab.toml`` in the folder that holds the session), recorded
        when it is not the one recorded last (saved at once unless ``save`` is False; the
        time of the last change stays). Nothing is recorded on a read-only session."""
        rule = read_policy(self.folder.parent)
        if self.frozen or self.readonly:
            return rule
        now = PolicyRecord(
            self._clock().isoformat(timespec="seconds"), rule.answers_first, rule.problem, rule.file
        )
        got = self.policies()
        if not got or not got[-1].same_rule(now):
            self._data["policy"] = [*(p.to_json() for p in got), now.to_json()]
            if save:
                self.save(memo=True)
        return rule

    def _start_records(self) -> None:
        """At opening: a session of an older program begins to record what the group is shown
        from now on; the lab's policy is recorded when it is not the one recorded last."""
        if self.shown_since is None:
            self._data["shown_since"] = self._clock().isoformat(timespec="seconds")
            self._data.setdefault("shown", {})
            self.note_policy(save=False)
            self.save(memo=True)
        else:
            self.note_policy()

    # -- runs ----------------------------------------------------------------------------------

    @property
    def runs(self) -> list[RunInfo]:
        """Every recorded run, oldest first."""
        return list(self._runs)

    def run_path(self, name: str) -> Path:
        """The run-log CSV of run ``name``."""
        for r in self._runs:
            if r.name == name:
                return self.folder / r.file
        raise KeyError(name)

    def load_run(self, name: str) -> RunLog:
        """Run ``name`` read back as a RunLog, its u column the applied voltage u_A worked out
        now from the table's u_ss (a recorded run; an imported one as it stands). KeyError for
        an unknown run, InputError if its file is damaged."""
        for r in self._runs:
            if r.name == name:
                return read_run(self.folder, r, self.table_pairs(), logs=self._cache.logs)
        raise KeyError(name)

    def run_changed(self, name: str) -> ChangedFile | None:
        """The line saying that run ``name``'s file is not as it was written (edited by hand?)
        or cannot be checked (an older program kept no checksum), else None
        (:func:`minseg_tui.lab.saving.runs.changed_file`: the one rule the lab's Tasks 11-15,
        the report and the class view say). KeyError for an unknown run."""
        for r in self._runs:
            if r.name == name:
                return changed_file(self.folder, r)
        raise KeyError(name)

    def response_run(self) -> RunInfo | None:
        """The run Tasks 11-15 use: the one the group chose (it stays until they choose
        another), else the newest complete 25 ms step run (the manual's), else the newest
        complete step run of another period; never an interrupted run they did not choose,
        nor an imported log they did not choose (an import feeds the model check:
        :meth:`check_run`; walk 16, D3).

        Read by Tasks 11-15 (:meth:`results`, :meth:`comparisons`, the run an answer is given
        on), the runs list's mark, the report's Tasks 11-15 and the class view's K and T."""
        sel = self._data.get("selected_run")
        for r in self._runs:
            if r.name == sel:
                return r
        complete = [
            r
            for r in reversed(self._runs)
            if r.kind in RESPONSE_KINDS and r.kind != "imported" and r.complete
        ]
        manual = [r for r in complete if abs(r.ts - RunPlan().ts) < 1e-6]
        for r in (*manual, *complete):
            return r
        return None

    def chosen_run(self) -> str | None:
        """The run the group chose for Tasks 11-15 (None: no choice, :meth:`response_run`'s
        default holds)."""
        sel = self._data.get("selected_run")
        return sel if isinstance(sel, str) else None

    def select_run(self, name: str | None) -> None:
        """Use run ``name`` for Tasks 11-15 and the model check until the group picks another
        (None: the default of :meth:`response_run`); saved in the session. The model check's
        own run (an import's, :meth:`check_run`) gives way to it."""
        self._writable()
        if name is not None:
            self.run_path(name)
        self._data["selected_run"] = name
        self._data.pop("check_run", None)
        self._run_version += 1
        self._changed()

    def check_run(self) -> RunInfo | None:
        """The run the model check uses: the log imported last, until the group picks a run
        with :meth:`select_run`; else the run Tasks 11-15 use (:meth:`response_run`). Saved
        in the session (``check_run``; a session of an older program has none, and its
        model check goes on with Tasks 11-15's run, an import it chose included).

        Read by the model check (:meth:`model_check`: its screen, the report's section, the
        class view's cause) and the lines that say which run it uses."""
        sel = self._data.get("check_run")
        for r in self._runs:
            if r.name == sel:
                return r
        return self.response_run()

    def _new_name(self, kind: str) -> str:
        return new_name(self.folder, kind, (r.name for r in self._runs))

    def start_run(
        self,
        kind: str = "steps",
        plan: RunPlan | None = None,
        ts: float | None = None,
        flush_interval: float | None = None,
    ) -> Recorder:
        """Begin recording a run (``steps``/``fast`` for Task 10, ``free`` otherwise); returns
        the Recorder to append samples to. Nothing is lost to a crash beyond its flush
        interval, nor to a write that fails (the Recorder keeps the samples). Raises
        SessionNotWritable (one line) when its file cannot be made."""
        self._change()
        if self.readonly:
            raise InputError(str(self.folder), None, READ_ONLY)
        ts_ = ts if ts is not None else (plan.ts if plan else 0.025)
        try:
            name = self._new_name(kind)
            header = run_header(
                name,
                kind,
                ts_,
                self._clock().isoformat(timespec="seconds"),
                {
                    k: float(getattr(plan, k))
                    for k in ("low", "high", "half_period", "periods", "ts")
                }
                if plan
                else None,
            )
            return Recorder(
                self.folder / RUNS_DIR / f"{name}{PARTIAL_SUFFIX}",
                header,
                FLUSH_INTERVAL if flush_interval is None else flush_interval,
            )
        except OSError as exc:
            self._failed(exc)
            raise SessionNotWritable(
                str(self.folder / RUNS_DIR),
                None,
                f"cannot record a run here ({os_reason(exc)}); nothing was started",
            ) from None

    def finish_run(
        self, recorder: Recorder, stopped_early: bool = False, ended_by: str = ""
    ) -> RunInfo | None:
        """End a recording: its samples become runs/<name>.csv (atomically), the session
        records the run (saved) and the partial file goes. None (and nothing kept) when it
        holds fewer than 2 samples. ``stopped_early``: the run ended before its plan did
        (stopped, board lost, program closed; kept as ``interrupted``, ``ended_by`` a key of
        :data:`minseg_tui.lab.saving.runs.ENDED_BY` saying which). When the log cannot
        be written the run is kept in memory, saved with the next save that works, and
        SessionNotWritable says so."""
        self._change()
        recorder.close()
        raw = recorder.raw()
        if raw.seq.size < 2:
            with contextlib.suppress(OSError):
                recorder.path.unlink(missing_ok=True)
            return None
        try:
            info = self._keep(recorder.name, raw, stopped_early, ended_by)
        except OSError as exc:
            self._unkept.append((recorder, stopped_early, ended_by))
            self._failed(exc)
            raise SessionNotWritable(
                str(self.folder / RUNS_DIR),
                None,
                f"run {recorder.name} ({recorder.samples} samples) is kept in memory, not yet "
                f"on disk ({os_reason(exc)}); it is saved with the session as soon as it can be",
            ) from None
        with contextlib.suppress(OSError):
            recorder.path.unlink(missing_ok=True)
        return info

    def discard_run(self, recorder: Recorder) -> None:
        """Throw a recording away (the partial file is removed)."""
        self._change()
        recorder.close()
        with contextlib.suppress(OSError):
            recorder.path.unlink(missing_ok=True)

    def _keep(
        self, name: str, raw: RawRun, interrupted: bool, ended_by: str = ""
    ) -> RunInfo | None:
        """Write run ``name`` from ``raw`` and record it (saved); None when it is known or
        too short. OSError when its log cannot be written."""
        if any(r.name == name for r in self._runs):
            return None
        info = keep_run(self.folder, name, raw, interrupted, ended_by)
        if info is None:
            return None
        self._hold(info)
        self._runs.append(info)
        self._run_version += 1
        self._changed()
        return info

    def _keep_unkept(self) -> None:
        """Write the runs that finished while nothing could be written (OSError if still not)."""
        while self._unkept:
            rec, stopped_early, ended_by = self._unkept[0]
            raw = rec.raw()
            if not any(r.name == rec.name for r in self._runs):
                info = keep_run(self.folder, rec.name, raw, stopped_early, ended_by)
                if info is not None:
                    self._hold(info)
                    self._runs.append(info)
                    self._run_version += 1
            self._unkept.pop(0)
            with contextlib.suppress(OSError):
                rec.path.unlink(missing_ok=True)

    def _hold(self, run: RunInfo) -> bool:
        """Hold a copy of ``run``'s file in memory (True), unless it cannot be read, is
        larger than :data:`MAX_RUN_COPY` or would take the copies past :data:`MAX_RUN_COPIES`."""
        try:
            data = read_regular(self.folder / run.file, MAX_RUN_COPY)
        except OSError:
            return False
        held = sum(len(b) for k, b in self._copies.items() if k != run.name)
        if len(data) > MAX_RUN_COPY or held + len(data) > MAX_RUN_COPIES:
            return False
        self._copies[run.name] = data
        return True

    def _hold_copies(self) -> None:
        """At open: hold a copy of every run file; say which runs listed have no file."""
        for r in self._runs:
            if not self._hold(r) and not exists(self.folder / r.file):
                self._lost.add(r.name)
                self.recovery_notes.append(self._gone(r))

    def _gone(self, run: RunInfo) -> str:
        """The line for a run whose file is gone and of which no copy is held."""
        return (
            f"{run.file} is gone (deleted?) and no copy of it was held: the {run.samples} "
            f"samples of run {run.name} are lost"
            + (" (Tasks 11-15 and the model check use it)" if run == self.response_run() else "")
        )

    def restore_runs(self) -> bool:
        """Write back from memory every run file deleted (by hand, or with its runs/ folder)
        since it was written or since the session was opened; one line for each run written
        back and for each found gone with no copy held (said once), for :meth:`take_restored`.
        True when every run held is on disk; a file that cannot be written back keeps its copy
        held and becomes :attr:`save_problem` (the next save tries again). Never raises; does
        nothing for a read-only session or a snapshot."""
        if self.readonly or self.frozen:
            return True
        ok = True
        for r in self._runs:
            path = self.folder / r.file
            if exists(path):
                continue
            held = self._copies.get(r.name)
            if held is None:
                if r.name not in self._lost:
                    self._lost.add(r.name)
                    self._restored.append(self._gone(r))
                continue
            try:
                # runs/ made again, never the session's folder: one deleted whole is a save
                # problem (its lock went with it), and move_to saves it elsewhere, runs too
                path.parent.mkdir(exist_ok=True)
                atomic_write_bytes(path, held)
            except OSError as exc:
                self._failed(exc)
                ok = False
                continue
            self._restored.append(
                f"{r.file} was deleted: written back from memory ({r.samples} samples)"
            )
        self._unrestored = not ok
        return ok

    def take_restored(self) -> list[str]:
        """The lines of :meth:`restore_runs` (run by every save) since the last call: a run
        file written back from memory, or found gone with no copy held."""
        said, self._restored = self._restored, []
        return said

    def _recover_runs(self) -> None:
        try:
            partials = sorted((self.folder / RUNS_DIR).glob(f"*{PARTIAL_SUFFIX}"))
        except OSError:
            return
        for partial in partials:
            name = partial.name[: -len(PARTIAL_SUFFIX)]
            if not re.fullmatch(RUN_NAME, name):
                self.recovery_notes.append(
                    f"{RUNS_DIR}/{partial.name}: not a run this program recorded (its name is "
                    "no run name); left as it is"
                )
                continue
            try:
                raw = read_partial(partial)
                info = self._keep(name, raw, interrupted=True, ended_by="crash")
            except OSError as exc:
                self.recovery_notes.append(
                    f"{RUNS_DIR}/{partial.name}: not rebuilt yet ({os_reason(exc)}); "
                    "it is left as it is and rebuilt when the session is opened again"
                )
                continue
            if raw.damage:
                self.recovery_notes.append(
                    f"{RUNS_DIR}/{partial.name}: {raw.damage}; rebuilt from its samples as "
                    f"{name} (ts {ts_of(raw):g} s)"
                )
            if info is not None:
                self.recovered.append(info.name)
            with contextlib.suppress(OSError):
                partial.unlink(missing_ok=True)

    def import_run(self, path: Path) -> RunInfo:
        """Copy a run log recorded elsewhere into runs/ (checked by read_run_log; InputError
        with file and line if it is not one, SessionNotWritable if it cannot be written) for
        the model check (:meth:`check_run`); Tasks 11-15 keep their run unless the group
        chooses it (:meth:`select_run`: walk 16, D3). A path in quotes, as a terminal pastes
        a file dropped on it ('/home/ada/step log.csv'), is read without them when the quoted
        name is no file (s38 attack). The same as :meth:`import_order`, :func:`copy_import`
        and :meth:`add_import` in turn (the TUI runs the middle one in a worker)."""
        order = self.import_order(path)
        return self.add_import(order, copy_import(order))

    def import_order(self, path: Path) -> ImportOrder:
        """What :func:`copy_import` needs to bring in the log at ``path``: refused at once
        (InputError) by a snapshot or a session opened read-only."""
        self._writable()
        return ImportOrder(
            folder=self.folder,
            path=pasted_path(str(path)),
            name=self._new_name("imported"),
            started=self._clock().isoformat(timespec="seconds"),
            logs=self._cache.logs,
        )

    def add_import(self, order: ImportOrder, got: RunInfo | OSError) -> RunInfo:
        """Take the run :func:`copy_import` copied for ``order`` (``got``) as the model
        check's run; when the copy could not be written (an OSError), SessionNotWritable."""
        self._writable()
        if isinstance(got, OSError):
            self._failed(got)
            raise SessionNotWritable(
                str(order.folder / RUNS_DIR),
                None,
                f"cannot copy the log here ({os_reason(got)})",
            )
        if order.folder != self.folder or any(r.name == got.name for r in self._runs):
            self._cache.logs.drop(order.folder / got.file)
            raise SessionNotWritable(  # moved, or the name taken, while the copy was made
                str(self.folder / RUNS_DIR), None, "the session changed while the log was read"
            )
        self._hold(got)
        self._runs.append(got)
        self._data["check_run"] = got.name
        self._run_version += 1
        self._changed()
        return got


@dataclass(frozen=True)
class ImportOrder:
    """A run log to copy into a session: from ``path`` into ``folder``/runs as run ``name``,
    begun at ``started`` (ISO 8601); ``logs``: the session's logs read, given the copy's as
    the import read it."""

    folder: Path
    path: Path
    name: str
    started: str
    logs: LogCache | None = None


def copy_import(order: ImportOrder) -> RunInfo | OSError:
    """Read, check and copy the log of ``order`` (:func:`~minseg_tui.lab.saving.runs.
    import_log`); it touches no session, so it may run in a worker. InputError when the log
    is refused; the OSError when the copy cannot be written, for :meth:`Session.add_import`
    to say."""
    try:
        return import_log(order.folder, order.path, order.name, order.started, order.logs)
    except OSError as exc:
        return exc


__all__ = [
    "Comparison",
    "Entry",
    "ImportOrder",
    "ModelCheck",
    "Moved",
    "Notice",
    "Results",
    "SaveProblem",
    "Session",
    "TableRow",
    "copy_import",
]
