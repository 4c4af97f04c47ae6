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

import json
import math
import re
import tomllib
from collections.abc import Callable, Collection, Iterable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from minseg_tui.errors import InputError
from minseg_tui.lab.content import needs as lab_needs
from minseg_tui.lab.content.model_eq import read_model
from minseg_tui.lab.content.steps import FIELDS, Field, RunPlan
from minseg_tui.lab.saving.kept import ResponseFigures
from minseg_tui.lab.saving.store import read_regular
from minseg_tui.lab.state.results import Comparison, Results, response_figures
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
from minseg_tui.units import KA_OVER_KV

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

STEP_LEVEL: float = RunPlan().high
"""The requested voltage of Task 10's steps (V): the table row whose u_ss K divides by."""

SLIP: float = 0.01
"""How close (relative) a group's value must come to the value a named slip gives to be
called that slip (:func:`_is_slip`): 3 significant digits round by at most 0.6 %, and a
value is called a slip only when it is also nearer the slip than the right value."""


J_WAITS = (
    "J needs R, k_v and f from the table of Tasks 2-9, and the table gives none yet (see "
    "why under the results); the run alone gives omega_ss, K and T"
)
"""Why J is not judged while the table cannot give Tasks 6-9 but the run gives Tasks 11-12."""


def j_waits(has: Callable[[str], bool] | None, whose: str = "your") -> str:
    """Why J is not judged while the table gives no k_v, k_a and f but the run gives Tasks
    11-12, from the one table of inputs: 'J needs R (Task 2); the run alone gives omega_ss,
    K and T' (:data:`J_WAITS` when ``has`` is None or every input is there, the table
    failing for another reason)."""
    said = lab_needs.needs(lab_needs.missing("J", has), whose) if has is not None else ""
    return f"J {said}; the run alone gives omega_ss, K and T" if said else J_WAITS


def _is_slip(own: float, slip: float, right: float) -> bool:
    """Whether ``own`` is the value a slip gives (``slip``) rather than the ``right`` one:
    within :data:`SLIP` of it and nearer to it than to ``right``."""
    if not (slip and right and math.isfinite(slip) and math.isfinite(right)):
        return False
    off = abs(own / slip - 1.0)
    return off <= SLIP and off < abs(own / right - 1.0)


def K_by_request(own_K: float, omega: float, u_ss: float) -> bool:
    """Whether a group's K (rad/s/V) is its omega_ss (rad/s) divided by the step's requested
    :data:`STEP_LEVEL` (V) rather than by the measured ``u_ss`` (V) the task asks for: the
    slip Task 11 names, within :data:`SLIP` of it and nearer to it than to the right K."""
    if not (u_ss and omega):
        return False
    return _is_slip(own_K, omega / STEP_LEVEL, omega / u_ss)


def u_ss_missing(level: float = STEP_LEVEL) -> str:
    """Why K is not judged while the group's u_ss at ``level`` (V) is not entered."""
    return (
        f"u_ss at {level:g} V is not entered (Task 4); K divides by it, so K is judged once "
        "it is there"
    )


@dataclass(frozen=True)
class Policy:
    """The lab's policy: ``answers_first`` (the group's own value before the computed one);
    ``problem``: one line when the policy file could not be read (the default then holds);
    ``file``: whether there was a policy file at all (no file: the default)."""

    answers_first: bool = True
    problem: str = ""
    file: bool = False


POLICY_KEYS = ("answers_first",)
"""The settings ``lab.toml`` may hold; any other name (a typo, a section) is reported, not
silently passed over."""

MAX_POLICY_BYTES = 64 << 10
"""The largest policy file read (a few lines are expected)."""


def _as_toml(value: object) -> str:
    """``value`` as lab.toml spells it ("false" in quotes, [false], 0), not as Python does
    ('false', [False]; s38 attack); a date or a table as Python gives it."""
    try:
        return json.dumps(value, ensure_ascii=False)
    except (TypeError, ValueError):
        return str(value)


