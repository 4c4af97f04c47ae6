"""The lab's computations, Tasks 6-15, and what the numbers show.

Units: R ohm, u V, omega rad/s, i_ss mA as entered (A inside the formulas), k_v V s/rad,
k_a N m/A, f N m s/rad, J kg m^2, T s, K rad/s per V.

Steady state (Tasks 6-9), per row of the table:
    k_v = (u_ss - R i_ss) / omega_ss        f = k_a i_ss / omega_ss
final k_v and f are the medians of the rows, k_a = 0.65 k_v.

Step response (Tasks 11-15), from a step log:
    K = omega_ss of the step / u_ss at the step's requested voltage (from the table)
    T: the manual's 63 % reading per rising step (median), and a least-squares fit over all
       rising steps with a 95 % confidence interval; the model uses the least-squares T.
    J = T (R f + k_v k_a) / R,  model T omega' = -omega + K u_A,  omega at 5 V = 5 K.

The least-squares fit models what is measured. The speed a log records is a difference of
encoder angles over a sample interval: the mean speed over that interval, half a sample
late, and its noise is the encoder's rounding, differenced. So the fit works on the angle
(from ``theta`` or ``count`` when the log has them, else rebuilt from omega read as the mean
speed over each interval) at the board's timestamps (``t_us`` when present). Around each
rising step at t_e, with tau = t - t_e, the angle is

    before the step:  theta = a + w0 tau
    after the step:   theta = a + w0 T (1 - e^(-tau/T)) + w1 (tau - T (1 - e^(-tau/T)))

(the integral of a first-order response from speed w0 towards w1). a, w0, w1 belong to each
step (so dry friction, which lowers w1, does not bias T); T is shared. For a given T the rest
is linear, so T is found by a one-dimensional search on the residual sum of squares, and its
95 % interval from the Jacobian with the residual variance (Student t). Falling steps are
not used: at zero command the driver brakes or coasts, and dry friction stops the wheel in
finite time, so they do not follow the model from u_A.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.errors import InputError
from minseg_tui.model.motor import FirstOrder, inertia_from_time_constant
from minseg_tui.model.steplog import Edge, StepLog, command, find_edges, problem, segment_end
from minseg_tui.units import KA_OVER_KV

FloatArray = NDArray[np.float64]

E63: float = 1.0 - math.exp(-1.0)
"""Fraction of the final change reached after one time constant (about 63 %)."""

U_TASK15: float = 5.0
"""The applied voltage of Task 15, V."""

KV_OUTLIER: float = 0.15
"""A row's k_v this far (relative) from the median is called a bad reading."""

STEP_VS_TABLE: float = 0.10
"""Step and table steady-state speeds further apart than this (relative) are reported."""

SHORT_T_SAMPLES: float = 3.0
"""T below this many sample periods: the 63 % reading measures the sampling, not the motor."""


# -- steady state ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Reading:
    """One row of the table: requested u_req (V), u_ss (V), omega_ss (rad/s), i_ss (mA).

    ``line`` is the row's line in its file, for messages (None when typed in).
    """

    u_req: float
    u_ss: float
    omega_ss: float
    i_ss: float
    line: int | None = None

    def problem(self) -> str | None:
        """What is wrong with this row for Tasks 6-9, as an 'expected ...' sentence, or None."""
        values = {
            "u_req": self.u_req,
            "u_ss": self.u_ss,
            "omega_ss": self.omega_ss,
            "i_ss": self.i_ss,
        }
        for name, v in values.items():
            if not math.isfinite(v):
                return f"expected a number for {name}, got {v}"
        if self.omega_ss <= 0:
            return f"expected omega_ss > 0 rad/s (a zero speed gives no k_v or f), got {self.omega_ss:g}"
        if self.u_ss <= 0:
            return f"expected u_ss > 0 V (the voltage measured on the motor), got {self.u_ss:g}"
        if self.i_ss <= 0:
            return f"expected i_ss > 0 mA (the current measured in Task 5), got {self.i_ss:g}"
        return None


