"""The group's own values of Tasks 11-15 first, then fair comparisons.

The instructor's policy for a lab (:func:`read_policy`, ``lab.toml`` in the sessions folder)
says whether the group enters its own value before the program shows the computed one;
:func:`concealed` says which values are still hidden. :func:`compare_fields` sets each of the
group's values beside the value computed the group's way (K from their omega_ss and u_ss, J
from their own T or from the 63 % reading, ...), with the least-squares value and one
sentence on why the two differ (a relative difference written by
:func:`minseg_tui.quantities.format_diff`). Pure
functions apart from reading the policy file; no Textual. Units: SI (V, rad/s, s, kg m^2).
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable, Collection, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from minseg_tui.errors import InputError
from minseg_tui.lab.content.model_eq import read_model
from minseg_tui.lab.content.steps import Field
from minseg_tui.lab.saving.kept import ResponseFigures
from minseg_tui.lab.state.results import Comparison, Results
from minseg_tui.model.identify import U_TASK15, ResponseResult
from minseg_tui.model.motor import inertia_from_time_constant
from minseg_tui.quantities import (
    format_constant,
    format_diff,
    format_number,
    format_percent,
    format_quantity,
    format_reading,
    format_typed,
    shown_unit,
)

POLICY_FILE = "lab.toml"
"""The instructor's settings for every session in a sessions folder (beside the sessions)."""

ANSWERED_FIRST: tuple[str, ...] = (
    "own.omega_step",
    "own.K",
    "own.T",
    "own.J",
    "own.model",
    "own.omega_5",
)
"""The fields of Tasks 11-15 the group answers before the computed value is shown."""

REVEALED_EARLY = "revealed before answering"
"""Said of a computed value a lab assistant showed before the group answered (the TUI's
comparisons and the report)."""


@dataclass(frozen=True)
class Policy:
    """The lab's policy: ``answers_first`` (the group's own value before the computed one);
    ``problem``: one line when the policy file could not be read (the default then holds);
    ``file``: whether there was a policy file at all (no file: the default)."""

    answers_first: bool = True
    problem: str = ""
    file: bool = False


def read_policy(sessions: Path) -> Policy:
    """The policy in ``sessions``/lab.toml (``answers_first = true|false``); answers first
    when there is no file, or when it cannot be read (then ``problem`` says why)."""
    path = Path(sessions) / POLICY_FILE
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return Policy()
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        return Policy(True, f"{path}: cannot be read ({exc}); answers first", file=True)
    value = data.get("answers_first", True)
    if not isinstance(value, bool):
        return Policy(
            True,
            f"{path}: answers_first must be true or false, got {value!r}; answers first",
            file=True,
        )
    return Policy(value, file=True)


def concealed(policy: Policy, answered: Collection[str], revealed: Collection[str]) -> set[str]:
    """The fields of :data:`ANSWERED_FIRST` whose computed value is still hidden: not
    answered by the group and not revealed by a lab assistant (none when the policy lets the
    program show everything)."""
    if not policy.answers_first:
        return set()
    return {k for k in ANSWERED_FIRST if k not in answered and k not in revealed}


def _ms(T: float) -> str:
    return format_constant(T, "s")


def format_u_ss(st: ResponseResult | ResponseFigures) -> str:
    """The u_ss a step's K divides by: the table's row as typed there ("4,05" is "4.05 V",
    never "4.050 V"), or, interpolated between rows, a computed number with its digits (the
    numbers a session file keeps do not say which: as a reading)."""
    if not isinstance(st, ResponseResult) or st.u_ss_how == "row":
        return format_reading(st.u_ss, "V")
    return format_quantity(st.u_ss, "V")


def _model(T: str, K: str) -> str:
    """The model with T (s) and K (rad/s/V) as written: the program's with its digits, the
    group's as they typed them."""
    return f"{T} omega' = -omega + {K} u_A"


def _theirs(whose: str, name: str) -> str:
    """The group's value of ``name`` standing alone: "yours", or "the group's K"."""
    return "yours" if whose == "your" else f"{whose} {name}"


