"""Session files on disk: atomic writes, the session file's schema, the lock, the list.

A session is a folder ``<sessions>/<id>/`` holding ``session.json`` (what the group
entered; schema :data:`SCHEMA`), ``runs/<name>.csv`` (recorded runs as run logs),
``runs/<name>.partial`` while a run is being recorded, ``lock`` (locked by the program
that has it open, :mod:`minseg_tui.lock`) and the reports.

Every write of a whole file goes to a temporary file in the same folder, is flushed and
fsynced, replaces the old file with ``os.replace`` and then the folder is fsynced: a crash
leaves either the old or the new file, never a mix. A session file that cannot be read
(bad JSON, a part that breaks the schema of :mod:`minseg_tui.lab.saving.schema`) raises
:class:`SessionDamaged` and is never written over. A write that fails (a full disk, a
read-only folder, a drive pulled out) is a :class:`SaveProblem` the session keeps.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import re
import stat
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from minseg_tui.errors import InputError, MinsegError
from minseg_tui.lab.content.keys import in_palette
from minseg_tui.lab.saving.schema import KIND, SCHEMA, SESSION, problem, salvage
from minseg_tui.lock import FileLock, LockHeld, holder, pid_alive

MAX_SESSION_BYTES = 16 * 2**20
"""Largest session.json read (16 MiB; a full lab's is a few tens of kB)."""

SESSION_FILE = "session.json"
LOCK_FILE = "lock"
RUNS_DIR = "runs"


class SessionDamaged(InputError):
    """session.json exists but cannot be used; the message says what to do. It is kept as is."""


class SessionMissing(InputError):
    """No session at the given place."""


class SessionLocked(MinsegError):
    """Another running program has the session open."""


class SessionsUnreadable(InputError):
    """The sessions folder itself cannot be listed (permissions, a vanished drive)."""


class SessionNotWritable(InputError):
    """A session cannot be made, opened for writing, moved or a run kept where asked; the
    message says why and what to do. Nothing typed is lost."""


def os_reason(exc: OSError) -> str:
    """The system's words for a failed write, with the file: ``Read-only file system``."""
    why = exc.strerror or str(exc) or type(exc).__name__
    return f"{why} ({exc.filename})" if exc.filename else why


@dataclass(frozen=True)
class SaveProblem:
    """Why the session is not all on disk, and where it will be saved once it can.

    folder: the session's folder, where every change goes (and will, once it can);
    reason: the system's words (``Read-only file system (/media/stick/...)``); since: ISO
    time of the first failed save; attempts: failed saves so far.
    """

    folder: Path
    reason: str
    since: str
    attempts: int

    @property
    def line(self) -> str:
        """One line for the status bar: what is wrong and where it will save."""
        return (
            f"not saved: {self.reason}; everything is kept in memory and saved to "
            f"{self.folder} as soon as it can be (or save it to another folder)"
        )


def fsync_dir(path: Path) -> None:
    """fsync a folder so a rename in it survives a power cut (no-op where unsupported)."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Replace ``path`` by ``data`` atomically (temp file, fsync, os.replace, fsync folder).

    An OSError (a full disk, a folder that cannot be written, a drive gone) comes through
    with the old file untouched and no temporary file left behind (as far as the folder
    can still be written; :func:`clean_leftovers` takes what a kill -9 leaves).
    """
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    except OSError as exc:  # named by the file meant, not by the temporary one
        raise type(exc)(exc.errno, exc.strerror, str(path)) from None
    try:
        try:
            view = memoryview(data)
            while view:
                n = os.write(fd, view)
                view = view[n:]
            os.fsync(fd)
        finally:
            os.close(fd)
        try:
            os.replace(tmp, path)
        except OSError as exc:  # a folder where the file goes: named by it, not the temp file
            if exc.errno is None:  # no system error to name a file for: as it came
                raise
            raise type(exc)(exc.errno, exc.strerror, str(path)) from None
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    fsync_dir(path.parent)


_LEFTOVER = re.compile(r"\..+\.(\d+)\.(tmp|build)")
"""A temporary file of :func:`atomic_write_bytes` (``.<name>.<pid>.tmp``) or of a run's
log being built (``.<name>.<pid>.build``)."""


def clean_leftovers(folder: Path) -> list[str]:
    """Remove the temporary files a killed program left in ``folder`` and its runs/ (those
    of a pid that is not running); the names removed. Never raises."""
    removed = []
    for where in (Path(folder), Path(folder) / RUNS_DIR):
        try:
            names = os.listdir(where)
        except OSError:
            continue
        for name in names:
            m = _LEFTOVER.fullmatch(name)
            if m is None or pid_alive(int(m.group(1))):
                continue
            with contextlib.suppress(OSError):
                os.unlink(where / name)
                removed.append(str((where / name).relative_to(folder)))
    return sorted(removed)


def atomic_write_text(path: Path, text: str) -> None:
    """Replace ``path`` by UTF-8 ``text`` atomically."""
    atomic_write_bytes(path, text.encode("utf-8"))


def damaged_message(path: Path, why: str) -> str:
    """The one-line message for a damaged session file: what is wrong and what to do."""
    return (
        f"{why}; the file is left untouched. Start a new session (this folder is kept), "
        f"or repair {path.name} by hand (or restore it from a backup) and open it again"
    )


def not_permitted(folder: Path, exc: OSError) -> str:
    """The line for a session folder (or its file) this user may not read: nothing is
    damaged, so no repair is offered (s38 attack: "repair session.json by hand")."""
    return (
        f"cannot be read ({exc.strerror or 'Permission denied'}): this user may not read "
        f"the folder {folder.name}; nothing in it was changed. Make it readable (chmod -R u+rwX "
        f"{folder.name}, or as the user who made it) and open it again"
    )


def read_regular(path: Path, limit: int) -> bytes:
    """At most ``limit`` + 1 bytes of the regular file ``path`` (more than ``limit``: the file
    is larger). OSError when it cannot be read, and when it is not a regular file: a FIFO
    or a device would make the read wait for ever or never end."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    try:
        mode = os.fstat(fd).st_mode
        if stat.S_ISDIR(mode):
            raise OSError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
        if not stat.S_ISREG(mode):
            raise OSError(errno.EINVAL, "not a regular file (a pipe or a device?)", str(path))
        chunks, size = [], 0
        while size <= limit:
            chunk = os.read(fd, min(1 << 20, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        return b"".join(chunks)
    finally:
        os.close(fd)


def _load(path: Path) -> object:
    """The JSON value in ``path``; SessionMissing / SessionDamaged with one line."""
    try:
        raw = read_regular(path, MAX_SESSION_BYTES)
    except FileNotFoundError:
        raise SessionMissing(str(path.parent), None, f"no session here (no {path.name})") from None
    except PermissionError as exc:
        raise SessionDamaged(str(path), None, not_permitted(path.parent, exc)) from None
    except OSError as exc:
        why = exc.strerror or type(exc).__name__
        raise SessionDamaged(
            str(path), None, damaged_message(path, f"cannot be read ({why})")
        ) from None
    if len(raw) > MAX_SESSION_BYTES:
        raise SessionDamaged(
            str(path),
            None,
            damaged_message(path, f"is larger than any session ({MAX_SESSION_BYTES >> 20} MiB)"),
        )
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise SessionDamaged(str(path), None, damaged_message(path, "is not UTF-8 text")) from None
    except json.JSONDecodeError as exc:
        raise SessionDamaged(
            str(path), exc.lineno, damaged_message(path, f"is not valid JSON ({exc.msg})")
        ) from None
    except RecursionError:
        raise SessionDamaged(
            str(path), None, damaged_message(path, "is nested too deeply to be a session")
        ) from None
    except ValueError as exc:  # a whole number longer than Python reads (4300 digits)
        raise SessionDamaged(
            str(path), None, damaged_message(path, f"holds a number too long to read ({exc})")
        ) from None


def _identity_problem(data: object) -> str | None:
    """Why ``data`` is not a session file of this schema at all (nothing to salvage)."""
    if not isinstance(data, dict):
        return "does not hold a JSON object"
    if data.get("kind") != KIND:
        return f"is not a minseg-tui session file (kind {data.get('kind')!r})"
    if data.get("schema") != SCHEMA:
        return f"has schema {data.get('schema')!r}, this program reads schema {SCHEMA}"
    return None


def _refused(path: Path, data: object, why: str) -> str:
    """The line for a session file this program cannot use: a newer program's is not
    damaged, so no repair is offered (s38 attack: "repair session.json by hand")."""
    schema = data.get("schema") if isinstance(data, dict) else None
    if (
        isinstance(data, dict)
        and data.get("kind") == KIND
        and isinstance(schema, int)
        and not isinstance(schema, bool)
        and schema > SCHEMA
    ):
        return (
            f"was written by a newer minseg-tui (schema {schema}; this one reads schema "
            f"{SCHEMA}); the file is left untouched: open it with the newer program"
        )
    return damaged_message(path, why)


def schema_problem(data: object) -> str | None:
    """Why ``data`` is not a session of this schema (:data:`minseg_tui.lab.saving.schema.SESSION`,
    checked whole), or None when it is."""
    why = _identity_problem(data)
    if why:
        return why
    where = problem(data, SESSION)
    return f"has a broken {where}" if where else None


def read_session_file(path: Path) -> dict[str, Any]:
    """The JSON object of ``path`` (a session.json), checked whole against the schema.

    Raises SessionMissing when there is no file and SessionDamaged (naming the file, the
    line when JSON is broken, where the schema breaks, and what to do) when it cannot be
    used.
    """
    path = Path(path)
    data = _load(path)
    why = schema_problem(data)
    if why:
        raise SessionDamaged(str(path), None, _refused(path, data, why))
    assert isinstance(data, dict)
    return data


def salvage_session_file(path: Path) -> tuple[dict[str, Any], str | None]:
    """For a read-only look: the sound parts of ``path`` and, when the file breaks the
    schema, the one-line reason (what was left out). SessionDamaged only when nothing can
    be read (not JSON, not a session of this schema)."""
    path = Path(path)
    data = _load(path)
    why = _identity_problem(data)
    if why:
        raise SessionDamaged(str(path), None, _refused(path, data, why))
    assert isinstance(data, dict)
    broken = problem(data, SESSION)
    if broken is None:
        return data, None
    kept, lost = salvage(data)
    more = f" (and {len(lost) - 1} more)" if len(lost) > 1 else ""
    return kept, (
        f"{path}: has a broken {broken}{more}; shown read-only without it, the file is left untouched"
    )


# -- the lock ----------------------------------------------------------------------------------


def lock_owner(folder: Path) -> int | None:
    """pid of the live program holding the session in ``folder``, or None (nobody holds it;
    a lock file a dead program left is nobody's)."""
    who = holder(Path(folder) / LOCK_FILE)
    return who.pid if who is not None else None


def take_lock(folder: Path) -> FileLock:
    """The session's lock (:class:`minseg_tui.lock.FileLock` on ``<folder>/lock``), taken;
    SessionLocked naming the program that has it open."""
    lock = FileLock(Path(folder) / LOCK_FILE)
    try:
        lock.acquire()
    except LockHeld as exc:
        raise SessionLocked(
            f"session {Path(folder).name} is open in {exc.holder}; close it there first"
        ) from None
    return lock


# -- session folders -----------------------------------------------------------------------


def exists(path: Path) -> bool:
    """Whether ``path`` exists, False also when it cannot be looked at."""
    try:
        return os.path.lexists(path)
    except OSError:
        return False


def new_session_folder(root: Path, base: str) -> tuple[Path, FileLock]:
    """A new, locked session folder ``root/<base>`` (``-2``, ``-3``, ... if taken), with its
    runs/; SessionNotWritable (one line) when ``root`` cannot take one."""
    try:
        root.mkdir(parents=True, exist_ok=True)
        sid, k = base, 1
        while True:
            folder = root / sid
            try:
                # mkdir is the claim: a name another program took between looking and making
                # (a race) is passed over for the next free one, never an error
                folder.mkdir()
                break
            except FileExistsError:
                k += 1
                sid = f"{base}-{k}"
        (folder / RUNS_DIR).mkdir()
    except OSError as exc:
        raise SessionNotWritable(
            str(root),
            None,
            f"cannot make a session folder here ({os_reason(exc)}): choose a sessions folder "
            "that can be written (--sessions DIR)",
        ) from None
    try:
        return folder, take_lock(folder)
    except OSError as exc:
        raise SessionNotWritable(
            str(folder), None, f"cannot lock the new session folder ({os_reason(exc)})"
        ) from None


# -- listing -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class SessionInfo:
    """One line of the resume picker.

    id: folder name; path: the folder; members; date; last_step: step id the group was at;
    modified: ISO time of the last change; damaged: why it cannot be opened (None if it
    can); locked_by: pid of a live program that has it open, or None.
    """

    id: str
    path: Path
    members: tuple[str, ...]
    date: str
    last_step: str
    modified: str
    damaged: str | None = None
    locked_by: int | None = None
    runs_left: tuple[str, ...] | None = None
    """For a folder whose session.json is gone but whose runs/ is left: the run logs in it
    (``runs/<name>.csv``), what can be recovered (None for every other line)."""


def names_key(members: Sequence[str]) -> tuple[str, ...]:
    """The group's names as compared: each without case or extra spaces, in any order
    ("Ada, Bo" and "bo,  ada" are one group); empty names left out."""
    return tuple(sorted(k for m in members if (k := " ".join(m.split()).casefold())))


def same_names(sessions: Sequence[SessionInfo], members: Sequence[str]) -> list[SessionInfo]:
    """The sessions of ``sessions`` that can be opened (not damaged, not in use) whose
    group has the names ``members`` (:func:`names_key`), in the order given."""
    key = names_key(members)
    return [
        s
        for s in sessions
        if key and names_key(s.members) == key and not s.damaged and s.locked_by is None
    ]


def list_sessions(root: Path) -> list[SessionInfo]:
    """Every session folder under ``root``, newest change first. A damaged one is listed
    with the reason; one that cannot even be looked at is listed as damaged too, and none
    hides another. A ``root`` that cannot be read raises SessionsUnreadable (one line)."""
    root = Path(root)
    out: list[SessionInfo] = []
    try:
        if not root.is_dir():
            return out
        folders = sorted(p for p in root.iterdir() if _is_dir(p))
    except OSError as exc:
        raise SessionsUnreadable(
            str(root), None, f"cannot list the sessions folder ({exc.strerror or exc})"
        ) from None
    for folder in folders:
        info = _info(folder)
        if info is not None:
            out.append(info)
    out.sort(key=lambda s: s.modified, reverse=True)
    return out


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:
        return False


def _info(folder: Path) -> SessionInfo | None:
    """The picker's line for ``folder``; None when it holds no session.json, unless its
    runs/ folder is left (a session whose file was deleted: listed with what it lacks and
    what can be recovered, as the class view lists it)."""
    path = folder / SESSION_FILE
    what = folder_holds(folder)
    if what == "lost":
        return _lost(folder)
    if what == "closed":
        return SessionInfo(
            folder.name, folder, (), "", "", _mtime(folder), damaged=str(_closed(folder))
        )
    if what != "session":
        return None
    locked_by = lock_owner(folder)
    try:
        data = read_session_file(path)
    except InputError as exc:
        return SessionInfo(
            folder.name, folder, (), "", "", _mtime(path), damaged=str(exc), locked_by=locked_by
        )
    except Exception as exc:
        why = damaged_message(path, f"cannot be read ({type(exc).__name__}: {exc})")
        return SessionInfo(
            folder.name, folder, (), "", "", _mtime(path), damaged=why, locked_by=locked_by
        )
    return SessionInfo(
        id=folder.name,  # a copied folder's file still says the first folder's id
        path=folder,
        members=tuple(str(m) for m in data["members"]),
        date=data["date"],
        last_step=data["current_step"],
        modified=data["modified"],
        locked_by=locked_by,
    )


NEVER_A_SESSION = frozenset({"lost+found"})
"""Folders that no program of ours made and that a plain user cannot look into (the root of
an ext4 USB stick holds ``lost+found``): never listed as a session that cannot be read."""


def folder_holds(folder: Path) -> str:
    """What the folder ``folder`` of a sessions folder holds: ``session`` (a session.json),
    ``lost`` (a session's runs/ folder without its session.json), ``closed`` (this user may
    not look into it: listed as a session that cannot be read, never left out in silence:
    s38 attack, ``chmod 000`` hid a group from the start screen and the class view) or ``''``
    (no session)."""
    try:
        os.lstat(folder / SESSION_FILE)
        return "session"
    except FileNotFoundError:
        pass
    except PermissionError:
        return "" if folder.name in NEVER_A_SESSION else "closed"
    except OSError:
        return ""
    try:
        return "lost" if (folder / RUNS_DIR).is_dir() else ""
    except OSError:
        return ""


def _closed(folder: Path) -> SessionDamaged:
    return SessionDamaged(
        str(folder),
        None,
        not_permitted(folder, PermissionError(errno.EACCES, os.strerror(errno.EACCES))),
    )


def _lost(folder: Path) -> SessionInfo:
    """The picker's line for a session folder whose session.json is gone and whose runs/
    folder is left: the run logs in it can be imported into a new session."""
    try:
        logs = sorted(
            f"{RUNS_DIR}/{p.name}" for p in (folder / RUNS_DIR).iterdir() if p.suffix == ".csv"
        )
    except OSError:
        logs = []
    left = (
        f"{len(logs)} run log{'s' if len(logs) != 1 else ''} left in it ({', '.join(logs)}): "
        f"start a new session and load each with {in_palette('import_log')}"
        if logs
        else "nothing in its runs/ folder can be recovered"
    )
    return SessionInfo(
        folder.name,
        folder,
        (),
        "",
        "",
        _mtime(folder / RUNS_DIR),
        damaged=f"no session.json (deleted?): names and entries are lost; {left}",
        locked_by=lock_owner(folder),
        runs_left=tuple(logs),
    )


def _mtime(path: Path) -> str:
    try:
        stamp = path.stat().st_mtime
    except OSError:
        return ""
    return datetime.fromtimestamp(stamp, UTC).isoformat(timespec="seconds")


def resolve(session: str, root: Path) -> Path:
    """The folder of a session given as a folder path or as an id under ``root``.

    Raises SessionMissing with one line when neither exists.
    """
    p = Path(session)
    if (p / SESSION_FILE).exists():
        return p
    q = Path(root) / session
    if (q / SESSION_FILE).exists():
        return q
    looked = f"{p / SESSION_FILE}" + ("" if q == p else f" and {q / SESSION_FILE}")
    raise SessionMissing(session, None, f"no session found (looked for {looked})")
