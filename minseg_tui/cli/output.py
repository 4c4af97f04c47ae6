"""What the headless commands write: JSON that is JSON, and files that never overwrite
their own input.

JSON has no NaN or Infinity (Python's json module writes them by default, and a reader in
another language refuses the whole document): a value that is not a finite number is
written as null, the JSON for "no value".
"""

from __future__ import annotations

import argparse
import errno
import json
import math
import os
import stat
from collections.abc import Mapping
from pathlib import Path
from typing import TextIO

from minseg_tui.errors import InputError
from minseg_tui.lab.saving.csvread import STDIN, Stdin

_CONTROLS = {c: repr(chr(c))[1:-1] for c in (*range(0x20), *range(0x7F, 0xA0))}


def one_line(text: str) -> str:
    """``text`` with its control characters written as escapes (``\\n``, ``\\x1b``): a
    file or folder name holding a newline or a terminal escape stays on its one line and
    cannot drive the terminal. Other characters (``ü``, spaces) are kept."""
    return text.translate(_CONTROLS)


def finite_or_none(obj: object) -> object:
    """``obj`` with every float that is NaN or infinite replaced by None (recursively through
    dicts, lists and tuples; tuples become lists, as JSON has them)."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: finite_or_none(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [finite_or_none(v) for v in obj]
    if hasattr(obj, "dtype") and hasattr(obj, "tolist"):  # a numpy scalar or array
        return finite_or_none(obj.tolist())
    return obj


def json_text(obj: object, indent: int | None = None) -> str:
    """``obj`` as strict JSON: NaN and infinities become null (see the module docstring)."""
    return json.dumps(finite_or_none(obj), indent=indent, allow_nan=False)


def print_json(obj: object, indent: int | None = None) -> None:
    """Print ``obj`` as strict JSON, one document and a newline."""
    print(json_text(obj, indent))


def input_file(name: str, flag: str = "") -> str | Stdin:
    """A file argument of a command that reads CSV: ``-`` is the standard input (read once:
    :func:`one_stdin`), any other name the file of that name."""
    if name == "":
        raise InputError(flag, None, "expected a file name (or - for stdin), got ''")
    return STDIN if name == "-" else name


def one_stdin(*inputs: tuple[str, str | Stdin | None]) -> None:
    """Refuse ``-`` given for more than one input ((flag, input) pairs): stdin is read once."""
    given = [flag for flag, value in inputs if isinstance(value, Stdin)]
    if len(given) > 1:
        raise InputError(
            " and ".join(given) + " -",
            None,
            "stdin can be read only once: give all but one of these as a file",
        )


def folder(text: str) -> Path:
    """An argument naming a folder (argparse's ``type``): '' is refused, since Path('') is
    '.', the folder the command was started in (s39 attack: ``class --out ''`` wrote the
    class report there without a word)."""
    if not text:
        raise argparse.ArgumentTypeError("expected a folder, got ''")
    return Path(text)


def not_stdio(name: str | Path, flag: str, what: str, why: str = "") -> None:
    """Refuse ``-`` for an argument that names a folder or a file to write (``what``): it
    would be taken as a file or folder called '-'; ``why``: what stdio holds instead."""
    if str(name) == "-":
        raise InputError(
            flag,
            None,
            f"expected {what}, got - ("
            + (why or "only a CSV to read, as identify's TABLE.csv, takes - for stdin")
            + ")",
        )


def _not_regular(path: Path) -> str | None:
    """What ``path`` is when it exists and is not a regular file (a FIFO, a device, a
    socket), else None."""
    try:
        mode = path.stat().st_mode
    except OSError:
        return None
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISFIFO(mode):
        return "a FIFO (a named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def open_output(path: str, what: str) -> TextIO:
    """``path`` opened for writing text (created or truncated) without ever blocking: a FIFO
    or a device swapped in after :func:`output_file` looked is refused (InputError)."""
    try:
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_NONBLOCK | os.O_CLOEXEC, 0o644)
    except OSError as exc:
        if exc.errno == errno.ENXIO:  # a FIFO nobody reads
            raise InputError(
                path, None, f"expected a regular file for the {what}; this is a FIFO, not written"
            ) from None
        raise
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise InputError(
                path, None, f"expected a regular file for the {what}; this is not one, not written"
            )
        os.set_blocking(fd, True)
        os.ftruncate(fd, 0)
        return os.fdopen(fd, "w", encoding="utf-8", newline="")
    except BaseException:
        os.close(fd)
        raise


def output_file(path: str, inputs: Mapping[str, str], what: str) -> Path:
    """``path`` checked as a file to write ``what`` into (InputError otherwise): a name, not a
    directory nor a FIFO, device or socket (writing would block or go nowhere), in a folder that exists, and none of ``inputs`` (path -> what it is, for the
    message), whatever the name: the same path spelled differently, a symlink or a hard
    link to it."""
    if not path:
        raise InputError(f"--{what}", None, f"expected a file name for the {what}, got ''")
    out = Path(path)
    if out.is_dir():
        raise InputError(path, None, f"expected a file name for the {what}, got a directory")
    kind = _not_regular(out)
    if kind:
        raise InputError(
            path, None, f"expected a regular file for the {what}; this is {kind}, not written"
        )
    for name, role in inputs.items():
        same = out.resolve() == Path(name).resolve()
        if not same and out.exists():
            try:
                same = os.path.samefile(out, name)
            except OSError:
                same = False
        if same:
            raise InputError(
                path,
                None,
                f"expected a new file for the {what}; this is {role} ({name}), which "
                "writing would destroy",
            )
    if not out.parent.is_dir():
        raise InputError(
            path, None, f"cannot write the {what}: the folder {out.parent} does not exist"
        )
    return out