READ_63 = (
    "the program's reading by {whose} method: 63 % of each rise of this run, median over the rises"
)
"""What the T the group's is compared with is (``whose``: "your" or "the group's"): the
program's own 63 % reading of the run, read the group's way, not computed from their values."""


def two_T(T: float, T_63: float | None, whose: str = "your", dead_time: float = 0.0) -> str:
    """The one sentence on the two readings of T, the same on the screen and in the report
    (and from the numbers a session file keeps, which it needs no more of): both are fair,
    the group's T is graded against the 63 % reading ``T_63`` (s; None: no rise crossed
    63 %), the model and its J use the least-squares ``T`` (s), and why the two differ (the
    sampling; the model's ``dead_time``, s, too). ``whose``: "your" (the screen) or "the
    group's" (the report)."""
    uses = f"the least-squares T ({_ms(T)}) is the one the program's model and its J use"
    if T_63 is None:
        return (
            f"No rise of this run crossed 63 % of its step, so there is no 63 % reading for "
            f"{_theirs(whose, 'T')} to be graded against; {uses}."
        )
    apart = T_63 - T
    dead = (
        f"counts from the logged step, so it holds the dead time of {_ms(dead_time)} that the "
        "model keeps apart from T, and it "
        if dead_time > 0
        else ""
    )
    return (
        f"Both are fair readings of T: the 63 % reading ({_ms(T_63)}), the manual's way, is "
        f"the one {_theirs(whose, 'T')} is graded against, and {uses}; the 63 % reading "
        f"{dead}is read off the logged samples, which move it (each logged speed is the mean "
        "over its sample interval, half a sample late, and the reading joins the samples by "
        f"straight lines): here it is {_ms(abs(apart))} "
        f"{'longer' if apart >= 0 else 'shorter'}, while the least-squares fit models the "
        "sampling, so its T describes the motor."
    )


def two_T_of(step: ResponseResult, whose: str = "your") -> str:
    """:func:`two_T` of a step result."""
    return two_T(step.T, step.T_63, whose, step.dead_time)