@dataclass(frozen=True)
class Row:
    """A reading with its k_v (V s/rad, Task 6) and f (N m s/rad, Task 9)."""

    reading: Reading
    k_v: float
    f: float


@dataclass(frozen=True)
class Finding:
    """Something the numbers show: a short code and a sentence a student understands."""

    code: str
    message: str


def _check_R(R: float) -> None:
    if not (math.isfinite(R) and R > 0):
        raise InputError("--R", None, f"expected a positive resistance in ohm, got {R:g}")


def steady_state(
    readings: Sequence[Reading], R: float, source: str = "table"
) -> tuple[tuple[Row, ...], float, float, float]:
    """Tasks 6-9: the rows with k_v and f, and the final (median) k_v, k_a = 0.65 k_v and f."""
    _check_R(R)
    if not readings:
        raise InputError(source, None, "expected at least one row u_req,u_ss,omega_ss,i_ss")
    for r in readings:
        problem = r.problem()
        if problem:
            raise InputError(source, r.line, problem)
    k_v_rows = [(r.u_ss - R * r.i_ss * 1e-3) / r.omega_ss for r in readings]
    k_v = float(np.median(k_v_rows))
    if not k_v > 0:  # no motor has it: every figure from here on would be false
        raise InputError(
            source,
            None,
            f"expected the rows to give a positive k_v (V s/rad), their median is {k_v:.3g}: "
            "u_ss - R i_ss is not above 0 on enough rows; check R and i_ss (mA)",
        )
    k_a = KA_OVER_KV * k_v
    rows = tuple(
        Row(reading=r, k_v=kv, f=k_a * r.i_ss * 1e-3 / r.omega_ss)
        for r, kv in zip(readings, k_v_rows, strict=True)
    )
    for row in rows:
        if not (math.isfinite(row.k_v) and math.isfinite(row.f)):
            r = row.reading
            raise InputError(
                source,
                r.line,
                (
                    f"expected readings of a plausible size (R i_ss = {R * r.i_ss * 1e-3:g} V, "
                    f"omega_ss = {r.omega_ss:g} rad/s), they give k_v = {row.k_v:g} and f = {row.f:g}"
                ),
            )
    f = float(np.median([row.f for row in rows]))
    return rows, k_v, k_a, f


def _row_name(index: int, r: Reading) -> str:
    where = f", line {r.line}" if r.line is not None else ""
    return f"row {index + 1} (u_req {r.u_req:g} V{where})"


def table_findings(rows: Sequence[Row], R: float, k_v: float, k_a: float) -> list[Finding]:
    """What the table shows: dry friction, a bad reading, currents in the wrong unit."""
    out: list[Finding] = []
    for i, row in enumerate(rows):
        r = row.reading
        if r.i_ss < 1.0:
            out.append(
                Finding(
                    "i_ss_units",
                    f"{_row_name(i, r)}: i_ss = {r.i_ss:g} looks like amperes; the table wants mA ({r.i_ss * 1e3:g} mA?).",
                )
            )
        elif r.i_ss > 100.0:
            out.append(
                Finding(
                    "i_ss_high",
                    f"{_row_name(i, r)}: i_ss = {r.i_ss:g} mA is above 100 mA; the manual says you are probably measuring the wrong thing or the meter is in the wrong mode.",
                )
            )
        if row.k_v <= 0:
            out.append(
                Finding(
                    "k_v_nonpositive",
                    f"{_row_name(i, r)}: R i_ss = {R * r.i_ss * 1e-3:.3g} V is not below u_ss = {r.u_ss:g} V, so k_v comes out {row.k_v:.3g}; check R and i_ss.",
                )
            )
    if len(rows) >= 3:
        for i, row in enumerate(rows):
            dev = (row.k_v - k_v) / k_v if k_v else math.inf
            if abs(dev) > KV_OUTLIER:
                out.append(
                    Finding(
                        "k_v_outlier",
                        (
                            f"{_row_name(i, row.reading)}: k_v = {row.k_v:.4g} V s/rad is {abs(dev) * 100:.0f} % "
                            f"{'above' if dev > 0 else 'below'} the median {k_v:.4g}: probably a bad reading "
                            "(u_ss, omega_ss or i_ss of that row); the median keeps it out of the result."
                        ),
                    )
                )
    elif len(rows) == 2:
        a, b = rows[0].k_v, rows[1].k_v
        if abs(a - b) / abs(k_v) > 2 * KV_OUTLIER:
            out.append(
                Finding(
                    "k_v_disagree",
                    (
                        f"The two rows give k_v = {a:.4g} and {b:.4g} V s/rad, {abs(a - b) / abs(k_v) * 100:.0f} % apart: "
                        "one is probably a bad reading, and with two rows the median cannot tell which. Measure a third voltage."
                    ),
                )
            )
    out += _dry_friction(rows, k_a)
    return out


