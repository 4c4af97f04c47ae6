"""Task 14's answer: the motor model a group writes, read into its T and K.

The step asks for T omega' = -omega + K u_A with numbers. A group writes it in many ways
that all mean the same first-order model: ``0.043 omega' = -omega + 1.9 u_A``,
``0,043 ω' + ω = 1,9 u``, ``omega' = -omega/0.043 + 44 u_A``, ``0.043 dw/dt + w = 1.9 u``.
:func:`read_model` reads any linear equation in the speed's derivative, the speed and the
voltage (numbers and arithmetic as :mod:`minseg_tui.lab.content.expr` reads them) and brings
it to that form: T (s) and K (rad/s/V). A text that is no such model is refused with one
line saying what is expected. Pure functions.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from minseg_tui.errors import InputError
from minseg_tui.lab.content.expr import FormulaRefused, parse_formula

EXPECTED = "expected the model with numbers, as T omega' = -omega + K u_A (e.g. 0.5 omega' = -omega + 12 u_A)"
"""What a model answer must look like (the example is no motor's answer)."""

_DERIVATIVE = re.compile(
    r"d\s*(?:omega|w|y)\s*(?:\(t\))?\s*/\s*dt|(?<![\w.])(?:omega|w|y)\s*(?:'|_dot\b|dot\b|\u0307)",
    re.IGNORECASE,
)
_SPEED = re.compile(r"(?<![\w.])(?:omega|w|y)(?![\w'])", re.IGNORECASE)
_VOLTAGE = re.compile(r"(?<![\w.])u(?:_?a)?(?![\w'])", re.IGNORECASE)


@dataclass(frozen=True)
class ModelAnswer:
    """A model read as T omega' = -omega + K u_A: T (s) and K (rad/s/V)."""

    T: float
    K: float


class ModelUnreadable(FormulaRefused):
    """A model text that cannot be read as an equation at all (nothing typed, not one '=',
    a side that is no formula, T or K left as letters): refused as the entry is typed, the
    text kept to mend, as any other entry that cannot be read. An equation that is read but
    is no first-order model (no omega' term, not linear, T < 0) is :class:`FormulaRefused`
    only: an answer, and a wrong one."""


def _refuse(why: str) -> FormulaRefused:
    return FormulaRefused("your model", None, f"{why}; {EXPECTED}")


def _unreadable(why: str) -> ModelUnreadable:
    return ModelUnreadable("your model", None, f"{why}; {EXPECTED}")


def read_model(text: str) -> ModelAnswer:
    """The T (s) and K (rad/s/V) of the first-order model written in ``text``.

    FormulaRefused (one line) when it is not one equation, linear in omega', omega and u_A,
    with an omega' term, an omega term and a u_A term, and T > 0; :class:`ModelUnreadable`
    when it cannot be read as an equation at all."""
    t = text.strip().replace("ω", "omega").replace("\u2032", "'").replace("−", "-")
    t = re.sub(r"\(t\)", "", t)
    if not t:
        raise _unreadable("nothing typed")
    sides = t.split("=")
    if len(sides) != 2:
        raise _unreadable("one equation with one '=' is needed")
    parts = []
    for side in sides:
        s = _DERIVATIVE.sub(" D ", side)
        s = _SPEED.sub(" W ", s)
        s = _VOLTAGE.sub(" U ", s)
        try:
            parts.append(parse_formula(s, ("D", "W", "U")))
        except InputError as exc:
            if re.search(r"unknown names? [^;]*'(T|K)'", str(exc)):
                raise _unreadable("put the numbers in for T and K") from None
            raise _unreadable(f"{side.strip()!r} cannot be read") from None
    left, right = parts

    def g(d: float, w: float, u: float) -> float:
        env = {"D": d, "W": w, "U": u}
        return left.value(env) - right.value(env)

    c0 = g(0, 0, 0)
    a, b, c = (g(1, 0, 0) - c0, g(0, 1, 0) - c0, g(0, 0, 1) - c0)
    coeffs = (c0, a, b, c)
    if not all(math.isfinite(x) for x in coeffs):
        raise _refuse("its numbers cannot be worked out")
    scale = max(abs(a), abs(b), abs(c), 1e-300)
    for d, w, u in ((2.0, 3.0, 5.0), (-1.5, 0.7, 2.5)):
        if abs(g(d, w, u) - (c0 + a * d + b * w + c * u)) > 1e-9 * scale * 10:
            raise _refuse("it is not linear in omega', omega and u_A")
    if abs(c0) > 1e-9 * scale:
        raise _refuse("it has a constant term that is in no first-order model")
    if a == 0:
        raise _refuse("there is no omega' term: the model must say how fast omega changes")
    if b == 0:
        raise _refuse("there is no omega term")
    if c == 0:
        raise _refuse("there is no u_A term")
    T, K = a / b, -c / b
    if T <= 0:
        raise _refuse(f"it gives T = {T:.3g} s, and a time constant is positive (check the signs)")
    return ModelAnswer(T, K)


__all__ = ["EXPECTED", "ModelAnswer", "ModelUnreadable", "read_model"]