def compare_fields(
    fields: Iterable[Field],
    value: Callable[[str], float | None],
    text: Callable[[str], str | None],
    res: Results,
    revealed: Collection[str] = (),
    reading: Callable[[str], str | None] | None = None,
    whose: str = "your",
) -> list[Comparison]:
    """Each field with ``compare`` beside the value computed the group's way.

    value(key): the group's number for a field (SI) or None; text(key): its text (a model)
    or None; ``res``: the session's results; ``revealed``: fields shown before the group
    answered (said in the comparison); reading(key): the group's value as they typed it,
    with its unit ("57 ms"), wherever a text quotes it (default: the number in SI units with
    the digits it has); ``whose``: the group's values as the texts name them, "your" on the
    group's screen, "the group's" in the report an instructor reads."""

    def typed(key: str, si: float, unit: str) -> str:
        said = reading(key) if reading is not None else None
        return said if said is not None else format_reading(si, unit)

    ident = res.identification
    st = res.step if ident is not None else None
    # true of both of the fit's ways (the whole log, or each rise; the report's "How T was
    # fitted" says which), and of the numbers the session file keeps, which do not say
    span = "whole stretches of the run"
    own_T = value("own.T")
    own_K = value("own.K")
    own_w = value("own.omega_step")
    out: list[Comparison] = []
    for fld in fields:
        if not fld.compare:
            continue
        T_used: float | None = None
        own: float | str | None = text(fld.key) if fld.kind == "text" else value(fld.key)
        computed: float | str | None = res.lookup(fld.compare)
        how = why = verdict = ""
        right: bool | None = None
        lsq: float | str | None = None
        if st is not None and ident is not None:
            if fld.key == "own.K":
                lsq = st.K
                if own_w is not None and st.u_ss:
                    computed = own_w / st.u_ss
                    how = (
                        f"{whose} omega_ss / u_ss = {typed('own.omega_step', own_w, 'rad/s')} ÷ "
                        f"{format_u_ss(st)}"
                    )
                    why = (
                        "The least-squares K is the median over every rise of the fitted "
                        f"steady speed over u_ss; {_theirs(whose, 'K')} is one reading of it over u_ss."
                    )
                else:
                    computed, lsq = st.K, None
            elif fld.key == "own.T":
                computed, lsq = st.T_63, st.T
                how = READ_63.format(whose=whose)
                why = two_T(st.T, st.T_63, whose, st.dead_time)
            elif fld.key == "own.J":
                T_used, how = (
                    (own_T, f"from {whose} T = {typed('own.T', own_T, 's')}")
                    if own_T is not None
                    else (st.T_63, "from the program's 63 % reading T = " + _ms(st.T_63))
                    if st.T_63 is not None
                    else (None, "")
                )
                lsq = st.J
                if T_used is not None:
                    computed = inertia_from_time_constant(
                        T_used, ident.R, ident.f, ident.k_v, ident.k_a
                    )
                    why = (
                        f"The least-squares J uses T = {_ms(st.T)} fitted over {span}; "
                        "J grows in proportion to T, so the two differ as the two T do."
                    )
                else:
                    computed, lsq, how = st.J, None, ""
            elif fld.key == "own.model":
                T_m = own_T if own_T is not None else st.T_63
                K_m = own_K if own_K is not None else st.K
                lsq = _model(format_number(st.T), format_number(st.K))
                if T_m is not None:
                    computed = _model(
                        format_typed(T_m) if own_T is not None else format_number(T_m),
                        format_typed(K_m) if own_K is not None else format_number(K_m),
                    )
                    how = (
                        f"with {whose} T and K"
                        if own_T is not None and own_K is not None
                        else "with "
                        + (f"{whose} T" if own_T is not None else "the program's 63 % reading T")
                        + " and "
                        + (f"{whose} K" if own_K is not None else "the least-squares K")
                    )
                    why = "The least-squares model uses the fitted T and K."
                    if _model(format_number(T_m), format_number(K_m)) == lsq:
                        lsq, why = None, ""
                    if isinstance(own, str):
                        right, verdict = judge_model(own, T_m, K_m)
            elif fld.key == "own.omega_5":
                lsq = st.K * U_TASK15
                if own_K is not None:
                    computed = own_K * U_TASK15
                    how = f"5 V × {whose} K = {typed('own.K', own_K, 'rad/s/V')}"
                    why = "The least-squares value uses the K fitted over every rise."
                else:
                    lsq = None
        rel = None
        if isinstance(own, float) and isinstance(computed, float) and computed != 0:
            rel = own / computed - 1.0
        tol = TOLERANCE.get(fld.key)
        if rel is not None and tol is not None and right is None:
            right = abs(rel) <= tol
            if not right:
                verdict = f"wrong: more than the {format_percent(tol)} off that reading or rounding explains"
                if fld.key == "own.J" and ident and T_used is not None and isinstance(own, float):
                    verdict += _j_slip(own, T_used, ident.R, ident.f, ident.k_v, ident.k_a)
        if isinstance(lsq, float) and not math.isfinite(lsq):
            lsq = None
        out.append(
            Comparison(
                fld.key,
                fld.label,
                fld.unit,
                own,
                computed,
                rel,
                how=how,
                least_squares=lsq,
                why=why,
                revealed_early=fld.key in revealed,
                right=right,
                verdict=verdict,
            )
        )
    return out


