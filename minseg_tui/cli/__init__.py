"""The `minseg-tui` command: the TUI by default, headless subcommands beside it.

Each subcommand lives in its own module with ``add_arguments(parser)`` and
``run(args) -> int``; this table is the only place that lists them.
Exit codes: 0 ok, 2 bad input or usage (or output that cannot be written, a closed stdout
included), 1 device or other failure (a memory limit met: the limit said in one line). A
headless command never prints a Python warning: numeric warnings while it computes become
one note on stderr.
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import io
import os
import sys
import warnings
from collections.abc import Sequence
from typing import NoReturn, TextIO

from minseg_tui.cli.output import one_line
from minseg_tui.errors import InputError, MinsegError

SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "identify": (
        "minseg_tui.cli.identify",
        "Tasks 6-15 from a table of steady-state readings (and a run log)",
    ),
    "analyze": (
        "minseg_tui.cli.analyze",
        "model check: what the first-order model gets wrong in a run log",
    ),
    "ports": ("minseg_tui.cli.ports", "list serial ports and say which looks like a MinSeg"),
    "sim": ("minseg_tui.cli.sim", "run a virtual MinSeg on a pseudo-terminal"),
    "board-check": (
        "minseg_tui.cli.board_check",
        "does the wheel turn when asked, and does the count follow it?",
    ),
    "flash": (
        "minseg_tui.cli.flash",
        "write the lab firmware to a MinSeg with avrdude and check that it answers",
    ),
    "report": ("minseg_tui.cli.report", "write a session's report (Markdown, HTML, CSV)"),
    "class": (
        "minseg_tui.cli.classview",
        "the class at a glance: one row per group of a sessions folder, what stands out",
    ),
    "tui": ("minseg_tui.cli.tui", "start the lab assistant (the default)"),
}


class _Parser(argparse.ArgumentParser):
    """argparse that exits with 2 and one line, as every bad input does here."""

    chosen: argparse.ArgumentParser | None = None
    """The subcommand's own parser (set on the top parser by :func:`build_parser`): an
    unknown argument is said in its name."""

    def error(self, message: str) -> NoReturn:
        # an argument with a newline or a terminal escape: still one line, nothing driven
        self.exit(2, f"{self.prog}: {one_line(message)} (see {self.prog} --help)\n")


def _available() -> dict[str, tuple[str, str]]:
    found = {}
    for name, (module, help_text) in SUBCOMMANDS.items():
        if importlib.util.find_spec(module) is not None:
            found[name] = (module, help_text)
    return found


def build_parser(selected: str | None = None) -> argparse.ArgumentParser:
    """The parser; only the ``selected`` subcommand's module is imported (start-up time).

    Every available subcommand is listed with its help line; its own arguments are added
    only when it is the one being run, so `minseg-tui sim` does not pay for the model.
    """
    parser = _Parser(prog="minseg-tui", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", parser_class=_Parser)
    for name, (module, help_text) in _available().items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if name == selected:
            importlib.import_module(module).add_arguments(p)
            parser.chosen = p
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the console script; returns the exit code."""
    args = list(sys.argv[1:] if argv is None else argv)
    command = args[0] if args and args[0] in SUBCOMMANDS else ""
    if sys.stdout is None:  # started with stdout closed (`>&-`): Python gives None
        return _fail(command, "cannot write the output (stdout is closed)", 2)
    try:
        return _main(args)
    except KeyboardInterrupt:
        return 130
    except MemoryError as exc:
        exc.__traceback__ = None  # let the frames and their arrays go before saying so
        del exc
        return _fail(command, f"ran out of memory: {memory_limit()}", 1)
    except BrokenPipeError:  # `minseg-tui ports | head`: the reader left, not an error of ours
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


def _main(args_list: list[str]) -> int:
    available = _available()
    if "tui" in available and (
        not args_list or (args_list[0].startswith("-") and args_list[0] not in ("-h", "--help"))
    ):
        args_list.insert(0, "tui")
    selected = args_list[0] if args_list and args_list[0] in available else None
    parser = build_parser(selected)
    args = _parse(parser, args_list)
    if args.command is None:
        parser.print_help()
        return 2
    module = importlib.import_module(available[args.command][0])
    if args.command == "tui":  # the app reports its own troubles on screen, start-up's here
        try:
            return int(module.run(args))
        except InputError as exc:
            return _fail(args.command, str(exc), 2)
        except MinsegError as exc:
            return _fail(args.command, str(exc), 1)
    out = _Stdout(sys.stdout)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RuntimeWarning)
        sys.stdout = out
        try:
            code = int(module.run(args))
            sys.stdout.flush()
        except InputError as exc:
            return _fail(args.command, str(exc), 2)
        except MinsegError as exc:
            return _fail(args.command, str(exc), 1)
        except OSError as exc:
            if exc is not out.failed or isinstance(exc, BrokenPipeError):
                raise
            _drop_stdout(out.stream)
            return _fail(args.command, f"cannot write the output ({exc.strerror})", 2)
        finally:
            sys.stdout = out.stream
    _note_warnings(args.command, caught)
    return code


