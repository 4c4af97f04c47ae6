"""The lab's two file formats: the table of steady-state readings and run logs.

TABLE.csv: header ``u_req,u_ss,omega_ss,i_ss`` (V, V, rad/s, mA, the manual's units), one
row per requested voltage.

Run log: CSV with a header row; ``#`` comment lines anywhere (``# key: value`` lines
before the header are metadata, such as the sample period and the source); required
columns ``t`` (s), ``u`` (V applied to the motor, u_A, in force from this row on) and
``omega`` (rad/s as measured); any others (``u_req``, ``theta``, ``count``, ``t_us``, ...)
are kept.

Generous where it is unambiguous (a BOM, \\r\\n, whitespace around fields, blank lines,
column names in any case); anything else is refused with an InputError naming the file,
the line and what was expected. Files are streamed in bounded memory
(:mod:`minseg_tui.lab.saving.csvread`, which also caps lines, bytes and waits); values beyond what
a MinSeg produces are refused (LIMITS), and so are more rows than a lab produces.
"""

from __future__ import annotations

import csv
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from minseg_tui.errors import InputError
from minseg_tui.lab.content.identify_says import identify_refusal_words
from minseg_tui.lab.content.log_says import header_words, refusal_words
from minseg_tui.lab.saving.csvread import CsvColumns, Stdin, read_csv
from minseg_tui.model.identify import Reading
from minseg_tui.model.runlog import (
    COLUMN_UNITS,
    RunLog,
    clock_problem,
    command,
    find_edges,
    header_problem,
)
from minseg_tui.quantities import NUMBER

TABLE_COLUMNS: dict[str, str] = {
    "u_req": "V",
    "u_ss": "V",
    "omega_ss": "rad/s",
    "i_ss": "mA",
}
"""Columns of TABLE.csv and their units."""

LOG_REQUIRED: dict[str, str] = {name: unit for name, unit in COLUMN_UNITS.items()}
"""Required columns of a run log and their units (the model's :data:`~minseg_tui.model.
runlog.COLUMN_UNITS`)."""

LOG_NUMERIC: dict[str, str] = {
    "u_req": "V",
    "theta": "rad",
    "count": "counts",
    "t_us": "us",
    "seq": "samples",
    "current": "A",
    "omega_true": "rad/s",
}
"""Optional run-log columns that must hold numbers when present."""

MAX_TABLE_ROWS: int = 1000
"""Most rows a table may have (one per requested voltage; the lab's tables have about ten)."""

MAX_LOG_ROWS: int = 2_000_000
"""Most rows a run log may have: what the link keeps of one recording, 67 min of samples
at the board's fastest period of 2 ms."""

LIMITS: dict[str, tuple[float, str]] = {
    "t": (1e6, "the time of a lab recording (11 days)"),
    "u": (100.0, "a motor on a lab supply"),
    "u_req": (100.0, "a motor on a lab supply"),
    "u_ss": (100.0, "a motor on a lab supply"),
    "omega": (1e4, "a small DC motor (95 000 rpm)"),
    "omega_ss": (1e4, "a small DC motor (95 000 rpm)"),
    "omega_true": (1e4, "a small DC motor (95 000 rpm)"),
    "omega_lab": (1e4, "a small DC motor (95 000 rpm)"),
    "theta": (1e9, "the angle of a lab recording"),
    "count": (1e12, "the encoder count of a lab recording"),
    "current": (100.0, "a small DC motor"),
    "i_ss": (1e5, "a small DC motor"),
}
"""The largest magnitude, in the column's unit, of each known column, and what that is a
plausible size for: beyond it a value is no MinSeg's (1e308 in t, 1e300 in theta)."""

UINT32_COLUMNS: dict[str, str] = {"t_us": "the board's micros()", "seq": "the board's counter"}
"""Columns the board writes as uint32: integers from 0 to 2^32 - 1."""

TS_KEYS: tuple[str, ...] = ("ts", "Ts", "sample_period")
"""Metadata keys that give the nominal sample period in s (``# ts: 0.025``)."""

TS_AGREE: float = 0.02
"""How far (relative) the metadata's sample period may be from the t column's median
interval: a loop's lateness or a clock's error. Outside it the log is refused: the speed may
have been computed over either period, and a 4 % difference is a 4 % error in K."""


def _show(value: float) -> str:
    return f"{value:.15g}"


