#!/usr/bin/env python3
"""What is made from the one table of pins and profiles, minseg-fw/src/board/pins.def (the
firmware and its simavr harnesses read the same file; the Makefile reads its profiles):

- firmware/README.md's pin table and sources, between the lines PINS_BEGIN and PINS_END;
- minseg-fw/src/board/profiles.h: the profiles' defines (MINSEG_PROFILE_<NAME UPPER CASE>,
  the first profile of the table the default), MINSEG_BOARD_NAME, the exactly-one check and
  the MINSEG_ONLY_<name> switch hal.cpp expands the table with;
- minseg_tui/device/board_profiles.py: the package's list (``minseg-tui flash``, the shipped
  .hex check, the benchmarks).

    python3 tools/pins_table.py            print the table and the sources (Markdown)
    python3 tools/pins_table.py --check    exit 1 if a made file differs, silent if not
                                           (make host-test)
    python3 tools/pins_table.py --write    rewrite the made files
    python3 tools/pins_table.py --profiles the profiles, in order (the Makefile's PROFILES)

A profile is added by its connectors in pins.def, then --write. Standard library only.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parents[1]
PINS = HERE / "minseg-fw" / "src" / "board" / "pins.def"
README = HERE / "README.md"
PROFILES_H = HERE / "minseg-fw" / "src" / "board" / "profiles.h"
PACKAGE_LIST = HERE.parent / "minseg_tui" / "device" / "board_profiles.py"
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


def profiles() -> list[str]:
    """The profiles of pins.def, in the table's order (the first is the default)."""
    names = [m.group(1) for m in CONNECTOR.finditer(PINS.read_text(encoding="ascii"))]
    return list(dict.fromkeys(names))


def profiles_h() -> str:
    """minseg-fw/src/board/profiles.h, made from the profiles of pins.def."""
    names = profiles()
    define = {p: f"MINSEG_PROFILE_{p.upper()}" for p in names}
    out = [
        "// Made by tools/pins_table.py from pins.def (--write); do not edit: make host-test",
        "// fails while it differs. The board profiles of pins.def, chosen at build time (or in",
        "// profile.h, which includes this file): one of",
        "// " + ", ".join(f"-D{define[p]}" for p in names),
        f"// (make PROFILE={'|'.join(names)}); without one, {names[0]}, the first of the table.",
        "#ifndef MINSEG_PROFILES_H",
        "#define MINSEG_PROFILES_H",
        "",
        "#if " + " && ".join(f"!defined({define[p]})" for p in names),
        f"#define {define[names[0]]}",
        "#endif",
        "",
        "#if " + " + ".join(f"defined({define[p]})" for p in names) + " != 1",
        '#error "define exactly one MINSEG_PROFILE_*"',
        "#endif",
        "",
        "// MINSEG_ONLY_<profile>(...): the connectors of pins.def of the profile built expand to",
        "// MINSEG_BODY(...) (hal.cpp defines it at each use), those of the others to nothing.",
    ]
    for p in names:
        out += [
            f"#if defined({define[p]})",
            f'#define MINSEG_BOARD_NAME "{p}"',
            f"#define MINSEG_ONLY_{p}(...) MINSEG_BODY(__VA_ARGS__)",
            "#else",
            f"#define MINSEG_ONLY_{p}(...)",
            "#endif",
        ]
    out += ["", "#endif", ""]
    return "\n".join(out)


def package_list() -> str:
    """minseg_tui/device/board_profiles.py, made from the profiles of pins.def."""
    names = profiles()
    return (
        '"""The board profiles the firmware is built for, in the order of its table of pins\n'
        "(firmware/minseg-fw/src/board/pins.def); the first is the firmware's default.\n\n"
        "Made by firmware/tools/pins_table.py (--write) from that table; do not edit: make\n"
        'host-test fails while it differs."""\n\n'
        "PROFILES = (\n" + "".join(f'    "{p}",\n' for p in names) + ")\n"
        f'DEFAULT_PROFILE = "{names[0]}"\n'
    )


def main(argv: list[str]) -> int:
    if argv == ["--profiles"]:
        print(" ".join(profiles()))
        return 0
    table = render()
    if not argv:
        print(table)
        return 0
    readme = README.read_text(encoding="utf-8")
    start, end = readme.find(BEGIN), readme.find(END)
    if start < 0 or end < start:
        print(f"pins_table: {README} has no {BEGIN} ... {END} block", file=sys.stderr)
        return 2
    made = {
        README: readme[:start] + table + readme[end + len(END) :],
        PROFILES_H: profiles_h(),
        PACKAGE_LIST: package_list(),
    }
    if argv == ["--check"]:
        differ = [
            path.relative_to(HERE.parent)
            for path, text in made.items()
            if not path.exists() or path.read_text(encoding="utf-8") != text
        ]
        if differ:
            print(
                f"pins_table: {', '.join(map(str, differ))} differ from pins.def: run "
                "firmware/tools/pins_table.py --write"
            )
            return 1
        return 0  # silent, so the unit tests' closing line stays the last one
    if argv == ["--write"]:
        for path, text in made.items():
            path.write_text(text, encoding="utf-8")
        return 0
    print("usage: pins_table.py [--check | --write | --profiles]", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
