"""One object for the event loop and the worker threads, used by one of them at a time."""

from __future__ import annotations

import threading
from typing import Generic, TypeVar

T = TypeVar("T")


class Shared(Generic[T]):
    """Holds ``value`` behind a lock: ``with shared as value: ...``. The lab's Session is
    meant for one thread; the UI uses it from the event loop and from the stream worker
    (the Task 10 procedure records and keeps its run), so every use goes through here. The
    workers that only read it (views, the report) get a frozen snapshot instead
    (:meth:`minseg_tui.lab.state.session.Session.snapshot`). Re-entrant."""

    def __init__(self, value: T) -> None:
        self._value = value
        self._lock = threading.RLock()

    def __enter__(self) -> T:
        self._lock.acquire()
        return self._value

    def __exit__(self, *exc: object) -> None:
        self._lock.release()
