"""The lab's two file formats: the table of steady-state readings and step logs.

TABLE.csv: header ``u_req,u_ss,omega_ss,i_ss`` (V, V, rad/s, mA, the manual's units), one
row per requested voltage.

Step log: CSV with a header row; ``#`` comment lines anywhere (``# key: value`` lines
before the header are metadata, such as the sample period and the source); required
columns ``t`` (s), ``u`` (V applied to the motor, u_A, in force from this row on) and
``omega`` (rad/s as measured); any others (``u_req``, ``theta``, ``count``, ``t_us``, ...)
are kept.

Generous where it is unambiguous (a BOM, \\r\\n, whitespace around fields, blank lines,
column names in any case); anything else is refused with an InputError naming the file,
the line and what was expected.
"""

from __future__ import annotations

import csv
import math
import re
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from minseg_tui.errors import InputError
from minseg_tui.model.identify import Reading
from minseg_tui.model.steplog import StepLog, command, find_edges, header_problem

TABLE_COLUMNS: dict[str, str] = {
    "u_req": "V",
    "u_ss": "V",
    "omega_ss": "rad/s",
    "i_ss": "mA",
}
"""Columns of TABLE.csv and their units."""

LOG_REQUIRED: dict[str, str] = {"t": "s", "u": "V", "omega": "rad/s"}
"""Required columns of a step log and their units."""

LOG_NUMERIC: dict[str, str] = {
    "u_req": "V",
    "theta": "rad",
    "count": "counts",
    "t_us": "us",
    "seq": "samples",
    "current": "A",
    "omega_true": "rad/s",
}
"""Optional step-log columns that must hold numbers when present."""

_INT = re.compile(r"^[+-]?\d+$")
_META = re.compile(r"^#\s*([A-Za-z_][\w.-]*)\s*[:=]\s*(.*?)\s*$")


def _read_text(path: Path) -> str:
    try:
        raw = path.read_bytes()
    except IsADirectoryError:
        raise InputError(str(path), None, "expected a file, got a directory") from None
    except OSError as exc:
        raise InputError(str(path), None, f"cannot read the file ({exc.strerror})") from None
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise InputError(str(path), line, "expected UTF-8 text (a CSV file)") from None


class _Csv:
    """A CSV file split into comments, a header and data rows, each with its line number."""

    def __init__(self, path: Path, expected_header: str) -> None:
        self.source = str(path)
        text = _read_text(path)
        self.metadata: dict[str, str] = {}
        self.metadata_lines: dict[str, int] = {}
        self.header: list[str] = []
        self.header_line = 0
        self.rows: list[tuple[int, list[str]]] = []
        for number, line in enumerate(text.splitlines(), start=1):
            stripped = line.strip()
            if not stripped:
                continue
            if stripped.startswith("#"):
                m = _META.match(stripped)
                if m and not self.header:
                    self.metadata[m.group(1)] = m.group(2)
                    self.metadata_lines[m.group(1)] = number
                continue
            fields = [f.strip() for f in next(csv.reader([stripped]))]
            if not self.header:
                self.header, self.header_line = [f.lower() for f in fields], number
                self._check_header(expected_header)
            else:
                self.rows.append((number, fields))
        if not self.header:
            raise InputError(
                self.source, None, f"expected a header row '{expected_header}', the file is empty"
            )
        if not self.rows:
            raise InputError(
                self.source, self.header_line, "expected data rows after the header, found none"
            )

    def _check_header(self, expected: str) -> None:
        if len(self.header) == 1 and ";" in self.header[0]:
            raise InputError(
                self.source,
                self.header_line,
                f"expected columns separated by commas ('{expected}'), got semicolons",
            )
        seen: set[str] = set()
        for name in self.header:
            if not name:
                raise InputError(
                    self.source,
                    self.header_line,
                    f"expected a name for every column ('{expected}'), found an empty one",
                )
            if name in seen:
                raise InputError(
                    self.source,
                    self.header_line,
                    f"expected each column once, '{name}' appears twice",
                )
            seen.add(name)

    def require(self, required: Mapping[str, str]) -> None:
        missing = [c for c in required if c not in self.header]
        if missing:
            want = ", ".join(f"{c} ({required[c]})" for c in missing)
            raise InputError(
                self.source,
                self.header_line,
                f"expected a column {want}; found {','.join(self.header)}",
            )

    def check_widths(self) -> None:
        for number, fields in self.rows:
            if len(fields) != len(self.header):
                hint = (
                    " (a decimal comma? write 2.5, not 2,5)"
                    if len(fields) > len(self.header)
                    else ""
                )
                raise InputError(
                    self.source,
                    number,
                    f"expected {len(self.header)} fields ({','.join(self.header)}), got {len(fields)}{hint}",
                )

    def numbers(self, name: str, unit: str) -> NDArray[np.float64]:
        """Column ``name`` as floats; InputError on text, empty, NaN or infinity."""
        j = self.header.index(name)
        out = np.empty(len(self.rows))
        for k, (number, fields) in enumerate(self.rows):
            out[k] = _number(fields[j], self.source, number, name, unit)
        return out

    def lines(self) -> NDArray[np.int64]:
        return np.array([n for n, _ in self.rows], dtype=np.int64)