def read_policy(sessions: Path) -> Policy:
    """The policy in ``sessions``/lab.toml (``answers_first = true|false``); answers first
    when there is no file, or when it cannot be read, or holds a name other than
    :data:`POLICY_KEYS` (then ``problem`` says why). A byte-order mark (Notepad's UTF-8) is
    allowed; a FIFO or a device in its place is refused, never waited on."""
    path = Path(sessions) / POLICY_FILE

    def problem(why: str) -> Policy:
        return Policy(True, f"{path}: {why}; answers first", file=True)

    try:
        raw = read_regular(path, MAX_POLICY_BYTES)
    except FileNotFoundError:
        if path.is_symlink():
            return problem("cannot be read (a link to a file that does not exist)")
        return Policy()
    except OSError as exc:
        return problem(f"cannot be read ({exc.strerror or type(exc).__name__})")
    if len(raw) > MAX_POLICY_BYTES:
        return problem(f"is larger than a policy file ({MAX_POLICY_BYTES >> 10} KiB)")
    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        return problem("cannot be read (not UTF-8 text)")
    except tomllib.TOMLDecodeError as exc:
        return problem(f"cannot be read ({exc})")
    unknown = [k for k in data if k not in POLICY_KEYS]
    if unknown:
        names = ", ".join(repr(k) for k in unknown)
        return problem(f"unknown setting {names}, expected only answers_first = true or false")
    value = data.get("answers_first", True)
    if not isinstance(value, bool):
        return problem(f"answers_first must be true or false, got {_as_toml(value)}")
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


def format_u_ss(st: ResponseResult | ResponseFigures, typed: str = "") -> str:
    """The u_ss a step's K divides by: the table's row as typed there, ``typed`` the text
    of the row of :data:`STEP_LEVEL` ("4,05" is "4.05 V", never "4.050 V"; "4,0" is
    "4.0 V", never "4 V"), or, interpolated between rows, a computed number with its digits
    (the numbers a session file keeps do not say which: as a reading)."""
    if not isinstance(st, ResponseResult) or st.u_ss_how == "row":
        return format_reading(st.u_ss, "V", typed=typed)
    return format_quantity(st.u_ss, "V")


def model_text(T: str, K: str) -> str:
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


