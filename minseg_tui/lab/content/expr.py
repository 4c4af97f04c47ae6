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
import difflib
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


_TOKEN = re.compile(
    r"""(?P<space>\s+)
    |(?P<number>\d[\d.]*(?:,\d[\d.]*)?(?:[eE][-+]?\d+)?|\.\d[\d.]*)
    |(?P<name>[^\W\d]\w*)
    |(?P<op>\*\*|[-+*/^·×−])
    |(?P<open>\()|(?P<close>\))|(?P<percent>%)|(?P<other>.)""",
    re.VERBOSE,
)
"""The pieces of a typed formula as :func:`formula_fault` reads them (before the
implicit products and the decimal commas are worked out)."""


def _split(name: str, known: tuple[str, ...]) -> list[str] | None:
    """``name`` as known names run together ('Ri_ss' -> R, i_ss), or None."""
    if not name:
        return []
    for k in sorted(known, key=len, reverse=True):
        if name.startswith(k):
            rest = _split(name[len(k) :], known)
            if rest is not None:
                return [k, *rest]
    return None


def _name_hint(name: str, names: tuple[str, ...]) -> str:
    """What an unknown name probably is: allowed names run together (write the product
    with *), or an allowed name misspelt ('' when neither)."""
    known = (*names, *_CONSTS)
    parts = _split(name, known)
    if parts is not None and len(parts) > 1:
        return f" (write products with *: {'*'.join(parts)})"
    close = difflib.get_close_matches(name, names, n=1, cutoff=0.6)
    if not close:  # 'w' for omega, as the lab writes it by hand ('wss': omega_ss)
        short = {n.replace("omega", "w").replace("_", ""): n for n in names}
        close = [short[k]] if (k := name.replace("_", "")) in short else []
    return f" (did you mean {close[0]}?)" if close else ""


def _tail(text: str, most: int = 16) -> str:
    """The end of ``text``, at most ``most`` characters ('…' before it when cut)."""
    return text if len(text) <= most else "…" + text[-most:]


def formula_fault(text: str) -> str | None:
    """The first fault in ``text`` that keeps it from being a formula, in one line that
    names it (an unclosed '(', a ')' with no '(' before it, two operators in a row, an
    operator with nothing before or after it, a number with two decimal points, two
    numbers side by side, a ',' or a character no formula has); None when it finds none
    (the caller then says the text cannot be read)."""
    t = text.strip()
    depth = 0
    prev: tuple[str, str, int] | None = None  # the kind, text and start of the last piece
    for m in _TOKEN.finditer(t):
        kind, piece = m.lastgroup or "other", m.group()
        if kind == "space":
            continue
        before = t[: m.start()].rstrip()
        operand = prev is not None and prev[0] in ("number", "name", "close", "percent")
        if kind == "number" and not re.fullmatch(
            r"(?:\d+(?:[.,]\d*)?|\.\d+)(?:[eE][-+]?\d+)?", piece
        ):
            return f"{piece!r} is not a number: one decimal point at most"
        if kind == "number" and prev is not None and prev[0] == "number":
            return f"two numbers side by side ({prev[1]} {piece}): put an operator between them"
        if kind in ("name", "number") and prev is not None and prev[1] in _FUNCS:
            return f"{prev[1]} takes its argument in parentheses: {prev[1]}(x)"
        if kind == "op" and piece not in "+-−" and not operand:
            if prev is None:
                return f"{piece!r} at the start: something must come before it"
            if prev[0] == "open":
                return f"{piece!r} right after '(': something must come before it"
            return f"two operators in a row ({t[prev[2] : m.end()]!r}): one is too many"
        if kind == "close":
            if prev is not None and prev[0] == "open":
                return "'()' with nothing inside"
            if depth == 0:
                where = f" after {_tail(before)!r}" if before else ""
                return f"the ')'{where} has no '(' left to close"
            if prev is not None and prev[0] == "op":
                return f"nothing between {prev[1]!r} and ')'"
            depth -= 1
        if kind == "open":
            depth += 1
        if kind == "percent" and not (prev is not None and prev[0] == "number"):
            return "'%' goes right after a number (63 %)"
        if kind == "other":
            if piece == ",":
                return "a ',' outside a number: a decimal comma goes between digits (5,3)"
            if piece == "=":
                return "an '=' in the formula: type only what comes after it"
            return f"{piece!r} has no place in a formula (numbers, names, + - * / ^ and ( ))"
        prev = (kind, piece, m.start())
    if prev is not None and prev[0] == "op":
        return f"{prev[1]!r} at the end: something must come after it"
    if depth == 1:
        return "a '(' is not closed: add the ')'"
    if depth > 1:
        return f"{depth} '(' are not closed: add {depth} ')'"
    return None


def _unknown_names(tree: ast.AST, names: tuple[str, ...]) -> list[str]:
    """The names in ``tree`` that are neither ``names`` nor a constant or function the
    formulas know, each once, in the order they stand in the text (a name called as a
    function is not one: the call is refused as a call)."""
    called = {id(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
    found = sorted(
        (n for n in ast.walk(tree) if isinstance(n, ast.Name) and id(n) not in called),
        key=lambda n: (n.lineno, n.col_offset),
    )
    return list(
        dict.fromkeys(
            n.id for n in found if n.id not in names and n.id not in _CONSTS and n.id not in _FUNCS
        )
    )


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
        fault = formula_fault(text)
        raise FormulaRefused(
            label, None, fault or f"{text.strip()!r} cannot be read; expected {allowed}"
        ) from None
    unknown = _unknown_names(tree, names)
    if unknown:  # every one at once, as typed (walk 14, D6: one refusal for each, the last first)
        said = ", ".join(f"{n!r}{_name_hint(n, names)}" for n in unknown)
        many = "names" if len(unknown) > 1 else "name"
        raise FormulaRefused(label, None, f"unknown {many} {said}; expected {allowed}")
    used: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
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
            fault = formula_fault(text)
            raise FormulaRefused(
                label, None, fault or f"{text.strip()!r} is not a formula; expected {allowed}"
            )
    for node in ast.walk(tree):
        if isinstance(node, ast.BinOp) and not isinstance(
            node.op, ast.Add | ast.Sub | ast.Mult | ast.Div | ast.Pow
        ):
            fault = formula_fault(text)
            raise FormulaRefused(
                label, None, fault or f"only + - * / ^ are allowed; expected {allowed}"
            )
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
