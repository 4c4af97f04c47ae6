"""The bounded buffer between the device worker and the plots (thread-safe, newest kept)."""

from __future__ import annotations

import threading
from collections import deque

import numpy as np
from numpy.typing import NDArray

from minseg_tui.ui.ports import Batch


class LiveBuffer:
    """The last ``size`` samples: board time t (s), encoder count, requested u (V).

    The worker thread extends it; the redraw timer takes a snapshot as arrays.
    """

    def __init__(self, size: int = 1200) -> None:
        self._lock = threading.Lock()
        self._t: deque[float] = deque(maxlen=size)
        self._count: deque[int] = deque(maxlen=size)
        self._u: deque[float] = deque(maxlen=size)
        self.total = 0
        self._rec: list[tuple[float, int, float]] | None = None

    def extend(self, batch: Batch) -> None:
        """Append one batch (called from the worker)."""
        with self._lock:
            self._t.extend(batch.t)
            self._count.extend(batch.count)
            self._u.extend(batch.u_req)
            self.total += len(batch.t)
            if self._rec is not None:
                self._rec.extend(zip(batch.t, batch.count, batch.u_req, strict=True))

    def start_recording(self) -> None:
        """Keep every sample from now on (a run), besides the bounded window."""
        with self._lock:
            self._rec = []

    @property
    def recorded(self) -> int:
        """Samples recorded so far in the current run (0 when not recording)."""
        with self._lock:
            return len(self._rec) if self._rec is not None else 0

    def stop_recording(self) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]:
        """End the run; its (t, count, u_req) arrays."""
        with self._lock:
            rec, self._rec = self._rec or [], None
        if not rec:
            return np.zeros(0), np.zeros(0, dtype=np.int64), np.zeros(0)
        t, c, u = zip(*rec, strict=True)
        return np.array(t, dtype=float), np.array(c, dtype=np.int64), np.array(u, dtype=float)

    def clear(self) -> None:
        """Forget everything (new device)."""
        with self._lock:
            self._t.clear()
            self._count.clear()
            self._u.clear()

    def snapshot(self) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]:
        """Copies of (t, count, u_req) as arrays, oldest first."""
        with self._lock:
            return (np.array(self._t, dtype=float), np.array(self._count, dtype=np.int64),
                    np.array(self._u, dtype=float))
