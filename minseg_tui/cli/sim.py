"""`minseg-tui sim`: a virtual MinSeg on a pseudo-terminal, until Ctrl-C or SIGTERM.

It prints the device path; any serial monitor (or `minseg-tui --port PATH`) can open
it at 500000 baud. Options are the virtual board's settings (seed, parameters, hidden
effects, faults; --fault for the wiring faults a board at the bench has). Ctrl-C and `kill` both stop it cleanly (the pty closed, the --link
symlink removed) with exit code 0.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
from types import FrameType

from minseg_tui.cli.output import not_stdio
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.virtual import (
    OPTIONS,
    WIRING_FAULTS,
    VirtualBoard,
    VirtualSettings,
    settings_from,
)
from minseg_tui.errors import InputError
from minseg_tui.quantities import NUMBER, EntryRefused, parse_quantity


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """One option per virtual board setting, plus --link for a stable symlink."""
    for name, opt in OPTIONS.items():
        flag = f"--{name}"
        if opt.kind is bool:
            parser.add_argument(flag, action="store_true", default=None, help=opt.help)
        else:
            parser.add_argument(
                flag, type=str, default=None, metavar=opt.kind.__name__.upper(), help=opt.help
            )
    parser.add_argument(
        "--fault",
        action="append",
        metavar="NAME",
        help=f"a wiring fault: {', '.join(WIRING_FAULTS)} (repeat it or join with commas "
        "for several)",
    )
    parser.add_argument("--link", metavar="PATH", help="also make a symlink PATH to the device")


def _ours(path: str) -> bool:
    """``path`` is a link a sim makes (a symlink to a pseudo-terminal, maybe one left by a sim
    that was killed), which may be replaced."""
    if not os.path.islink(path):
        return False
    return os.readlink(path).startswith(("/dev/pts/", "/dev/tty"))


def check_link_path(path: str) -> None:
    """InputError unless ``path`` (and the ``.new`` name the link is made under) is free or
    a link of ours: the sim never replaces a file, a folder or another symlink."""
    for p in (path, f"{path}.new"):
        if os.path.lexists(p) and not _ours(p):
            kind = (
                "a folder"
                if os.path.isdir(p) and not os.path.islink(p)
                else "a symlink"
                if os.path.islink(p)
                else "a file"
            )
            raise InputError(
                p,
                None,
                f"expected a new path for the device link; this is {kind} that is not a "
                "link to a pseudo-terminal, and it is left as it is",
            )


def _read(name: str, raw: str) -> str | float:
    """An option's text, or, for a number the TUI reads in an entry but settings_from does
    not take (the decimal comma: '5,3' is 5.3), its value; settings_from checks the range
    and refuses the rest with its words."""
    if OPTIONS[name].kind is not float or NUMBER.match(raw.strip()):
        return raw
    try:
        return parse_quantity(raw, "", allow_negative=True, allow_zero=True).value
    except EntryRefused:
        return raw


def settings_of(args: argparse.Namespace) -> VirtualSettings:
    """The virtual board's settings from the command line; InputError for a bad option."""
    values: dict[str, str | float | bool] = {
        name: _read(name, v) if isinstance(v, str) else v
        for name in OPTIONS
        if (v := getattr(args, name)) is not None
    }
    if args.fault:
        values["fault"] = ",".join(args.fault)
    try:
        return settings_from(values)
    except ValueError as exc:
        raise InputError("", None, str(exc)) from None


class _Terminated(Exception):
    """SIGTERM arrived (`kill PID`, a service manager stopping the sim)."""


def _terminate(signum: int, frame: FrameType | None) -> None:
    raise _Terminated


def run(args: argparse.Namespace) -> int:
    """Serve until Ctrl-C or SIGTERM; exit 0. (Started in the background by a shell
    without job control, the sim inherits Ctrl-C ignored, as every such job does: stop it
    with `kill`.)"""
    settings = settings_of(args)
    if args.link is not None:
        if not args.link:
            raise InputError("--link", None, "expected a path for the device link, got ''")
        not_stdio(
            args.link, "--link", "a path for the device link", "stdout holds the device's path"
        )
        check_link_path(args.link)
    try:
        server = PtyServer(VirtualBoard(settings), link_path=args.link)
    except OSError as exc:
        raise InputError(
            args.link or "pty", None, f"cannot make the device ({exc.strerror})"
        ) from None
    signal.signal(signal.SIGTERM, _terminate)  # before the path is out: a kill may follow it
    try:
        print(server.path, flush=True)
        if args.link:
            print(f"(symlink to {server.slave_name})", file=sys.stderr, flush=True)
        server.serve_forever()
    except (KeyboardInterrupt, _Terminated):
        pass
    finally:
        server.stop()
    return 0
