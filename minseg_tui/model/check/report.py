"""The model check's result: dataclasses that give the JSON contract, and the text a student reads."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.anomalies import Anomaly
from minseg_tui.model.check.deviations import Deviation

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ModelFit:
    """A model as reported: name, parameters (T in s, K in rad/s/V, the cause's own), and how
    well its simulation matches every row: rmse (rad/s) and fit_percent."""

    model: str
    params: dict[str, float]
    rmse: float
    fit_percent: float

    def to_dict(self) -> dict[str, object]:
        return {
            "model": self.model,
            "params": dict(self.params),
            "rmse": self.rmse,
            "fit_percent": self.fit_percent,
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
class Finding:
    """The cause (a contract name), its evidence in words and the other effects found."""

    cause: str
    evidence: str
    others: list[Other] = field(default_factory=list)

    def to_dict(self) -> dict[str, object]:
        return {
            "cause": self.cause,
            "evidence": self.evidence,
            "others": [o.to_dict() for o in self.others],
        }


@dataclass(frozen=True)
class CheckResult:
    """Everything the model check says about one log.

    baseline / extended: the fitted models; finding; gain: rmse_reduction_percent and the
    other figures; deviations: the baseline's residual per region, and ``where`` in words;
    anomalies; t, omega, baseline_pred, extended_pred: every row (s, rad/s) so anyone can
    recompute the figures.
    """

    baseline: ModelFit
    finding: Finding
    extended: ModelFit
    gain: dict[str, float]
    deviations: list[Deviation]
    where: str
    anomalies: list[Anomaly]
    t: FloatArray
    omega: FloatArray
    baseline_pred: FloatArray
    extended_pred: FloatArray

    def to_dict(self) -> dict[str, object]:
        """The JSON object of ``minseg-tui analyze --json``."""
        return {
            "baseline": self.baseline.to_dict(),
            "finding": self.finding.to_dict(),
            "extended": self.extended.to_dict(),
            "gain": dict(self.gain),
            "deviations": {"where": self.where, "regions": [d.to_dict() for d in self.deviations]},
            "anomalies": [a.to_dict() for a in self.anomalies],
            "rows": int(self.t.size),
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


_UNITS = {
    "T": "s",
    "K": "rad/s/V",
    "u_c": "V",
    "delay": "s",
    "taps": "samples",
    "T_coast": "s",
    "T2": "s",
}


def _params(p: dict[str, float]) -> str:
    return ", ".join(f"{k} = {v:.4g} {_UNITS.get(k, '')}".rstrip() for k, v in p.items())


def text(r: CheckResult) -> str:
    """The human report: baseline, where it deviates, the cause and evidence, the extended
    model, the gain, the anomalies."""
    b, e, f = r.baseline, r.extended, r.finding
    lines = [
        f"Baseline (first order): {_params(b.params)}",
        f"  simulated on the measured input: rmse {b.rmse:.3f} rad/s, fit {b.fit_percent:.1f} %",
        f"Where it deviates: {r.where}",
    ]
    for d in r.deviations:
        lines.append(
            f"  {d.region.replace('_', ' '):<20} {d.rows:6d} rows  rms {d.rms:.3f} rad/s"
            f"  mean {d.mean:+.3f} rad/s"
        )
    lines.append(f"Cause: {f.cause}")
    lines.append(f"  {f.evidence}")
    for o in f.others:
        lines.append(f"  also: {o.cause} ({_params(o.params)}): {o.evidence}")
    if f.cause != "none":
        lines.append(f"Extended model ({e.model}): {_params(e.params)}")
        lines.append(f"  rmse {e.rmse:.3f} rad/s, fit {e.fit_percent:.1f} %")
        lines.append(
            f"Gain: rmse {r.gain['rmse_reduction_percent']:.1f} % lower, fit "
            f"{r.gain['fit_percent_gain']:+.1f} points"
        )
    else:
        lines.append("Extended model: none needed (it is the baseline)")
    if r.anomalies:
        lines.append("Anomalies (reported, not counted as causes):")
        lines.extend(f"  - {a.text}" for a in r.anomalies)
    return "\n".join(lines)
