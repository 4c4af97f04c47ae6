"""The step response (Tasks 11-12): the rising steps of a log, the manual's 63 % reading and
the least-squares time constant T.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.steplog import Edge, StepLog, command, find_edges, segment_end

FloatArray = NDArray[np.float64]

E63: float = 1.0 - math.exp(-1.0)
"""Fraction of the final change reached after one time constant (about 63 %)."""


@dataclass(frozen=True)
class RisingStep:
    """One rising step of the log.

    row: first row (0-based) at the high level; line: its file line; t: step time (s);
    u_req: requested high level (V, None if the log has no u_req); u_high: mean applied u
    over the high level (V); omega0: speed before (rad/s); omega_ss: mean measured speed over
    the second half of the high level (rad/s); duration: time at the high level (s);
    T_63: the 63 % reading (s, None if the speed never crosses 63 %).
    """

    row: int
    line: int | None
    t: float
    u_req: float | None
    u_high: float
    omega0: float
    omega_ss: float
    duration: float
    T_63: float | None


@dataclass(frozen=True)
class TimeConstantFit:
    """The least-squares T (s) with its 95 % interval (s), the residual standard deviation of
    the angle (rad), the rows and steps used, and where the angle came from."""

    T: float
    ci: tuple[float, float]
    se: float
    sigma: float
    n_rows: int
    n_steps: int
    angle_source: str
    time_source: str


@dataclass(frozen=True)
class _Window:
    edge: Edge
    rows: NDArray[np.int64]  # angle rows used (pre and post)
    post_last: int  # last row whose omega belongs to the high level


def step_windows(log: StepLog) -> tuple[list[_Window], list[Edge]]:
    """The rising steps usable for a fit, and the rising steps that are not (too short)."""
    cmd, _ = command(log)
    edges = find_edges(cmd)
    n = len(log)
    used: list[_Window] = []
    skipped: list[Edge] = []
    span = float(np.ptp(cmd))
    for e in edges:
        if not e.rising:
            continue
        last = segment_end(cmd, e)
        post_last = min(last + 1, n - 1)  # the angle at the next edge is read before it acts
        first = e.start - 1
        while first > 0 and abs(cmd[first - 1] - e.before) <= 0.1 * span:
            first -= 1
        pre_len = e.start - first
        pre_from = e.start - max(1, math.ceil(pre_len / 3))
        if e.start < 1 or post_last - e.end < 4:
            skipped.append(e)
            continue
        rows = np.arange(max(pre_from, 0), post_last + 1)
        used.append(_Window(e, rows, post_last))
    return used, skipped


def _basis(tau: FloatArray, T: float) -> FloatArray:
    """Columns [1, phi0, phi1, phi2] of the angle model around a step (see the module
    docstring); phi2 = tau^2/2 before the step lets the speed there change steadily (a
    wheel still slowing down from the previous step), 0 after it."""
    after = tau >= 0
    g = np.where(after, -T * np.expm1(-np.where(after, tau, 0.0) / T), 0.0)
    phi0 = np.where(after, g, tau)
    phi1 = np.where(after, tau - g, 0.0)
    phi2 = np.where(after, 0.0, 0.5 * tau * tau)
    return np.column_stack((np.ones_like(tau), phi0, phi1, phi2))


def _dbasis_dT(tau: FloatArray, T: float) -> FloatArray:
    """d/dT of [phi0, phi1]: +-(1 - e^-x - x e^-x), x = tau/T, after the step; 0 before."""
    x = np.where(tau > 0, tau / T, 0.0)
    d = -np.expm1(-x) - x * np.exp(-x)
    return np.column_stack((d, -d, np.zeros_like(d)))


class _Problem:
    """The variable-projection problem: angle windows around each rising step.

    When the wheel stands still before a step (the angle does not change), its speed there
    is 0 and the rows before the step repeat one reading: they count once (the row of the
    step) and the step's w0 is fixed at 0. Otherwise w0 is fitted from the rows before.
    """

    def __init__(self, log: StepLog, windows: list[_Window]) -> None:
        tb = log.board_time()
        theta, self.angle_source = log.angle()
        self.time_source = (
            "the board's timestamps (t_us)" if "t_us" in log.extra else "the t column"
        )
        self.taus: list[FloatArray] = []
        self.thetas: list[FloatArray] = []
        self.cols: list[list[int]] = []
        for w in windows:
            rows = w.rows
            pre = rows[rows <= w.edge.start]
            if np.all(theta[pre] == theta[w.edge.start]):
                rows = rows[rows >= w.edge.start]
                self.cols.append([0, 2])
            else:
                self.cols.append([0, 1, 2, 3] if pre.size >= 4 else [0, 1, 2])
            self.taus.append(tb[rows] - tb[w.edge.start])
            self.thetas.append(theta[rows] - theta[w.edge.start])
        self.n = sum(len(x) for x in self.taus)
        self.p = 1 + sum(len(c) for c in self.cols)

    def solve(self, T: float) -> tuple[float, list[FloatArray]]:
        rss, coefs = 0.0, []
        for tau, th, cols in zip(self.taus, self.thetas, self.cols, strict=True):
            B = _basis(tau, T)[:, cols]
            c, *_ = np.linalg.lstsq(B, th, rcond=None)
            r = th - B @ c
            rss += float(r @ r)
            full = np.zeros(4)
            full[cols] = c
            coefs.append(full)
        return rss, coefs

    def info_T(self, T: float, coefs: list[FloatArray]) -> float:
        """sum over steps of |(I - P) dtheta/dT|^2 (the Fisher information of T times sigma^2)."""
        total = 0.0
        for tau, c, cols in zip(self.taus, coefs, self.cols, strict=True):
            B = _basis(tau, T)[:, cols]
            j = _dbasis_dT(tau, T) @ c[1:]
            resid, *_ = np.linalg.lstsq(B, j, rcond=None)
            r = j - B @ resid
            total += float(r @ r)
        return total


def fit_time_constant(log: StepLog) -> TimeConstantFit | None:
    """Least-squares T over all usable rising steps of ``log`` (None if there are none)."""
    windows, _ = step_windows(log)
    if not windows:
        return None
    prob = _Problem(log, windows)
    ts = log.ts
    longest = max(float(tau[-1]) for tau in prob.taus)
    lo, hi = max(ts / 50.0, 1e-5), max(longest, ts)
    grid = np.geomspace(lo, hi, 60)
    rss = np.array([prob.solve(T)[0] for T in grid])
    i = int(np.argmin(rss))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    from scipy import optimize  # imported here: scipy costs ~0.5 s at start-up

    res = optimize.minimize_scalar(
        lambda x: prob.solve(math.exp(x))[0],
        bounds=(math.log(a), math.log(b)),
        method="bounded",
        options={"xatol": 1e-7},
    )
    T = math.exp(float(res.x))
    rss_min, coefs = prob.solve(T)
    dof = max(prob.n - prob.p, 1)
    sigma = math.sqrt(rss_min / dof)
    info = prob.info_T(T, coefs)
    se = sigma / math.sqrt(info) if info > 0 else math.inf
    from scipy import stats

    q = float(stats.t.ppf(0.975, dof))
    return TimeConstantFit(
        T=T,
        ci=(max(T - q * se, 0.0), T + q * se),
        se=se,
        sigma=sigma,
        n_rows=prob.n,
        n_steps=len(windows),
        angle_source=prob.angle_source,
        time_source=prob.time_source,
    )


def _reading_63(
    t: FloatArray, omega: FloatArray, start: int, post_last: int, w0: float, w_ss: float
) -> float | None:
    """The manual's reading: time from the step until omega first reaches 63 % of the way
    from w0 to w_ss, interpolated linearly between samples (s)."""
    level = w0 + E63 * (w_ss - w0)
    if w_ss <= w0:
        return None
    for k in range(start + 1, post_last + 1):
        if omega[k] >= level:
            prev_t, prev_w = (t[k - 1], omega[k - 1]) if k - 1 > start else (t[start], w0)
            frac = (level - prev_w) / (omega[k] - prev_w) if omega[k] != prev_w else 1.0
            return float(prev_t + frac * (t[k] - prev_t) - t[start])
    return None


def rising_steps(log: StepLog) -> list[RisingStep]:
    """Each usable rising step with its levels and the manual's 63 % reading (Tasks 11-12)."""
    windows, _ = step_windows(log)
    cmd, name = command(log)
    out = []
    for w in windows:
        e = w.edge
        pre = w.rows[w.rows <= e.start]
        pre = pre[pre >= 1] if pre.size > 1 else pre  # row 0 has no previous sample
        post = np.arange(e.end + 1, w.post_last + 1)
        w0 = float(np.mean(log.omega[pre]))
        w_ss = float(np.mean(log.omega[post[post.size // 2 :]]))
        out.append(
            RisingStep(
                row=e.start,
                line=log.line_of(e.start),
                t=float(log.t[e.start]),
                u_req=float(e.after) if name == "u_req" else None,
                u_high=float(np.mean(log.u[e.end : w.post_last])),
                omega0=w0,
                omega_ss=w_ss,
                duration=float(log.t[w.post_last] - log.t[e.start]),
                T_63=_reading_63(log.t, log.omega, e.start, w.post_last, w0, w_ss),
            )
        )
    return out
