"""`minseg-tui ports`: every serial port, and why it was or was not picked as a MinSeg."""

from __future__ import annotations

import argparse

from minseg_tui.cli.output import print_json
from minseg_tui.device import discovery


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """--json for a machine-readable list."""
    parser.add_argument("--json", action="store_true", help="print the list as JSON")


def run(args: argparse.Namespace) -> int:
    """Print the ports (best first) with their verdicts; exit 0 even when there are none."""
    found = discovery.candidates()
    if args.json:
        print_json([c.as_dict() for c in found], indent=2)
        return 0
    if not found:
        print("no serial ports found (use `minseg-tui sim` for a virtual MinSeg)")
        return 0
    best = next((c for c in found if c.picked), None)  # found is best first, as find_board reads it
    for c in found:
        ids = "----:----" if c.vid is None or c.pid is None else f"{c.vid:04X}:{c.pid:04X}"
        mark = "*" if best is not None and c.device == best.device else " "
        print(f"{mark} {c.device:<24} {ids}  {c.verdict:<8} {c.reason}")
    if best is None:
        print("no MinSeg found: `auto` will use the virtual board")
    else:
        print(f"* = what `auto` opens: {best.device}")
    return 0
