"""Where the words and numbers people read are written (issue 19, item 3 "Words once").

Counts, over minseg_tui/ (and README.md for the keys), each thing that should come from one
place, and says where it stands:

- number formats: format specs in f-strings (``{x:.3g}``, ``{x:.1f}``, ``{x:g}``...) outside
  quantities.py (an SVG's coordinates left out), the one module that writes numbers for people; split into those in modules
  of words people read (the UI, the report, the CLI, lab/views, identify's sentences)
  and the rest (messages of refusals, files, the board's protocol, the model check);
- formatting helpers: module-level ``_num``/``_fmt``/``_g``-like wrappers around quantities;
- the places that spell how u_ss was found (a table with an ``"interpolated"`` entry, or the
  bare code shown), the
  model check's figure names (a table naming the angle error), the key help (a table or
  README line saying what F5 does), a palette command's title ('Export report' quoted);
- names defined in more than one module: classes, and UPPER_CASE tables at module level;
- words in the model (issue 19 item 4: the model gives records, the words are made outside
  it): string literals and f-strings of model/ with a space and over 20 characters of
  text, docstrings left out, by folder; a refusal's 'expected ...' message counted apart.

Run: ``.venv/bin/python benchmarks/words_audit.py`` (``--list`` prints every hit;
``--against REV`` also counts the words in model/ at a git revision of this checkout and
prints before -> after by folder).
"""

import argparse
import ast
import io
import re
import subprocess
import sys
import tarfile
import tempfile
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tests.prose import prose  # noqa: E402

SPEC = re.compile(r"\{[^{}]*?:[+ ]?\d*(?:\.\d+)?[gfe%]\}")
"""A number's format spec inside an f-string: {x:.3g}, {x:+.1f}, {x:g}, {x:.0f}."""

PEOPLE = (
    "ui/",
    "report/",
    "cli/",
    "lab/views/",
    "lab/content/identify_says.py",
    "lab/content/u_ss_says.py",
    "lab/content/log_says.py",
)
"""Modules whose text is the words a student reads (screens, report, headless output)."""

HELPER = re.compile(r"^(?:def (_num|_fmt|_q|_g|_v|_w|_s|_read)\(|(_g|_fmt|_num) = format)", re.M)

PLACES: dict[str, re.Pattern[str]] = {
    "how u_ss was found": re.compile(r'"interpolated":|\{st\.u_ss_how\}'),
    "the check's figure names": re.compile(r'"(?:rms error of the angle|angle error)", "rad"'),
    "the key help (what F5 does)": re.compile(r'^\| F5|\("F5", "|\("f5", "|Key\(\s*"F5"', re.M),
    "a palette command's title (Export report)": re.compile(r"[\"'(]Export report[\"')]"),
}


def _geometry(text: str, m: re.Match[str]) -> bool:
    """A number in an SVG attribute or a point list (x="{px:.1f}", "{a:.1f},{b:.1f}"): a
    drawing's coordinates, not a number people read."""
    before, after = text[m.start() - 2 : m.start()], text[m.end() : m.end() + 1]
    return before == '="' or before.endswith(",") or after == ","


def _sources(pkg: Path) -> list[Path]:
    return sorted(p for p in pkg.rglob("*.py") if ".venv" not in p.parts)


def _defined(tree: ast.Module) -> tuple[list[str], list[str]]:
    """Classes and UPPER_CASE module-level names a module defines."""
    classes, tables = [], []
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            classes.append(node.name)
        targets: list[ast.expr] = []
        if isinstance(node, ast.Assign):
            targets = node.targets
        elif isinstance(node, ast.AnnAssign):
            targets = [node.target]
        for t in targets:
            if isinstance(t, ast.Name) and t.id.isupper() and len(t.id) > 1:
                tables.append(t.id)
    return classes, tables


def _model_words(pkg: Path) -> dict[str, list[str]]:
    """The prose literals of model/ (tests/prose.py's rule) under ``pkg``, by folder."""
    said: dict[str, list[str]] = defaultdict(list)
    for p in _sources(pkg / "model"):
        rel = str(p.relative_to(pkg))
        for line, words in sorted(prose(ast.parse(p.read_text(encoding="utf-8")))):
            said[str(Path(rel).parent)].append(f"{rel}:{line}: {words[:90]}")
    return said


def _refusals(said: dict[str, list[str]]) -> int:
    return sum(h.split(": ", 1)[1].startswith("expected") for v in said.values() for h in v)


