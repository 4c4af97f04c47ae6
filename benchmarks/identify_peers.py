"""T and K side by side: what students use, what MATLAB's procest does, and `identify`.

    .venv/bin/python benchmarks/identify_peers.py [--seeds 200] [--tiers 25ms,fast,5ms]

Logs come from the project's generator (minseg_tui.model.synth.identification_log: the
plant of minseg_tui.model.plant with the published MinSeg motor, its inertia set for the
wanted T, no dry friction, brake at zero command, 0.45 V driver drop, 720-count encoder read
as integer counts, starting at a random fraction of a count), seeded. Each log: 4 rises (the lab's plan has 4
periods) to 2, 3 or 4 V, each level held 5 T; the speed column is the Euler derivative of the
counts at the nominal Ts, as the lab's sketch computes it. Tiers: T 0.08-0.3 s at Ts = 25 ms
and at 5 ms, and a fast tier, T 0.04-0.08 s at 25 ms. The loop is late by a uniform 0-2 ms
(0-1 ms at 5 ms), never early, as a busy Arduino loop is. Two ways the command meets the
samples:

- grid: the command changes on the board's grid k Ts, the count is read late (a firmware
  that sets the output on a timer); the issue's logs behave like this;
- sample: the command changes right after the late count is read (this project's firmware,
  and what minseg_tui.model.plant.record plays).

Each log is written with the board's timestamps (t = t_us, the instants the counts were
read) or without them (t = k Ts).

Estimators, all on the same logs:

- 63 % reading: the manual's Task 12 on the speed column, per rise (final value: mean
  of the step's last quarter; start: the speed before the step; linear interpolation between
  samples), median over the steps; K = final value / u;
- curve fit: scipy.optimize.curve_fit of w_ss - (w_ss - w0) e^(-(t - t_step)/T) to the speed
  samples of every rise, T shared, what curve_fit or lmfit users do; interval from pcov;
- ARX(1,1): omega_k = a omega_k-1 + b u_k-1 by least squares over the whole log (what
  sysidentpy fits), T = -Ts / ln a, K = b / (1 - a);
- FOPDT: the first-order-plus-dead-time model T w' = -w + K u(t - Td) simulated with the held
  input and fitted to the speed by least squares (MATLAB's procest with 'P1D'), Td >= 0;
  interval from the Jacobian and the residual variance;
- identify: minseg_tui.model.identify.identify with the exact table (u_ss = u_A at 2, 3, 4 V).

Printed per tier and timing: median and 90th percentile of |T error| and |K error| (%), the
mean signed T error (bias, %), how often the 95 % interval holds the true T (and K), and the
time per log. With N seeds a coverage p has a binomial standard error sqrt(p (1 - p) / N):
1.5 points at 95 % with 200 seeds.
"""

from __future__ import annotations

import argparse
import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy import optimize, signal
from scipy import stats as sstats

from minseg_tui.model.identify import identify
from minseg_tui.model.motor import PUBLISHED
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import identification_log, identification_table

F = NDArray[np.float64]
TIERS: dict[str, tuple[float, float, float, float]] = {
    # name: (Ts s, T low s, T high s, largest lateness us)
    "25ms": (0.025, 0.08, 0.30, 2000.0),
    "fast": (0.025, 0.04, 0.08, 2000.0),
    "5ms": (0.005, 0.08, 0.30, 1000.0),
}


@dataclass(frozen=True)
class Log:
    """A generated log and its truth: T (s), K (rad/s per V of u_A)."""

    log: RunLog
    T: float
    K: float
    ts: float


def make(tier: str, seed: int, stamped: bool, timing: str) -> Log:
    """One seeded log of ``tier`` with (``stamped``) or without the board's timestamps;
    ``timing`` "grid": the command changes on the board's grid and the count is read late,
    "sample": the command changes right after the read (this firmware)."""
    ts, lo, hi, late_us = TIERS[tier]
    g = identification_log(seed, ts, (lo, hi), late_us, on_grid=timing == "grid", stamped=stamped)
    return Log(g.log, g.T, g.K, ts)


