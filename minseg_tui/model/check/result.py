"""The model check's result: dataclasses that give the JSON contract of ``analyze --json``.

Every key that existed keeps its meaning; new ones are added (see :meth:`CheckResult.to_dict`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal, Protocol

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.anomalies import Anomaly
from minseg_tui.model.check.decide import Reason
from minseg_tui.model.check.deviations import Deviation
from minseg_tui.model.check.effects import Shown
from minseg_tui.model.check.evidence import Lacks
from minseg_tui.model.check.figures import CloseUp, Gain, Lead
from minseg_tui.model.check.sampling import Sampling

FloatArray = NDArray[np.float64]


class Says(Protocol):
    """Who words the records for the JSON (:mod:`minseg_tui.lab.views.check_says`: the
    model gives records, the sentences are made outside it)."""

    def anomaly(self, a: Anomaly) -> str:
        """The sentence of anomaly ``a``."""
        ...

    def caveat(self, c: Caveat) -> str:
        """The sentence of caveat ``c``."""
        ...

    def evidence(self, f: Finding) -> str:
        """The evidence of finding ``f`` in words."""
        ...

    def other(self, o: Other) -> str:
        """The evidence of a further effect ``o`` in words."""
        ...

    def lead_why(self, g: Lead) -> str:
        """Why figure ``g`` leads, in words."""
        ...

    def close_up_what(self, c: CloseUp) -> str:
        """What close-up ``c`` shows, in words."""
        ...

    def sampling(self, s: Sampling) -> str:
        """How the log was sampled, in words."""
        ...

    def resolution_how(self, s: Sampling) -> str:
        """Where the speed's resolution came from, in words ('' when unknown)."""
        ...

    def where(self, devs: list[Deviation]) -> str:
        """Where the first-order model deviates most, in words."""
        ...

    def runner_up_why(self, f: Finding) -> str:
        """Why the runner-up of ``f`` lost, in words ('' without one)."""
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
class Because:
    """The evidence of a cause in the model: what it reads off the log (``shown``, the
    cause's own record), the share of the whitened residual it removes (``reduction``, 0-1)
    and its criterion gain (``gain``) against the model without it, and the claim it makes
    against a rival (:attr:`.effects.Candidate.claim`): ``rival_ratio``: the rival in its
    place leaves this many times the whitened residual (None: not fitted), ``holds``: by
    enough to make the claim; ``void``: the log cannot rule the rival out, the claim is
    taken back."""

    cause: str
    shown: Shown
    reduction: float
    gain: float
    rival_ratio: float | None = None
    holds: bool = False
    void: bool = False


FitSaid = Literal["fits", "turning", "at_noise", "above", "unexplained"]
"""What the first-order model does when no cause is named: fits a log without noise,
misses where the wheel turns (it stands still in most rows), errs at the level of the noise,
misses above it but no cause is clear, or misses what no cause explains."""


@dataclass(frozen=True)
class Plain:
    """The evidence when no cause is named (``how``, with its figures: the noise level,
    rad/s; the rows where the wheel turns of all ``rows``; the miss above the noise there,
    ``left_turning``, and over the log, ``left``; the rms error ``rms``, rad/s; ``low_fit``:
    the fit (%) when it is low only because of the noise, else None)."""

    how: FitSaid
    level: float = 0.0
    turning: int = 0
    rows: int = 0
    left_turning: float = 0.0
    rms: float = 0.0
    left: float = 0.0
    low_fit: float | None = None


RunnerKind = Literal[
    "held_back", "too_small", "short_of_gain", "misses_more", "not_named", "leaves_more"
]
"""Why the runner-up lost. With no cause named, the best extension: is held back by the
selection (``reason``), removes too small a share of the whitened residual, or falls short
of the criterion gain a cause needs. With a cause named, the next best explanation: leaves
less whitened residual but misses the speed by more, leaves less but is not named
(``reason``), or leaves more."""


@dataclass(frozen=True)
class RunnerUp:
    """Why the runner-up (``name``, a model's contract name) lost (``kind``), with what its
    sentence needs: the selection's ``reason`` it was left out (None: none), the share of
    the whitened residual it removes (0-1) against the share a cause needs (``needs``), its
    criterion gain against the ``threshold``, the rms errors of it and of the model named
    (``rms``, rad/s), or how many times the named model's whitened residual it leaves."""

    kind: RunnerKind
    name: str
    reason: Reason | None = None
    share: float = 0.0
    needs: float = 0.0
    gain: float = 0.0
    threshold: float = 0.0
    rms: tuple[float, float] = (0.0, 0.0)
    ratio: float = 0.0


@dataclass(frozen=True)
class Other:
    """A further effect found on top of the cause: its name, parameter and evidence."""

    cause: str
    params: dict[str, float]
    evidence: Because

    def to_dict(self, says: Says) -> dict[str, object]:
        """The effect's JSON, its evidence in words by ``says``."""
        return {"cause": self.cause, "params": dict(self.params), "evidence": says.other(self)}


@dataclass(frozen=True)
class OnBound:
    """A candidate that came out clear but sits on a bound: its parameter and T as fitted
    (SI, by name) and why it is not named (the selection's reason)."""

    params: dict[str, float]
    why: Reason


