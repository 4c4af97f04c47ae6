"""Reading one of the lab's CSV files (a table, a run log) in bounded memory and time.

The file is streamed: lines are split, checked and turned into columns of numbers a block
of rows at a time, so memory grows with the numbers kept (8 bytes each), not with the
text. What no lab produces is refused with the limit in the message, as soon as it is
seen: a line over MAX_LINE_BYTES (a field of megabytes, or /dev/zero, which has no
newline), more rows than the caller allows, more than MAX_FILE_BYTES in all (an endless
input), and a pipe or device that sends nothing for PIPE_WAIT_S (a FIFO nobody writes).

A number is plain decimal notation, ``[+-]digits[.digits][e[+-]digits]``: Python's float()
also reads ``3_6``, ``nan``, ``infinity`` and non-ASCII digits, which no lab file holds.
Every refusal is an InputError naming the file, the line and what was expected.

A file whose header is separated by semicolons (what a German or Swedish spreadsheet
writes: ``t;u;omega`` and ``0,025;4,5;3,61``) is read as the comma file it stands for,
with decimal commas read as points, when that is unambiguous: the whole file uses one
decimal mark. A file with both (``2,5`` on one line, ``1.250`` on another, or
``1.234,5`` in one field) is refused: with semicolons a point may be a thousands
separator.
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
import re
import select
import stat
from collections.abc import Callable, Generator, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from minseg_tui.errors import InputError
from minseg_tui.quantities import NUMBER

MAX_LINE_BYTES: int = 4096
"""Longest line read, bytes (a lab CSV line is under 200; Python's csv module stops at
131072 characters per field)."""

MAX_FILE_BYTES: int = 512 * 2**20
"""Most bytes read from one file (a 2-million-row run log is about 200 MB)."""

PIPE_WAIT_S: float = 10.0
"""Longest wait for data from a pipe, FIFO or device, s."""


_NUMBER_BYTES = b"0123456789.eE+-\n"
_NUMBER_FIELD_BYTES = b"0123456789.eE+-\n,"
_INTEGER_BYTES = b"0123456789+-\n"
_NOT_SEPARATORS = bytes(b for b in range(256) if b not in b",\n")
_META = re.compile(r"^#\s*([A-Za-z_][\w.-]*)\s*[:=]\s*(.*?)\s*$")


def metadata_key(line: str) -> str | None:
    """The key of a ``# key: value`` line as :func:`read_csv` takes it before the header
    (``line`` stripped or not), else None."""
    m = _META.match(line.strip())
    return m.group(1) if m else None


_CHUNK = 1 << 20


class Stdin:
    """The standard input as a file to read (``-`` on the command line: see
    :func:`minseg_tui.cli.output.input_file`); named ``stdin`` in messages."""

    def __str__(self) -> str:
        return "stdin"


STDIN = Stdin()
"""The one :class:`Stdin`: :func:`read_csv` reads file descriptor 0 for it."""
_BLOCK = 8192  # rows turned into columns at a time


def _size(n: int) -> str:
    return f"{n / 2**20:.0f} MB" if n >= 2**20 else f"{n} bytes"


def _chunks(path: Path | Stdin, source: str) -> Generator[bytes, None, None]:
    """The file's bytes, a chunk at a time, within MAX_FILE_BYTES; never waits for ever."""
    try:
        if isinstance(path, Stdin):
            if os.isatty(0):
                raise InputError(
                    source, None, "is a terminal: pipe the file in (< FILE.csv) or give its name"
                )
            fd = os.dup(0)
            os.set_blocking(fd, False)
        else:
            fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except IsADirectoryError:
        raise InputError(source, None, "expected a file, got a directory") from None
    except OSError as exc:
        raise InputError(source, None, f"cannot read the file ({exc.strerror})") from None
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise InputError(source, None, "expected a file, got a directory")
        regular = stat.S_ISREG(st.st_mode)
        if regular and st.st_size > MAX_FILE_BYTES:
            raise InputError(
                source,
                None,
                f"expected a file of at most {_size(MAX_FILE_BYTES)}, this one has "
                f"{_size(st.st_size)}: no lab recording is that large",
            )
        if regular:
            os.set_blocking(fd, True)
        poller = select.poll()
        poller.register(fd, select.POLLIN)
        total = 0
        while True:
            if not regular and not poller.poll(PIPE_WAIT_S * 1000.0):
                raise InputError(
                    source,
                    None,
                    f"expected data, but nothing arrived for {PIPE_WAIT_S:g} s "
                    "(a pipe or FIFO that nothing writes to?)",
                )
            try:
                chunk = os.read(fd, _CHUNK)
            except BlockingIOError:
                continue
            except OSError as exc:
                raise InputError(source, None, f"cannot read the file ({exc.strerror})") from None
            if not chunk:
                return
            total += len(chunk)
            if total > MAX_FILE_BYTES:
                raise InputError(
                    source,
                    None,
                    f"expected at most {_size(MAX_FILE_BYTES)}; stopped reading there "
                    "(an endless input?)",
                )
            yield chunk
    finally:
        os.close(fd)


