"""The evidence for a finding, in words a student understands, with the numbers behind it."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from minseg_tui.model.check.decide import MIN_REDUCTION, PENALTY, Verdict
from minseg_tui.model.check.fit import Fit


def _coulomb(ext: Fit, base: Fit, u_max: float) -> str:
    uc = ext.params["u_c"]
    if u_max <= uc or uc <= 0:
        return f"a breakaway voltage of {uc:.3f} V explains the log"
    t_stop = ext.T * math.log(u_max / uc)
    left = base.K * u_max * math.exp(-t_stop / base.T)
    return (
        f"the step-downs stop in finite time, faster than any exponential: from the "
        f"{u_max:.2f} V step the wheel stands still {t_stop * 1e3:.0f} ms after the command "
        f"drops, where the first-order model still turns at {left:.2f} rad/s; dry friction "
        f"with a breakaway voltage u_c = {ext.params['u_c']:.3f} V does exactly that"
    )


def _dead(ext: Fit, base: Fit, u_max: float) -> str:
    d = ext.params["delay"]
    return (
        f"for about {d * 1e3:.0f} ms after every step nothing happens, then the speed "
        f"changes with a sharp corner as a first-order model does: a pure delay of "
        f"{d * 1e3:.1f} ms (an extra pole would start smoothly instead)"
    )


def _filter(ext: Fit, base: Fit, u_max: float) -> str:
    n = int(ext.params["taps"])
    return (
        f"the measured speed is smoother than an Euler velocity of encoder counts can be, "
        f"and every edge becomes a straight ramp {n} samples long: the speed was averaged "
        f"over {n} samples (a moving-average filter), which also divides the encoder noise "
        f"by {n}"
    )


def _coast(ext: Fit, base: Fit, u_max: float) -> str:
    tc = ext.params["T_coast"]
    slower = "more slowly" if tc > ext.T else "faster"
    return (
        f"the step-downs to zero decay {slower} than the step-ups: time constant "
        f"{tc:.3f} s at zero command against T = {ext.T * 1e3:.0f} ms when driven; the "
        f"bridge lets the wheel coast instead of braking it"
    )


def _pole(ext: Fit, base: Fit, u_max: float) -> str:
    t2 = ext.params["T2"]
    return (
        f"every step starts with zero slope (an S-shaped start) instead of the sharp "
        f"corner of a first-order model: an extra pole of {t2 * 1e3:.1f} ms delays the "
        f"torque (a pure delay would show a corner after a flat stretch)"
    )


WORDS: dict[str, Callable[[Fit, Fit, float], str]] = {
    "coulomb_friction": _coulomb,
    "dead_time": _dead,
    "velocity_filter": _filter,
    "coast_on_zero": _coast,
    "second_pole": _pole,
}
"""Cause -> the sentence that states its evidence."""


def evidence(
    cause: str,
    ext: Fit,
    base: Fit,
    verdicts: dict[str, Verdict],
    fits: dict[str, Fit],
    u: np.ndarray,
) -> str:
    """Evidence for ``cause`` (or for ``none``): the shape in words, then the numbers."""
    if cause == "none":
        best = max(verdicts.items(), key=lambda kv: kv[1].reduction, default=None)
        if best is None:
            return "the first-order model explains the log"
        name, v = best
        share = f"{100 * max(v.reduction, 0.0):.1f} %"
        threshold = PENALTY * math.log(max(fits[name].rows, 2)) if name in fits else 0.0
        if v.reduction < MIN_REDUCTION:
            why = (
                f"removes only {share} of the whitened residual, and a cause needs at least "
                f"{100 * MIN_REDUCTION:.0f} %"
            )
        elif v.d <= threshold:
            why = (
                f"removes {share} of the whitened residual, but its criterion gain "
                f"{v.d:.0f} is below the {threshold:.0f} a cause needs on a log this long"
            )
        else:
            why = (
                f"removes {share} of the whitened residual but makes the plain speed error "
                f"worse or is not the effect it claims (a coast no slower than braking)"
            )
        return (
            f"the first-order model explains the log down to the encoder's noise: the best "
            f"extension ({name}) {why}"
        )
    u_max = float(np.max(np.abs(u))) if u.size else 0.0
    v = verdicts[cause]
    rivals = sorted((f.sse_white, n) for n, f in fits.items() if n != cause)
    rival = ""
    if rivals and ext.sse_white > 0:
        ratio = rivals[0][0] / ext.sse_white
        rival = f"; the next best explanation ({rivals[0][1]}) leaves {ratio:.1f}x as much"
    return (
        f"{WORDS[cause](ext, base, u_max)}. It removes {100 * v.reduction:.1f} % of the "
        f"whitened residual (criterion gain {v.d:.0f}){rival}"
    )