def _check_limits(f: CsvColumns, units: Mapping[str, str]) -> None:
    """Refuse a value no MinSeg produces (LIMITS, UINT32_COLUMNS), naming its line."""
    for name in f.header:
        if not f.is_numeric(name):
            continue
        v = f.numbers(name)
        unit = units.get(name, "a number")
        if name in LIMITS:
            limit, what = LIMITS[name]
            _refuse_first(
                f,
                np.abs(v) > limit,
                v,
                f"expected |{name} ({unit})| below {limit:g}, a plausible size for {what}",
            )
        if name in UINT32_COLUMNS:
            _refuse_first(
                f,
                (v < 0) | (v > 2.0**32 - 1) | (v != np.floor(v)),
                v,
                f"expected {name} ({unit}) to be {UINT32_COLUMNS[name]}, an integer from 0 "
                "to 4294967295",
            )


def _refuse_first(
    f: CsvColumns, bad: NDArray[np.bool_], v: NDArray[np.float64], expected: str
) -> None:
    """Refuse the first row where ``bad`` holds: ``expected``, and the value it got."""
    rows = np.flatnonzero(bad)
    if rows.size:
        k = int(rows[0])
        raise InputError(f.source, int(f.lines[k]), f"{expected}; got {_show(float(v[k]))}")


def _check_sample_period(f: CsvColumns, t: NDArray[np.float64]) -> None:
    """A ``# ts:`` header (TS_KEYS) must be a period in s that agrees with the t column."""
    if t.size < 2:
        return
    median = float(np.median(np.diff(t)))
    for key in TS_KEYS:
        if key not in f.metadata:
            continue
        raw = f.metadata[key]
        first, *unit = raw.split() or [""]
        where = (f.source, f.metadata_lines[key])
        if not NUMBER.match(first) or not float(first) > 0 or unit not in ([], ["s"]):
            raise InputError(
                *where, f"expected the sample period in s after '# {key}:', got '{raw}'"
            )
        ts = float(first)
        if abs(median / ts - 1.0) > TS_AGREE:
            raise InputError(
                *where,
                f"expected the header '# {key}: {raw}' to agree with the t column within "
                f"{TS_AGREE * 100:g} %; its median interval is {median:.6g} s ({median / ts:.4g} "
                "times the header's): which is right? Fix the other",
            )


# -- TABLE.csv ---------------------------------------------------------------------------------


def read_table(path: str | Path | Stdin) -> list[Reading]:
    """The steady-state readings of Tasks 4-5, one Reading per row (i_ss in mA as entered).

    Refuses (InputError): an empty file, a missing column, a field that is not a number, a
    value beyond what a MinSeg produces (LIMITS), more than MAX_TABLE_ROWS rows, and values
    that give no k_v or f: u_ss, omega_ss or i_ss zero or negative.
    """
    f = read_csv(
        path,
        expected_header=",".join(TABLE_COLUMNS),
        required=TABLE_COLUMNS,
        numeric=TABLE_COLUMNS,
        max_rows=MAX_TABLE_ROWS,
        rows_are="one per requested voltage; a lab table has about ten",
    )
    _check_limits(f, TABLE_COLUMNS)
    cols = {name: f.numbers(name) for name in TABLE_COLUMNS}
    readings = []
    for k, number in enumerate(f.lines.tolist()):
        r = Reading(
            u_req=float(cols["u_req"][k]),
            u_ss=float(cols["u_ss"][k]),
            omega_ss=float(cols["omega_ss"][k]),
            i_ss=float(cols["i_ss"][k]),
            line=number,
        )
        problem = r.problem()
        if problem:
            raise InputError(f.source, number, identify_refusal_words(problem))
        if not r.u_req > 0:  # the other values are > 0: a wheel turning forwards
            raise InputError(
                f.source,
                number,
                f"expected u_req > 0 V (the row's omega_ss, u_ss and i_ss say the wheel turns "
                f"forwards, as a positive request drives it), got {r.u_req:g}",
            )
        readings.append(r)
    return readings


def write_table(path: str | Path, readings: list[Reading]) -> None:
    """Write readings as TABLE.csv (V, V, rad/s, mA)."""
    lines = [",".join(TABLE_COLUMNS)]
    lines += [f"{r.u_req:g},{r.u_ss:g},{r.omega_ss:g},{r.i_ss:g}" for r in readings]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")


# -- run logs ---------------------------------------------------------------------------------