_SEPARATORS = "\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"  # str.splitlines() breaks on these too


def _longest_line(body: bytes) -> int:
    """Length in bytes of the longest line of ``body`` (lines split at b"\\n")."""
    ends = np.flatnonzero(np.frombuffer(body, dtype=np.uint8) == 10)
    bounds = np.concatenate(([-1], ends, [len(body)]))
    return int(np.max(np.diff(bounds))) - 1


def _batches(chunks: Iterator[bytes], source: str) -> Iterator[tuple[int, str]]:
    """Batches of whole lines: (number of the first line, the lines joined by \\n), numbered
    as str.splitlines() numbers them. A chunk's lines are decoded at once; only a chunk with
    a line break other than \\n or \\r\\n, or with bad UTF-8, is looked at line by line."""
    number = 0
    rest = b""
    first = True

    def too_long(at: int) -> InputError:
        return InputError(
            source,
            at,
            f"expected lines of at most {MAX_LINE_BYTES} bytes (a lab CSV line is far "
            "shorter); this one is longer, so reading stopped here",
        )

    def one_by_one(body: bytes) -> str:
        nonlocal number, first
        out: list[str] = []
        for segment in body.split(b"\n"):
            if len(segment) > MAX_LINE_BYTES:
                raise too_long(number + 1)
            try:
                text = segment.decode("utf-8-sig" if first else "utf-8")
            except UnicodeDecodeError:
                raise InputError(source, number + 1, "expected UTF-8 text (a CSV file)") from None
            first = False
            pieces = text.splitlines() or [""]
            number += len(pieces)
            out += pieces
        return "\n".join(out)

    def batch(body: bytes) -> tuple[int, str]:
        nonlocal number, first
        start = number + 1
        if _longest_line(body) > MAX_LINE_BYTES:
            return start, one_by_one(body)  # raises at the long line, with its number
        try:
            text = body.decode("utf-8-sig" if first else "utf-8").replace("\r\n", "\n")
        except UnicodeDecodeError:
            return start, one_by_one(body)
        if any(c in text for c in _SEPARATORS):
            return start, one_by_one(body)
        first = False
        number += text.count("\n") + 1
        return start, text

    for chunk in chunks:
        rest += chunk
        cut = rest.rfind(b"\n")
        if cut >= 0:
            yield batch(rest[:cut])
            rest = rest[cut + 1 :]
        if len(rest) > MAX_LINE_BYTES:
            raise too_long(number + 1)
    if rest:
        yield batch(rest)


@dataclass
class _Column:
    """One column being read: numbers block by block, or its texts when not all numbers."""

    name: str
    unit: str | None  # a unit: the column must hold numbers
    numbers: list[NDArray[np.float64]] = field(default_factory=list)
    texts: list[NDArray[np.str_]] = field(default_factory=list)
    numeric: bool = True  # every field so far is a number
    integers: bool = True  # every field so far is an integer


@dataclass
class CsvColumns:
    """A CSV file read: its ``# key: value`` lines before the header (and their lines),
    the header (lower case) and its line, the file line of every row, and the columns.

    A column is numbers (float64) when it must be or when every field is a number, else
    text.
    """

    source: str
    metadata: dict[str, str]
    metadata_lines: dict[str, int]
    header: list[str]
    header_line: int
    lines: NDArray[np.int64]
    _numbers: dict[str, NDArray[np.float64]]
    _integers: set[str]
    _texts: dict[str, NDArray[np.str_]]

    def __len__(self) -> int:
        return int(self.lines.size)

    def is_numeric(self, name: str) -> bool:
        """True if column ``name`` holds numbers."""
        return name in self._numbers

    def is_integer(self, name: str) -> bool:
        """True if every field of column ``name`` is an integer."""
        return name in self._integers

    def numbers(self, name: str) -> NDArray[np.float64]:
        """Column ``name`` as floats (KeyError if it is text)."""
        return self._numbers[name]

    def texts(self, name: str) -> NDArray[np.str_]:
        """Column ``name`` as text (KeyError if it is numbers)."""
        return self._texts[name]


