"""What a session keeps of its run's results: the model check's cause and figures and the
numbers of Tasks 11-13, under the key of what they were computed from.

The lab computes the model check and Tasks 11-15 on the run in use anyway (the screens show
them); the class view needs a few of their numbers for every group of a class, and
computing them again costs about 0.4 s of CPU per group. So the session file keeps them,
in an optional part ``kept`` of session.json (:data:`KEPT`), written with the rest of the
file (atomically, :mod:`~minseg_tui.lab.saving.store`)::

    "kept": {"version": 1, "run": "steps-1", "key": "<sha256 hex>",
             "step": {"K": ..., "T": ..., "T_63": ..., "u_ss": ..., "omega_ss": ...,
                      "dead_time": ...},
             "check": {"cause": "coulomb_friction", "model": "first_order+coulomb_friction",
                       "others": [], "params": {"T": ..., "K": ..., "u_c": ...},
                       "gain": {...}, "problem": ""}}

:func:`run_key` hashes everything these numbers follow from: :data:`VERSION`, the source
of the code that computes them (:func:`code_fingerprint`), the run's
log file byte for byte, its kind and sample period, and the table's (u_req, u_ss) pairs
the applied voltage is mapped through. A reader uses what is kept only when the key it
computes now is the one kept (:func:`read`): a run, a u_ss or a program that changed gives
another key, and the numbers are computed again. What is kept is a memo: a part that cannot
be read is passed over (never a reason to refuse the session), and the file's schema stays
1 (an older program reads such a file and ignores the part; a file without it, written
before, reads as before).

Units: SI (K rad/s/V, T, T_63, dead_time s, u_ss V, omega_ss rad/s; the check's
parameters in the units of :data:`minseg_tui.model.check.effects.PARAM_UNITS`).
"""

from __future__ import annotations

import functools
import hashlib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from minseg_tui.lab.saving.runs import RunInfo
from minseg_tui.lab.saving.store import read_regular

VERSION: int = 1
"""Version of the shape of what is kept. The code that computes it is keyed apart, by
:func:`code_fingerprint`, so a changed model check or identify never reuses old results."""

_COMPUTED_BY = ("model", "signals.py")
"""The package and module of minseg_tui whose code the kept numbers follow from."""


def computing_sources() -> list[Path]:
    """The source files the kept numbers are computed by (:data:`_COMPUTED_BY`), in a fixed
    order."""
    root = Path(__file__).resolve().parents[2]
    out: list[Path] = []
    for part in _COMPUTED_BY:
        out += [root / part] if part.endswith(".py") else sorted((root / part).rglob("*.py"))
    return out


@functools.cache
def code_fingerprint() -> str:
    """A SHA-256 of :func:`computing_sources`: any change to the model check or identify,
    even one nobody remembered to mark with a new :data:`VERSION`, gives every run another
    key. Computed once per process (a few ms: the files are small)."""
    root = Path(__file__).resolve().parents[2]
    h = hashlib.sha256()
    for source in computing_sources():
        h.update(source.relative_to(root).as_posix().encode() + b"\0")
        h.update(source.read_bytes())
    return h.hexdigest()


MAX_LOG = 64 << 20
"""A run's log larger than this is not hashed (its results are then never kept)."""


@dataclass(frozen=True)
class ResponseFigures:
    """Tasks 11-13's numbers of a run: K (rad/s/V), the least-squares T (s), the 63 %
    reading T_63 (s, None when no step crossed 63 %), the applied voltage u_ss K divides by
    (V), the fitted steady speed omega_ss (rad/s), the dead time (s) and J (kg m^2; NaN
    when not computed: J follows the table's R, k_v and f, so it is never kept)."""

    K: float
    T: float
    T_63: float | None
    u_ss: float
    omega_ss: float
    dead_time: float = 0.0
    J: float = math.nan


@dataclass(frozen=True)
class CheckFigures:
    """The model check of a run in brief: ``cause`` (``finding.cause``, a contract name;
    '' when the check could not run, then ``problem`` says why in one line), the extended
    ``model`` and its ``params``, the ``others`` causes named beside it, and the ``gain``
    figures (rad/s, rad, %; None where the check had none)."""

    cause: str
    model: str = ""
    others: tuple[str, ...] = ()
    params: Mapping[str, float] = field(default_factory=dict)
    gain: Mapping[str, float | None] = field(default_factory=dict)
    problem: str = ""


