"""Samples as the link hands them over: batches of numpy arrays, and their angle and velocity.

A :class:`SampleBatch` holds samples in arrival order with ``seq`` and ``t_us`` already
unwrapped by the link (int64) and the connection (``epoch``) each came in;
:func:`motion` turns a batch into angle (rad) and velocity (rad/s) from the board's
timestamps, restarting the velocity at each new epoch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui import signals


@dataclass(frozen=True)
class SampleBatch:
    """Samples in arrival order: seq and t_us unwrapped (int64, us), count (int, encoder),
    u_req (V, in force from the sample on), epoch (connection number), t_host (host
    monotonic arrival time, s)."""

    seq: NDArray[np.int64]
    t_us: NDArray[np.int64]
    count: NDArray[np.int64]
    u_req: NDArray[np.float64]
    epoch: NDArray[np.int64]
    t_host: NDArray[np.float64]

    def __len__(self) -> int:
        return int(self.seq.size)

    @property
    def t(self) -> NDArray[np.float64]:
        """Board time of each sample, s."""
        return self.t_us / 1e6

    def newest(self) -> SampleBatch:
        """The newest sample alone, as a batch of one (empty from an empty batch)."""
        return SampleBatch(*(getattr(self, f)[-1:] for f in _FIELDS))

    @staticmethod
    def from_rows(rows: list[tuple[int, int, int, int, int, float]]) -> SampleBatch:
        """From (seq, t_us, count, u_mV, epoch, t_host) tuples."""
        if not rows:
            return SampleBatch.concat([])
        a = np.array(rows, dtype=np.float64)
        ints = np.array([r[:5] for r in rows], dtype=np.int64)
        return SampleBatch(
            ints[:, 0], ints[:, 1], ints[:, 2], ints[:, 3] / 1000.0, ints[:, 4], a[:, 5]
        )

    @staticmethod
    def concat(batches: list[SampleBatch]) -> SampleBatch:
        """One batch from several (an empty batch from none)."""
        if not batches:
            e = np.zeros(0, dtype=np.int64)
            return SampleBatch(e, e, e, np.zeros(0), e, np.zeros(0))
        return SampleBatch(*(np.concatenate([getattr(b, f) for b in batches]) for f in _FIELDS))


_FIELDS = ("seq", "t_us", "count", "u_req", "epoch", "t_host")


@dataclass(frozen=True)
class Motion:
    """Angle and velocity of a batch: t in s (board time), theta in rad, omega in rad/s."""

    t: NDArray[np.float64]
    theta: NDArray[np.float64]
    omega: NDArray[np.float64]


def motion(batch: SampleBatch, before: SampleBatch | None = None, window: float = 0.0) -> Motion:
    """Angle and velocity (board timestamps, :func:`signals.timestamp_velocity`) of a batch.

    ``before`` is what came earlier (only its tail is used), so the first samples of a
    batch get a velocity too. Velocity restarts (0) at the first sample of each epoch.
    """
    n = len(batch)
    if before is not None and len(before) and n:
        keep = before.epoch == batch.epoch[0]
        t_first = batch.t_us[0] / 1e6
        keep &= before.t_us / 1e6 >= t_first - max(window, 0.0) - 1e-9
        idx = np.nonzero(keep)[0]
        if idx.size == 0 and before.epoch[-1] == batch.epoch[0]:
            idx = np.array([len(before) - 1])
        elif idx.size and window <= 0:
            idx = idx[-1:]
        if idx.size == 0 and before.epoch[-1] == batch.epoch[0]:
            idx = np.array([len(before) - 1])
        head = SampleBatch(*(getattr(before, f)[idx] for f in _FIELDS))
        full = SampleBatch.concat([head, batch])
    else:
        full = batch
    t = full.t_us / 1e6
    omega = np.zeros(len(full))
    bounds = np.flatnonzero(np.diff(full.epoch)) + 1
    for seg in np.split(np.arange(len(full)), bounds):
        if seg.size:
            omega[seg] = signals.timestamp_velocity(t[seg], full.count[seg], window)
    skip = len(full) - n
    return Motion(t[skip:], signals.angle(full.count[skip:]), omega[skip:])


__all__ = ["Motion", "SampleBatch", "motion"]
