"""Naming the cause: an information criterion with a margin, and the evidence in words.

Each candidate adds one parameter to the first-order model. On the whitened residual
(white under the encoder's quantisation noise) twice the log-likelihood gain of a
candidate over the baseline is

    D = n ln(SSE_baseline / SSE_candidate)

A candidate is *clear* when D exceeds ``PENALTY`` ln n (BIC asks for 1 ln n per added
parameter; we ask for much more, because a real log's residual is never exactly white)
**and** it removes at least ``MIN_REDUCTION`` of the whitened sum of squares. Clean
first-order data improve by a few per cent at most, so it comes out ``none``; the
hidden effects of the test suite remove 80-100 %. The cause is the clear candidate
with the smallest SSE; another effect is listed when, fitted on top of the cause, it is
clear again against the cause's own fit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from minseg_tui.model.check.fit import Fit

MIN_REDUCTION = 0.25
"""Fraction of the whitened sum of squares a candidate must remove to be named."""

COAST_RATIO = 1.5
"""A coast must be this many times slower than the driven time constant to be named."""

PENALTY = 10.0
"""Criterion margin in units of ln n (BIC's is 1 per parameter)."""


@dataclass(frozen=True)
class Verdict:
    """Whether ``fit`` is a clear improvement on ``against``: criterion gain D and the
    fraction of the whitened SSE it removes."""

    d: float
    reduction: float
    clear: bool


def compare(fit: Fit, against: Fit) -> Verdict:
    """D = n ln(SSE_against / SSE_fit) and the relative reduction, with the decision."""
    n = max(fit.rows, 2)
    if fit.sse_white <= 0 or not math.isfinite(fit.sse_white) or against.sse_white <= 0:
        return Verdict(0.0, 0.0, False)
    d = n * math.log(against.sse_white / fit.sse_white)
    red = 1.0 - fit.sse_white / against.sse_white
    return Verdict(d, red, d > PENALTY * math.log(n) and red >= MIN_REDUCTION)


def choose(
    base: Fit, fits: dict[str, Fit], vetoed: set[str] | frozenset[str] = frozenset()
) -> tuple[str, dict[str, Verdict]]:
    """The cause ('none' when no candidate is clear) and every candidate's verdict.

    ``vetoed`` candidates (their plain speed residual is worse than the baseline's) are
    never clear.
    """
    verdicts = {name: compare(f, base) for name, f in fits.items()}
    for name in vetoed:
        v = verdicts[name]
        verdicts[name] = Verdict(v.d, v.reduction, False)
    if "coast_on_zero" in fits:  # a coast no slower than braking is no coast
        f = fits["coast_on_zero"]
        if f.params["T_coast"] < COAST_RATIO * f.T:
            v = verdicts["coast_on_zero"]
            verdicts["coast_on_zero"] = Verdict(v.d, v.reduction, False)
    clear = [name for name, v in verdicts.items() if v.clear]
    if not clear:
        return "none", verdicts
    return min(clear, key=lambda name: fits[name].sse_white), verdicts


COMBINABLE: dict[str, frozenset[str]] = {
    "coulomb_friction": frozenset({"dead_time", "velocity_filter", "coast_on_zero"}),
    "dead_time": frozenset({"coulomb_friction", "velocity_filter", "coast_on_zero", "second_pole"}),
    "velocity_filter": frozenset({"coulomb_friction", "dead_time", "coast_on_zero", "second_pole"}),
    "coast_on_zero": frozenset({"coulomb_friction", "dead_time", "velocity_filter"}),
    "second_pole": frozenset({"dead_time", "velocity_filter"}),
}
"""Which effects the exact simulator can put on top of which (a second pole has no closed
form together with dry friction or coasting here)."""