def read_run_log(
    path: str | Path | Stdin,
    require_step: bool = True,
    tee: Callable[[bytes], None] | None = None,
) -> RunLog:
    """A run log (see the module docstring) as a RunLog, ``source`` the path as given.

    Refuses (InputError naming file and line): a header field the log format defines with a
    value it does not allow (``# cpr:`` not a whole number above 0, ``# omega_over:`` other
    than interval or nominal), an empty file, a missing t/u/omega column,
    a field that is not a number in t, u, omega or a known numeric column (u_req, theta,
    count, t_us, seq, ...), a value beyond what a MinSeg produces (LIMITS, UINT32_COLUMNS),
    more than MAX_LOG_ROWS rows, time (t, or t_us modulo 2^32) that does not increase, a
    ``# ts:`` header more than TS_AGREE (2 %) from t's median interval, a t_us that does not
    keep time with t (within runlog.CLOCK_AGREE, 2 %), and, unless ``require_step``
    is False, a log in which the command (u_req, else u) never steps or u is 0 on every
    row while u_req steps (no voltage on the motor: no K). Unknown columns are kept: as
    numbers when every field is one, else as text. ``tee`` is given the file's bytes as
    they are read (see :func:`~minseg_tui.lab.saving.csvread.read_csv`): when this returns,
    they are the very bytes checked.
    """
    units = {**LOG_REQUIRED, **LOG_NUMERIC}
    f = read_csv(
        path,
        expected_header=",".join(LOG_REQUIRED),
        required=LOG_REQUIRED,
        numeric=units,
        max_rows=MAX_LOG_ROWS,
        rows_are="what the link keeps of one recording, 67 min at 2 ms",
        tee=tee,
    )
    for key, value in f.metadata.items():
        refused = header_problem(key, value)
        if refused:
            raise InputError(f.source, f.metadata_lines[key], header_words(refused))
    _check_limits(f, units)
    lines = f.lines
    t = f.numbers("t")
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        raise InputError(
            f.source,
            int(lines[k]),
            f"expected t (s) to increase, got {_show(float(t[k]))} after "
            f"{_show(float(t[k - 1]))} on line {lines[k - 1]}",
        )
    u = f.numbers("u")
    omega = f.numbers("omega")
    extra: dict[str, NDArray[Any]] = {}
    for name in f.header:
        if name in LOG_REQUIRED:
            continue
        if not f.is_numeric(name):
            extra[name] = f.texts(name)
        elif f.is_integer(name):
            extra[name] = f.numbers(name).astype(np.int64)
        else:
            extra[name] = f.numbers(name)
    if "t_us" in extra:  # the board's micros(): increases, wrapping at 2^32
        still = np.flatnonzero(np.mod(np.diff(extra["t_us"].astype(np.float64)), 2.0**32) == 0)
        if still.size:
            k = int(still[0]) + 1
            raise InputError(
                f.source,
                int(lines[k]),
                f"expected t_us (us) to increase, got {int(extra['t_us'][k])} again",
            )
    _check_sample_period(f, t)
    if "t_us" in extra:
        clock = clock_problem(t, extra["t_us"])
        if clock:
            raise InputError(f.source, int(lines[0]), refusal_words(clock))
    log = RunLog(
        t=t, u=u, omega=omega, extra=extra, metadata=f.metadata, source=f.source, lines=lines
    )
    if require_step:
        check_step(log)
    return log


def check_step(log: RunLog) -> None:
    """What :func:`read_run_log` refuses with ``require_step`` in a log it read (InputError
    naming file and line): a command (u_req, else u) that never steps, or u 0 V on every row
    while u_req steps."""
    cmd, name = command(log)
    edges = find_edges(cmd)
    line = log.line_of
    if not edges:
        lo, hi = float(np.min(cmd)), float(np.max(cmd))
        raise InputError(
            log.source,
            line(0),
            f"expected a step in {name} (V) from here on; it stays between {lo:g} and {hi:g} V "
            f"up to line {line(len(log) - 1)}",
        )
    if name != "u" and not np.any(log.u):
        raise InputError(
            log.source,
            line(edges[0].start),
            "expected u (V, the voltage on the motor) to follow the steps of u_req, the "
            "first here; it is 0 V on every row (was u left unrecorded?)",
        )


def _format_column(values: NDArray[Any]) -> list[str]:
    if values.dtype.kind in "iu":
        return [str(int(v)) for v in values]
    if values.dtype.kind == "f":
        return [format(float(v), ".10g") for v in values]
    return [str(v) for v in values]


def write_run_log(path: str | Path, log: RunLog, metadata: Mapping[str, str] | None = None) -> None:
    """Write ``log`` as a run log: ``# key: value`` lines (the log's metadata, updated with
    ``metadata``), then the header t,u,omega,<extra columns>, then one row per sample."""
    meta = {"format": "minseg-tui step log 1", **dict(log.metadata), **dict(metadata or {})}
    names = log.columns
    columns = [_format_column(np.asarray(log.column(n))) for n in names]
    with Path(path).open("w", encoding="utf-8", newline="") as fh:
        for k, v in meta.items():
            fh.write(f"# {k}: {' '.join(str(v).split())}\n")
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(names)
        writer.writerows(zip(*columns, strict=True))
