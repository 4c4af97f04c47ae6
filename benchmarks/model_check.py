"""Model-check benchmark: confusion matrix, parameter errors, T spread against the Cramer-Rao
bound, and the CLI's times (Python start included).

    taskset -c 1 .venv/bin/python benchmarks/model_check.py [--seeds 30] [--skip-hour]

Logs come from minseg_tui.model.synth (20 s, steps of 1.55-3.55 V every second, 720-count
encoder, 300 us jitter), one hidden effect each, drawn from its realistic range. Logs with
two effects and a hand on the wheel: benchmarks/model_check_pairs.py.
"""

from __future__ import annotations

import argparse
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.saving.files import write_run_log
from minseg_tui.model.check import check
from minseg_tui.model.check.simulate import Effects, Stretches, pieces
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import CAUSES, PARAM_RANGES, make_log

ROOT = Path(__file__).resolve().parents[1]


def confusion(seeds: int) -> None:
    names = list(CAUSES)
    m = np.zeros((len(names), len(names)), dtype=int)
    errors: dict[str, list[float]] = {c: [] for c in PARAM_RANGES}
    rel: dict[str, list[float]] = {c: [] for c in PARAM_RANGES}
    t0 = time.perf_counter()
    for i, cause in enumerate(names):
        for s in range(seeds):
            log = make_log(cause, seed=1000 + s)
            r = check(log.t, log.u, log.omega)
            j = names.index(r.finding.cause)
            m[i, j] += 1
            if cause != "none" and r.finding.cause == cause:
                p = PARAM_RANGES[cause][0]
                err = abs(r.extended.params[p] - float(log.param))
                errors[cause].append(err)
                rel[cause].append(err / float(log.param))
    el = time.perf_counter() - t0
    print(f"Confusion matrix ({seeds} seeds per cause; rows: truth, columns: finding)")
    short = [n[:9] for n in names]
    print(" " * 18 + " ".join(f"{s:>9}" for s in short))
    for i, n in enumerate(names):
        print(f"{n:>17} " + " ".join(f"{v:9d}" for v in m[i]))
    acc = np.trace(m) / m.sum()
    print(
        f"accuracy {100 * acc:.1f} %   false alarms on clean logs: {m[0, 1:].sum()} of {seeds}"
        f"   ({el / m.sum():.2f} s per log in process)"
    )
    print("\nParameter errors (correctly named logs): |estimate - truth|")
    for c, errs in errors.items():
        if not errs:
            continue
        p, lo, hi = PARAM_RANGES[c]
        e, q = np.asarray(errs), np.asarray(rel[c])
        print(
            f"  {c:>17} {p:>7} (range {lo:g}-{hi:g}): median {np.median(e):.4g}, 90th pct "
            f"{np.percentile(e, 90):.4g}   relative: median {100 * np.median(q):.1f} %, "
            f"90th pct {100 * np.percentile(q, 90):.1f} %"
        )


def _t63(t: np.ndarray, u: np.ndarray, y: np.ndarray) -> float:
    """The manual's 63 % reading averaged over the rises: time from the edge until the
    measured speed first reaches 63 % of the step's final value (linear interpolation)."""
    out = []
    edges = np.flatnonzero(np.diff(u) > 0) + 1
    for e in edges.tolist():
        end = e + 40 if e + 40 <= u.size else u.size
        seg = y[e:end]
        final = float(np.mean(seg[-10:]))
        target = 0.632 * final
        k = int(np.argmax(seg >= target))
        if k == 0:
            continue
        # y[e + k] is the mean over the interval ending at t[e + k]: place it mid-interval
        tk1, tk = t[e + k - 1] - 0.0125, t[e + k] - 0.0125
        f = (target - seg[k - 1]) / (seg[k] - seg[k - 1])
        out.append(tk1 + f * (tk - tk1) - t[e])
    return float(np.mean(out))


