"""Session files on disk: atomic writes, the session file's schema, the lock, the list.

A session is a folder ``<sessions>/<id>/`` holding ``session.json`` (what the group
entered; schema :data:`SCHEMA`), ``runs/<name>.csv`` (recorded runs as step logs),
``runs/<name>.partial`` while a run is being recorded, ``lock`` (locked by the program
that has it open, :mod:`minseg_tui.lock`) and the reports.

Every write of a whole file goes to a temporary file in the same folder, is flushed and
fsynced, replaces the old file with ``os.replace`` and then the folder is fsynced: a crash
leaves either the old or the new file, never a mix. A session file that cannot be read
(bad JSON, another schema) raises :class:`SessionDamaged` and is never written over.
"""

from __future__ import annotations

import contextlib
import json
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from minseg_tui.errors import InputError, MinsegError
from minseg_tui.lock import FileLock, LockHeld, holder

SCHEMA: int = 1
"""Version of session.json's layout; a file with another version is refused."""

KIND: str = "minseg-tui session"
"""The ``kind`` every session file carries."""

SESSION_FILE = "session.json"
LOCK_FILE = "lock"
RUNS_DIR = "runs"


class SessionDamaged(InputError):
    """session.json exists but cannot be used; the message says what to do. It is kept as is."""


class SessionMissing(InputError):
    """No session at the given place."""


class SessionLocked(MinsegError):
    """Another running program has the session open."""


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
    """Replace ``path`` by ``data`` atomically (temp file, fsync, os.replace, fsync folder)."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
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
    except OSError:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    fsync_dir(path.parent)


def atomic_write_text(path: Path, text: str) -> None:
    """Replace ``path`` by UTF-8 ``text`` atomically."""
    atomic_write_bytes(path, text.encode("utf-8"))


def damaged_message(path: Path, why: str) -> str:
    """The one-line message for a damaged session file: what is wrong and what to do."""
    return (
        f"{why}; the file is left untouched. Start a new session (this folder is kept), "
        f"or repair {path.name} by hand (or restore it from a backup) and open it again"
    )


def read_session_file(path: Path) -> dict[str, Any]:
    """The JSON object of ``path`` (a session.json), checked against the schema.

    Raises SessionMissing when there is no file and SessionDamaged (naming the file, the
    line when JSON is broken, and what to do) when it cannot be used.
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise SessionMissing(str(path.parent), None, f"no session here (no {path.name})") from None
    except OSError as exc:
        raise SessionDamaged(
            str(path), None, damaged_message(path, f"cannot be read ({exc.strerror})")
        ) from None
    try:
        data = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise SessionDamaged(str(path), None, damaged_message(path, "is not UTF-8 text")) from None
    except json.JSONDecodeError as exc:
        raise SessionDamaged(
            str(path), exc.lineno, damaged_message(path, f"is not valid JSON ({exc.msg})")
        ) from None
    problem = schema_problem(data)
    if problem:
        raise SessionDamaged(str(path), None, damaged_message(path, problem))
    return data


_REQUIRED: dict[str, type | tuple[type, ...]] = {
    "id": str,
    "members": list,
    "date": str,
    "current_step": str,
    "entries": dict,
    "captures": dict,
    "runs": list,
    "created": str,
    "modified": str,
}


def schema_problem(data: object) -> str | None:
    """Why ``data`` is not a session of this schema, or None when it is."""
    if not isinstance(data, dict):
        return "does not hold a JSON object"
    if data.get("kind") != KIND:
        return f"is not a minseg-tui session file (kind {data.get('kind')!r})"
    if data.get("schema") != SCHEMA:
        return f"has schema {data.get('schema')!r}, this program reads schema {SCHEMA}"
    for key, typ in _REQUIRED.items():
        if not isinstance(data.get(key), typ):
            return f"has no valid {key!r}"
    for key, e in data["entries"].items():
        if (
            not isinstance(e, dict)
            or not isinstance(e.get("text"), str)
            or not isinstance(e.get("ok"), bool)
        ):
            return f"has a broken entry {key!r}"
    for r in data["runs"]:
        if (
            not isinstance(r, dict)
            or not isinstance(r.get("name"), str)
            or not isinstance(r.get("file"), str)
        ):
            return "has a broken run record"
    return None


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


def list_sessions(root: Path) -> list[SessionInfo]:
    """Every session folder under ``root``, newest change first (damaged ones listed too)."""
    root = Path(root)
    out: list[SessionInfo] = []
    if not root.is_dir():
        return out
    for folder in sorted(p for p in root.iterdir() if p.is_dir()):
        path = folder / SESSION_FILE
        if not path.exists():
            continue
        try:
            data = read_session_file(path)
        except InputError as exc:
            out.append(
                SessionInfo(
                    folder.name,
                    folder,
                    (),
                    "",
                    "",
                    _mtime(path),
                    damaged=str(exc),
                    locked_by=lock_owner(folder),
                )
            )
            continue
        out.append(
            SessionInfo(
                id=data["id"],
                path=folder,
                members=tuple(str(m) for m in data["members"]),
                date=data["date"],
                last_step=data["current_step"],
                modified=data["modified"],
                locked_by=lock_owner(folder),
            )
        )
    out.sort(key=lambda s: s.modified, reverse=True)
    return out


def _mtime(path: Path) -> str:
    from datetime import UTC, datetime

    return datetime.fromtimestamp(path.stat().st_mtime, UTC).isoformat(timespec="seconds")


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
    raise SessionMissing(
        session, None, f"no session found (looked for {p / SESSION_FILE} and {q / SESSION_FILE})"
    )