TOLERANCE: dict[str, float] = {
    "own.k_v": 0.10,
    "own.k_a": 0.10,
    "own.f": 0.10,
    "own.omega_step": 0.15,
    "own.K": 0.10,
    "own.T": 0.30,
    "own.J": 0.10,
    "own.omega_5": 0.10,
}
"""How far (relative) each of the group's numbers may be from the value computed their way
and still be right (farther: marked wrong, ✗ in the list of steps). Measured over 300 seeded
sessions of the virtual board's plant (``benchmarks/grading_tolerances.py``: an honest group
reading with the program's cursor, typing 3 significant digits):

- a value worked out from their own readings (k_v, k_a, f from their table, K from their
  omega_ss, J from their T, omega at 5 V from their K) differs by rounding: at most 0.6 %,
  7.6 % for f taken as the mean of the rows instead of their median: 10 %;
- omega_ss read off one rise (the sample at its end) against the median over the rises of
  the fitted steady speed: p95 3.5 %, max 4.6 %; 15 % leaves room for a real motor's noise;
- T read at 63 % of one rise on the sample nearest the level (25 ms apart) against the
  program's reading interpolated between samples, median over the rises: p95 21 %, max
  27 % (25 % marked one session in 300 wrong): 30 %. Read on the line between the samples
  (the cursor between them) it is at most 12 %; a group that takes the first sample past the
  level is late by up to a sample, up to +57 %, and is marked wrong."""


def _j_slip(own: float, T: float, R: float, f: float, k_v: float, k_a: float) -> str:
    """Task 13: the usual slip behind a J that is wrong (``own``, kg m^2, against ``T`` s,
    ``R`` ohm, ``f`` N m s/rad, ``k_v`` V s/rad, ``k_a`` N m/A), as a clause: f put in the
    formula in mN m s/rad (as the table shows it), or T in ms; '' when neither explains it."""
    slips = (
        (f * 1e3, T, "; f goes into this formula in N m s/rad (the table shows mN m s/rad)"),
        (f, T * 1e3, "; T goes into this formula in s, not ms"),
    )
    for f_slip, T_slip, said in slips:
        J = inertia_from_time_constant(T_slip, R, f_slip, k_v, k_a)
        if J and abs(own / J - 1.0) <= TOLERANCE["own.J"]:
            return said
    return ""


MODEL_TOLERANCE = 0.10
"""How far (relative) the T and the K of a group's model may be from the ones computed
their way and still be right: their own readings rounded, or read off the plot."""


def judge_model(text: str, T: float, K: float) -> tuple[bool, str]:
    """Task 14: whether the model in ``text`` is T omega' = -omega + K u_A with the ``T`` (s)
    and ``K`` (rad/s/V) computed the group's way (each within :data:`MODEL_TOLERANCE`), and
    one line saying so (what is wrong, when it is); the group's T and K with the digits
    they typed, T in ms as everywhere it is shown ("0,057" is "57 ms", never "0.05700 s")."""
    try:
        got = read_model(text)
    except InputError as exc:
        return False, f"not the model: {exc.expected}"
    wrong = []
    for name, mine, want, unit in (("T", got.T, T, "s"), ("K", got.K, K, "rad/s/V")):
        if want and abs(mine / want - 1.0) > MODEL_TOLERANCE:
            wrong.append(
                f"{name} = {format_reading(mine, shown_unit(unit))} where "
                f"{format_constant(want, unit)} "
                f"was expected ({format_diff(mine / want - 1.0)})"
            )
    if wrong:
        return False, "wrong: " + "; ".join(wrong)
    return True, (
        f"right: T = {format_reading(got.T, 'ms')} and K = {format_reading(got.K, 'rad/s/V')}"
    )


def reveal_keys(fields: Sequence[Field], answered: Collection[str]) -> list[str]:
    """The fields of a step a lab assistant's reveal marks as "revealed before answering":
    those of :data:`ANSWERED_FIRST` the group has not answered yet."""
    return [f.key for f in fields if f.key in ANSWERED_FIRST and f.key not in answered]


__all__ = [
    "ANSWERED_FIRST",
    "TOLERANCE",
    "POLICY_FILE",
    "READ_63",
    "REVEALED_EARLY",
    "Policy",
    "compare_fields",
    "concealed",
    "two_T",
    "two_T_of",
    "format_u_ss",
    "judge_model",
    "read_policy",
    "reveal_keys",
]