TABLE = identification_table()


# -- the estimators: (T, K, T interval or None, K interval or None) ---------------------------

Estimate = tuple[float, float, tuple[float, float] | None, tuple[float, float] | None]


def _rising(u_req: F) -> list[tuple[int, int]]:
    """(first row at the high level, last row at it) of every rise."""
    up = np.flatnonzero(np.diff(u_req) > 0) + 1
    down = np.flatnonzero(np.diff(u_req) < 0) + 1
    out = []
    for s in up.tolist():
        later = down[down > s]
        out.append((s, int(later[0]) - 1 if later.size else u_req.size - 1))
    return out


def reading_63(g: Log) -> Estimate:
    t, w, u = g.log.t, g.log.omega, g.log.u
    u_req = np.asarray(g.log.extra["u_req"], float)
    Ts, Ks = [], []
    for s, e in _rising(u_req):
        w0 = float(np.mean(w[max(s - 3, 1) : s]))
        n = e - s + 1
        final = float(np.mean(w[e - max(n // 4, 1) + 1 : e + 1]))
        level = w0 + (1 - math.exp(-1)) * (final - w0)
        seg = w[s : e + 1]
        k = int(np.argmax(seg >= level))
        if k == 0:
            continue
        f = (level - seg[k - 1]) / (seg[k] - seg[k - 1])
        Ts.append(t[s + k - 1] + f * (t[s + k] - t[s + k - 1]) - t[s])
        Ks.append(final / float(np.mean(u[s : e + 1])))
    return float(np.median(Ts)), float(np.median(Ks)), None, None


def curve_fit(g: Log) -> Estimate:
    t, w, u = g.log.t, g.log.omega, g.log.u
    u_req = np.asarray(g.log.extra["u_req"], float)
    steps = _rising(u_req)
    rows = np.concatenate([np.arange(s, e + 1) for s, e in steps])
    which = np.concatenate([np.full(e - s + 1, i) for i, (s, e) in enumerate(steps)])
    t0 = np.array([t[s] for s, _ in steps])
    m = len(steps)

    def model(x: F, T: float, *p: float) -> F:
        ws, w0 = np.asarray(p[:m]), np.asarray(p[m:])
        dt = x - t0[which]
        return ws[which] - (ws[which] - w0[which]) * np.exp(-dt / T)

    finals = [float(np.mean(w[e - 3 : e + 1])) for _, e in steps]
    p0 = [0.1, *finals, *([0.0] * m)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        p, cov = optimize.curve_fit(model, t[rows], w[rows], p0=p0, maxfev=20000)
    T = float(p[0])
    Ks = [p[1 + i] / float(np.mean(u[s : e + 1])) for i, (s, e) in enumerate(steps)]
    q = float(sstats.t.ppf(0.975, rows.size - p.size))
    half = q * math.sqrt(max(float(cov[0, 0]), 0.0))
    return T, float(np.median(Ks)), (T - half, T + half), None


def arx(g: Log) -> Estimate:
    w, u = g.log.omega, g.log.u
    A = np.column_stack((w[:-1], u[:-1]))
    (a, b), *_ = np.linalg.lstsq(A, w[1:], rcond=None)
    return -g.ts / math.log(a), b / (1 - a), None, None


def _fopdt_speed(p: F, u: F, ts: float) -> F:
    """omega at k ts of T w' = -w + K u(t - Td), u held from each sample on (exact)."""
    K, T, Td = float(p[0]), float(p[1]), max(float(p[2]), 0.0)
    m = int(Td // ts)
    frac = Td - m * ts
    a = math.exp(-ts / T)
    older = K * (math.exp(-(ts - frac) / T) - a)
    newer = K * (1.0 - math.exp(-(ts - frac) / T))
    u_old = np.concatenate((np.zeros(m + 1), u))[: u.size]
    u_new = np.concatenate((np.zeros(m), u))[: u.size]
    return signal.lfilter([0.0, 1.0], [1.0, -a], older * u_old + newer * u_new)


def fopdt(g: Log) -> Estimate:
    u, w, ts = np.asarray(g.log.u, float), np.asarray(g.log.omega, float), g.ts
    K0 = float(np.percentile(w, 99) / max(float(np.percentile(u, 99)), 1e-9))
    best = None
    for T0 in (ts, 4 * ts, 16 * ts):
        res = optimize.least_squares(
            lambda p: _fopdt_speed(p, u, ts) - w,
            [K0, T0, ts / 2],
            bounds=([0.0, ts / 50, 0.0], [np.inf, 100.0, 20 * ts]),
            x_scale=[K0, T0, ts],
        )
        if best is None or res.cost < best.cost:
            best = res
    assert best is not None
    K, T, _ = (float(v) for v in best.x)
    J = best.jac
    dof = w.size - 3
    cov = np.linalg.pinv(J.T @ J) * (2 * best.cost / dof)
    q = float(sstats.t.ppf(0.975, dof))
    hT, hK = q * math.sqrt(cov[1, 1]), q * math.sqrt(cov[0, 0])
    return T, K, (T - hT, T + hT), (K - hK, K + hK)


def project(g: Log) -> Estimate:
    r = identify(TABLE, PUBLISHED.R, g.log)
    s = r.step
    assert s is not None
    K_ci = getattr(s, "K_ci", None)  # absent before issue 11
    return s.T, s.K, s.T_ci, K_ci if K_ci and all(map(math.isfinite, K_ci)) else None


ESTIMATORS: dict[str, Callable[[Log], Estimate]] = {
    "63 % reading": reading_63,
    "curve fit": curve_fit,
    "ARX(1,1)": arx,
    "FOPDT (procest)": fopdt,
    "identify": project,
}


def _pct(x: list[float], q: float) -> str:
    return f"{np.percentile(np.abs(x), q):6.2f}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=200)
    ap.add_argument("--tiers", default="25ms,fast,5ms")
    ap.add_argument("--timings", default="grid,sample")
    ap.add_argument("--only", default="", help="comma-separated estimator names to run")
    a = ap.parse_args()
    names = [n for n in ESTIMATORS if not a.only or n in a.only.split(",")]
    print(
        f"{a.seeds} seeds per row (seeds 1000-{999 + a.seeds}); errors in %, coverage: share of logs "
        f"whose 95 % interval holds the truth (binomial se at 95 %: "
        f"{100 * math.sqrt(0.95 * 0.05 / a.seeds):.1f} points)"
    )
    head = (
        f"{'tier':5} {'timing':6} {'t_us':4} {'estimator':16} {'T med':>6} {'T p90':>6} "
        f"{'T bias':>7} {'T cov':>6} {'K med':>6} {'K p90':>6} {'K cov':>6} {'ms/log':>7}"
    )
    print(head)
    for tier in a.tiers.split(","):
        for timing in a.timings.split(","):
            for stamped in (True, False):
                logs = [make(tier, 1000 + s, stamped, timing) for s in range(a.seeds)]
                for name in names:
                    eT, eK, inT, inK, secs = [], [], [], [], []
                    for g in logs:
                        t0 = time.perf_counter()
                        T, K, ciT, ciK = ESTIMATORS[name](g)
                        secs.append(time.perf_counter() - t0)
                        eT.append(100 * (T / g.T - 1))
                        eK.append(100 * (K / g.K - 1))
                        if ciT is not None:
                            inT.append(ciT[0] <= g.T <= ciT[1])
                        if ciK is not None:
                            inK.append(ciK[0] <= g.K <= ciK[1])
                    cT = f"{100 * np.mean(inT):5.1f}%" if inT else "     -"
                    cK = f"{100 * np.mean(inK):5.1f}%" if inK else "     -"
                    print(
                        f"{tier:5} {timing:6} {'yes' if stamped else 'no':4} {name:16} "
                        f"{_pct(eT, 50)} {_pct(eT, 90)} {np.mean(eT):+7.2f} {cT} "
                        f"{_pct(eK, 50)} {_pct(eK, 90)} {cK} {1e3 * np.median(secs):7.1f}",
                        flush=True,
                    )


if __name__ == "__main__":
    main()
