"""Formulas a student types as answers (``(u_ss - R*i_ss)/omega_ss``, ``2*pi/720``), read safely.

Only numbers, the names a question allows, ``pi``, ``e``, the functions ``exp``, ``ln``,
``log``, ``sqrt``, ``+ - * / ^ **`` and parentheses are accepted; nothing is executed.
``^`` is a power, ``,`` is a decimal comma inside numbers, ``·``/``×`` are products, and a
number written against a name or a parenthesis multiplies it (``2pi``, ``2(a+b)``), and so
do names written apart, the way the lab's own text writes products (``R i_ss``,
``T (R f + k_v k_a)``). Two names run together (``Kc``) are not a product: write ``K*c``.
"""

from __future__ import annotations

import ast
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from minseg_tui.errors import InputError

_FUNCS: dict[str, Callable[[float], float]] = {
    "exp": math.exp,
    "ln": math.log,
    "log": math.log,
    "sqrt": math.sqrt,
}
_CONSTS = {"pi": math.pi, "π": math.pi, "e": math.e}


class FormulaRefused(InputError):
    """A formula that cannot be read; ``str()`` is the one-line message."""


@dataclass(frozen=True)
class Formula:
    """A parsed formula: the text as typed and its syntax tree (evaluate with :meth:`value`)."""

    text: str
    tree: ast.Expression
    names: frozenset[str]

    def value(self, env: Mapping[str, float]) -> float:
        """The formula's value with the names bound by ``env``; nan when it cannot be computed."""
        try:
            return float(_eval(self.tree.body, env))
        except (ZeroDivisionError, OverflowError, ValueError):
            return math.nan


_ALIAS = re.compile(r"(?<![\w.])(?:w|omega)(?:_\w+)?(?!\w)")
"""A name that may be omega written otherwise: ``w_ss``, ``w``, ``omega`` (ω was spelt
out before)."""


def _alias(name: str, names: tuple[str, ...]) -> str:
    """The allowed name ``name`` stands for when it is not one itself: omega spelt ``w``
    (``w_ss`` is omega_ss), or ``w``/``omega`` alone for the one allowed omega name
    (omega_ss in Preparation 11); else ``name`` unchanged."""
    if name in names:
        return name
    spelt = "omega" + name[1:] if name.startswith("w") else name
    if spelt in names:
        return spelt
    omegas = [n for n in names if n.startswith("omega")]
    return omegas[0] if spelt == "omega" and len(omegas) == 1 else name


def _prepare(text: str, names: tuple[str, ...] = ()) -> str:
    t = (
        text.strip()
        .replace("·", "*")
        .replace("×", "*")
        .replace("−", "-")
        .replace("π", "pi")
        .replace("ω", "omega")
    )
    t = _ALIAS.sub(lambda m: _alias(m.group(0), names), t)
    t = re.sub(r"(?<=\d),(?=\d)", ".", t)
    # a percentage: a number with % and nothing after it to take the remainder by (63 %)
    t = re.sub(r"(\d+(?:\.\d*)?|\.\d+)\s*%(?!\s*[\w(.])", r"(\1/100)", t)
    t = t.replace("^", "**")
    # implicit product: a number directly followed by a name or '(' (but not an exponent)
    t = re.sub(r"(\d\.?)(?![eE][-+]?\d)\s*(?=[A-Za-z_(])", r"\1*", t)
    t = re.sub(r"\)\s*(?=[A-Za-z_(\d])", ")*", t)

    # implicit product: a name (not a function) followed by a space and a name, a number or
    # '(', or, when it is one of the allowed names, directly by '(' (R i_ss, k_v k_a, T (R f),
    # T(R f))
    def times(m: re.Match[str]) -> str:
        name = m.group(1)
        apart = m.group(0) != name
        if name in _FUNCS or not (apart or name in names or name in _CONSTS):
            return m.group(0)
        return name + "*"

    return _NAME_APART.sub(times, t)