def _at(root: Path, rev: str) -> dict[str, list[str]]:
    """:func:`_model_words` of minseg_tui/ at git revision ``rev`` of the checkout ``root``."""
    tar = subprocess.run(
        ["git", "-C", str(root), "archive", rev, "minseg_tui"], capture_output=True, check=True
    ).stdout
    with tempfile.TemporaryDirectory() as tmp:
        with tarfile.open(fileobj=io.BytesIO(tar)) as t:
            t.extractall(tmp, filter="data")
        return _model_words(Path(tmp) / "minseg_tui")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--list", action="store_true", help="print every hit")
    ap.add_argument("--root", type=Path, default=ROOT, help="a checkout to count in")
    ap.add_argument("--against", metavar="REV", help="count model/'s words at REV too")
    args = ap.parse_args()
    root = args.root.resolve()
    pkg = root / "minseg_tui"
    people: Counter[str] = Counter()
    given = 0
    rest: Counter[str] = Counter()
    helpers: list[str] = []
    places: dict[str, list[str]] = defaultdict(list)
    classes: dict[str, list[str]] = defaultdict(list)
    tables: dict[str, list[str]] = defaultdict(list)
    for p in _sources(pkg):
        text = p.read_text(encoding="utf-8")
        rel = str(p.relative_to(pkg))
        if rel != "quantities.py":
            found = [m for m in SPEC.finditer(text) if not _geometry(text, m)]
            n = len(found)
            if n:
                (people if rel.startswith(PEOPLE) else rest)[rel] += n
                if rel.startswith(PEOPLE):
                    given += sum(m.group().endswith(":g}") for m in found)
        helpers += [f"{rel}: {m.group(1) or m.group(2)}" for m in HELPER.finditer(text)]
        for what, pattern in PLACES.items():
            if pattern.search(text):
                places[what].append(rel)
        tree = ast.parse(text)
        c, t = _defined(tree)
        for name in c:
            classes[name].append(rel)
        for name in t:
            tables[name].append(rel)
    said = _model_words(pkg)
    readme = (root / "README.md").read_text(encoding="utf-8")
    for what, pattern in PLACES.items():
        if pattern.search(readme):
            places[what].append("README.md")
    twice_c = {k: v for k, v in classes.items() if len(v) > 1}
    twice_t = {k: v for k, v in tables.items() if len(v) > 1}

    print(
        f"number formats outside quantities.py, in modules people read: "
        f"{sum(people.values())} in {len(people)} modules, of which {given} are :g (a level, "
        "a setting or a reading written as given)"
    )
    if args.list:
        for rel, n in people.most_common():
            print(f"    {n:3d}  {rel}")
    print(f"number formats elsewhere (refusals, files, protocol, check): {sum(rest.values())}")
    if args.list:
        for rel, n in rest.most_common():
            print(f"    {n:3d}  {rel}")
    print(f"formatting helpers beside quantities': {len(helpers)}")
    if args.list:
        for h in helpers:
            print(f"    {h}")
    for what in PLACES:
        print(f"{what}: written in {len(places[what])} places ({', '.join(places[what])})")
    refusals = _refusals(said)
    print(
        f"words in model/ (literals with a space, over 20 characters, no docstrings): "
        f"{sum(len(v) for v in said.values())}, of which {refusals} refusals ('expected ...'); "
        + ", ".join(f"{k} {len(v)}" for k, v in sorted(said.items()))
    )
    if args.against:
        then = _at(root, args.against)
        print(
            f"words in model/ at {args.against} -> now: "
            f"{sum(len(v) for v in then.values())} -> {sum(len(v) for v in said.values())} "
            f"(refusals {_refusals(then)} -> {refusals}); "
            + ", ".join(
                f"{k} {len(then.get(k, []))} -> {len(said.get(k, []))}"
                for k in sorted(set(then) | set(said))
            )
        )
    if args.list:
        for where in said.values():
            for h in where:
                print(f"    {h}")
    print(f"classes defined in more than one module: {len(twice_c)}")
    for name, where in sorted(twice_c.items()):
        print(f"    {name}: {', '.join(where)}")
    print(f"UPPER_CASE tables defined in more than one module: {len(twice_t)}")
    for name, where in sorted(twice_t.items()):
        print(f"    {name}: {', '.join(where)}")


if __name__ == "__main__":
    main()
