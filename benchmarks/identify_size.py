"""Time and memory of identify (Tasks 11-15) against the length of the run log.

    .venv/bin/python benchmarks/identify_size.py [--rows 10000,100000,1000000]

The log: the published MinSeg with its dry friction, a square wave 0 -> 4 V every second at
25 ms with up to 2 ms of loop lateness, with the board's timestamps and the count, as a session
records it. Generated with a vectorised plant (the closed-form first-order response, the count
floored) so that a million rows take seconds; then only the computation is timed, in process
(reading the CSV is lab.files' business). Printed: seconds, microseconds per row and rows per
second, and the peak memory the computation allocated (tracemalloc; numpy reports to it).
Before issue 11 a million rows took 187 s and ten million did not finish in 15 minutes.
"""

from __future__ import annotations

import argparse
import math
import time
import tracemalloc

import numpy as np

from minseg_tui.model.identify import Reading, identify
from minseg_tui.model.motor import PUBLISHED
from minseg_tui.model.runlog import RunLog

TS = 0.025
HALF = 40  # rows per level: 1 s
V_DROP = 0.45
U_C = 0.12  # breakaway voltage of the dry friction, V (tau_c R / k_a of the MinSeg)


def make(rows: int, seed: int = 1) -> RunLog:
    """A long square-wave log: first-order motor with dry friction, integer counts."""
    rng = np.random.default_rng(seed)
    T, K = PUBLISHED.T, PUBLISHED.K
    k = np.arange(rows)
    u_req = np.where((k // HALF) % 2 == 1, 4.0, 0.0)
    t = k * TS + rng.uniform(0.0, 0.002, rows)
    u = np.where(u_req > 0, u_req - V_DROP, 0.0)
    # speed at each sample, held input from each sample on: exact first-order steps with the
    # friction's offset while driven; the wheel stops after each fall (1 s is 23 T)
    theta = np.empty(rows)
    w = 0.0
    angle = float(rng.uniform(0.0, 2 * math.pi / 720))
    theta[0] = angle
    for i in range(1, rows):
        dt = t[i] - t[i - 1]
        target = K * (u[i - 1] - U_C) if u[i - 1] > U_C else 0.0
        if u[i - 1] > U_C:
            e = math.exp(-dt / T)
            angle += target * dt + (w - target) * T * (1 - e)
            w = target + (w - target) * e
        else:  # slowing towards -K u_c, stopping at 0
            floor_ = -K * U_C
            stop = T * math.log((w - floor_) / -floor_) if w > 0 else 0.0
            h = min(dt, stop)
            e = math.exp(-h / T)
            angle += floor_ * h + (w - floor_) * T * (1 - e)
            w = 0.0 if h < dt else max(floor_ + (w - floor_) * e, 0.0)
        theta[i] = angle
    count = np.floor(theta / (2 * math.pi / 720)).astype(np.int64)
    omega = np.concatenate(([0.0], np.diff(count) * (2 * math.pi / 720) / np.diff(t)))
    return RunLog(
        t=t,
        u=u,
        omega=omega,
        extra={"u_req": u_req, "count": count, "t_us": np.round(t * 1e6).astype(np.int64)},
    )


TABLE = [Reading(4.0, 4.0 - V_DROP, PUBLISHED.K * (4.0 - V_DROP - U_C), 30.0)]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", default="10000,100000,1000000")
    a = ap.parse_args()
    for rows in (int(x) for x in a.rows.split(",")):
        log = make(rows)
        t0 = time.perf_counter()
        r = identify(TABLE, PUBLISHED.R, log)
        secs = time.perf_counter() - t0
        tracemalloc.start()  # a second run for the memory: tracing slows numpy down
        identify(TABLE, PUBLISHED.R, log)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        s = r.step
        assert s is not None
        print(
            f"{rows:>9} rows: {secs:7.2f} s, {1e6 * secs / rows:5.1f} us/row, "
            f"{rows / secs:9.0f} rows/s, peak {peak / 2**20:7.1f} MiB; "
            f"T {s.T * 1e3:.3f} ms (true {PUBLISHED.T * 1e3:.3f}), {s.fit.method}",
            flush=True,
        )


if __name__ == "__main__":
    main()
