"""Where a model's simulation deviates: after rising edges, after falling edges, steady state."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

REGIONS: tuple[str, ...] = ("after_rising_edges", "after_falling_edges", "steady_state")


@dataclass(frozen=True)
class Deviation:
    """The residual (measured - simulated, rad/s) in one region: rows, rms and mean; and
    ``edges``, how many steps of the region's kind the log has (:func:`edge_count`)."""

    region: str
    rows: int
    rms: float
    mean: float
    edges: int = 0

    def to_dict(self) -> dict[str, object]:
        return {"region": self.region, "rows": self.rows, "rms": self.rms, "mean": self.mean}


def _width(T: float, ts: float) -> int:
    """Rows after a step that belong to its region: 4 T, at least 4 samples."""
    return max(4, int(np.ceil(4 * T / ts)))


def regions(u: FloatArray, T: float, ts: float) -> NDArray[np.int64]:
    """Region index per row: 0 within 4 T (at least 4 samples) after a rise of |u|,
    1 after a fall, 2 elsewhere."""
    out = np.full(u.size, 2, dtype=np.int64)
    width = _width(T, ts)
    for e in (np.flatnonzero(np.diff(u) != 0) + 1).tolist():
        kind = 0 if abs(u[e]) > abs(u[e - 1]) else 1
        out[e + 1 : e + 1 + width] = kind
    return out


def edge_count(
    u: FloatArray,
    region: str,
    T: float | None = None,
    ts: float | None = None,
    keep: NDArray[np.bool_] | None = None,
) -> int:
    """How many steps of ``region``'s kind the input ``u`` (V) has: rises of |u| for
    'after_rising_edges', falls for 'after_falling_edges'; 0 for the steady state. With
    ``keep`` (and the model's ``T`` and the sample period ``ts``, s) a step counts only where
    a row of the region that follows it is kept: a step whose rows the fit left out is not
    one the region's figures speak of."""
    if region not in REGIONS[:2]:
        return 0
    e = np.flatnonzero(np.diff(u) != 0) + 1
    rise = np.abs(u[e]) > np.abs(u[e - 1])
    kind = rise if region == REGIONS[0] else ~rise
    if keep is None or T is None or ts is None:
        return int(np.count_nonzero(kind))
    counted = (regions(u, T, ts) == REGIONS.index(region)) & keep
    width = _width(T, ts)
    return sum(1 for i in e[kind].tolist() if np.any(counted[i + 1 : i + 1 + width]))


def deviations(
    u: FloatArray, residual: FloatArray, T: float, ts: float, keep: NDArray[np.bool_] | None = None
) -> list[Deviation]:
    """The residual summarised per region (rows where ``keep`` is False and regions with no
    rows are left out)."""
    reg = regions(u, T, ts)
    if keep is not None:
        reg = np.where(keep, reg, -1)
    out = []
    for i, name in enumerate(REGIONS):
        r = residual[reg == i]
        if r.size:
            out.append(
                Deviation(
                    name,
                    int(r.size),
                    float(np.sqrt(np.mean(r * r))),
                    float(np.mean(r)),
                    edge_count(u, name, T, ts, keep),
                )
            )
    return out
