"""The model check from start to end: fit, look for wild samples, try every cause, decide,
look for more, report.

:func:`check` is the one entry point; it does no I/O.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui.model.check import anomalies as an
from minseg_tui.model.check.candidates import BY_CAUSE, Effects
from minseg_tui.model.check.decide import COMBINABLE, choose, compare
from minseg_tui.model.check.deviations import describe, deviations
from minseg_tui.model.check.evidence import WORDS, evidence
from minseg_tui.model.check.fit import (
    MAX_FIT_ROWS,
    Fit,
    Problem,
    fit_all,
    fit_baseline,
    fit_candidate,
    whiten,
)
from minseg_tui.model.check.report import CheckResult, Finding, ModelFit, Other, fit_percent, rmse
from minseg_tui.model.check.search import golden
from minseg_tui.model.steplog import problem

FloatArray = NDArray[np.float64]


def check(t: ArrayLike, u: ArrayLike, omega: ArrayLike, ts: float | None = None) -> CheckResult:
    """The model check of one step log.

    t: sample times, s; u: voltage applied to the motor (u_A), V, in force from each row on;
    omega: measured speed, rad/s (the Euler velocity (theta_k - theta_k-1)/Ts, or a moving
    average of it); ts: the nominal sample period used for omega, s (default: the median
    interval of t).
    """
    t = np.asarray(t, dtype=float)
    u = np.asarray(u, dtype=float)
    y = np.asarray(omega, dtype=float)
    refused = problem(t, u, y, ts)
    if refused:
        raise ValueError(refused)
    ts = float(np.median(np.diff(t))) if ts is None else float(ts)
    full = Problem(t, u, y, ts)
    notes: list[an.Anomaly] = []
    if _in_motion(y):
        if u[0] != 0:
            full.z0 = None
            how = f"taken as the steady speed under its first input ({u[0]:g} V)"
        else:
            full.z0 = _initial_speed(full)
            how = "its initial speed was fitted"
        notes.append(
            an.Anomaly(
                "starts_moving",
                0,
                float(t[0]),
                float(y[min(1, y.size - 1)]),
                "rad/s",
                f"the log starts with the wheel already turning; {how}",
            )
        )

    # first pass: baseline, wild samples out
    head = full.head(MAX_FIT_ROWS)
    base = fit_baseline(head)
    moving = an.moving_rows(y)
    wild = an.find_wild(y - base.predict(full), 1, moving=moving)
    if wild:
        full, head, base = _repaired(full, y - base.predict(full), wild, 1)

    fits = fit_all(head, base)
    cause, verdicts = choose(base, fits, _raw_worse(head, base, fits))
    if cause != "none" and fits[cause].effects.taps > 1:
        # the speed was averaged: look for wild samples again, in the averaged form
        taps = fits[cause].effects.taps
        orig = Problem(t, u, y, ts, full.z0)
        again = an.find_wild(y - fits[cause].predict(orig), taps, moving=moving)
        if again != wild:
            if again:
                full, head, base = _repaired(orig, y - fits[cause].predict(orig), again, taps)
            else:
                full, head = orig, orig.head(MAX_FIT_ROWS)
                base = fit_baseline(head)
            wild = again
            fits = fit_all(head, base)
            cause, verdicts = choose(base, fits, _raw_worse(head, base, fits))
    ext = fits[cause] if cause != "none" else base

    others: list[Other] = []
    if cause != "none":
        others = _others(head, base, ext, cause, float(np.max(np.abs(u))))

    # predictions on every row of the log as given
    b_pred = base.predict(full)
    e_pred = ext.predict(full) if cause != "none" else b_pred
    baseline = ModelFit(
        "first_order", {"T": base.T, "K": base.K}, rmse(y, b_pred), fit_percent(y, b_pred)
    )
    if cause == "none":
        extended = baseline
    else:
        extended = ModelFit(
            f"first_order+{cause}",
            {"T": ext.T, "K": ext.K, **ext.params},
            rmse(y, e_pred),
            fit_percent(y, e_pred),
        )
    v = verdicts.get(cause)
    gain = {
        "rmse_reduction_percent": 100.0 * (1.0 - extended.rmse / baseline.rmse)
        if baseline.rmse > 0
        else 0.0,
        "fit_percent_gain": extended.fit_percent - baseline.fit_percent,
        "whitened_reduction_percent": 100.0 * v.reduction if v else 0.0,
        "criterion_gain": v.d if v else 0.0,
    }
    keep = np.ones(y.size, dtype=bool)  # where it deviates: without the wild rows
    for m in wild:
        keep[m : m + ext.effects.taps + 1] = False
    devs = deviations(u, np.where(keep, y - b_pred, 0.0), base.T, ts, keep)
    finding = Finding(cause, evidence(cause, ext, base, verdicts, fits, u), others)

    # anomalies: against the model the finding settles on
    res = full.y - e_pred
    found = list(notes)
    found += an.wild_anomalies(t, y, y - e_pred, wild, ext.effects.taps)
    cr = an.creep(t, u, res, e_pred, ext.T, ts)
    if cr:
        found.append(cr)
    shift = 0.5 * ts
    moved = replace(ext, effects=replace(ext.effects, delay=ext.effects.delay + shift))
    taps = ext.effects.taps
    angle_noise = taps * ts * an.robust_sigma(whiten(res, taps)[moving]) if np.any(moving) else 0.0
    found += an.late_steps(
        t, u, res, moved.predict(full) - e_pred, shift, ts, ext.T, e_pred, angle_noise
    )
    gp = an.gaps(t, ts)
    if gp:
        found.append(gp)
    return CheckResult(
        baseline, finding, extended, gain, devs, describe(devs), found, t, y, b_pred, e_pred
    )


def _others(
    head: Problem, base: Fit, ext: Fit, cause: str, u_max: float, most: int = 2
) -> list[Other]:
    """Further effects on top of the cause, greedily: the best clear one, then again."""
    found: list[Other] = []
    current = ext
    left = set(COMBINABLE[cause])
    while left and len(found) < most:
        tries = {
            n: fit_candidate(head, BY_CAUSE[n], current, extra=current.effects)
            for n in sorted(left)
        }
        clear = {n: f for n, f in tries.items() if compare(f, current).clear}
        if not clear:
            break
        name = min(clear, key=lambda n: clear[n].sse_white)
        both = clear[name]
        red = compare(both, current).reduction
        found.append(
            Other(
                name,
                dict(both.params),
                f"{WORDS[name](both, base, u_max)}; on top of {cause} it removes a "
                f"further {100 * red:.0f} % of the whitened residual",
            )
        )
        current = both
        left = (left & COMBINABLE[name]) - {name}
    return found


def _raw_worse(prob: Problem, base: Fit, fits: dict[str, Fit]) -> set[str]:
    """Candidates whose simulation matches the measured speed itself worse than the baseline's
    (the whitened fit can be led astray by a slow drift; such a candidate is not named)."""
    w = prob.weights

    def sse(f: Fit) -> float:
        r = prob.y - f.predict(prob)
        return float(np.dot(w * r, r))

    ref = sse(base)
    return {name for name, f in fits.items() if sse(f) > ref}


def _repaired(
    full: Problem, residual: FloatArray, rows: list[int], taps: int
) -> tuple[Problem, Problem, Fit]:
    y2 = an.repair(full.y, residual, rows, taps)
    fixed = Problem(full.t, full.u, y2, full.ts, full.z0)
    head = fixed.head(MAX_FIT_ROWS)
    return fixed, head, fit_baseline(head)


def _in_motion(y: FloatArray) -> bool:
    """True when the log starts with the wheel turning (rows 1-2 fast against the log's top speed)."""
    top = float(np.max(np.abs(y)))
    return top > 0 and float(np.min(np.abs(y[1:3]))) > 0.2 * top


def _initial_speed(prob: Problem) -> float:
    """Initial speed in K = 1 units (V) for a log that starts moving: fitted with the baseline."""
    head = prob.head(MAX_FIT_ROWS)
    u_top = float(np.max(np.abs(prob.u))) or 1.0
    z_guess = u_top * math.copysign(1.0, float(prob.y[1]))
    for _ in range(2):
        head.z0 = z_guess
        base = fit_baseline(head)
        k = base.K if base.K != 0 else 1.0

        def sse(z: float, base: Fit = base) -> float:
            head.z0 = z
            return float(np.sum((head.y - base.predict(head)) ** 2))

        w1 = float(prob.y[1]) / k
        lo, hi = sorted((0.0, 3.0 * w1))
        z_guess = golden(sse, lo, hi, xatol=1e-4 * max(abs(hi - lo), 1e-9))[0]
    head.z0 = z_guess
    return z_guess


__all__ = ["Effects", "check"]
