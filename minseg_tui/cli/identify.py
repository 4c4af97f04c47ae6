"""`minseg-tui identify TABLE.csv --R OHMS [--step LOG.csv] [--json]`: Tasks 6-15 headless.

--R is read as Task 2's entry reads R; a value outside its usual range is accepted, as there,
with that entry's question as one note on stderr (above 20 Ω: a decimal comma lost?)."""

from __future__ import annotations

import argparse
import sys
import textwrap
from typing import NamedTuple

from minseg_tui.cli.output import input_file, one_stdin, print_json
from minseg_tui.errors import InputError
from minseg_tui.lab.content.identify_says import (
    as_json,
    fit_why,
    friction_equation,
    identify_refusal,
    model_equation,
    sentence,
    t63_note,
    time_from,
)
from minseg_tui.lab.content.log_says import angle_words, log_refusal
from minseg_tui.lab.content.steps import FIELDS
from minseg_tui.lab.content.u_ss_says import u_ss_words, zero_volt_refusal
from minseg_tui.lab.saving.files import read_run_log, read_table
from minseg_tui.lab.state.entries import read_entry, read_quantity
from minseg_tui.model.identify import (
    U_TASK15,
    Identification,
    IdentifyRefused,
    ZeroVoltRefusal,
    identify,
)
from minseg_tui.model.identify.risefit import RISE_SPAN
from minseg_tui.model.runlog import LogRefused
from minseg_tui.quantities import (
    F_UNIT,
    NO_WIDTH,
    NOT_DETERMINED,
    EntryRefused,
    format_interval,
    format_number,
    format_reading,
    format_signed,
    in_unit,
)


class Typed(NamedTuple):
    """A reading given on the command line: its value (SI), the text it was typed as and the
    warnings its entry in the TUI would show (outside the usual range)."""

    value: float
    text: str
    warnings: tuple[str, ...] = ()


def _ohms(text: str) -> Typed:
    """--R read as Task 2's entry reads R in the TUI (the decimal comma, a unit, '5300 mΩ'),
    refused with that entry's words; its warnings are the entry's (above 20 Ω: a decimal
    comma lost?)."""
    try:
        value = read_quantity(FIELDS["R"], text).value
    except EntryRefused as exc:
        raise argparse.ArgumentTypeError(exc.expected) from None
    return Typed(value, text, read_entry(FIELDS["R"], text).warnings)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Arguments of the identify subcommand."""
    parser.add_argument(
        "table",
        metavar="TABLE.csv",
        help="steady-state readings: u_req,u_ss,omega_ss,i_ss (V, V, rad/s, mA); - reads stdin",
    )
    parser.add_argument(
        "--R",
        dest="R",
        type=_ohms,
        required=True,
        metavar="OHMS",
        help="motor resistance measured in Task 2, ohm",
    )
    parser.add_argument(
        "--step",
        metavar="LOG.csv",
        help="run log (t,u,omega,...) for K, T, J and the model (Tasks 11-15); - reads stdin",
    )
    parser.add_argument(
        "--json", action="store_true", help="print one JSON object instead of the report"
    )


def run(args: argparse.Namespace) -> int:
    """Read the files, compute, print. InputError reaches the dispatcher (exit 2)."""
    if args.step == "":
        raise InputError("--step", None, "expected a run log file name, got ''")
    table = input_file(args.table, "TABLE.csv")
    step = input_file(args.step, "--step") if args.step is not None else None
    one_stdin(("TABLE.csv", table), ("--step", step))
    readings = read_table(table)
    log = read_run_log(step) if step is not None else None
    try:
        result = identify(readings, args.R.value, log, source=str(table))
    except IdentifyRefused as refused:
        raise identify_refusal(refused) from None
    except ZeroVoltRefusal as refused:
        raise zero_volt_refusal(refused) from None
    except LogRefused as refused:
        raise log_refusal(refused) from None
    except (ArithmeticError, ValueError) as exc:  # numpy's LinAlgError is a ValueError
        raise InputError(
            args.step or args.table,
            None,
            f"expected a run log whose rises can be fitted; the fit failed ({exc})",
        ) from None
    for warning in args.R.warnings:  # accepted, as the TUI accepts it, with its question
        print(
            f"minseg-tui identify: note: --R {args.R.text}: {warning}; computed with "
            f"R = {format_reading(args.R.value, '', typed=args.R.text)} ohm",
            file=sys.stderr,
        )
    if args.json:
        print_json(as_json(result))
    else:
        sys.stdout.write(render(result, args.R.text))
    return 0


def _wrap(text: str) -> list[str]:
    """A long sentence as indented lines of at most 96 characters."""
    return textwrap.wrap(text, width=96, initial_indent="   ", subsequent_indent="   ")


def _task15(result: Identification) -> list[str]:
    """Task 15's line, and when the fit found dry friction that changes the answer, the model
    with the friction and its speed beside the lab's K u_A (the observation says why)."""
    s, lab = result.step, result.omega_at_5V
    assert s is not None and lab is not None
    line = f"At u_A = {U_TASK15:g} V (Task 15): omega = {format_number(lab)} rad/s"
    equation = friction_equation(s, "w")
    friction = s.task15_with_friction
    if friction is None or equation is None:
        return [line]
    return [
        *_wrap(
            f"(the lab's model has no dry friction; with the friction the fit found: {equation} "
            "while the wheel turns)"
        ),
        f"{line} by the lab's model, {format_number(friction)} rad/s with the friction",
    ]


