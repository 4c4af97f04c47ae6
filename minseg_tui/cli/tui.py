"""`minseg-tui [--port P] [--sim] [--sessions DIR]`: the lab assistant in the terminal."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from minseg_tui.cli.output import not_stdio
from minseg_tui.errors import InputError
from minseg_tui.lab.saving.store import list_sessions


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of the TUI."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--port", help="serial port of the board (or a pyserial URL); default: find it"
    )
    group.add_argument(
        "--sim", action="store_true", help="use the virtual MinSeg even if a board is plugged in"
    )
    parser.add_argument(
        "--sessions", default="sessions", help="folder of the sessions (default: sessions)"
    )


def run(args: argparse.Namespace) -> int:
    """Start the app; returns 0 when the user quits, 128 + n when signal n (SIGTERM,
    SIGHUP) ended it, what was typed stored first."""
    from minseg_tui.report.write import write_class, write_report
    from minseg_tui.ui.app import make_app
    from minseg_tui.ui.config import UiConfig

    if args.sessions == "":  # Path('') is '.': the folder it was started in, as sessions
        raise InputError("--sessions", None, "expected a folder, got ''")
    not_stdio(args.sessions, "--sessions", "the folder of the sessions")
    sessions = Path(args.sessions)
    if os.path.lexists(sessions) and not sessions.is_dir():
        raise InputError(str(sessions), None, "--sessions must be a folder")
    list_sessions(sessions)  # a folder that cannot be listed: one line, exit 2
    for name, stream in (("stdin", sys.stdin), ("stderr", sys.stderr)):
        # the app reads keys from stdin and draws on stderr: without a terminal it drew
        # into a file (or a pipe) and waited for keys for ever (s39 attack)
        if stream is None or not stream.isatty():
            raise InputError(
                name,
                None,
                "is not a terminal: the lab assistant runs in one; without a terminal use "
                "identify, analyze, report or class",
            )
    device = "sim" if args.sim else (args.port or "auto")
    app = make_app(
        UiConfig(device=device, sessions=sessions),
        lambda s: write_report(s).paths,
        write_class,
    )
    app.run()
    return app.return_code or 0  # 128 + n after signal n (SIGTERM: 143), as shells expect
