"""`minseg-tui class [--sessions DIR] [--json] [--out DIR]`: the class at a glance.

One row per group of the sessions folder (names, date, the step reached, R, k_v, k_a, f,
K, T by the 63 % reading and by least squares, J, the model check's cause, the group's own
values against the computed ones) and, per group, what stands out, in words. ``--json``
prints ``{"groups": [...]}`` instead (SI units); ``--out DIR`` also writes class.md,
class.html (self-contained, fit to print) and class.csv into DIR.

The sessions are opened read-only: no lock is taken and nothing in them is written.

Bad input, one line on stderr and exit 2: a folder that does not exist or holds no
session, an --out that cannot be written, and a session that cannot be read at all (the
others are still listed and written first; the unreadable one is listed with why).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from minseg_tui.cli.output import folder, not_stdio, one_line, print_json
from minseg_tui.errors import InputError
from minseg_tui.lab.saving.store import os_reason
from minseg_tui.lab.views import classread
from minseg_tui.lab.views.classview import (
    MARKED,
    NOT_MARKED,
    OWN_VS_COMPUTED,
    QUANTITIES,
    ClassView,
    members,
    nothing_marked,
    own_cell,
)
from minseg_tui.quantities import MISSING


def _workers(text: str) -> int:
    """--workers as a whole number (argparse said 'invalid int value: 'abc'')."""
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected a whole number of at least 1, got {text!r}"
        ) from None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Arguments of `minseg-tui class`."""
    parser.add_argument(
        "--sessions",
        metavar="DIR",
        type=folder,
        default=Path("sessions"),
        help="folder holding the groups' sessions (default: ./sessions)",
    )
    parser.add_argument("--json", action="store_true", help="print the class as JSON (SI units)")
    parser.add_argument(
        "--out",
        metavar="DIR",
        type=folder,
        default=None,
        help="also write class.md, class.html and class.csv into DIR (made if needed)",
    )
    parser.add_argument(
        "--workers",
        metavar="N",
        type=_workers,
        default=None,
        help="processes for the sessions not read before (default: the CPUs; 1: none)",
    )


def text(view: ClassView) -> str:
    """The class as plain text: a table, then per group what stands out and what is missing."""
    head = [
        "#",
        "group",
        "members",
        "step",
        *(q.key for q in QUANTITIES),
        "model check",
        OWN_VS_COMPUTED,
    ]
    rows = [
        [
            str(k),
            one_line(g.id),
            one_line(members(g)),
            g.step or MISSING,
            *(g.text(q.key) for q in QUANTITIES),
            g.cause or MISSING,
            own_cell(g),
        ]
        for k, g in enumerate(view.groups, 1)
    ]
    widths = [max(len(r[c]) for r in [head, *rows]) for c in range(len(head))]
    lines = [
        "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
        for r in [head, *rows]
    ]
    lines.append("units: " + ", ".join(f"{q.key} {q.display}" for q in QUANTITIES))
    for k, g in enumerate(view.groups, 1):
        if not (g.flags or g.lacks or g.notes or g.unanswered):
            continue
        lines.append("")
        who = f"{members(g)}, {g.date or 'no date'}" if g.readable else "cannot be read"
        lines.append(one_line(f"#{k} {g.id} ({who})"))
        lines += [one_line(f"  ! {f}") for f in g.flags]
        lines += [one_line(f"  - lacks: {x}") for x in g.lacks]
        lines += [one_line(f"  - note: {x}") for x in g.notes]
        lines += [f"  - not answered yet: {g.unanswered}"] if g.unanswered else []
    if not any(g.flags for g in view.groups):
        lines += ["", nothing_marked(view)]
    lines += ["", f"'!': {MARKED}. {NOT_MARKED}"]
    return "\n".join(lines)


def write(view: ClassView, out: Path) -> tuple[Path, ...]:
    """Write class.md, class.html and class.csv into ``out`` (made if needed); InputError,
    one line, when it cannot be written."""
    from minseg_tui.report.write import write_class  # only for --out: slow to load

    if out.exists() and not out.is_dir():
        raise InputError(
            str(out), None, "is a file, not a folder: give a folder for --out DIR (made if needed)"
        )
    try:
        return write_class(view, out)
    except OSError as exc:
        raise InputError(
            str(out),
            None,
            f"cannot write the class report here ({os_reason(exc)}): give another --out DIR",
        ) from None


def run(args: argparse.Namespace) -> int:
    """Show (and write) the class view; 2 when a session could not be read at all."""
    if args.workers is not None and args.workers < 1:
        raise InputError(
            "--workers", None, f"expected a whole number of at least 1, got {args.workers}"
        )
    not_stdio(args.sessions, "--sessions", "the folder holding the sessions")
    if args.out is not None:
        not_stdio(args.out, "--out", "a folder for the class report (made if needed)")
    view = classread.build(args.sessions, workers=args.workers)
    written = write(view, args.out) if args.out is not None else ()
    if args.json:
        print_json(view.to_json(), indent=2)
    else:
        print(text(view))
        for p in written:
            print(p)
    bad = view.unreadable
    for g in bad:
        print(f"minseg-tui class: {one_line(g.damaged or '')}", file=sys.stderr)
    return 2 if bad else 0
