"""`minseg-tui analyze LOG.csv [--json] [--predictions OUT.csv]`: the model check of a run log.

Fits the first-order model, simulates it on the measured input, says where it deviates,
names the causes and their evidence, fits the extended model and measures the gain. Under
the first-order model's fit a line says which T it is and sets identify's T of the same log
beside it (why they differ where the speed creeps on after the rise). The
log's header lines ``# ts:``, ``# cpr:`` and ``# omega_over:`` tell it the nominal period,
the encoder's resolution and how the speed was computed (else they are read off the data).
Bad input exits 2 with one line (from read_run_log).
"""

from __future__ import annotations

import argparse
import csv
import math

from minseg_tui.cli.output import open_output, output_file, print_json
from minseg_tui.errors import InputError
from minseg_tui.lab.content.identify_says import check_T_beside
from minseg_tui.lab.content.log_says import refusal_words
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_says import as_json, in_words
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.identify import IdentifyRefused, ZeroVoltRefusal, response_observed
from minseg_tui.model.runlog import LogRefused, RunLog, problem


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The subcommand's arguments."""
    parser.add_argument(
        "log", metavar="LOG.csv", help="run log: columns t (s), u (V), omega (rad/s)"
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


def in_words_text(r: CheckResult) -> str:
    """The check's text (:func:`minseg_tui.lab.views.check_text.text`) with its headings naming the
    cause, the other causes and the extended model in words ("Cause: dry friction",
    "Extended model (first order + dry friction)"), not by their contract names, which stay
    in ``--json``."""
    f, e = r.finding, r.extended
    heads = {f"Cause: {f.cause}": f"Cause: {in_words(f.cause)}"}
    heads[f"Extended model ({e.model}):"] = f"Extended model ({in_words(e.model)}):"
    for o in f.others:
        heads[f"  also: {o.cause} ("] = f"  also: {in_words(o.cause)} ("
    out = []
    for line in text(r).split("\n"):
        for old, new in heads.items():
            if line == old or (old.endswith((":", "(")) and line.startswith(old)):
                line = new + line[len(old) :]
                break
        out.append(line)
    return "\n".join(out)


def run(args: argparse.Namespace) -> int:
    """Analyse the log; 0 on success (InputError propagates: exit 2 with one line)."""
    if args.predictions is not None:
        output_file(args.predictions, {args.log: "the log being analysed"}, "predictions")
    log = read_run_log(args.log)
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
    if args.json:
        print_json(as_json(result), indent=2)
    else:
        print(with_identify(in_words_text(result), result, log))
    return 0


def with_identify(text: str, r: CheckResult, log: RunLog) -> str:
    """The check's text with a line under the first-order model's fit saying which T it is
    and what identify's T of the same log is (:func:`check_T_beside`), so that the two T
    do not stand apart without a word (where the speed creeps on after the rise, why they
    differ)."""
    T = r.baseline.params.get("T")
    if T is None:
        return text
    try:
        st, observations = response_observed(log, [])
    except (IdentifyRefused, LogRefused, ZeroVoltRefusal, ArithmeticError, ValueError):
        st, observations = None, []  # identify refuses this log and says why itself
    lines = text.split("\n")
    at = next(
        (k for k, line in enumerate(lines) if line.startswith("  simulated on the measured")),
        None,
    )
    if at is None:
        return text
    e = r.extended
    T_ext = e.params.get("T") if e.model != r.baseline.model else None
    extended = (in_words(e.model), T_ext) if T_ext is not None else None
    lines.insert(at + 1, f"  {check_T_beside(T, st, observations, extended)}")
    return "\n".join(lines)