class _Stdout(io.TextIOBase):
    """stdout, remembering the error a write or flush of it raised (a full disk, /dev/full),
    so that the error is told apart from one of a file the command writes."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.failed: OSError | None = None

    def write(self, text: str) -> int:
        try:
            return self.stream.write(text)
        except OSError as exc:
            self.failed = exc
            raise

    def flush(self) -> None:
        try:
            self.stream.flush()
        except OSError as exc:
            self.failed = exc
            raise

    def fileno(self) -> int:
        return self.stream.fileno()

    def isatty(self) -> bool:
        return self.stream.isatty()


def _parse(parser: argparse.ArgumentParser, args_list: list[str]) -> argparse.Namespace:
    """The parsed arguments; --help's text that cannot be written (argparse swallows the error)
    exits with 2 and one line, not 0 with nothing."""
    out = _Stdout(sys.stdout)
    sys.stdout = out
    try:
        args, extra = parser.parse_known_args(args_list)
        if extra:  # said by the subcommand's parser: 'minseg-tui class: ... (see minseg-tui
            # class --help)', not the top one's, which named no command (s37 attack)
            chosen = getattr(parser, "chosen", None) if args.command else None
            (chosen or parser).error(f"unrecognized arguments: {' '.join(extra)}")
        return args
    except SystemExit:
        if out.failed is not None and not isinstance(out.failed, BrokenPipeError):
            _drop_stdout(out.stream)
            raise SystemExit(
                _fail("", f"cannot write the output ({out.failed.strerror})", 2)
            ) from None
        raise
    finally:
        sys.stdout = out.stream


def _fail(command: str, message: str, code: int) -> int:
    if sys.stderr is not None:  # closed too: the exit code is all that can be said
        said = one_line(message)  # a name with a newline or an escape: still one line
        print(f"minseg-tui{' ' if command else ''}{command}: {said}", file=sys.stderr)
    return code


def memory_limit() -> str:
    """Which memory limit a MemoryError met, in words: the process's address-space limit
    (``ulimit -v``, RLIMIT_AS) or data limit (``ulimit -d``, RLIMIT_DATA) when one is set,
    in MiB, else the machine's memory."""
    import resource

    for name, what, shell in (
        ("RLIMIT_AS", "of address space", "ulimit -v"),
        ("RLIMIT_DATA", "of data", "ulimit -d"),
    ):
        which = getattr(resource, name, None)
        if which is None:
            continue
        soft, _hard = resource.getrlimit(which)
        if soft != resource.RLIM_INFINITY:
            return (
                f"this process may use at most {soft / 2**20:.0f} MiB {what} ({shell}, "
                f"{name}); raise that limit or give a shorter input"
            )
    return "the machine has no memory left for this input; give a shorter one"


def _drop_stdout(stream: TextIO) -> None:
    """Send what is still buffered for stdout nowhere, so that exit does not fail again."""
    try:
        fd = stream.fileno()
    except (OSError, ValueError):
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, fd)
    os.close(devnull)


def _note_warnings(command: str, caught: list[warnings.WarningMessage]) -> None:
    """One line for the numeric warnings (RuntimeWarning, numpy's RankWarning) a computation
    raised, instead of Python's dump of each; other warnings are shown as Python shows them."""
    numeric = [w for w in caught if issubclass(w.category, RuntimeWarning)]
    for w in caught:
        if w not in numeric:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    if not numeric:
        return
    caught = numeric
    first = caught[0]
    where = f"{os.path.basename(first.filename)}:{first.lineno}"
    more = f" and {len(caught) - 1} more" if len(caught) > 1 else ""
    print(
        f"minseg-tui {command}: note: the computation warned ({first.message} in {where}{more}); "
        "a figure may rest on an unusual input",
        file=sys.stderr,
    )
