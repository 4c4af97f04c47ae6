"""`minseg-tui analyze LOG.csv [--json] [--predictions OUT.csv]`: the model check of a run log.

Fits the first-order model, simulates it on the measured input, says where it deviates,
names the causes and their evidence, fits the extended model and measures the gain. Under
the first-order model's fit a line says which T it is and sets identify's T of the same log
beside it (why they differ where the speed creeps on after the rise); ``--json`` gives
the same as ``T_beside``, typed, with that sentence (:func:`beside_json`). The log's header lines ``# ts:``, ``# cpr:`` and ``# omega_over:`` tell it the nominal period,
the encoder's resolution and how the speed was computed (else they are read off the data).
Bad input exits 2 with one line (from read_run_log).
"""

from __future__ import annotations

import argparse
import csv
import math
from collections.abc import Sequence
from dataclasses import dataclass

from minseg_tui.cli.output import input_file, not_stdio, open_output, output_file, print_json
from minseg_tui.errors import InputError
from minseg_tui.lab.content.identify_says import check_T_beside
from minseg_tui.lab.content.log_says import refusal_words
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_says import as_json, in_words, late_speed
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.identify import (
    IdentifyRefused,
    ResponseResult,
    ZeroVoltRefusal,
    response_observed,
)
from minseg_tui.model.identify.observations import Observation, TRowsApart
from minseg_tui.model.runlog import LogRefused, RunLog, problem


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The subcommand's arguments."""
    parser.add_argument(
        "log", metavar="LOG.csv", help="run log: columns t (s), u (V), omega (rad/s); - reads stdin"
    )
    parser.add_argument(
        "--json", action="store_true", help="print one JSON object instead of the report"
    )
    parser.add_argument(
        "--predictions",
        metavar="OUT.csv",
        help="write t,omega,baseline,extended (s, rad/s) for every row",
    )


def _sample_period(meta: dict[str, str]) -> float | None:
    """The nominal sample period (s) from a ``# ts:`` / ``# Ts:`` metadata line, if one is there."""
    for key in ("ts", "Ts", "sample_period"):
        if key in meta:
            try:
                value = float(meta[key].split()[0])
            except (ValueError, IndexError):
                continue
            if math.isfinite(value) and value > 0:
                return value
    return None


def write_predictions(path: str, r: CheckResult) -> None:
    """t,omega,baseline,extended for every row (s, rad/s), full precision."""
    with open_output(path, "predictions") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["t", "omega", "baseline", "extended"])
        for row in zip(r.t, r.omega, r.baseline_pred, r.extended_pred, strict=True):
            w.writerow([repr(float(v)) for v in row])


def in_words_text(r: CheckResult, lag: float | None = None) -> str:
    """The check's text (:func:`minseg_tui.lab.views.check_text.text`) with its headings naming the
    cause, the other causes and the extended model in words ("Cause: dry friction",
    "Extended model (first order + dry friction)"), not by their contract names, which stay
    in ``--json``. ``lag`` (s): how late the log's speed column runs behind its angle column
    (:func:`~minseg_tui.lab.views.check_says.late_speed`), None when it does not."""
    f, e = r.finding, r.extended
    heads = {f"Cause: {f.cause}": f"Cause: {in_words(f.cause)}"}
    heads[f"Extended model ({e.model}):"] = f"Extended model ({in_words(e.model)}):"
    for o in f.others:
        heads[f"  also: {o.cause} ("] = f"  also: {in_words(o.cause)} ("
    out = []
    for line in text(r, lag).split("\n"):
        for old, new in heads.items():
            if line == old or (old.endswith((":", "(")) and line.startswith(old)):
                line = new + line[len(old) :]
                break
        out.append(line)
    return "\n".join(out)


