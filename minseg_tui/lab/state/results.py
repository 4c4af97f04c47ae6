"""What the session computes from the entries and a run: Tasks 6-15, the table, the model check.

Nothing here is stored: :func:`compute` derives Tasks 6-15 with
:func:`minseg_tui.model.identify.identify` from R, the table's complete rows and the run
Tasks 11-15 use, and :func:`check_run` runs the model check on a recorded run. The
dataclasses are what :class:`~minseg_tui.lab.state.session.Session` hands to the UI and the report.
:func:`response_figures` and :func:`check_figures` take from them what the session file keeps
(:mod:`minseg_tui.lab.saving.kept`); :func:`compute` given kept figures does not fit the run
again.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from minseg_tui.errors import InputError
from minseg_tui.lab.content import identify_says
from minseg_tui.lab.content.log_says import log_refusal, refusal_words
from minseg_tui.lab.content.u_ss_says import zero_volt_refusal
from minseg_tui.lab.saving.kept import CheckFigures, ResponseFigures
from minseg_tui.lab.saving.runs import LogCache, RunInfo, read_run
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.identify import (
    U_TASK15,
    Identification,
    IdentifyRefused,
    Reading,
    ResponseResult,
    ZeroVoltRefusal,
    identify,
    response_alone,
)
from minseg_tui.model.motor import inertia_from_time_constant
from minseg_tui.model.runlog import LogRefused, RunLog
from minseg_tui.quantities import format_number


@dataclass(frozen=True)
class Notice:
    """A warning to show: ``source`` is a field key or a finding code; ``message`` one line."""

    source: str
    message: str


I_SS_FALL: float = 0.05
"""i_ss at a higher voltage this far (relative) below i_ss at a lower one is called a fall.
The free-running wheel's current rises slowly with speed (k_a i_ss = tau_c + f omega): on
the virtual board by about 3.7 mA (10 %) from one row to the next, so readings one row off
fall by that much. Its meter's own noise (0.05 mA and the 0.1 mA digit) made falls of at most
0.9 % over 200 seeds even with f = 0, where the current does not rise at all: 5 % is well
above the noise and well below a mix-up."""


def falling_currents(rows: Sequence[tuple[float, float, str]]) -> list[Notice]:
    """A warning, on the row's i_ss field, for each row whose current is clearly below that of
    a row at a lower voltage (:data:`I_SS_FALL`): a slip, or readings typed one row off.
    ``rows``: (u_req V, i_ss A, i_ss as the warning writes it)."""
    out = []
    ordered = sorted(rows)
    for k, (level, i_ss, typed) in enumerate(ordered):
        above = [r for r in ordered[:k] if r[0] < level and i_ss < (1.0 - I_SS_FALL) * r[1]]
        if not above:
            continue
        low_level, _, low_typed = max(above, key=lambda r: r[1])
        out.append(
            Notice(
                f"i_ss@{level:g}",
                f"i_ss falls from {low_typed} at {low_level:g} V to {typed} at {level:g} V, "
                "while i_ss should rise a little with the speed: check that each reading is in its row.",
            )
        )
    return out


@dataclass(frozen=True)
class TableRow:
    """One row of the table of Tasks 4-9 (None where not known yet).

    level: requested u_req (V); u_ss (V); omega_ss (rad/s); spread (rad/s, of the capture);
    window: (t0, t1) s of the capture; i_ss (A); k_v (V s/rad); f (N m s/rad).
    """

    level: float
    u_ss: float | None = None
    omega_ss: float | None = None
    spread: float | None = None
    window: tuple[float, float] | None = None
    i_ss: float | None = None
    k_v: float | None = None
    f: float | None = None


@dataclass(frozen=True)
class Results:
    """Tasks 6-15 computed now from the entries: ``identification`` (None when the table is
    not far enough), the run used for Tasks 11-15 (None without one), and ``problems``:
    one line each for what keeps a result from being computed.

    ``kept_response``: Tasks 11-13's numbers as the session file keeps them, when :func:`compute`
    was given them instead of fitting the run (``identification.step`` is then None and its
    observations are the table's only); :attr:`step` gives them either way."""

    identification: Identification | None
    run: str | None
    problems: tuple[str, ...] = ()
    kept_response: ResponseFigures | None = None
    response: ResponseResult | None = None
    """Tasks 11-12 from the run and the table's u_ss alone, when the table cannot give
    Tasks 6-9 (no R, or no positive k_v): omega_ss in the steps, K and T need neither R nor
    i_ss; J (Task 13) waits for k_v and f (NaN here)."""
    table_problems: tuple[str, ...] = ()
    """Those of :attr:`problems` that keep the table's k_v, k_a and f (and so J) from being
    computed (R not entered, no complete row, a row left out): not why the run gives no K
    or T, which need only the run and a u_ss (walk 10, D4)."""
    speed_only: ResponseResult | None = None
    """The run's rises and T (the 63 % reading and the least squares) from its speed alone,
    when the table has no u_ss yet to map the requested voltage to the one on the motor:
    T needs no u_ss (walk 18, D4), but its K (and u_ss, J, the model, omega at 5 V) here are
    of the requested voltage, none of Tasks 11-15's: only the rises and T are to be read."""

    @property
    def run_problems(self) -> tuple[str, ...]:
        """:attr:`problems` less :attr:`table_problems`: why the run gives no step result."""
        return tuple(p for p in self.problems if p not in self.table_problems)

    @property
    def step(self) -> ResponseFigures | None:
        """Tasks 11-13's numbers (J included): of the identification's step, else the kept
        ones, else those of the run alone (:attr:`response`, J NaN); None without a step
        result."""
        ident = self.identification
        if ident is not None and ident.step is not None:
            return response_figures(ident.step)
        if self.kept_response is None and self.response is not None:
            return response_figures(self.response)
        return self.kept_response

    @property
    def response_result(self) -> ResponseResult | None:
        """The run's step result: the identification's, else that of the run alone."""
        ident = self.identification
        if ident is not None and ident.step is not None:
            return ident.step
        return self.response

    def to_json(self) -> dict[str, object] | None:
        """The --json dict of ``minseg-tui identify`` for these results, or None (with kept
        numbers, their part of ``step``, ``model`` and ``omega_at_5V``)."""
        if self.identification is None:
            return None
        out = identify_says.as_json(self.identification)
        k = self.kept_response
        if k is not None and "step" not in out:
            out["step"] = {
                "K": k.K,
                "T": k.T,
                "T_63": k.T_63,
                "J": k.J,
                "omega_ss": k.omega_ss,
                "u_ss": k.u_ss,
                "dead_time": k.dead_time,
            }
            out["model"] = {"T": k.T, "K": k.K, "dead_time": k.dead_time}
            out["omega_at_5V"] = k.K * U_TASK15
        return out

    def lookup(self, path: str) -> float | str | None:
        """A computed value by path (``k_v``, ``step.K``, ``step.T_63``, ``omega_at_5V``,
        ``model`` as a sentence); None when not computed."""
        d = self.to_json()
        if d is None:
            return None
        if path == "model":
            m = d.get("model")
            if not isinstance(m, dict):
                return None
            return f"{format_number(m['T'])} omega' = -omega + {format_number(m['K'])} u_A"
        node: object = d
        for part in path.split("."):
            if not isinstance(node, dict) or part not in node:
                return None
            node = node[part]
        return float(node) if isinstance(node, int | float) else None


@dataclass(frozen=True)
class Comparison:
    """A student's own reading beside the value computed the group's way (same SI unit;
    ``unit`` is the form unit for display); rel_diff = own / computed - 1 when both are
    numbers. ``how``: how the group's way was computed ("from your T = 56.8 ms"; '' when
    it is the program's value); ``least_squares``: the program's least-squares value when it
    differs from the group's way (None otherwise), ``why`` one sentence on why the two
    differ; ``revealed_early``: a lab assistant showed the value before the group answered;
    ``right``: for an answer judged right or wrong (Task 14's model), whether it is (None when
    not judged), ``verdict`` one line saying so; ``caveat``: see below."""

    key: str
    label: str
    unit: str
    own: float | str | None
    computed: float | str | None
    rel_diff: float | None
    how: str = ""
    least_squares: float | str | None = None
    why: str = ""
    revealed_early: bool = False
    right: bool | None = None
    verdict: str = ""
    caveat: str = ""
    """For a value right the group's way that rests on a value of theirs marked wrong (Task
    14's model with their wrong T): one clause saying so ('' otherwise)."""


@dataclass(frozen=True)
class ModelCheck:
    """The model check of one run: its name, the result (None when it could not run) and,
    then, why in one line (``problem``)."""

    run: str | None
    result: CheckResult | None
    problem: str = ""


def response_figures(st: ResponseResult) -> ResponseFigures:
    """What the session file keeps of a step result (and J)."""
    return ResponseFigures(
        K=st.K,
        T=st.T,
        T_63=st.T_63,
        u_ss=st.u_ss,
        omega_ss=st.omega_ss,
        dead_time=st.dead_time,
        J=st.J,
    )


def check_figures(mc: ModelCheck) -> CheckFigures:
    """What the session file keeps of a model check: its cause and figures, or its problem."""
    r = mc.result
    if r is None:
        return CheckFigures("", problem=mc.problem)
    return CheckFigures(
        cause=r.finding.cause,
        model=r.extended.model,
        others=tuple(o.cause for o in r.finding.others),
        params={k: float(v) for k, v in r.extended.params.items()},
        gain={k: None if v is None else float(v) for k, v in r.gain.to_dict().items()},
    )


def _why_no_step(exc: Exception) -> str:
    """Why a run gives no step result, in one line: identify's refusal as it says it (a
    rise at 0 V on the motor worded by lab/content/u_ss_says.py, a log it cannot take by
    lab/content/log_says.py, a table, R or log without a usable rise by lab/content/
    identify_says.py), or the fit's failure."""
    if isinstance(exc, IdentifyRefused):
        return str(identify_says.identify_refusal(exc, identify_says.R_IN_SESSION))
    if isinstance(exc, ZeroVoltRefusal):
        return str(zero_volt_refusal(exc))
    if isinstance(exc, LogRefused):
        return str(log_refusal(exc))
    return f"its steps cannot be fitted ({exc})"


def compute(
    R: float | None,
    complete_rows: Sequence[Reading],
    run: RunInfo | None,
    folder: Path,
    u_ss_table: Sequence[tuple[float, float]] | None = None,
    kept: ResponseFigures | None = None,
    R_missing: str = "",
    logs: LogCache | None = None,
) -> Results:
    """Tasks 6-15 from R (ohm), the table's complete rows and the run Tasks 11-15 use (its
    log read from ``folder``); every reason a result is missing becomes a problem line.
    ``R_missing``: why R is None when it is not that nothing was entered (the line said).

    ``u_ss_table``: the (u_req, u_ss) pairs (V) of every row with a u_ss, complete or not,
    the mapping K divides by (default: the complete rows'), as the run's u column uses it.
    ``kept``: Tasks 11-13's numbers of ``run`` as the session file keeps them (computed
    from this very log and table, :func:`minseg_tui.lab.saving.kept.read`): the run is then
    neither read nor fitted again, J follows from them and the table (``kept_response``).
    ``logs``: the logs read before (:func:`~minseg_tui.lab.saving.runs.read_run`)."""
    problems: list[str] = []
    if R is None:
        problems.append(R_missing or "R is not entered yet (Task 2)")
    readings = []
    for r in complete_rows:
        wrong = r.problem()
        if wrong:
            problems.append(
                f"row {r.u_req:g} V left out: {identify_says.identify_refusal_words(wrong)}"
            )
        else:
            readings.append(r)
    if not readings:
        problems.append("no complete row in the table yet (u_ss, omega_ss and i_ss; Tasks 4-5)")
    table_problems = tuple(problems)
    log: RunLog | None = None
    if run is not None and kept is None:
        try:
            table = [(r.u_req, r.u_ss) for r in complete_rows] if u_ss_table is None else u_ss_table
            log = read_run(folder, run, table, require_step=True, logs=logs)
        except InputError as exc:
            problems.append(f"run {run.name} cannot be used: {exc}")
    read = run is not None and (log is not None or kept is not None)
    pairs = (
        list(u_ss_table) if u_ss_table is not None else [(r.u_req, r.u_ss) for r in complete_rows]
    )

    def run_alone() -> Results:
        """The table cannot give Tasks 6-9: the run's Tasks 11-12 alone, which need neither
        R nor k_v (the plot, omega_ss, K and the 63 % reading)."""
        name = run.name if run and read else None
        if log is not None and not pairs:
            try:  # u_ss is the requested voltage here: only the rises and T are kept
                speed = response_alone(log, [])
            except (IdentifyRefused, LogRefused, ZeroVoltRefusal, ArithmeticError, ValueError):
                speed = None  # why is said once a u_ss lets the step be worked out
            return Results(
                None, name, tuple(problems), table_problems=table_problems, speed_only=speed
            )
        if log is None or not pairs:
            return Results(None, name, tuple(problems), table_problems=table_problems)
        try:
            alone = response_alone(log, pairs)
        except (IdentifyRefused, LogRefused, ZeroVoltRefusal, ArithmeticError, ValueError) as exc:
            why = _why_no_step(exc)
            problems.append(f"run {run.name if run else ''} gives no step result: {why}")
            return Results(None, name, tuple(problems), table_problems=table_problems)
        return Results(None, name, tuple(problems), response=alone, table_problems=table_problems)

    if R is None or not readings:
        return run_alone()
    try:
        ident = identify(readings, R, log, source="table", u_ss_table=u_ss_table)
    except (IdentifyRefused, LogRefused, ZeroVoltRefusal, ArithmeticError, ValueError) as exc:
        # ArithmeticError, ValueError (numpy's LinAlgError): a log the fit cannot take; the
        # table's results stand, and the step says why it has none (never a traceback)
        why = _why_no_step(exc)
        if not read:
            return Results(None, None, (*problems, why), table_problems=(*table_problems, why))
        try:
            ident = identify(readings, R, None, source="table")
        except IdentifyRefused as exc2:  # the table's fault, not the run's
            said = str(identify_says.identify_refusal(exc2, identify_says.R_IN_SESSION))
            problems.append(said)
            table_problems = (*table_problems, said)
            return run_alone()
        problems.append(f"run {run.name if run else ''} gives no step result: {why}")
        return Results(ident, None, tuple(problems), table_problems=table_problems)
    with_J = None
    if kept is not None:
        J = inertia_from_time_constant(kept.T, ident.R, ident.f, ident.k_v, ident.k_a)
        with_J = replace(kept, J=J)
    return Results(
        ident,
        run.name if (run and read) else None,
        tuple(problems),
        with_J,
        table_problems=table_problems,
    )


def check_run(
    folder: Path,
    run: RunInfo,
    u_ss_table: Sequence[tuple[float, float]] = (),
    logs: LogCache | None = None,
) -> ModelCheck:
    """The model check (:func:`minseg_tui.model.check.check`) of ``run``, read from ``folder``
    (its applied voltage mapped through ``u_ss_table``, the (u_req, u_ss) pairs in V), told
    the log's ``# cpr:`` and ``# omega_over:`` when its header says (a recorded run's
    does); a run that cannot be read or checked gives the reason in one line. ``logs``: the
    logs read before (:func:`~minseg_tui.lab.saving.runs.read_run`)."""
    try:
        log = read_run(folder, run, u_ss_table, require_step=True, logs=logs)
        result = check(
            log.t, log.u, log.omega, ts=run.ts, cpr=log.declared_cpr, omega_over=log.omega_over
        )
        return ModelCheck(run.name, result)
    except InputError as exc:
        return ModelCheck(run.name, None, str(exc))
    except LogRefused as exc:
        return ModelCheck(run.name, None, f"run {run.name}: {refusal_words(exc.why)}")
    except ValueError as exc:
        return ModelCheck(run.name, None, f"run {run.name}: {exc}")


__all__ = [
    "Comparison",
    "ModelCheck",
    "Notice",
    "Results",
    "TableRow",
    "check_figures",
    "check_run",
    "compute",
    "response_figures",
]
