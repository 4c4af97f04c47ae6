#!/usr/bin/env python3
"""The pin table of firmware/README.md, made from the one table of pins,
minseg-fw/src/board/pins.def (the firmware and its simavr harnesses read the same file).

    python3 tools/pins_table.py            print the table and the sources (Markdown)
    python3 tools/pins_table.py --check    exit 1 if README.md's copy differs, silent if not
                                           (make host-test)
    python3 tools/pins_table.py --write    rewrite README.md's copy

README.md holds the copy between the lines PINS_BEGIN and PINS_END. Standard library only.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parents[1]
PINS = HERE / "minseg-fw" / "src" / "board" / "pins.def"
README = HERE / "README.md"
BEGIN = "<!-- PINS_BEGIN: made by tools/pins_table.py from minseg-fw/src/board/pins.def -->"
END = "<!-- PINS_END -->"

PIN = r"\((\w+), (\w), (\d), (\w+)\)"
CONNECTOR = re.compile(
    r"MINSEG_CONNECTOR\((\w+), (\d),\s*" + PIN + r", " + PIN + r",\s*" + PIN + r", " + PIN + r"\)"
)
SOURCE = re.compile(r"MINSEG_SOURCE\((\w+), (\d),\s*((?:\"(?:[^\"\\]|\\.)*\"\s*)+)\)")


def unit_name(unit: str) -> str:
    """EXTINT6 -> INT6, PCINT_9 -> PCINT9 (pins.def avoids avr/io.h's bit-number macros)."""
    if unit.startswith("EXTINT"):
        return "INT" + unit[len("EXTINT") :]
    return unit.replace("_", "")


def cell(name: str, port: str, bit: str, unit: str) -> str:
    """One pin as 'D44 (PL5, OC5C)'; a pin without an Arduino number is its port name."""
    port_bit = f"P{port}{bit}"
    return (
        f"{name} ({unit_name(unit)})"
        if name == port_bit
        else f"{name} ({port_bit}, {unit_name(unit)})"
    )


def render() -> str:
    """The Markdown table and the sources, from pins.def."""
    text = PINS.read_text(encoding="ascii")
    rows = CONNECTOR.findall(text)
    sources = {
        (p, n): "".join(re.findall(r"\"((?:[^\"\\]|\\.)*)\"", s))
        for p, n, s in SOURCE.findall(text)
    }
    if not rows or len(sources) != len(rows):
        raise SystemExit(
            f"pins_table: cannot read {PINS} (rows {len(rows)}, sources {len(sources)})"
        )
    out = [
        BEGIN,
        "| profile | connector | bridge IN1 (high for u > 0) | bridge IN2 | encoder A | encoder B |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        pins = [cell(*r[k : k + 4]) for k in (2, 6, 10, 14)]
        out.append(f"| `{r[0]}` | M{r[1]} | " + " | ".join(pins) + " |")
    out.append("")
    out.append("Sources, per connector:")
    out.append("")
    for r in rows:
        out.append(f"- **{r[0]} M{r[1]}.** {sources[(r[0], r[1])]}")
    out.append(END)
    return "\n".join(out)


def main(argv: list[str]) -> int:
    table = render()
    if not argv:
        print(table)
        return 0
    readme = README.read_text(encoding="utf-8")
    start, end = readme.find(BEGIN), readme.find(END)
    if start < 0 or end < start:
        print(f"pins_table: {README} has no {BEGIN} ... {END} block", file=sys.stderr)
        return 2
    current = readme[start : end + len(END)]
    if argv == ["--check"]:
        if current != table:
            print(
                "pins_table: README.md's pin table differs from pins.def: run tools/pins_table.py --write"
            )
            return 1
        return 0  # silent, so the unit tests' closing line stays the last one
    if argv == ["--write"]:
        README.write_text(readme[:start] + table + readme[end + len(END) :], encoding="utf-8")
        return 0
    print("usage: pins_table.py [--check | --write]", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