def _numbers(texts: list[str], checked: bool = False) -> NDArray[np.float64] | None:
    """``texts`` as floats if every one is a NUMBER, else None. Fast: the characters are
    checked at once (digits, '.', 'e', 'E', '+', '-' only; ``checked``: they were), and
    within them float() reads exactly the NUMBER grammar, refusing an empty text or one
    like '1-2'."""
    if not checked:
        try:
            raw = "\n".join(texts).encode("ascii")
        except UnicodeEncodeError:
            return None
        if raw.translate(None, _NUMBER_BYTES):
            return None
    try:
        return np.fromiter(map(float, texts), dtype=np.float64, count=len(texts))
    except ValueError:
        return None


def _integers(texts: list[str]) -> bool:
    """True if every text (each already a NUMBER) is an integer."""
    return not "\n".join(texts).encode("ascii").translate(None, _INTEGER_BYTES)


def _bad_number(source: str, line: int, name: str, unit: str, text: str) -> InputError:
    what = f"expected a number for {name} ({unit})"
    if not text:
        return InputError(source, line, f"{what}, got an empty field")
    return InputError(source, line, f"{what}, got '{text}'")


class _Reader:
    """Rows to columns, a block at a time, with every check a row needs."""

    def __init__(
        self,
        source: str,
        expected_header: str,
        required: Mapping[str, str],
        numeric: Mapping[str, str],
        max_rows: int,
        rows_are: str,
    ) -> None:
        self.source = source
        self.expected = expected_header
        self.required = required
        self.numeric = numeric
        self.max_rows = max_rows
        self.rows_are = rows_are
        self.metadata: dict[str, str] = {}
        self.metadata_lines: dict[str, int] = {}
        self.header: list[str] = []
        self.header_line = 0
        self.columns: list[_Column] = []
        self.lines: list[NDArray[np.int64]] = []
        self.block: list[list[str]] = []  # per column: the texts of the rows not yet flushed
        self.block_lines: list[NDArray[np.int64]] = []  # their file lines, in pieces
        self.block_rows = 0
        self.block_numeric = True  # every text in the block is made of number characters
        self.rows = 0
        self.semicolons = False  # the header is separated by semicolons: see decomma
        self.marks: dict[str, tuple[int, str]] = {}  # decimal mark -> (line, field) first seen

    # -- one line at a time ----------------------------------------------------------------
    def line(self, number: int, line: str) -> None:
        stripped = line.strip()
        if not stripped:
            return
        if stripped.startswith("#"):
            m = _META.match(stripped)
            if m and not self.header:
                self.metadata[m.group(1)] = m.group(2)
                self.metadata_lines[m.group(1)] = number
            return
        if not self.header and ";" in stripped and "," not in stripped:
            self.semicolons = True
            fields = [f.strip() for f in next(csv.reader([stripped], delimiter=";"))]
            self.header_row(number, fields)
            return
        if '"' in stripped:  # quoted fields are rare: the csv module only for them
            fields = [f.strip() for f in next(csv.reader([stripped]))]
        else:
            fields = [f.strip() for f in stripped.split(",")]
        if not self.header:
            self.header_row(number, fields)
            return
        self.check_width(number, len(fields))
        self.count_rows(1, [number])
        for col, text in zip(self.block, fields, strict=True):
            col.append(text)
        self.block_lines.append(np.array([number], dtype=np.int64))
        self.block_rows += 1
        self.block_numeric = False  # checked column by column at the flush
        if self.block_rows >= _BLOCK:
            self.flush()

    # -- a batch of plain rows at once -----------------------------------------------------
    def plain_rows(self, first: int, text: str) -> bool:
        """Take the lines of ``text`` (numbered from ``first``) at once if every one is a plain
        data row: no comment, quote, blank or whitespace, the right number of fields. False
        if not (then nothing was taken)."""
        if not self.header or not text or text[0] == "\n" or text[-1] == "\n":
            return False
        if any(c in text for c in '#" \t') or "\n\n" in text:
            return False
        try:
            raw = text.encode("ascii")
        except UnicodeEncodeError:
            return False
        n, count = len(self.header), text.count("\n") + 1
        # every line n - 1 commas: the separators are n - 1 commas and a newline, repeated
        separators = raw.translate(None, _NOT_SEPARATORS)
        if separators != (b"," * (n - 1) + b"\n") * (count - 1) + b"," * (n - 1):
            return False
        numbers = np.arange(first, first + count, dtype=np.int64)
        self.count_rows(count, numbers)
        flat = text.replace("\n", ",").split(",")
        for j, col in enumerate(self.block):
            col += flat[j::n]
        self.block_lines.append(numbers)
        self.block_rows += count
        self.block_numeric = self.block_numeric and not raw.translate(None, _NUMBER_FIELD_BYTES)
        if self.block_rows >= _BLOCK:
            self.flush()
        return True

    # -- a semicolon file -------------------------------------------------------------------
    def decomma(self, first: int, text: str) -> str:
        """Lines of a semicolon file (numbered from ``first``) as the comma file they stand
        for: decimal commas read as points, semicolons as commas. InputError when the file
        uses both decimal marks (a point may then be a thousands separator)."""
        if "#" not in text and '"' not in text and not ("." in text and "," in text):
            for mark in ".,":
                at = text.find(mark)
                if at >= 0:
                    start = text.rfind("\n", 0, at) + 1
                    end = text.find("\n", at)
                    line = text[start : end if end >= 0 else len(text)]
                    self.decimal_mark(first + text.count("\n", 0, at), mark, line.split(";"))
            return text.replace(",", ".").replace(";", ",")
        out: list[str] = []
        for number, line in enumerate(text.split("\n"), start=first):
            if line.strip().startswith("#") or not line.strip():
                out.append(line)
                continue
            fields = next(csv.reader([line], delimiter=";")) if '"' in line else line.split(";")
            for mark in ".,":
                if any(mark in f for f in fields):
                    self.decimal_mark(number, mark, fields)
            buffer = io.StringIO()
            csv.writer(buffer, lineterminator="").writerow(f.replace(",", ".") for f in fields)
            out.append(buffer.getvalue())
        return "\n".join(out)

    def decimal_mark(self, number: int, mark: str, fields: list[str]) -> None:
        """Note that line ``number`` (its ``fields``) uses the decimal ``mark``; refuse it
        when the file has used the other one, or a field holds both."""
        both = next((f.strip() for f in fields if "." in f and "," in f), None)
        field = both or next(f.strip() for f in fields if mark in f)
        self.marks.setdefault(mark, (number, field))
        if both is None and len(self.marks) < 2:
            return
        other = "," if mark == "." else "."
        at, seen = self.marks.get(other, (number, field))
        if both is not None:
            said = f"'{field}' has both a point and a comma"
        else:
            said = (
                f"'{field}' has a decimal {'point' if mark == '.' else 'comma'}, and line {at} "
                f"a decimal {'point' if other == '.' else 'comma'} ('{seen}')"
            )
        raise InputError(
            self.source,
            number,
            f"expected one decimal mark in a file separated by semicolons; {said}, and a "
            "point may be a thousands separator there: save it again with one of them",
        )

    # -- checks ----------------------------------------------------------------------------
    def header_row(self, number: int, fields: list[str]) -> None:
        self.header, self.header_line = [f.lower() for f in fields], number
        where = (self.source, number)
        seen: set[str] = set()
        for name in self.header:
            if not name:
                raise InputError(
                    *where,
                    f"expected a name for every column ('{self.expected}'), found an empty one",
                )
            if name in seen:
                raise InputError(*where, f"expected each column once, '{name}' appears twice")
            seen.add(name)
        missing = [c for c in self.required if c not in self.header]
        if missing:
            want = ", ".join(f"{c} ({self.required[c]})" for c in missing)
            raise InputError(*where, f"expected a column {want}; found {','.join(self.header)}")
        self.columns = [_Column(name, self.numeric.get(name)) for name in self.header]
        self.block = [[] for _ in self.header]

    def check_width(self, number: int, width: int) -> None:
        if width != len(self.header):
            hint = " (a decimal comma? write 2.5, not 2,5)" if width > len(self.header) else ""
            raise InputError(
                self.source,
                number,
                f"expected {len(self.header)} fields ({','.join(self.header)}), got {width}{hint}",
            )

    def count_rows(self, n: int, numbers: Sequence[int] | NDArray[np.int64]) -> None:
        if self.rows + n > self.max_rows:
            over = self.max_rows - self.rows  # index of the first row too many
            raise InputError(
                self.source,
                int(numbers[over]),
                f"expected at most {self.max_rows} rows ({self.rows_are}); this is row "
                f"{self.max_rows + 1}, so reading stopped here",
            )
        self.rows += n

    # -- texts to numbers ------------------------------------------------------------------
    def flush(self) -> None:
        if not self.block_rows:
            return
        lines = np.concatenate(self.block_lines)
        for col, texts in zip(self.columns, self.block, strict=True):
            values = _numbers(texts, self.block_numeric) if col.numeric else None
            if col.unit is not None and values is None:
                k = next(k for k, s in enumerate(texts) if not NUMBER.match(s))
                raise _bad_number(self.source, int(lines[k]), col.name, col.unit, texts[k])
            if values is not None:
                if not np.all(np.isfinite(values)):  # 1e999: a number too large for a float
                    k = int(np.flatnonzero(~np.isfinite(values))[0])
                    unit = col.unit or "a number"
                    raise _bad_number(self.source, int(lines[k]), col.name, unit, texts[k])
                col.integers = col.integers and _integers(texts)
                col.numbers.append(values)
            else:
                col.numeric = col.integers = False
            if col.unit is None:
                col.texts.append(np.array(texts, dtype=np.str_))
            texts.clear()
        self.lines.append(lines)
        self.block_lines.clear()
        self.block_rows = 0
        self.block_numeric = True

    def result(self) -> CsvColumns:
        self.flush()
        numbers: dict[str, NDArray[np.float64]] = {}
        texts: dict[str, NDArray[np.str_]] = {}
        integers: set[str] = set()
        for col in self.columns:
            if col.numeric:
                numbers[col.name] = np.concatenate(col.numbers)
                if col.integers:
                    integers.add(col.name)
            else:
                texts[col.name] = np.concatenate(col.texts)
        return CsvColumns(
            source=self.source,
            metadata=self.metadata,
            metadata_lines=self.metadata_lines,
            header=self.header,
            header_line=self.header_line,
            lines=np.concatenate(self.lines),
            _numbers=numbers,
            _integers=integers,
            _texts=texts,
        )


