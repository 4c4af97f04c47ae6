"""identify's 95 % interval of T on an angle read in whole counts and then interpolated, as
the ev3 logs of ../shared/data/real-motors were (issue 17, stop 35): does it hold the true T?

    .venv/bin/python benchmarks/identify_interpolated.py [--seeds 40] [--real DIR]

Each simulated log is made the way convert.py made ev3-large-duty100 and -duty30 from the
EV3's own file: a first-order rise from rest (T and the steady speed identify finds on the
real log: 74.1 ms and 17.01 rad/s at 8 V, 56.5 ms and 4.632 rad/s at 2.4 V), starting 0-1 ms
or 5-7 ms after the logged step (the real logs' fits start it about 6 ms late), read in whole
degrees with a random phase at the real log's own loop times (original.txt's intervals, 3.4-9
ms, from a random place), linearly interpolated onto 5 ms, 20 rest rows put before it,
written to 6 significant digits, the Euler speed. Held-out seeds 5000 on; nothing was tuned
on them.

The interpolated values sit on no grid of counts, so the fit finds no count, and T's interval
on the one rise rests on its residuals' lagged covariance alone, which is low on a single
step (minseg_tui.model.identify.lsq.cluster_covariance): the rounding the interpolation hides
is not in it. Printed for each case, without and with a ``# cpr: 360`` line (which puts the
counts' rounding in the interval since stop 35): how often the interval holds T, T's median
and rms error, and the median half width of the interval (% of T).
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from minseg_tui.model.identify import Reading, identify
from minseg_tui.model.runlog import RunLog

DEGREE = math.radians(1.0)
CASES = {
    "ev3-large-duty100": (0.0741, 17.01, 8.0),
    "ev3-large-duty30": (0.0565, 4.632, 2.4),
}
"""Folder -> T (s), steady speed (rad/s) and applied voltage (V) of the simulated rise."""


def _six(x: np.ndarray) -> np.ndarray:
    return np.array([float(f"{v:.6g}") for v in x])


def make(real: Path, case: str, seed: int, late: tuple[float, float], cpr: int | None) -> RunLog:
    """One simulated log of ``case`` (see the module docstring); ``late``: the range the
    rise's start is drawn from (s after the logged step); ``cpr``: the ``# cpr:`` line."""
    T, w, u_on = CASES[case]
    rng = np.random.default_rng(seed)
    raw_t = np.genfromtxt(real / case / "original.txt", names=True)["time"]
    dt = np.roll(np.diff(raw_t), int(rng.integers(raw_t.size - 1)))
    t = np.concatenate(([0.0], np.cumsum(dt)))
    s = np.maximum(t - float(rng.uniform(*late)), 0.0)
    counts = np.floor(w * (s + T * np.expm1(-s / T)) / DEGREE + float(rng.uniform()))
    ts = 0.005
    grid = ts * np.arange(int(math.floor(t[-1] / ts + 1e-9)) + 1)
    angle = _six(np.concatenate((np.zeros(20), np.interp(grid, t, (counts - counts[0]) * DEGREE))))
    tt = np.round(np.concatenate((-ts * np.arange(20, 0, -1), grid)), 6)
    return RunLog(
        t=tt,
        u=np.where(tt >= 0, u_on, 0.0),
        omega=_six(np.concatenate(([0.0], np.diff(angle) / ts))),
        extra={"theta": angle},
        metadata={"ts": "0.005", **({"cpr": str(cpr)} if cpr else {})},
        source=f"{case} seed {seed}",
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=40)
    ap.add_argument("--real", type=Path, default=Path("../shared/data/real-motors"))
    a = ap.parse_args()
    print(f"{a.seeds} held-out seeds per row (5000-{4999 + a.seeds}); errors and widths in % of T")
    print(
        f"{'log':18} {'start ms':>8} {'# cpr':>6} {'held':>7} {'T med':>6} {'T rms':>6} "
        f"{'half w':>6} {'s/log':>6}"
    )
    for case, (T, _, u_on) in CASES.items():
        for late in ((0.0, 0.001), (0.005, 0.007)):
            for cpr in (None, 360):
                started = time.process_time()
                held, err, half = 0, [], []
                for seed in range(5000, 5000 + a.seeds):
                    log = make(a.real, case, seed, late, cpr)
                    r = identify([Reading(u_on, u_on, 10.0, 50.0)], 5.0, log)
                    assert r.step is not None
                    lo, hi = r.step.T_ci
                    held += lo <= T <= hi
                    err.append(r.step.T / T - 1.0)
                    half.append((hi - lo) / 2.0 / T)
                e = np.array(err) * 100.0
                print(
                    f"{case[10:]:18} {late[0] * 1e3:3g}-{late[1] * 1e3:<4g} {cpr or '-':>6} "
                    f"{held:3d}/{a.seeds:<3d} {np.median(e):+6.2f} {math.sqrt(np.mean(e**2)):6.2f} "
                    f"{np.median(half) * 100.0:6.2f} {(time.process_time() - started) / a.seeds:6.2f}",
                    flush=True,
                )


if __name__ == "__main__":
    main()