def _number(text: str, source: str, line: int, name: str, unit: str) -> float:
    what = f"expected a number for {name} ({unit})"
    if not text:
        raise InputError(source, line, f"{what}, got an empty field")
    try:
        value = float(text)
    except ValueError:
        raise InputError(source, line, f"{what}, got '{text}'") from None
    if not math.isfinite(value):
        raise InputError(source, line, f"{what}, got '{text}'")
    return value


# -- TABLE.csv ---------------------------------------------------------------------------------


def read_table(path: str | Path) -> list[Reading]:
    """The steady-state readings of Tasks 4-5, one Reading per row (i_ss in mA as entered).

    Refuses (InputError): an empty file, a missing column, a field that is not a finite
    number, and values that give no k_v or f: u_ss, omega_ss or i_ss zero or negative.
    """
    f = _Csv(Path(path), ",".join(TABLE_COLUMNS))
    f.require(TABLE_COLUMNS)
    f.check_widths()
    cols = {name: f.numbers(name, unit) for name, unit in TABLE_COLUMNS.items()}
    readings = []
    for k, (number, _) in enumerate(f.rows):
        r = Reading(
            u_req=float(cols["u_req"][k]),
            u_ss=float(cols["u_ss"][k]),
            omega_ss=float(cols["omega_ss"][k]),
            i_ss=float(cols["i_ss"][k]),
            line=number,
        )
        problem = r.problem()
        if problem:
            raise InputError(f.source, number, problem)
        readings.append(r)
    return readings


def write_table(path: str | Path, readings: list[Reading]) -> None:
    """Write readings as TABLE.csv (V, V, rad/s, mA)."""
    lines = [",".join(TABLE_COLUMNS)]
    lines += [f"{r.u_req:g},{r.u_ss:g},{r.omega_ss:g},{r.i_ss:g}" for r in readings]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")


# -- step logs ---------------------------------------------------------------------------------


def read_step_log(path: str | Path, require_step: bool = True) -> StepLog:
    """A step log (see the module docstring) as a StepLog, ``source`` the path as given.

    Refuses (InputError naming file and line): a header field the log format defines with a
    value it does not allow (``# cpr:`` not a whole number above 0, ``# omega_over:`` other
    than interval or nominal), an empty file, a missing t/u/omega column,
    a field that is not a finite number in t, u, omega or a known numeric column (u_req,
    theta, count, t_us, seq, ...), time (t, or t_us modulo 2^32) that does not increase,
    and, unless ``require_step`` is False, a log in which the command (u_req, else u) never steps.
    Unknown columns are kept: as numbers when every field is one, else as text.
    """
    f = _Csv(Path(path), ",".join(LOG_REQUIRED))
    for key, value in f.metadata.items():
        refused = header_problem(key, value)
        if refused:
            raise InputError(f.source, f.metadata_lines[key], refused)
    f.require(LOG_REQUIRED)
    f.check_widths()
    lines = f.lines()
    t = f.numbers("t", "s")
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        raise InputError(
            f.source,
            int(lines[k]),
            f"expected t (s) to increase, got {f.rows[k][1][f.header.index('t')]} after "
            f"{f.rows[k - 1][1][f.header.index('t')]} on line {lines[k - 1]}",
        )
    u = f.numbers("u", "V")
    omega = f.numbers("omega", "rad/s")
    extra: dict[str, NDArray] = {}
    for j, name in enumerate(f.header):
        if name in LOG_REQUIRED:
            continue
        texts = [fields[j] for _, fields in f.rows]
        if name in LOG_NUMERIC or all(_is_number(s) for s in texts):
            values = f.numbers(name, LOG_NUMERIC.get(name, "a number"))
            if all(_INT.match(s) for s in texts):
                extra[name] = values.astype(np.int64)
            else:
                extra[name] = values
        else:
            extra[name] = np.array(texts, dtype=str)
    if "t_us" in extra:  # the board's micros(): increases, wrapping at 2^32
        still = np.flatnonzero(np.mod(np.diff(extra["t_us"].astype(np.float64)), 2.0**32) == 0)
        if still.size:
            k = int(still[0]) + 1
            raise InputError(
                f.source,
                int(lines[k]),
                f"expected t_us (us) to increase, got {int(extra['t_us'][k])} again",
            )
    log = StepLog(
        t=t, u=u, omega=omega, extra=extra, metadata=f.metadata, source=f.source, lines=lines
    )
    if require_step:
        cmd, name = command(log)
        if not find_edges(cmd):
            lo, hi = float(np.min(cmd)), float(np.max(cmd))
            raise InputError(
                f.source,
                int(lines[0]),
                f"expected a step in {name} (V) from here on; it stays between {lo:g} and {hi:g} V "
                f"up to line {lines[-1]}",
            )
    return log


def _is_number(text: str) -> bool:
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def _format_column(values: NDArray) -> list[str]:
    if values.dtype.kind in "iu":
        return [str(int(v)) for v in values]
    if values.dtype.kind == "f":
        return [format(float(v), ".10g") for v in values]
    return [str(v) for v in values]


def write_step_log(
    path: str | Path, log: StepLog, metadata: Mapping[str, str] | None = None
) -> None:
    """Write ``log`` as a step log: ``# key: value`` lines (the log's metadata, updated with
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
