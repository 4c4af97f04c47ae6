"""The bounded buffer between the device worker and the plots (thread-safe, newest kept)."""

from __future__ import annotations

import threading
from collections import deque

import numpy as np
from numpy.typing import NDArray

from minseg_tui.device.samples import SampleBatch


class LiveBuffer:
    """The last ``size`` samples: board time t (s), encoder count, requested u (V).

    The worker thread extends it; the redraw timer takes a snapshot as arrays.
    """

    def __init__(self, size: int = 4000) -> None:
        self._lock = threading.Lock()
        self._t: deque[float] = deque(maxlen=size)
        self._count: deque[int] = deque(maxlen=size)
        self._u: deque[float] = deque(maxlen=size)
        self.size = size
        self.total = 0

    def extend(self, batch: SampleBatch) -> None:
        """Append one batch (called from the worker); only its newest ``size`` samples matter."""
        n = len(batch)
        if not n:
            return
        k = max(0, n - self.size)
        with self._lock:
            self._t.extend(batch.t[k:].tolist())
            self._count.extend(batch.count[k:].tolist())
            self._u.extend(batch.u_req[k:].tolist())
            self.total += n

    @property
    def latest(self) -> float | None:
        """The newest sample's board time, s (None: no sample yet)."""
        with self._lock:
            return self._t[-1] if self._t else None

    def clear(self) -> None:
        """Forget everything (new device)."""
        with self._lock:
            self._t.clear()
            self._count.clear()
            self._u.clear()

    def snapshot(self) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]:
        """Copies of (t, count, u_req) as arrays, oldest first."""
        with self._lock:
            return (
                np.array(self._t, dtype=float),
                np.array(self._count, dtype=np.int64),
                np.array(self._u, dtype=float),
            )


def at_level(
    t: NDArray[np.float64], count: NDArray[np.int64], u: NDArray[np.float64], level: float | None
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """The newest samples (board time s, counts) taken at requested voltage ``level`` (V),
    from the last sample at another voltage on: right after F3 the window of the old level
    is no steady state of the new one (None: all of them)."""
    if level is None or u.size == 0:
        return t, count
    other = np.flatnonzero(np.abs(u - level) > LEVEL_TOL)
    first = int(other[-1]) + 1 if other.size else 0
    return t[first:], count[first:]


LEVEL_TOL = 0.0005
"""Two requested voltages closer than this are one level, V (the link carries mV)."""
