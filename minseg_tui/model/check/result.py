"""The model check's result: dataclasses that give the JSON contract of ``analyze --json``.

Every key that existed keeps its meaning; new ones are added (see :meth:`CheckResult.to_dict`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.anomalies import Anomaly
from minseg_tui.model.check.deviations import Deviation
from minseg_tui.model.check.figures import CloseUp, Gain, Lead
from minseg_tui.model.check.sampling import Sampling

FloatArray = NDArray[np.float64]


class Says(Protocol):
    """Who words the records for the JSON (:mod:`minseg_tui.lab.views.check_says`: the
    model gives records, the sentences are made outside it)."""

    def anomaly(self, a: Anomaly) -> str:
        """The sentence of anomaly ``a``."""
        ...


@dataclass(frozen=True)
class ModelFit:
    """A model as reported: name, parameters (T in s, K in rad/s/V, each cause's own), how
    well its simulation matches the rows the fit used: rmse (rad/s) and fit_percent over
    ``rows`` rows (wild samples repaired; disturbances, glitches and logging artefacts left
    out; 0: every row of the log), and a 95 % interval (lo, hi) per parameter (empty for the
    baseline when not computed)."""

    model: str
    params: dict[str, float]
    rmse: float
    fit_percent: float
    intervals: dict[str, tuple[float, float]] = field(default_factory=dict)
    rows: int = 0

    def to_dict(self) -> dict[str, object]:
        return {
            "model": self.model,
            "params": dict(self.params),
            "rmse": self.rmse,
            "fit_percent": self.fit_percent,
            "rows": self.rows,
            "intervals": {k: [lo, hi] for k, (lo, hi) in self.intervals.items()},
        }


@dataclass(frozen=True)
class Other:
    """A further effect found on top of the cause: its name, parameter and evidence."""

    cause: str
    params: dict[str, float]
    evidence: str

    def to_dict(self) -> dict[str, object]:
        return {"cause": self.cause, "params": dict(self.params), "evidence": self.evidence}


@dataclass(frozen=True)
class Caveat:
    """Something the check says plainly instead of a cause: kind ('on_bound': a candidate
    whose parameter sits on its search bound; 'misses': the best model still misses clearly
    above the noise; 'cannot_judge': the log cannot show a cause; 'cannot_tell': two causes
    look alike in this log; 'noise': the speed scatters more than the encoder explains),
    the cause concerned (or None) and a sentence."""

    kind: str
    cause: str | None
    text: str

    def to_dict(self) -> dict[str, object]:
        return {"kind": self.kind, "cause": self.cause, "text": self.text}


@dataclass(frozen=True)
class Finding:
    """The cause (a contract name: the largest effect, or 'none'), its evidence in words,
    the other effects in the model, and what the check says plainly besides: caveats,
    whether the model explains the log down to its noise, the runner-up with why it lost,
    and the other explanations the log cannot tell from the one named."""

    cause: str
    evidence: str
    others: list[Other] = field(default_factory=list)
    caveats: list[Caveat] = field(default_factory=list)
    explained: bool = True
    runner_up: str | None = None
    runner_up_why: str = ""
    ambiguous_with: list[list[str]] = field(default_factory=list)
    """Other sets of causes (each like [cause, *others]) that fit this log about as well as
    the one named: the log cannot tell them apart (a 'cannot_tell' caveat says so)."""

    def to_dict(self) -> dict[str, object]:
        return {
            "cause": self.cause,
            "evidence": self.evidence,
            "others": [o.to_dict() for o in self.others],
            "caveats": [c.to_dict() for c in self.caveats],
            "explained": self.explained,
            "runner_up": self.runner_up,
            "runner_up_why": self.runner_up_why,
            "ambiguous_with": [list(a) for a in self.ambiguous_with],
        }


@dataclass(frozen=True)
class CheckResult:
    """Everything the model check says about one log.

    baseline / extended: the fitted models; finding; gain: the figures of how much better
    the extended model does (rad/s, rad, %; None where a figure cannot be had); deviations: the
    baseline's residual per region, and ``where`` in words; anomalies; t, omega,
    baseline_pred, extended_pred: every row (s, rad/s) so anyone can recompute the figures;
    sampling: how the log was sampled; lead: the figure that means most for this log and
    why; close_up: where to look at the cause (rows of t).
    """

    baseline: ModelFit
    finding: Finding
    extended: ModelFit
    gain: Gain
    deviations: list[Deviation]
    where: str
    anomalies: list[Anomaly]
    t: FloatArray
    omega: FloatArray
    baseline_pred: FloatArray
    extended_pred: FloatArray
    sampling: Sampling | None = None
    lead: Lead | None = None
    close_up: CloseUp | None = None

    def to_dict(self, says: Says) -> dict[str, object]:
        """The JSON object of ``minseg-tui analyze --json``, its sentences by ``says``."""
        return {
            "baseline": self.baseline.to_dict(),
            "finding": self.finding.to_dict(),
            "extended": self.extended.to_dict(),
            "gain": self.gain.to_dict(),
            "deviations": {"where": self.where, "regions": [d.to_dict() for d in self.deviations]},
            "anomalies": [a.to_dict(says.anomaly(a)) for a in self.anomalies],
            "rows": int(self.t.size),
            "sampling": self.sampling.to_dict() if self.sampling else None,
            "lead": self.lead.to_dict() if self.lead else None,
            "close_up": self.close_up.to_dict() if self.close_up else None,
        }


def rmse(y: FloatArray, yhat: FloatArray) -> float:
    """Root mean square of y - yhat over every row, in the units of y."""
    return float(np.sqrt(np.mean((y - yhat) ** 2)))


def fit_percent(y: FloatArray, yhat: FloatArray) -> float:
    """100 (1 - |y - yhat| / |y - mean y|), the usual 'fit' of a simulation, %."""
    den = float(np.linalg.norm(y - np.mean(y)))
    if den == 0:
        return 0.0
    return float(100.0 * (1.0 - np.linalg.norm(y - yhat) / den))
