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

With ``--grid`` (stop 36): whether the count could be read off the log itself instead, on the
same logs without the line and on the two real ones: how often the count finder of
minseg_tui.model.identify.counts finds a grid, and two readings of the angle's steps that
look for the count, each against the true 1 degree: the smallest step between rows (where
the wheel moves, beyond the written digits) and the largest step in 0.05-5 degrees whose
whole multiples every such step lies within 10 % of (a tolerant gcd).
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.identify import Reading, identify
from minseg_tui.model.identify.counts import count_quantum, written_error
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


def _tolerant_gcd(steps: np.ndarray, lo: float, hi: float, tol: float = 0.1) -> float | None:
    """The largest q (rad) in [lo, hi] whose whole multiples every step (rad) lies within
    ``tol`` q of, or None."""
    for q in np.geomspace(hi, lo, 4000):
        if bool(np.all(np.abs(steps / q - np.round(steps / q)) <= tol)):
            return float(q)
    return None


def read_grid(theta: np.ndarray) -> tuple[float | None, float, float | None]:
    """The count (rad) three ways from the angle values alone: the count finder's (None: no
    grid), the smallest step between rows where the wheel moves (beyond what the written
    digits allow) and the tolerant gcd of those steps (:func:`_tolerant_gcd`)."""
    steps = np.diff(theta)
    err = written_error(theta)
    moving = np.abs(steps) > 4.0 * (err[1:] + err[:-1])
    moved = np.abs(steps[moving])
    smallest = float(np.min(moved)) if moved.size else math.nan
    return (
        count_quantum(theta, 720),
        smallest,
        _tolerant_gcd(moved, DEGREE / 20, DEGREE * 5),
    )


def grids(real: Path, seeds: int) -> None:
    """--grid: can the count be read off an interpolated log itself?"""
    print(f"the count read off the angle alone, {seeds} seeds per row; against the true 1 degree")
    print(
        f"{'log':18} {'start ms':>8} {'finder':>7} {'smallest step, deg: med (range)':>32} "
        f"{'within 5 %':>10} {'gcd within 5 %':>14} {'gcd found':>9}"
    )
    for case in CASES:
        for late in ((0.0, 0.001), (0.005, 0.007)):
            found, small, gcd = [], [], []
            for seed in range(5000, 5000 + seeds):
                log = make(real, case, seed, late, None)
                f, s, g = read_grid(np.asarray(log.extra["theta"], dtype=float))
                found.append(f is not None)
                small.append(s / DEGREE)
                gcd.append(None if g is None else g / DEGREE)
            sm = np.array(small)
            print(
                f"{case[10:]:18} {late[0] * 1e3:3g}-{late[1] * 1e3:<4g} {sum(found):3d}/{seeds:<3d} "
                f"{np.median(sm):14.3f} ({sm.min():.3f}-{sm.max():.3f}) "
                f"{int(np.sum(np.abs(sm - 1) < 0.05)):6d}/{seeds:<3d} "
                f"{sum(g is not None and abs(g - 1) < 0.05 for g in gcd):10d}/{seeds:<3d} "
                f"{sum(g is not None for g in gcd):5d}/{seeds:<3d}"
            )
    for case in CASES:
        theta, _ = read_run_log(real / case / "step.csv").angle()
        f, s, g = read_grid(np.asarray(theta, dtype=float))
        print(
            f"{case} (real): finder {'none' if f is None else f'{f / DEGREE:.4f} deg'}, "
            f"smallest step {s / DEGREE:.4f} deg, gcd {'none' if g is None else f'{g / DEGREE:.4f} deg'}"
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=40)
    ap.add_argument("--real", type=Path, default=Path("../shared/data/real-motors"))
    ap.add_argument("--grid", action="store_true", help="only: can the count be read off the log?")
    a = ap.parse_args()
    if a.grid:
        grids(a.real, a.seeds)
        return
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
