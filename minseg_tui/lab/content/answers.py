"""Checking a group's answers against the steps' :class:`~minseg_tui.lab.content.steps.Check` data.

A formula answer is compared with the expected formula at seeded sample points, a number
with the expected value (which may use other entries), a choice with the right options;
a typical mistake gets its own message. Pure functions: no state, no I/O.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping

import numpy as np

from minseg_tui.lab.content.expr import Formula, parse_formula
from minseg_tui.lab.content.steps import (
    CONSISTENT,
    CONSISTENT_GRADER,
    FIELDS,
    Check,
    Feedback,
    Field,
)

_SAMPLE_SEED = 20240416


def _samples(names: tuple[str, ...], n: int = 6) -> list[dict[str, float]]:
    rng = np.random.default_rng(_SAMPLE_SEED)
    return [{name: float(rng.uniform(0.5, 2.0)) for name in names} for _ in range(n)]


def _close(a: float, b: float, rel: float, abs_: float) -> bool:
    return math.isfinite(a) and math.isfinite(b) and abs(a - b) <= abs_ + rel * abs(b)


def _same(
    answer: Formula | float,
    expected: str,
    names: tuple[str, ...],
    env: Mapping[str, float],
    rel: float,
    abs_: float,
) -> bool:
    target = parse_formula(expected, names + tuple(env))
    if isinstance(answer, Formula):
        points = _samples(names) if names else [{}]
        return all(
            _close(answer.value({**p, **env}), target.value({**p, **env}), rel, abs_)
            for p in points
        )
    return _close(answer, target.value(dict(env)), rel, abs_)


def check_answer(chk: Check, answer: object, entries: Mapping[str, object]) -> Feedback:
    """The verdict on ``answer`` for check ``chk``.

    answer: the parsed entry of the checked field (a float in SI for a quantity, a Formula,
    a tuple of option indices), or None when nothing valid has been entered; entries: the
    parsed values of the other fields by key (for ``env``).
    """
    fld = FIELDS[chk.key]
    if answer is None:
        return Feedback(chk.key, "missing", "no answer yet")
    if fld.kind == "choice":
        chosen = tuple(sorted(answer)) if isinstance(answer, tuple | list) else ()
        if chosen == tuple(sorted(chk.correct)):
            return Feedback(chk.key, "right", f"right: {chk.explain}")
        if fld.multiple and set(chosen) < set(chk.correct):
            return Feedback(chk.key, "wrong", "partly: something else matters too")
        return Feedback(chk.key, "wrong", "not quite; think again", "wrong")
    env: dict[str, float] = {}
    for name, key in chk.env:
        v = entries.get(key)
        if not isinstance(v, float):
            return Feedback(
                chk.key,
                "missing",
                f"enter {FIELDS[key].label} first",
                f"not checked: {FIELDS[key].label} is not entered",
            )
        env[name] = v
    if not isinstance(answer, Formula | float):
        return Feedback(chk.key, "missing", "no answer yet")
    if _same(answer, chk.expected, fld.names, env, chk.rel_tol, chk.abs_tol):
        said = f"{chk.holds}: {chk.explain}" if chk.explain else chk.holds
        grader = said.replace(CONSISTENT, CONSISTENT_GRADER) if chk.holds == CONSISTENT else ""
        return Feedback(chk.key, "right", said, grader)
    if fld.unit == "%" and isinstance(answer, float) and 0 < abs(answer) < 0.01:
        # a share typed as a fraction (0.5 for 50 %): said with the group's own number,
        # never the right one (walk 9, D1: every fraction got "0.63 %: type 63 %")
        typed = answer * 100
        return Feedback(
            chk.key,
            "wrong",
            f"that reads as {typed:.4g} %: did you mean {typed * 100:.4g} %?",
            f"typed as a fraction ({typed:.4g} %)",
        )
    for wrong, message in chk.mistakes:
        if _same(answer, wrong, fld.names, env, chk.rel_tol, chk.abs_tol):
            return Feedback(chk.key, "wrong", message)
    share = _constant(answer) if not fld.unit and not fld.names else None
    if (
        share is not None
        and 1 <= share <= 100
        and _same(share / 100, chk.expected, (), env, chk.rel_tol, chk.abs_tol)
    ):
        # a fraction typed as the per cent (walk 13: '63' for y(T) / (K c) was only "not
        # right yet"), said with the group's own number
        return Feedback(
            chk.key,
            "wrong",
            f"that reads as {share:.4g}: did you mean {share / 100:.4g}, the per cent as a "
            "fraction?",
            f"typed as per cent ({share:.4g})",
        )
    return Feedback(chk.key, "wrong", "not right yet; check your working", "not right")


def _constant(answer: object) -> float | None:
    """The number ``answer`` is when it is one (a float, or a formula of no names); else None."""
    if isinstance(answer, float):
        return answer
    if isinstance(answer, Formula) and not answer.names:
        v = answer.value({})
        return v if math.isfinite(v) else None
    return None


def read_formula(fld: Field, text: str) -> Formula:
    """Parse ``text`` typed in the formula field ``fld`` (FormulaRefused on bad text). The
    answer may begin with the field's own name and ``=``, as the step's text writes it
    (``k_v = (u_ss - R i_ss)/omega_ss``)."""
    m = re.match(rf"\s*{re.escape(fld.label)}\s*=(?!=)", text)
    return parse_formula(text[m.end() :] if m else text, fld.names, label=fld.label)


__all__ = ["check_answer", "read_formula"]