@dataclass(frozen=True)
class Misses:
    """The best model still misses clearly: its error held over 9 samples (rad/s rms) in
    the region where that is worst (a :data:`.deviations.REGIONS` name), against what the
    noise leaves there (rad/s; 0: the noise measures 0); ``edges``: how many steps of the
    region's kind the log has (0 for the steady state)."""

    size: float
    region: str
    level: float
    edges: int = 0


Alike = Literal["filters", "pole_measured"]
"""Why a smooth speed column cannot tell the causes that act on the reading apart: an
average and a pole on the drive look alike ('filters'), or the pole named is a filter of
the reading itself ('pole_measured')."""


@dataclass(frozen=True)
class Smooth:
    """A smooth speed column (not a difference of counts): the causes that act on the
    reading cannot be told from the one named, for the reason ``alike``."""

    alike: Alike


@dataclass(frozen=True)
class Scatter:
    """The speed scatters ``noise`` (rad/s) from sample to sample, more than the counts
    explain (``counts``, rad/s); ``left``: the model's rms error (rad/s); ``follows``: the
    model simulated at the log's own sample times follows it (the scatter is the sampling's
    timing), else it is noise no model explains."""

    noise: float
    counts: float
    left: float
    follows: bool


@dataclass(frozen=True)
class Unjudged:
    """The log cannot show the cause: ``why``, what it lacks."""

    why: Lacks


Compared = Literal["whitened", "squared", "squared_less", "split"]
"""How two models the log cannot tell apart were compared: by their whitened residuals
(same average), or by their squared speed errors (their averages differ), the second
ahead there ('squared_less') or not ('squared'); 'split': same average, the second behind
on the whitened residuals and ahead on the squared speed errors."""


@dataclass(frozen=True)
class Untold:
    """This log cannot tell the causes named (``named``) from ``other``: the second leaves
    ``ratio`` times the first's residual, compared as ``compared`` says."""

    named: tuple[str, ...]
    other: tuple[str, ...]
    ratio: float
    compared: Compared
    moves: float = 0.0
    """When ``other`` is ``named`` with one cause more that was left out as too small: the
    most that cause moves the simulated speed (held over 9 samples) as a share of the
    largest speed the model reaches (0: not that kind)."""
    squared: float = 0.0
    """When ``compared`` is 'split': the second's squared speed error over the first's
    (under 1; 0: not that kind)."""


@dataclass(frozen=True)
class Caveat:
    """Something the check says plainly instead of a cause: kind ('on_bound': a candidate
    whose parameter sits on its search bound; 'misses': the best model still misses clearly
    above the noise; 'cannot_judge': the log cannot show a cause; 'cannot_tell': two causes
    look alike in this log; 'noise': the speed scatters more than the encoder explains),
    the cause concerned (or None) and what its sentence needs (``facts``; the sentence is
    written outside the model, :mod:`minseg_tui.lab.views.check_says`)."""

    kind: str
    cause: str | None
    facts: OnBound | Misses | Smooth | Scatter | Unjudged | Untold

    def to_dict(self, text: str) -> dict[str, object]:
        """The caveat's JSON, ``text`` its sentence."""
        return {"kind": self.kind, "cause": self.cause, "text": text}


@dataclass(frozen=True)
class Finding:
    """The cause (a contract name: the largest effect, or 'none'), its evidence in words,
    the other effects in the model, and what the check says plainly besides: caveats,
    whether the model explains the log down to its noise, the runner-up with why it lost,
    and the other explanations the log cannot tell from the one named."""

    cause: str
    evidence: Because | Plain
    others: list[Other] = field(default_factory=list)
    caveats: list[Caveat] = field(default_factory=list)
    explained: bool = True
    runner_up: str | None = None
    runner_up_why: RunnerUp | None = None
    ambiguous_with: list[list[str]] = field(default_factory=list)
    """Other sets of causes (each like [cause, *others]) that fit this log about as well as
    the one named: the log cannot tell them apart (a 'cannot_tell' caveat says so)."""

    def to_dict(self, says: Says) -> dict[str, object]:
        """The finding's JSON, its sentences by ``says``."""
        return {
            "cause": self.cause,
            "evidence": says.evidence(self),
            "others": [o.to_dict(says) for o in self.others],
            "caveats": [c.to_dict(says.caveat(c)) for c in self.caveats],
            "explained": self.explained,
            "runner_up": self.runner_up,
            "runner_up_why": says.runner_up_why(self),
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
            "finding": self.finding.to_dict(says),
            "extended": self.extended.to_dict(),
            "gain": self.gain.to_dict(),
            "deviations": {
                "where": says.where(self.deviations),
                "regions": [d.to_dict() for d in self.deviations],
            },
            "anomalies": [a.to_dict(says.anomaly(a)) for a in self.anomalies],
            "rows": int(self.t.size),
            "sampling": self.sampling.to_dict(
                says.sampling(self.sampling), says.resolution_how(self.sampling)
            )
            if self.sampling
            else None,
            "lead": self.lead.to_dict(says.lead_why(self.lead)) if self.lead else None,
            "close_up": (
                self.close_up.to_dict(says.close_up_what(self.close_up)) if self.close_up else None
            ),
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