@dataclass(frozen=True)
class Kept:
    """What a session file keeps of run ``run``, under ``key`` (:func:`run_key`)."""

    run: str
    key: str
    step: ResponseFigures | None = None
    check: CheckFigures | None = None

    def merged(self, other: Kept) -> Kept:
        """This record with the parts of ``other`` (of the same key) it lacks; ``other``
        itself when the keys differ."""
        if (other.run, other.key) != (self.run, self.key):
            return other
        return Kept(self.run, self.key, other.step or self.step, other.check or self.check)

    def to_json(self) -> dict[str, object]:
        """The ``kept`` part of session.json (J is not kept: it follows the table)."""
        out: dict[str, object] = {"version": VERSION, "run": self.run, "key": self.key}
        if self.step is not None:
            s = self.step
            out["step"] = {
                "K": s.K,
                "T": s.T,
                "T_63": s.T_63,
                "u_ss": s.u_ss,
                "omega_ss": s.omega_ss,
                "dead_time": s.dead_time,
            }
        if self.check is not None:
            c = self.check
            out["check"] = {
                "cause": c.cause,
                "model": c.model,
                "others": list(c.others),
                "params": dict(c.params),
                "gain": dict(c.gain),
                "problem": c.problem,
            }
        return out


def _finite(x: object) -> float:
    if isinstance(x, bool) or not isinstance(x, int | float) or not math.isfinite(x):
        raise TypeError("expected a finite number")
    return float(x)


def _text(x: object) -> str:
    if not isinstance(x, str):
        raise TypeError("expected text")
    return x


def _map(x: object) -> dict[str, object]:
    if not isinstance(x, dict):
        raise TypeError("expected an object")
    return {str(k): v for k, v in x.items()}


def _step(d: object) -> ResponseFigures:
    m = _map(d)
    return ResponseFigures(
        K=_finite(m["K"]),
        T=_finite(m["T"]),
        T_63=None if m["T_63"] is None else _finite(m["T_63"]),
        u_ss=_finite(m["u_ss"]),
        omega_ss=_finite(m["omega_ss"]),
        dead_time=_finite(m["dead_time"]),
    )


def _check(d: object) -> CheckFigures:
    m = _map(d)
    others = m["others"]
    if not isinstance(others, list):
        raise TypeError("expected a list")
    return CheckFigures(
        cause=_text(m["cause"]),
        model=_text(m["model"]),
        others=tuple(_text(o) for o in others),
        params={k: _finite(v) for k, v in _map(m["params"]).items()},
        gain={k: None if v is None else _finite(v) for k, v in _map(m["gain"]).items()},
        problem=_text(m["problem"]),
    )


def from_json(d: object) -> Kept | None:
    """The record of a ``kept`` part, or None when it is not one this version wrote (an
    older or newer version, a part broken by hand): it is then computed again."""
    try:
        m = _map(d)
        if m.get("version") != VERSION:
            return None
        return Kept(
            run=_text(m["run"]),
            key=_text(m["key"]),
            step=_step(m["step"]) if "step" in m else None,
            check=_check(m["check"]) if "check" in m else None,
        )
    except (KeyError, TypeError, ValueError):
        return None


def run_key(folder: Path, run: RunInfo, table: Sequence[tuple[float, float]]) -> str | None:
    """The key of the results of ``run`` (its log in ``folder``) read through ``table``, the
    (u_req, u_ss) pairs in V: a SHA-256 of :data:`VERSION`, the code's fingerprint, the
    log's bytes, the run's kind and sample period and the pairs. None when the log cannot be read (nothing is kept)."""
    try:
        data = read_regular(Path(folder) / run.file, MAX_LOG)
    except OSError:
        return None
    if len(data) > MAX_LOG:
        return None
    h = hashlib.sha256(f"minseg-tui kept results {VERSION}\0{code_fingerprint()}\0".encode())
    h.update(f"{run.kind == 'imported'}\0{run.ts!r}\0".encode())
    h.update(repr([(float(a), float(b)) for a, b in table]).encode() + b"\0")
    h.update(len(data).to_bytes(8, "little"))
    h.update(data)
    return h.hexdigest()


def read(
    part: object, folder: Path, run: RunInfo | None, table: Sequence[tuple[float, float]]
) -> Kept | None:
    """The kept results in ``part`` (session.json's ``kept``) when they are of ``run`` as it
    is now read through ``table`` (the key matches), else None."""
    if run is None or part is None:
        return None
    kept = from_json(part)
    if kept is None or kept.run != run.name:
        return None
    return kept if run_key(folder, run, table) == kept.key else None


__all__ = [
    "VERSION",
    "CheckFigures",
    "Kept",
    "ResponseFigures",
    "from_json",
    "read",
    "run_key",
]