def render(result: Identification, R_typed: str = "") -> str:
    """The human report: the table of Tasks 4-9, then Tasks 11-15, then what the numbers show.
    ``R_typed``: the text R was given as, whose digits R is written with ('5,30' is 5.30)."""
    out = [f"R = {format_reading(result.R, '', typed=R_typed)} ohm (Task 2)", ""]
    head = ("u_req V", "u_ss V", "omega_ss rad/s", "i_ss mA", "k_v V s/rad", f"f {F_UNIT}")
    body = [
        (
            format_reading(r.reading.u_req, ""),
            format_reading(r.reading.u_ss, ""),
            format_reading(r.reading.omega_ss, ""),
            format_reading(r.reading.i_ss, ""),
            format_number(r.k_v),
            format_number(in_unit(r.f, F_UNIT)),
        )
        for r in result.rows
    ]
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(head)]
    out.append("  ".join(h.rjust(w) for h, w in zip(head, widths, strict=True)))
    out += ["  ".join(c.rjust(w) for c, w in zip(b, widths, strict=True)) for b in body]
    out += [
        "",
        f"k_v = {format_number(result.k_v)} V s/rad   (Task 7, median of the rows)",
        f"k_a = {format_number(result.k_a)} N m/A     (Task 8, 0.65 k_v)",
        f"f   = {format_number(in_unit(result.f, F_UNIT))} {F_UNIT} (Task 9, median of the rows)",
    ]
    s = result.step
    if s is not None:
        how = u_ss_words(s.u_ss_how)
        t63 = (
            f"{format_number(s.T_63 * 1e3)} ms"
            if s.T_63 is not None
            else "not read (the speed never reached 63 %)"
        )
        fit = s.fit
        interval = (
            f"95 % interval {format_interval(s.T_ci[0] * 1e3, s.T_ci[1] * 1e3, 'ms')}"
            if s.T_determined and s.T_ci[1] > s.T_ci[0]
            else f"95 % interval: {NO_WIDTH}"
            if s.T_determined
            else f"95 % interval: {NOT_DETERMINED}"
        )
        on_bound = " (on its bound)" if fit.T_on_bound else ""
        timing = (
            "with a time shift of the steps against the samples as a nuisance, kept within one "
            f"sample period: {format_signed(fit.shift * 1e3, 3)} ms"
            + (", on that bound" if fit.shift_on_bound else "")
        )
        if s.dead_time:
            timing = (
                f"with a dead time of {format_number(s.dead_time * 1e3)} ms (the wheel answers later than the one "
                "sample period the sampling's lateness explains), part of the model"
            )
        out += [
            "",
            f"Run log: {len(s.rises)} rise(s); angle from {angle_words(fit.angle_source)}, time from {time_from(fit)}",
            f"omega_ss = {format_number(s.omega_ss)} rad/s (fitted), u_ss = {format_reading(s.u_ss, '') if s.u_ss_how == 'row' else format_number(s.u_ss)} V ({how})",
            f"K = omega_ss / u_ss = {format_number(s.K)} rad/s per V "
            + (
                f"+- {format_number((s.K_ci[1] - s.K_ci[0]) / 2, 2)} (95 %, Task 11)"
                if s.K_determined and s.K_ci[1] > s.K_ci[0]
                else f"(95 % interval: {NO_WIDTH}; Task 11)"
                if s.K_determined
                else f"(95 % interval: {NOT_DETERMINED}; Task 11)"
            ),
            f"T, 63 % reading      = {t63} (Task 12, median over the rises)",
            f"T, least squares     = {format_number(s.T * 1e3)} ms{on_bound}, {interval}",
            *_wrap(
                "(the first-order response fitted to the encoder angle at the log's sample times, so "
                f"the sampling is part of the model, {timing}; {fit_why(fit.why)}; the model uses this T"
                + (
                    "; the interval holds both"
                    if fit.every_row_T is not None
                    else f"; the interval also holds the T of the rows up to {RISE_SPAN:g} T "
                    f"after each edge alone, {format_number(fit.rise_T * 1e3)} ms"
                    if fit.rise_T is not None
                    else ""
                )
                + (
                    "; the interval also holds the T of the fit with the shift free, "
                    f"{format_number(fit.free_T * 1e3)} ms"
                    if fit.free_T is not None
                    else ""
                )
                + ")"
            ),
            *(_wrap(t63_note(s.T_63_note)) if s.T_63_note else []),
            f"J = T (R f + k_v k_a) / R = {format_number(s.J)} kg m^2 (Task 13)",
            "",
            f"Model (Task 14): {model_equation(s, 'w')}",
            *_task15(result),
        ]
    out += ["", "What the numbers show:"]
    if result.observations:
        out += [f"- {sentence(f)}" for f in result.observations]
    else:
        out.append(
            "- nothing unusual: the rows agree and the step fits the model."
            if s is not None
            else "- nothing unusual: the rows agree (no run log, so no step to judge)."
        )
    return "\n".join(out) + "\n"