def cramer_rao(runs: int) -> None:
    """Spread of the least-squares T over clean logs, against the Cramer-Rao bound for white
    angle quantisation noise (variance (1 count)^2 / 12) plus the jitter's w^2 var(lateness)."""
    ts_, t63 = [], []
    crb = []
    for s in range(runs):
        log = make_log("none", seed=2000 + s)
        r = check(log.t, log.u, log.omega)
        T, K = r.baseline.params["T"], r.baseline.params["K"]
        ts_.append(T)
        t63.append(_t63(log.t, log.u, log.omega))
        st = Stretches.from_samples(log.t, log.u)

        def th(T_: float, K_: float, st: Stretches = st, t: np.ndarray = log.t) -> np.ndarray:
            return K_ * pieces(st, T_, Effects()).angle(t)

        dT, dK = 1e-6, 1e-6
        J = np.column_stack(
            ((th(T + dT, K) - th(T - dT, K)) / (2 * dT), (th(T, K + dK) - th(T, K - dK)) / (2 * dK))
        )
        w = log.omega_true
        var = (2 * math.pi / 720) ** 2 / 12 + w**2 * (300e-6) ** 2 / 12
        F = (J / var[:, None]).T @ J
        crb.append(math.sqrt(np.linalg.inv(F)[0, 0]))
    sd = float(np.std(ts_, ddof=1))
    bound = float(np.median(crb))
    print(f"\nT on {runs} clean logs (true T = {0.04277:.5f} s):")
    print(f"  least squares: mean {np.mean(ts_):.5f} s, spread (sd) {sd * 1e3:.3f} ms")
    print(
        f"  Cramer-Rao bound (white noise): {bound * 1e3:.3f} ms  -> ratio {sd / bound:.2f} "
        "(the baseline fit of the model check; the Task 12 estimator and its 1.2x target: "
        "benchmarks/t_estimate.py)"
    )
    print(
        f"  63 % reading:  mean {np.mean(t63):.5f} s, spread (sd) {np.std(t63, ddof=1) * 1e3:.3f} ms"
    )


def _cli_time(path: Path, runs: int) -> tuple[list[float], list[float]]:
    """Wall times and CPU times (user + system of the child) of ``runs`` CLI runs, s."""
    wall, cpu = [], []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(
            [sys.executable, "-m", "minseg_tui", "analyze", str(path)],
            check=True,
            stdout=subprocess.DEVNULL,
            cwd=ROOT,
        )
        wall.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return wall, cpu


TIMED: tuple[tuple[str, str | None], ...] = (
    ("coulomb_friction", None),
    ("coulomb_friction", "second_pole"),
    ("dead_time", "velocity_filter"),
    ("current_limit", "coast_on_zero"),
)
"""The 20 s logs the CLI is timed on: one effect, and pairs (with the slowest simulation)."""


def timings(skip_hour: bool) -> None:
    cores = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else set()
    load = os.getloadavg()
    print(
        f"\nCLI timing on {len(cores) or '?'} core(s) {sorted(cores)}; load average "
        f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (the machine is shared: CPU time is the "
        "fair figure)"
    )
    with tempfile.TemporaryDirectory() as d:
        for cause, also in TIMED:
            log = make_log(cause, seed=5, also=also)
            p = Path(d) / "20s.csv"
            write_run_log(p, RunLog(t=log.t, u=log.u, omega=log.omega, extra={"count": log.count}))
            wall, cpu = _cli_time(p, 7)
            name = cause + (f"+{also}" if also else "")
            print(
                f"  20 s log ({log.t.size} rows, {name}), `python -m minseg_tui analyze`, Python "
                f"start included: median {np.median(wall):.2f} s wall, {np.median(cpu):.2f} s CPU;"
                f" max {max(wall):.2f} s wall (target: median < 1.5 s)"
            )
        if skip_hour:
            return
        t0 = time.perf_counter()
        big = make_log("dead_time", param=0.03, seed=6, duration=3600.0)
        gen = time.perf_counter() - t0
        t0 = time.perf_counter()
        r = check(big.t, big.u, big.omega)
        inproc = time.perf_counter() - t0
        p = Path(d) / "hour.csv"
        write_run_log(p, RunLog(t=big.t, u=big.u, omega=big.omega, extra={"count": big.count}))
        cli = _cli_time(p, 1)[0][0]
        print(
            f"one-hour log at 40 Hz ({big.t.size} rows; generated in {gen:.1f} s): check() "
            f"{inproc:.2f} s in process, the CLI {cli:.2f} s with start and CSV reading "
            f"(target < 30 s); finding {r.finding.cause}, delay {r.extended.params.get('delay', 0) * 1e3:.1f} ms"
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=30)
    ap.add_argument("--skip-hour", action="store_true")
    ap.add_argument("--timing-only", action="store_true")
    a = ap.parse_args()
    if not a.timing_only:
        confusion(a.seeds)
        cramer_rao(a.seeds)
    timings(a.skip_hour)


if __name__ == "__main__":
    main()
