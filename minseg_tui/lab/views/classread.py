"""Reading a class: every group's row, computed once and kept outside the sessions.

Reading a group costs about a second of CPU (Tasks 11-15's fits and the model check on the
step run); a class of 100 groups would take minutes each time the view is opened. A group's
row depends on nothing but the files in its session folder and on this program's code, so
:func:`key` hashes exactly those, and the row computed once is kept under that key in the
user's cache folder (``$MINSEG_TUI_CACHE``, else ``$XDG_CACHE_HOME/minseg-tui/class``,
else ``~/.cache/minseg-tui/class``). Any change to a session's files, or to the code that
computes, gives a new key: a stale row is never shown.

The cache is never inside a session folder and is only a memo: a cache that cannot be read
or written is passed over in silence (the row is computed as if it were not there).
:func:`build` reads the rows not in the cache on several processes when there are many.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import math
import os
import warnings
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from functools import cache
from pathlib import Path

import minseg_tui
from minseg_tui.lab.saving.store import LOCK_FILE, read_regular
from minseg_tui.lab.state.compare import POLICY_FILE
from minseg_tui.lab.views.classview import (
    ClassView,
    Group,
    Own,
    judge,
    read_group,
    read_kept,
    session_folders,
)
from minseg_tui.lab.views.own_first import OwnRow

MAX_FILE = 64 << 20
"""Session files larger than this are not hashed (the row is then computed every time)."""

_SKIP = {LOCK_FILE, "report.md", "report.html"}
"""Files of a session folder a row does not depend on."""


def folder() -> Path:
    """The cache folder (see the module docstring)."""
    env = os.environ.get("MINSEG_TUI_CACHE")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "minseg-tui" / "class"


@cache
def code_fingerprint() -> str:
    """A hash of the package's computing code (every .py file outside ui/, cli/ and report/,
    which only show the rows)."""
    root = Path(minseg_tui.__file__).parent
    h = hashlib.sha256(minseg_tui.__version__.encode())
    for p in sorted(root.rglob("*.py")):
        rel = p.relative_to(root).as_posix()
        if rel.startswith(("ui/", "cli/", "report/")):
            continue
        h.update(rel.encode())
        h.update(p.read_bytes())
    return h.hexdigest()


def key(session_folder: Path) -> str | None:
    """The key of the row of ``session_folder``: a hash of the code, of the lab's policy
    beside the sessions (it says when the group was shown the computed values) and of every
    file in the folder (names and bytes); None when a file cannot be read."""
    h = hashlib.sha256(code_fingerprint().encode())
    try:
        policy = Path(session_folder).parent / POLICY_FILE
        h.update(read_regular(policy, MAX_FILE) if policy.is_file() else b"no policy")
        h.update(b"\0")
        files = sorted(
            p for p in Path(session_folder).rglob("*") if p.is_file() and p.name not in _SKIP
        )
        for p in files:
            data = read_regular(p, MAX_FILE)
            if len(data) > MAX_FILE:
                return None
            h.update(p.relative_to(session_folder).as_posix().encode() + b"\0")
            h.update(len(data).to_bytes(8, "little"))
            h.update(data)
    except OSError:
        return None
    return h.hexdigest()


def _to_json(g: Group) -> dict[str, object]:
    return {
        "id": g.id,
        "members": list(g.members),
        "date": g.date,
        "step": g.step,
        "at": g.at,
        "values": {
            k: v if v is not None and math.isfinite(v) else None for k, v in g.values.items()
        },
        "cause": g.cause,
        "cause_code": g.cause_code,
        "own": [[o.key, o.label, o.unit, o.own, o.computed, o.rel_diff, o.right] for o in g.own],
        "own_rows": [[r.key, list(r.cells), r.why] for r in g.own_rows],
        "lacks": list(g.lacks),
        "damaged": g.damaged,
        "readable": g.readable,
        "flags": list(g.flags),
        "slipped": list(g.slipped),
        "notes": list(g.notes),
        "typed": dict(g.typed),
        "unanswered": g.unanswered,
    }


def _texts(x: object) -> tuple[str, ...]:
    if not isinstance(x, list):
        raise TypeError("expected a list")
    return tuple(str(v) for v in x)


def _list(x: object) -> list[object]:
    if not isinstance(x, list):
        raise TypeError("expected a list")
    return x


def _typed(x: object) -> dict[str, str]:
    if not isinstance(x, dict):
        raise TypeError("expected a mapping")
    return {str(k): str(v) for k, v in x.items()}


def _own_row(x: object) -> OwnRow:
    k, cells, why = _list(x)
    return OwnRow(str(k), _texts(cells), str(why))


def _from_json(d: dict[str, object], session_folder: Path) -> Group:
    own = d["own"]
    values = d["values"]
    if not isinstance(own, list) or not isinstance(values, dict):
        raise TypeError("not a cached row")
    return Group(
        id=session_folder.name,  # the folder as it is named now (a rename keeps the key)
        folder=session_folder,
        members=_texts(d["members"]),
        date=str(d["date"]),
        step=str(d["step"]),
        at=str(d.get("at", "")),
        values={str(k): (None if v is None else float(v)) for k, v in values.items()},
        cause=str(d["cause"]),
        cause_code=str(d["cause_code"]),
        own=tuple(Own(*o) for o in own),
        own_rows=tuple(_own_row(r) for r in _list(d["own_rows"])),
        lacks=_texts(d["lacks"]),
        damaged=None if d["damaged"] is None else str(d["damaged"]),
        readable=bool(d["readable"]),
        flags=_texts(d["flags"]),
        slipped=_texts(d["slipped"]),
        notes=_texts(d.get("notes", [])),
        typed=_typed(d.get("typed", {})),
        unanswered=str(d.get("unanswered", "")),
    )


def load(k: str, session_folder: Path) -> Group | None:
    """The row kept under ``k`` (its folder, and the id it names, set to ``session_folder``:
    the key hashes what is in the folder, not its name), or None."""
    try:
        d = json.loads((folder() / f"{k}.json").read_text(encoding="utf-8"))
        return _from_json(d, session_folder)
    except (OSError, ValueError, KeyError, TypeError):
        return None


def store(k: str, g: Group) -> None:
    """Keep the row ``g`` under ``k`` (silently not, when the cache cannot be written).

    Written to a temporary file and renamed, so a reader never sees half a row, but not
    synced to the disk (200 syncs took over a second for 100 groups): a row that a power
    cut leaves empty or garbled fails to load and is computed again."""
    if not g.readable:
        return  # a session that cannot be read is read again next time
    with contextlib.suppress(OSError, ValueError):
        folder().mkdir(parents=True, exist_ok=True)
        path = folder() / f"{k}.json"
        tmp = path.with_name(f".{k}.{os.getpid()}.tmp")
        try:
            tmp.write_text(json.dumps(_to_json(g), allow_nan=False), encoding="utf-8")
            os.replace(tmp, path)
        finally:
            tmp.unlink(missing_ok=True)


def read(session_folder: Path) -> Group:
    """The row of ``session_folder`` (:func:`minseg_tui.lab.views.classview.read_group`), from the
    cache when its files and the code are unchanged, else computed and kept."""
    k = key(session_folder)
    if k is not None:
        got = load(k, session_folder)
        if got is not None:
            return got
    g = read_group(session_folder)
    if k is not None:
        store(k, g)
    return g


def _read_noting(session_folder: Path) -> tuple[Group, list[str]]:
    """In a worker process: the row, and the numeric warnings computing it raised (a
    worker's own would be lost; the caller raises them again where they are noted)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RuntimeWarning)
        g = read_group(session_folder)
    return g, [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]


PARALLEL_FROM: int = 4
"""Rows to compute (not in the cache) from which :func:`build` spreads them over processes."""


def build(
    root: Path, workers: int | None = None, each: Callable[[int, Group], None] | None = None
) -> ClassView:
    """The class view of every session under ``root`` (InputError, one line, when there is
    none), each row from the cache, else from the results its session file keeps (here:
    a few ms each), else computed (read-only: nothing written in the sessions, no lock
    taken). ``workers``: processes for the rows to compute (default: the CPUs this process
    may use; 1 computes here). ``each(number, group)`` is called as rows arrive."""
    folders = session_folders(root)
    keys = [key(f) for f in folders]
    rows: list[Group | None] = [
        None if k is None else load(k, f) for k, f in zip(keys, folders, strict=True)
    ]
    new = [i for i, g in enumerate(rows) if g is None]
    for i in new:
        rows[i] = read_kept(folders[i])
    todo = [i for i in new if rows[i] is None]
    n = workers if workers is not None else len(os.sched_getaffinity(0))
    if n > 1 and len(todo) >= PARALLEL_FROM:
        with ProcessPoolExecutor(max_workers=min(n, len(todo))) as pool:
            computed = pool.map(_read_noting, [folders[i] for i in todo])
            for i, (row, said) in zip(todo, computed, strict=True):
                rows[i] = row
                for message in said:
                    warnings.warn(message, RuntimeWarning, stacklevel=1)
    else:
        for i in todo:
            rows[i] = read_group(folders[i])
    done: list[Group] = []
    new_set = set(new)
    for i, got in enumerate(rows):
        assert got is not None
        k = keys[i]
        if i in new_set and k is not None:
            store(k, got)
        if each is not None:
            each(i + 1, got)
        done.append(got)
    view = judge(done)
    return ClassView(Path(root), view.groups, view.spreads)