def _dry_friction(rows: Sequence[Row], k_a: float) -> list[Finding]:
    by_speed = sorted(rows, key=lambda row: row.reading.omega_ss)
    w = np.array([row.reading.omega_ss for row in by_speed])
    f = np.array([row.f for row in by_speed])
    if len(rows) < 2 or np.ptp(w) <= 0.05 * np.max(w):
        return []
    falling = bool(np.all(np.diff(f) < 0)) and f[0] > 1.1 * f[-1]
    if not falling:
        return []
    torque = k_a * np.array([row.reading.i_ss * 1e-3 for row in by_speed])
    slope, intercept = np.polyfit(w, torque, 1)
    line = ""
    if slope > 0 and intercept > 0:
        line = (
            f" A straight line k_a i_ss = f omega + tau_c through the rows gives a viscous f = {slope:.3g} N m s/rad "
            f"and a dry friction torque tau_c = {intercept:.3g} N m."
        )
    return [
        Finding(
            "dry_friction",
            (
                f"f falls with speed, from {f[0]:.3g} at {w[0]:.3g} rad/s to {f[-1]:.3g} N m s/rad at {w[-1]:.3g} rad/s: "
                "part of the friction is dry (Coulomb) friction, a torque that does not grow with speed. "
                "The lab's model has viscous friction only, so its f depends on the speed it was measured at."
                + line
            ),
        )
    ]


# -- the step response -------------------------------------------------------------------------


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


def _windows(log: StepLog) -> tuple[list[_Window], list[Edge]]:
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
    windows, _ = _windows(log)
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
    windows, _ = _windows(log)
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


def u_ss_at(rows: Sequence[Row], u_req: float) -> tuple[float, str]:
    """u_ss (V) the table gives for a requested u_req (V), and how ('row', 'interpolated',
    'extrapolated'): a row with that u_req (their mean if several), else a straight line
    between the nearest rows on either side, else the nearest row's driver drop."""
    pts = sorted((row.reading.u_req, row.reading.u_ss) for row in rows)
    same = [us for ur, us in pts if abs(ur - u_req) <= 1e-6 * max(1.0, abs(u_req))]
    if same:
        return float(np.mean(same)), "row"
    below = [p for p in pts if p[0] < u_req]
    above = [p for p in pts if p[0] > u_req]
    if below and above:
        (x0, y0), (x1, y1) = below[-1], above[0]
        return y0 + (y1 - y0) * (u_req - x0) / (x1 - x0), "interpolated"
    x0, y0 = below[-1] if below else above[0]
    return u_req - (x0 - y0), "extrapolated"


def _omega_ss_at(rows: Sequence[Row], u_req: float) -> float | None:
    pts = sorted((row.reading.u_req, row.reading.omega_ss) for row in rows)
    xs = [p[0] for p in pts]
    if not (xs[0] - 1e-9 <= u_req <= xs[-1] + 1e-9):
        return None
    return float(np.interp(u_req, xs, [p[1] for p in pts]))


@dataclass(frozen=True)
class StepResult:
    """Tasks 11-13 from a step log.

    K: static gain (rad/s per V, median over rising steps of omega_ss / u_ss); T: the
    least-squares time constant (s), the one the model uses; T_63: the median 63 % reading
    (s, None if no step crossed); T_ci: 95 % interval of T (s); J: inertia (kg m^2);
    omega_ss: median steady speed of the steps (rad/s); u_ss: the applied voltage K divides by
    (V); u_ss_how: 'row', 'interpolated', 'extrapolated' or 'log'; steps: each rising step;
    fit: details of the least-squares fit.
    """

    K: float
    T: float
    T_63: float | None
    T_ci: tuple[float, float]
    J: float
    omega_ss: float
    u_ss: float
    u_ss_how: str
    steps: tuple[RisingStep, ...]
    fit: TimeConstantFit
    model_uses: str = "least_squares"


