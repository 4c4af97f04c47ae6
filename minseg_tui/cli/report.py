"""`minseg-tui report SESSION [--sessions DIR]`: write a session's report headless.

SESSION is a session folder or a session id under --sessions (default ./sessions).
Writes report.md (its figures as report-figure-1.svg, ... beside it, linked relatively) and
report.html (whole in one file) into the session's folder and prints the two paths and
the run CSVs. A missing or damaged session, or a folder the report cannot be written
into (a read-only stick): one line on stderr, exit 2.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from minseg_tui.cli.output import folder, not_stdio
from minseg_tui.errors import InputError
from minseg_tui.lab.saving.store import SessionDamaged, os_reason, resolve
from minseg_tui.lab.state.session import Session
from minseg_tui.report.write import write_report


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Arguments of `minseg-tui report`."""
    parser.add_argument(
        "session", metavar="SESSION", help="a session folder, or a session id under --sessions"
    )
    parser.add_argument(
        "--sessions",
        metavar="DIR",
        type=folder,
        default=Path("sessions"),
        help="folder holding the sessions (default: ./sessions)",
    )


def run(args: argparse.Namespace) -> int:
    """Write the report; 0 on success (InputError -> exit 2 via the CLI, one line)."""
    if not args.session:  # Path('') is '.': the folder the command was started in
        raise InputError("SESSION", None, "expected a session folder or a session id, got ''")
    not_stdio(args.session, "SESSION", "a session folder or a session id")
    not_stdio(args.sessions, "--sessions", "the folder holding the sessions")
    folder = resolve(args.session, args.sessions)
    session = Session.open(folder, readonly=True)
    if session.damaged:
        raise SessionDamaged(
            str(folder), None, f"no report of a damaged session: {session.damaged}"
        )
    try:
        written = write_report(session)
    except IsADirectoryError as exc:  # a folder of the report's name: moving it away does
        raise InputError(
            str(folder),
            None,
            f"cannot write the report into the session folder ({os_reason(exc)}): a folder "
            "stands where the report's file goes; move or rename it and run the report again",
        ) from None
    except OSError as exc:
        raise InputError(
            str(folder),
            None,
            f"cannot write the report into the session folder ({os_reason(exc)}): copy the "
            "folder where it can be written and run the report there",
        ) from None
    print(written.markdown)
    print(written.html)
    for p in written.runs:
        print(p)
    return 0