def run(args: argparse.Namespace) -> int:
    """Analyse the log; 0 on success (InputError propagates: exit 2 with one line)."""
    source = input_file(args.log, "LOG.csv")
    if args.predictions is not None:
        not_stdio(
            args.predictions,
            "--predictions",
            "a file name for the predictions",
            "stdout holds the report",
        )
        output_file(args.predictions, {args.log: "the log being analysed"}, "predictions")
    log = read_run_log(source)
    ts = _sample_period(dict(log.metadata))
    refused = problem(log.t, log.u, log.omega, ts)
    if refused:
        raise InputError(log.source, None, refusal_words(refused))
    result = check(log.t, log.u, log.omega, ts=ts, cpr=log.declared_cpr, omega_over=log.omega_over)
    if args.predictions is not None:
        try:
            write_predictions(args.predictions, result)
        except OSError as exc:
            raise InputError(
                args.predictions, None, f"cannot write the predictions: {exc.strerror}"
            ) from exc
    beside = identify_beside(result, log)
    lag = late_speed(log)
    if args.json:
        out = as_json(result)
        out["T_beside"] = beside_json(beside) if beside is not None else None
        out["speed_lag"] = lag
        print_json(out, indent=2)
    else:
        print(with_identify(in_words_text(result, lag), beside))
    return 0


@dataclass(frozen=True)
class Beside:
    """The check's first-order T (``T_check``, s) and identify's reading of the same log:
    ``st`` its result (None where identify cannot fit the log), ``observations`` what it
    observes of that fit, ``extended`` the check's extended model in words and its T (s),
    when it has one."""

    T_check: float
    st: ResponseResult | None
    observations: Sequence[Observation]
    extended: tuple[str, float] | None

    def words(self) -> str:
        """The line under the first-order model's fit (:func:`check_T_beside`)."""
        return check_T_beside(self.T_check, self.st, self.observations, self.extended)


def identify_beside(r: CheckResult, log: RunLog) -> Beside | None:
    """identify's T beside the check's first-order T for the same log, or None when the
    check's baseline has no T."""
    T = r.baseline.params.get("T")
    if T is None:
        return None
    try:
        st, observations = response_observed(log, [])
    except (InputError, IdentifyRefused, LogRefused, ZeroVoltRefusal, ArithmeticError, ValueError):
        st, observations = None, []  # identify refuses this log and says why itself
    e = r.extended
    T_ext = e.params.get("T") if e.model != r.baseline.model else None
    extended = (in_words(e.model), T_ext) if T_ext is not None else None
    return Beside(T, st, observations, extended)


def beside_json(b: Beside) -> dict[str, object]:
    """``T_beside`` of ``analyze --json``: the check's T (``check_T``, s), the sentence the
    text prints under the fit (``words``) and identify's reading of the same log
    (``identify``, None where identify cannot fit it): its ``T``, ``T_ci`` (95 %),
    ``dead_time``, ``rise_T`` (the rows up to 4 T after each edge) and ``every_row_T`` (s,
    None where not fitted apart), ``rows`` (which rows its T is fitted to:
    ``up_to_4T_after_each_edge``, ``rises`` or ``all_rows_it_uses``), ``creep`` (the speed
    after the rise, rad/s, first and last tenth of its rows, None where it does not creep on),
    ``follows_rise`` (T follows the rise, not every row) and ``T_over_check_T``."""
    st = b.st
    identify: dict[str, object] | None = None
    if st is not None and math.isfinite(st.T):
        apart = next(
            (o for o in b.observations if isinstance(o, TRowsApart) and o.follows_rise),
            None,
        )
        identify = {
            "T": st.T,
            "T_ci": [st.T_ci[0], st.T_ci[1]],
            "T_determined": st.T_determined,
            "dead_time": st.dead_time,
            "rows": (
                "up_to_4T_after_each_edge"
                if st.fit.every_row_T is not None
                else "rises"
                if st.fit.method == "rising_steps"
                else "all_rows_it_uses"
            ),
            "rise_T": st.fit.rise_T,
            "every_row_T": st.fit.every_row_T,
            "creep": list(apart.creep) if apart is not None and apart.creep is not None else None,
            "follows_rise": apart is not None,
            "T_over_check_T": st.T / b.T_check if b.T_check > 0 else None,
        }
    return {"check_T": b.T_check, "words": b.words(), "identify": identify}


def with_identify(text: str, beside: Beside | None) -> str:
    """The check's text with a line under the first-order model's fit saying which T it is
    and what identify's T of the same log is (:func:`check_T_beside`), so that the two T
    do not stand apart without a word (where the speed creeps on after the rise, why they
    differ)."""
    if beside is None:
        return text
    lines = text.split("\n")
    at = next(
        (k for k, line in enumerate(lines) if line.startswith("  simulated on the measured")),
        None,
    )
    if at is None:
        return text
    lines.insert(at + 1, f"  {beside.words()}")
    return "\n".join(lines)