def _teed(chunks: Iterator[bytes], tee: Callable[[bytes], None]) -> Iterator[bytes]:
    for chunk in chunks:
        tee(chunk)
        yield chunk


def read_csv(
    path: str | Path | Stdin,
    *,
    expected_header: str,
    required: Mapping[str, str],
    numeric: Mapping[str, str],
    max_rows: int,
    rows_are: str,
    tee: Callable[[bytes], None] | None = None,
) -> CsvColumns:
    """Read ``path`` (see the module docstring).

    expected_header: the header as a message shows it; required: column -> unit, each must
    be there; numeric: column -> unit of the columns that must hold numbers (the required
    ones and any known optional ones); max_rows: the most data rows read, and rows_are:
    what that limit stands for, for the message; tee: given each chunk of the file's bytes
    as it is read, before it is checked (all of them, in order, when this returns).
    Generous where it is unambiguous: a BOM, \\r\\n, blank lines, whitespace around fields,
    column names in any case, ``#`` comments anywhere.
    """
    source = str(path)
    reader = _Reader(source, expected_header, required, numeric, max_rows, rows_are)
    where = path if isinstance(path, Stdin) else Path(path)
    with contextlib.closing(_chunks(where, source)) as chunks:
        read: Iterator[bytes] = chunks if tee is None else _teed(chunks, tee)
        for first, text in _batches(read, source):
            while not reader.header and text:  # comments and the header, line by line
                line, _, text = text.partition("\n")
                reader.line(first, line)
                first += 1
            if reader.semicolons and text:
                text = reader.decomma(first, text)
            if reader.plain_rows(first, text):
                continue
            for number, line in enumerate(text.split("\n"), start=first):
                reader.line(number, line)
    if not reader.header:
        raise InputError(
            source, None, f"expected a header row '{expected_header}', the file is empty"
        )
    if not reader.rows:
        raise InputError(
            source, reader.header_line, "expected data rows after the header, found none"
        )
    return reader.result()