SPEED_ONLY: frozenset[str] = frozenset({"own.omega_step", "own.T"})
"""The group's values whose computed ones need only the run's speed, no u_ss (walk 18, D4):
compared with :attr:`~minseg_tui.lab.state.results.Results.speed_only` when the table has
no u_ss yet."""


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
    has: Callable[[str], bool] | None = None,
) -> list[Comparison]:
    """Each field with ``compare`` beside the value computed the group's way.

    value(key): the group's number for a field (SI) or None; text(key): its text (a model)
    or None; ``res``: the session's results; ``revealed``: fields shown before the group
    answered (said in the comparison); reading(key): the group's value as they typed it,
    with its unit ("57 ms"), wherever a text quotes it (default: the number in SI units with
    the digits it has); ``whose``: the group's values as the texts name them, "your" on the
    group's screen, "the group's" in the report an instructor reads; has(name): whether the
    session has input ``name`` of :data:`~minseg_tui.lab.content.needs.INPUTS`, for what a
    value not computed waits for (default: not said)."""

    def typed(key: str, si: float, unit: str) -> str:
        said = reading(key) if reading is not None else None
        return said if said is not None else format_reading(si, unit)

    ident = res.identification
    st = res.step
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
        st = res.step
        if st is None and fld.key in SPEED_ONLY and res.speed_only is not None:
            st = response_figures(res.speed_only)  # T needs only the speed (walk 18, D4)
        T_used: float | None = None
        own: float | str | None = text(fld.key) if fld.kind == "text" else value(fld.key)
        computed: float | str | None = res.lookup(fld.compare)
        if computed is None and st is not None and fld.compare.startswith("step."):
            got = getattr(st, fld.compare.removeprefix("step."), None)  # the run alone
            computed = float(got) if isinstance(got, float) else None
        how = why = verdict = ""
        right: bool | None = None
        lsq: float | str | None = None
        if st is not None:
            if fld.key == "own.K":
                lsq = st.K
                u_key = f"u_ss@{STEP_LEVEL:g}"
                u_row = value(u_key)
                if u_row is None:
                    # K would divide by a u_ss the group never gave (extrapolated): not judged
                    computed, lsq, verdict = None, None, u_ss_missing()
                elif own_w is not None and u_row:
                    computed = own_w / u_row
                    how = (
                        f"{whose} omega_ss / u_ss = {typed('own.omega_step', own_w, 'rad/s')} ÷ "
                        f"{typed(u_key, u_row, 'V')}"
                    )
                    why = (
                        "The least-squares K is the median over every rise of the fitted "
                        f"steady speed over u_ss; {_theirs(whose, 'K')} is one reading of it over u_ss."
                    )
                else:
                    computed, lsq = st.K, None
                w_used = own_w if own_w is not None else st.omega_ss
                if (
                    own_K is not None
                    and u_row is not None
                    and isinstance(computed, float)
                    and K_by_request(own_K, w_used, u_row)
                ):
                    right, verdict = (
                        False,
                        (
                            f"wrong: this is omega_ss / {STEP_LEVEL:g} V, the requested voltage; the "
                            f"task asks for the measured u_ss = {typed(u_key, u_row, 'V')}"
                        ),
                    )
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
                if ident is None:  # the run alone: J needs the table's k_v and f
                    computed, lsq, how, T_used = None, None, "", None
                    verdict = j_waits(has, whose)
                elif T_used is not None:
                    computed = inertia_from_time_constant(
                        T_used, ident.R, ident.f, ident.k_v, ident.k_a
                    )
                    # which k_v, k_a and f: the table's, not a k_v typed on Tasks 6-9 (walk 13)
                    how += " and the table's R, k_v, k_a and f"
                    why = (
                        f"The least-squares J uses T = {_ms(st.T)} fitted over {span}; "
                        "J grows in proportion to T, so the two differ as the two T do."
                    )
                else:
                    computed, lsq, how = st.J, None, ""
            elif fld.key == "own.model":
                T_m = own_T if own_T is not None else st.T_63
                K_m = own_K if own_K is not None else st.K
                lsq = model_text(format_number(st.T), format_number(st.K))
                if T_m is not None:
                    computed = model_text(
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
                    if model_text(format_number(T_m), format_number(K_m)) == lsq:
                        lsq, why = None, ""
                    if isinstance(own, str):
                        right, verdict = judge_model(own, T_m, K_m)
                else:  # no T at all: neither the group's nor a 63 % reading of the run
                    computed, lsq = None, None
                    verdict = (
                        f"the model {whose} way needs a T: {whose} own T (Task 12), "
                        "or a 63 % reading of the run, which reads none on any rise"
                    )
            elif fld.key == "own.omega_5":
                lsq = st.K * U_TASK15
                if own_K is not None:
                    computed = own_K * U_TASK15
                    how = f"5 V × {whose} K = {typed('own.K', own_K, 'rad/s/V')}"
                    why = "The least-squares value uses the K fitted over every rise."
                else:
                    lsq = None
                    if computed is None:  # the run alone gives K (the table gives none)
                        computed = st.K * U_TASK15
                w_used = own_w if own_w is not None else st.omega_ss
                slip_5 = w_used * U_TASK15 / STEP_LEVEL
                if (
                    isinstance(own, float)
                    and isinstance(computed, float)
                    and value(f"u_ss@{STEP_LEVEL:g}") is not None
                    and _is_slip(own, slip_5, computed)
                ):
                    right, verdict = (
                        False,
                        (
                            f"wrong: this is omega_ss × {U_TASK15:g} V / {STEP_LEVEL:g} V, scaled by "
                            f"the requested voltage; the speed follows u_A through K = omega_ss / u_ss "
                            "with the measured u_ss"
                        ),
                    )
        if ident is not None and fld.key == "own.k_a" and value("own.k_v") is not None:
            own_kv = value("own.k_v")
            assert own_kv is not None
            computed = KA_OVER_KV * own_kv
            how = f"{KA_OVER_KV:g} × {whose} k_v = {typed('own.k_v', own_kv, 'V s/rad')}"
        if ident is not None and fld.key == "own.k_v" and isinstance(own, float):
            with_req = sorted(
                (r.reading.u_req - ident.R * r.reading.i_ss * 1e-3) / r.reading.omega_ss
                for r in ident.rows
                if r.reading.omega_ss
            )
            if with_req and isinstance(computed, float):
                n = len(with_req)
                slip_kv = (with_req[(n - 1) // 2] + with_req[n // 2]) / 2.0
                if _is_slip(own, slip_kv, computed):
                    right, verdict = (
                        False,
                        (
                            "wrong: this is k_v with the requested voltages u_req in place of the "
                            "measured u_ss; Task 6's formula takes u_ss, the voltage at the motor"
                        ),
                    )
        rel = None
        if isinstance(own, float) and isinstance(computed, float) and computed != 0:
            rel = own / computed - 1.0
        tol = TOLERANCE.get(fld.key)
        if rel is not None and tol is not None and right is None:
            right = abs(rel) <= tol
            if not right:
                verdict = (  # walk 14, D11: "the 10 % off that reading ... explains"
                    f"wrong: off by more than the {format_percent(tol)} that reading or "
                    "rounding explains"
                )
                said = ""
                if fld.key == "own.J" and ident and T_used is not None and isinstance(own, float):
                    said = _j_slip(own, T_used, ident.R, ident.f, ident.k_v, ident.k_a)
                if not said and isinstance(own, float) and isinstance(computed, float):
                    said = _decimal_slip(own, computed, tol)
                verdict += said
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
    return _with_caveats(out, value, text, res, whose)


RESTS_ON: dict[str, tuple[str, ...]] = {
    "own.J": ("own.T",),
    "own.model": ("own.T", "own.K"),
    "own.omega_5": ("own.K",),
}
"""The group's values each of these is worked out from (and judged against, by design:
"computed your way")."""

_TASK_OF = {"own.T": "Task 12", "own.K": "Task 11"}


def _with_caveats(
    out: list[Comparison],
    value: Callable[[str], float | None],
    text: Callable[[str], str | None],
    res: Results,
    whose: str,
) -> list[Comparison]:
    """``out`` with the caveat of each value judged right the group's way that rests on a
    value of theirs marked wrong (Task 14's model is consistent with their T, and their T
    was marked wrong): said, so that a right mark never hides the wrong one beneath it."""
    need = {k for c in out if c.right for k in RESTS_ON.get(c.key, ()) if value(k) is not None}
    if not need:
        return out
    upstream = {
        c.key: c.right
        for c in compare_fields([FIELDS[k] for k in sorted(need)], value, text, res, whose=whose)
    }
    done = []
    for c in out:
        wrong = [k for k in RESTS_ON.get(c.key, ()) if k in need and upstream.get(k) is False]
        if c.right and wrong:
            rests = " and ".join(k.removeprefix("own.") for k in RESTS_ON[c.key] if k in need)
            names = " and ".join(k.removeprefix("own.") for k in wrong)
            where = " and ".join(_TASK_OF[k] for k in wrong)
            caveat = (
                f"consistent with {whose} {rests}, and {whose} {names} "
                f"{'was' if len(wrong) == 1 else 'were'} marked wrong ({where})"
            )
            c = replace(c, caveat=caveat)
        done.append(c)
    return done


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
  level is late by up to a sample, up to +57 %, and is marked wrong. On the ten real step
  logs of other motors (``--real``), with the steady speed read by eye, T read on the sample
  nearest the level is at most 8.5 % from the program's reading, on the first sample past it
  14.3 %: 30 % holds there too; a steady speed read on the last sample of a coarse encoder
  (5-6 counts a sample) put one log 46 % off."""


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


def _decimal_slip(own: float, computed: float, tol: float) -> str:
    """A wrong value ``own`` that is 10, 100 or 1000 times ``computed`` (or a tenth, a
    hundredth, a thousandth of it) within ``tol``, as a clause naming the likely slip (walk
    13: '96,5' for 9.650 rad/s was only "+900 %"); '' otherwise."""
    for k in (1, 2, 3, -1, -2, -3):
        if abs(own / (computed * 10.0**k) - 1.0) <= tol:
            times = f"{10**k:g} times" if k > 0 else f"1/{10 ** (-k):g} of"
            return f"; yours is {times} that: a decimal point in the wrong place?"
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
                f"{name} = {format_reading(mine, shown_unit(unit), typed=typed_as(text, mine))} where "
                f"{format_constant(want, unit)} "
                f"was expected ({format_diff(mine / want - 1.0)})"
            )
    if wrong:
        return False, "wrong: " + "; ".join(wrong)
    T_typed, K_typed = typed_as(text, got.T), typed_as(text, got.K)
    return True, (
        f"right: T = {format_reading(got.T, 'ms', typed=T_typed)} and "
        f"K = {format_reading(got.K, 'rad/s/V', typed=K_typed)}"
    )


_NUMBER = re.compile(r"(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d+)?")
"""A number as the group types it in a model (decimal point or comma)."""


def typed_as(text: str, value: float) -> str:
    """The number written in ``text`` that is ``value`` (a model's T in s, its K): the text
    to give :func:`format_reading`, which then shows the value with the digits typed, in the
    unit it is shown in ("0.0570" is "57.0 ms", "1,930" is "1.930 rad/s/V"; the model line
    dropped their trailing zeros). "" when none is (a T worked out, as in
    "omega' = -omega/0.057 + ...")."""
    for m in _NUMBER.finditer(text):
        n = float(m.group().replace(",", "."))
        if n and abs(value / n - 1.0) <= 1e-12:
            return m.group()
    return ""


def reveal_keys(fields: Sequence[Field], answered: Collection[str]) -> list[str]:
    """The fields of a step a lab assistant's reveal marks as "revealed before answering":
    those of :data:`ANSWERED_FIRST` the group has not answered yet."""
    return [f.key for f in fields if f.key in ANSWERED_FIRST and f.key not in answered]


__all__ = [
    "ANSWERED_FIRST",
    "J_WAITS",
    "TOLERANCE",
    "POLICY_FILE",
    "READ_63",
    "REVEALED_EARLY",
    "SLIP",
    "K_by_request",
    "STEP_LEVEL",
    "Policy",
    "compare_fields",
    "concealed",
    "two_T",
    "two_T_of",
    "format_u_ss",
    "judge_model",
    "model_text",
    "read_policy",
    "reveal_keys",
    "u_ss_missing",
]