@dataclass(frozen=True)
class Identification:
    """Everything of Tasks 6-15. ``step`` is None without a step log."""

    R: float
    rows: tuple[Row, ...]
    k_v: float
    k_a: float
    f: float
    step: StepResult | None
    findings: tuple[Finding, ...]

    @property
    def model(self) -> FirstOrder | None:
        """Task 14: T omega' = -omega + K u_A with the least-squares T and the step's K."""
        return FirstOrder(T=self.step.T, K=self.step.K) if self.step else None

    @property
    def omega_at_5V(self) -> float | None:
        """Task 15: the final speed for u_A = 5 V, rad/s."""
        return self.step.K * U_TASK15 if self.step else None

    def to_json(self) -> dict[str, object]:
        """The --json object of the issue (SI units, i_ss in mA as entered)."""
        out: dict[str, object] = {
            "R": self.R,
            "rows": [
                {
                    "u_req": r.reading.u_req,
                    "u_ss": r.reading.u_ss,
                    "omega_ss": r.reading.omega_ss,
                    "i_ss": r.reading.i_ss,
                    "k_v": r.k_v,
                    "f": r.f,
                }
                for r in self.rows
            ],
            "k_v": self.k_v,
            "k_a": self.k_a,
            "f": self.f,
        }
        if self.step is not None:
            s = self.step
            out["step"] = {
                "K": s.K,
                "T": s.T,
                "T_63": s.T_63,
                "T_ci": [s.T_ci[0], s.T_ci[1]],
                "J": s.J,
                "omega_ss": s.omega_ss,
            }
            out["model"] = {"T": s.T, "K": s.K}
            out["omega_at_5V"] = self.omega_at_5V
        return out