_NAME_APART = re.compile(r"(?<![\w.])([A-Za-z_]\w*)(?:\s+(?=[A-Za-z_(\d.])|(?=\())")


def parse_formula(text: str, names: tuple[str, ...] = (), label: str = "") -> Formula:
    """Read ``text`` as a formula in ``names``; raise :class:`FormulaRefused` with one line."""
    allowed = (
        f"a number or a formula in {', '.join(names)}"
        if names
        else "a number or a formula (pi, e, exp, sqrt allowed)"
    )
    if not text or not text.strip():
        raise FormulaRefused(label, None, f"nothing typed; expected {allowed}")
    try:
        tree = ast.parse(_prepare(text, names), mode="eval")
    except SyntaxError:
        raise FormulaRefused(
            label,
            None,
            f"{text.strip()!r} cannot be read; expected {allowed} (write products with *)",
        ) from None
    used: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if node.id not in names and node.id not in _CONSTS and node.id not in _FUNCS:
                hint = " (write products with *, e.g. K*c)" if len(node.id) > 1 else ""
                raise FormulaRefused(
                    label, None, f"unknown name {node.id!r}{hint}; expected {allowed}"
                )
            if node.id in names:
                used.add(node.id)
        elif isinstance(node, ast.Call):
            if (
                not isinstance(node.func, ast.Name)
                or node.func.id not in _FUNCS
                or len(node.args) != 1
                or node.keywords
            ):
                raise FormulaRefused(
                    label, None, f"only exp(x), ln(x), sqrt(x) may be called; expected {allowed}"
                )
        elif isinstance(node, ast.Constant):
            if not isinstance(node.value, int | float) or isinstance(node.value, bool):
                raise FormulaRefused(
                    label,
                    None,
                    f"{text.strip()!r} holds something that is not a number; expected {allowed}",
                )
        elif not isinstance(
            node, ast.Expression | ast.BinOp | ast.UnaryOp | ast.Load | ast.operator | ast.unaryop
        ):
            raise FormulaRefused(
                label, None, f"{text.strip()!r} is not a formula; expected {allowed}"
            )
    for node in ast.walk(tree):
        if isinstance(node, ast.BinOp) and not isinstance(
            node.op, ast.Add | ast.Sub | ast.Mult | ast.Div | ast.Pow
        ):
            raise FormulaRefused(label, None, f"only + - * / ^ are allowed; expected {allowed}")
    formula = Formula(text=text.strip(), tree=tree, names=frozenset(used))
    if not names and not math.isfinite(formula.value({})):
        raise FormulaRefused(
            label, None, f"{text.strip()!r} is not a finite number; expected {allowed}"
        )
    return formula


def _eval(node: ast.AST, env: Mapping[str, float]) -> float:
    if isinstance(node, ast.Constant):
        assert isinstance(node.value, int | float)  # the parser lets no other constant in
        return float(node.value)
    if isinstance(node, ast.Name):
        if node.id in env:
            return float(env[node.id])
        if node.id in _CONSTS:
            return _CONSTS[node.id]
        raise ValueError(node.id)
    if isinstance(node, ast.UnaryOp):
        v = _eval(node.operand, env)
        return -v if isinstance(node.op, ast.USub) else v
    if isinstance(node, ast.Call):
        assert isinstance(node.func, ast.Name)
        return _FUNCS[node.func.id](_eval(node.args[0], env))
    if isinstance(node, ast.BinOp):
        a, b = _eval(node.left, env), _eval(node.right, env)
        if isinstance(node.op, ast.Add):
            return a + b
        if isinstance(node.op, ast.Sub):
            return a - b
        if isinstance(node.op, ast.Mult):
            return a * b
        if isinstance(node.op, ast.Div):
            return a / b
        if abs(b) > 64 or abs(a) > 1e100:
            raise OverflowError
        r = a**b
        if isinstance(r, complex):
            raise ValueError("complex power")
        return float(r)
    raise ValueError("not a formula")
