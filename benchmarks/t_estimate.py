"""Spread of the time constant T over many clean run logs, against the Cramer-Rao bound.

Logs: the plant with the published MinSeg motor (T about 0.043 s), no dry friction, brake
at zero command, Ts = 0.025 s, loop jitter up to 2 ms, 720-count encoder; 5 rises
0 -> 4.5 V per log, each held 1 s. Every log is seeded.

Estimators (minseg_tui.model.identify):
- least squares: the first-order response fitted in the angle domain at the board's
  timestamps, i.e. it models what is measured (the mean speed over each sample interval =
  difference of angles / dt), not the instantaneous speed. Since issue 11 it fits the model
  of Task 14 to the whole log, every edge rising and falling, when the log follows it (these
  logs do: brake at zero command, no dry friction), so it uses about twice the data the bound
  below assumes and its spread may come out under it;
- the manual's 63 % reading on the recorded Euler speed, median over the rises.

Cramer-Rao bound. The measurement is the encoder angle theta_k = theta(t_k) + e_k, where
e_k is the count's rounding (one count q = 2 pi / 720 rad wide, variance q^2 / 12 when the
wheel moves); we treat e_k as white with the variance measured from the fits' residuals
(the "measured noise level"; it comes out close to q^2/12). Around each rise at t_e
the wheel is at rest (speed 0), and with tau = t - t_e >= 0

    theta(tau) = a_i + w_i (tau - T (1 - e^(-tau/T)))

with a per-step angle offset a_i and final speed w_i, and T shared. The Fisher information
is F = sum_k g_k g_k^T / sigma^2 with g_k the gradient of theta(tau_k) with respect to
(T, a_1, w_1, ..., a_n, w_n):

    d theta / d a_i = 1
    d theta / d w_i = tau - T (1 - e^(-tau/T))
    d theta / d T   = -w_i (1 - e^(-x) - x e^(-x)),  x = tau / T

evaluated at the true parameters and the log's own sample times (rows from the step to the
next edge). CRB(T) = [F^-1]_TT, averaged over the logs. The bound is the Gaussian one for
the measured variance: the rounding error is uniform, not Gaussian, so it is the bound an
estimator that treats the noise as Gaussian can reach, not a strict bound for every estimator.
Rows where the wheel stands still repeat one reading and carry no new noise, so they are not
counted as independent observations (neither by the bound nor by the fit).
"""

from __future__ import annotations

import math
import sys
import time

import numpy as np

from minseg_tui.model.identify import fit_time_constant, rises
from minseg_tui.model.motor import PUBLISHED
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.signals import timestamp_velocity

SEEDS = 300
TS = 0.025
HALF = 40  # samples per half period (1 s)
HIGH = 4.5
JITTER_US = 2000.0
TARGET = 1.2


def crb_T(t, u_req, T, w_inf, sigma):
    """Cramer-Rao bound (variance, s^2) of T for one log (see the module docstring)."""
    rises = np.flatnonzero(np.diff(u_req) > 0) + 1
    n = rises.size
    F = np.zeros((1 + 2 * n, 1 + 2 * n))
    for i, k in enumerate(rises):
        rows = np.arange(k, min(k + HALF, t.size - 1) + 1)
        tau = t[rows] - t[k]
        x = tau / T
        g = np.zeros((rows.size, 1 + 2 * n))
        g[:, 0] = -w_inf * (1 - np.exp(-x) - x * np.exp(-x))
        g[:, 1 + 2 * i] = 1.0
        g[:, 2 + 2 * i] = tau - T * (1 - np.exp(-x))
        F += g.T @ g
    return float(np.linalg.inv(F)[0, 0]) * sigma**2


def main() -> int:
    params = PlantParams(motor=PUBLISHED, tau_c=0.0, v_drop=0.45)
    T_true = PUBLISHED.T
    w_inf = PUBLISHED.K * params.u_applied(HIGH)
    cmd = square_wave(0.0, HIGH, HALF, 5, lead=20)
    started = time.perf_counter()
    T_ls, T_63, sig, inside, crb_unit = [], [], [], [], []
    methods: list[str] = []
    for seed in range(SEEDS):
        rec = record(params, cmd, ts=TS, seed=seed, jitter_us=JITTER_US)
        log = RunLog(
            t=rec.t,
            u=rec.u_A,
            omega=timestamp_velocity(rec.t, rec.count),
            extra={"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us},
        )
        fit = fit_time_constant(log)
        assert fit is not None
        T_ls.append(fit.T)
        sig.append(fit.sigma)
        inside.append(fit.ci[0] <= T_true <= fit.ci[1])
        methods.append(fit.method)
        reads = [s.T_63 for s in rises(log, fit) if s.T_63 is not None]
        T_63.append(float(np.median(reads)))
        crb_unit.append(crb_T(rec.t, rec.u_req, T_true, w_inf, 1.0))
    elapsed = time.perf_counter() - started
    T_ls, T_63 = np.array(T_ls), np.array(T_63)
    sigma = float(np.sqrt(np.mean(np.square(sig))))
    q = 2 * math.pi / params.cpr
    crb = math.sqrt(float(np.mean(crb_unit))) * sigma
    crb_q = math.sqrt(float(np.mean(crb_unit))) * q / math.sqrt(12)
    ratio = float(np.std(T_ls, ddof=1)) / crb

    print(
        f"T estimate over {SEEDS} clean seeded logs: Ts = {TS} s, jitter <= {JITTER_US / 1e3:g} ms, "
        f"5 rising steps 0 -> {HIGH} V each, true T = {T_true * 1e3:.3f} ms ({elapsed:.1f} s)"
    )
    print(
        f"noise on the angle: measured {sigma * 1e3:.3f} mrad (rounding alone q/sqrt(12) = {q / math.sqrt(12) * 1e3:.3f} mrad)"
    )
    print(
        f"least squares : mean {T_ls.mean() * 1e3:.3f} ms, bias {(T_ls.mean() - T_true) * 1e3:+.3f} ms, "
        f"std {np.std(T_ls, ddof=1) * 1e3:.4f} ms"
    )
    print(
        f"Cramer-Rao    : sqrt(CRB) {crb * 1e3:.4f} ms at the measured noise ({crb_q * 1e3:.4f} ms at q^2/12)"
    )
    print(
        f"LS spread / CRB = {ratio:.3f}  (target <= {TARGET}: {'met' if ratio <= TARGET else 'MISSED'})"
    )
    print(f"95 % interval coverage: {np.mean(inside) * 100:.1f} % of logs contain the true T")
    print(f"fit used: {', '.join(sorted(set(methods)))}")
    print(
        f"63 % reading  : mean {T_63.mean() * 1e3:.3f} ms, bias {(T_63.mean() - T_true) * 1e3:+.3f} ms, "
        f"std {np.std(T_63, ddof=1) * 1e3:.4f} ms ({np.std(T_63, ddof=1) / crb:.1f} x the CRB)"
    )
    if ratio > TARGET:
        print(
            "target missed: see the docstring; the rounding noise is not white when the wheel moves "
            "an almost whole number of counts per sample."
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