def _step_result(
    log: StepLog, rows: tuple[Row, ...], R: float, k_v: float, k_a: float, f: float
) -> tuple[StepResult, list[Finding]]:
    if not _windows(log)[0]:
        cmd, name = command(log)
        raise InputError(
            log.source,
            log.line_of(0),
            (
                f"expected a rising step in {name} (V) with at least one sample before it and 5 after it; "
                f"found {sum(e.rising for e in find_edges(cmd))} rising edge(s), none usable"
            ),
        )
    refused = problem(log.board_time(), log.u, log.omega)  # the fit runs on the board's clock
    if refused:
        raise InputError(log.source, None, refused)
    fit = fit_time_constant(log)
    steps = rising_steps(log)
    if fit is None or not steps:  # cannot happen with usable windows; keeps the types honest
        raise InputError(log.source, None, "expected a usable rising step")
    findings: list[Finding] = []
    u_used, hows = [], []
    for s in steps:
        if s.u_req is None:
            u_used.append(s.u_high)
            hows.append("log")
        else:
            u, how = u_ss_at(rows, s.u_req)
            u_used.append(u)
            hows.append(how)
    K_each = [s.omega_ss / u for s, u in zip(steps, u_used, strict=True)]
    K = float(np.median(K_each))
    omega_ss = float(np.median([s.omega_ss for s in steps]))
    u_ss = float(np.median(u_used))
    how = hows[len(hows) // 2] if len(set(hows)) > 1 else hows[0]
    levels = sorted({s.u_req for s in steps if s.u_req is not None})
    if "log" in hows:
        findings.append(
            Finding(
                "u_ss_from_log",
                (
                    f"The log has no u_req column, so K divides by the applied voltage the log recorded "
                    f"({u_ss:.3g} V) instead of u_ss from the table."
                ),
            )
        )
    if "interpolated" in hows or "extrapolated" in hows:
        which = "extrapolated beyond" if "extrapolated" in hows else "interpolated between"
        findings.append(
            Finding(
                f"u_ss_{'extrapolated' if 'extrapolated' in hows else 'interpolated'}",
                (
                    f"No table row has u_req = {', '.join(f'{v:g}' for v in levels)} V, the step's requested level; "
                    f"u_ss = {u_ss:.3g} V is {which} the table's rows."
                ),
            )
        )
    if len(levels) > 1:
        findings.append(
            Finding(
                "several_levels",
                (
                    f"The rising steps go to several levels ({', '.join(f'{v:g}' for v in levels)} V); K is the median "
                    "of omega_ss / u_ss over the steps and omega_ss the median of their speeds."
                ),
            )
        )
    for s in steps:
        if s.u_req is None:
            continue
        w_table = _omega_ss_at(rows, s.u_req)
        if w_table is not None and abs(s.omega_ss - w_table) > STEP_VS_TABLE * w_table:
            findings.append(
                Finding(
                    "step_vs_table",
                    (
                        f"The step at t = {s.t:.3g} s settles at {s.omega_ss:.3g} rad/s, but the table gives "
                        f"{w_table:.3g} rad/s at u_req = {s.u_req:g} V ({abs(s.omega_ss / w_table - 1) * 100:.0f} % apart): "
                        "the two experiments do not agree (a different wheel load, battery level, or a misread value)."
                    ),
                )
            )
            break
    T = fit.T
    reads = [s.T_63 for s in steps if s.T_63 is not None]
    T_63 = float(np.median(reads)) if reads else None
    ts = log.ts
    if T < SHORT_T_SAMPLES * ts:
        findings.append(
            Finding(
                "T_short",
                (
                    f"T = {T * 1e3:.3g} ms is shorter than {SHORT_T_SAMPLES:g} sample periods (Ts = {ts * 1e3:.3g} ms): "
                    "the speed rises within a few samples, so the 63 % reading measures the sampling and the "
                    "velocity computation as much as the motor. The least-squares T models the sampling and is the one to use."
                ),
            )
        )
    if T_63 is not None and abs(T_63 - T) > 0.25 * T:
        findings.append(
            Finding(
                "T_63_differs",
                (
                    f"The 63 % reading ({T_63 * 1e3:.3g} ms) and the least-squares T ({T * 1e3:.3g} ms) differ by "
                    f"{abs(T_63 / T - 1) * 100:.0f} %. The measured speed is the mean over each sample interval, so "
                    "it lags the true speed by half a sample; a velocity filter lags it more."
                ),
            )
        )
    short = [s for s in steps if s.duration < 5 * T]
    if short:
        findings.append(
            Finding(
                "not_settled",
                (
                    f"{len(short)} step(s) last less than 5 T ({5 * T:.3g} s): the speed may not have settled, "
                    "so omega_ss and K from them are uncertain."
                ),
            )
        )
    _, skipped = _windows(log)
    if skipped:
        findings.append(
            Finding(
                "steps_skipped",
                (
                    f"{len(skipped)} rising step(s) were too short or too close to the start of the log to use."
                ),
            )
        )
    J = inertia_from_time_constant(T, R, f, k_v, k_a)
    result = StepResult(
        K=K,
        T=T,
        T_63=T_63,
        T_ci=fit.ci,
        J=J,
        omega_ss=omega_ss,
        u_ss=u_ss,
        u_ss_how=how,
        steps=tuple(steps),
        fit=fit,
    )
    return result, findings


def identify(
    readings: Sequence[Reading], R: float, log: StepLog | None = None, source: str = "table"
) -> Identification:
    """Tasks 6-15 from the table's readings, the resistance R (ohm) and optionally a step log.

    Raises InputError for a bad R, a bad row, or a log without a usable rising step.
    """
    rows, k_v, k_a, f = steady_state(readings, R, source)
    findings = table_findings(rows, R, k_v, k_a)
    step = None
    if log is not None:
        step, more = _step_result(log, rows, R, k_v, k_a, f)
        findings += more
    return Identification(
        R=R, rows=rows, k_v=k_v, k_a=k_a, f=f, step=step, findings=tuple(findings)
    )
