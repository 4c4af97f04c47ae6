"""`minseg-tui board-check`: does the wheel turn when asked, and does the count follow it?

It drives 1.8 V for half a second and says what it found (minseg_tui/device/boardcheck.py):
ok; the count falls (then it sets the board's counting direction, unless --no-fix); or no
counts, with what to look at. The question "did the wheel turn?" is asked only at a
terminal; otherwise the text gives both answers. ``--turn`` counts one revolution turned by
hand instead (720 expected). Exit 0 ok, 1 a device problem (or a check that failed), 2 usage.

Without --port it uses the board discovery finds; the virtual MinSeg only with --sim.
"""

from __future__ import annotations

import argparse
import sys
import threading
import urllib.parse

from minseg_tui.cli.output import print_json
from minseg_tui.device import discovery
from minseg_tui.device.boardcheck import (
    CPR,
    check_board,
    count_revolution,
)
from minseg_tui.device.factory import VIRTUAL, open_device
from minseg_tui.device.link import Link
from minseg_tui.device.port import not_a_device
from minseg_tui.device.virtual import wiring_faults
from minseg_tui.errors import DeviceError, InputError
from minseg_tui.quantities import EntryRefused, parse_quantity


def _seconds(text: str) -> float:
    """--turn-seconds read as the TUI reads a number typed in an entry (the decimal comma
    too), refused with its words; its range is checked in :func:`run`."""
    try:
        return parse_quantity(text, "", allow_negative=True, allow_zero=True).value
    except EntryRefused as exc:
        raise argparse.ArgumentTypeError(exc.expected) from None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """--port, --sim (with --fault), --json, --no-fix, --turn (with --turn-seconds)."""
    parser.add_argument("--port", metavar="P", help="the board's port or a pyserial URL")
    parser.add_argument(
        "--sim", action="store_true", help="check the virtual MinSeg (for practice)"
    )
    parser.add_argument(
        "--fault",
        action="append",
        metavar="NAME",
        help="with --sim: a wiring fault (encoder-off, encoder-reversed, motor-off)",
    )
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument(
        "--no-fix",
        action="store_true",
        help="a reversed count is reported, not fixed (by default DIR is sent)",
    )
    parser.add_argument(
        "--turn",
        action="store_true",
        help=f"count one revolution turned by hand instead ({CPR} expected)",
    )
    parser.add_argument(
        "--turn-seconds",
        type=_seconds,
        default=10.0,
        metavar="S",
        help="with --turn and no terminal: how long to count, s (default 10)",
    )


def _spec(args: argparse.Namespace) -> str:
    """The port or URL to open (InputError for a bad combination, DeviceError: no board)."""
    if args.fault and not args.sim:
        raise InputError("--fault", None, "a wiring fault needs --sim (the virtual MinSeg)")
    if args.sim and args.port:
        raise InputError("--sim", None, "expected either --port or --sim, not both")
    if not 0 < args.turn_seconds <= 600:
        raise InputError("--turn-seconds", None, f"expected 0 to 600 s, got {args.turn_seconds:g}")
    if args.sim:
        spec = VIRTUAL
        if args.fault:
            try:
                wiring_faults(",".join(args.fault))
            except ValueError as exc:
                raise InputError("--fault", None, str(exc).replace("option fault: ", "")) from None
            spec += "&" + urllib.parse.urlencode({"fault": ",".join(args.fault)})
        return spec
    if args.port:
        why = not_a_device(str(args.port))
        if why:
            raise InputError("--port", None, why)
        return str(args.port)
    found = discovery.find_board()
    if found is None:
        raise DeviceError(
            "no MinSeg found (minseg-tui ports says why each port was not taken): plug the "
            "board in, give --port, or --sim to check the virtual MinSeg"
        )
    return found.device


def _at_terminal() -> bool:
    return sys.stdin is not None and sys.stdin.isatty() and sys.stderr.isatty()


def _ask_turned() -> bool | None:
    """At a terminal: did the wheel turn? (None: no answer)."""
    while True:
        print("Did the wheel turn? [y/n] ", end="", file=sys.stderr, flush=True)
        answer = sys.stdin.readline()
        if not answer:
            return None
        a = answer.strip().lower()
        if a in ("y", "yes", "j", "ja"):
            return True
        if a in ("n", "no", "nein"):
            return False


def run(args: argparse.Namespace) -> int:
    """Open the board, check it, print the result; 0 when ok, 1 otherwise."""
    spec = _spec(args)
    link = open_device(spec)
    try:
        if args.turn:
            return _turn(link, args)
        result = check_board(
            link, fix=not args.no_fix, wheel_turned=_ask_turned if _at_terminal() else None
        )
    finally:
        link.close()
    if args.json:
        print_json(result.as_json(), indent=2)
    else:
        print(result.text)
    return 0 if result.ok else 1


def _turn(link: Link, args: argparse.Namespace) -> int:
    pressed = threading.Event()
    if _at_terminal():
        print(
            "Turn the wheel one revolution by hand (mark it first), then press Enter.",
            file=sys.stderr,
            flush=True,
        )

        def wait_enter() -> None:
            sys.stdin.readline()
            pressed.set()

        threading.Thread(target=wait_enter, daemon=True).start()
        timeout = 600.0
    else:
        print(
            f"Turn the wheel one revolution by hand within {args.turn_seconds:g} s.",
            file=sys.stderr,
            flush=True,
        )
        timeout = args.turn_seconds
    result = count_revolution(link, pressed.is_set, timeout=timeout)
    if args.json:
        print_json({"ok": result.ok, "counts": result.counts, "text": result.text}, indent=2)
    else:
        print(result.text)
    return 0 if result.ok else 1
