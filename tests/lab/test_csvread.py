"""The streaming CSV reader against a plain reference reader, on seeded random files that
mix every form the lab files allow (comments, blank lines, \\r\\n, whitespace, quotes,
integers, text columns), with tiny chunks and blocks so that every boundary is crossed."""

from __future__ import annotations

import csv
import random

import numpy as np
import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.saving import csvread
from minseg_tui.lab.saving.csvread import NUMBER, read_csv


def reference(text: str) -> tuple[list[str], list[int], dict[str, list[str]]]:
    """header, row lines, column texts: the plain way, one line at a time."""
    header: list[str] = []
    lines: list[int] = []
    cols: dict[str, list[str]] = {}
    for number, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        fields = [f.strip() for f in next(csv.reader([s]))]
        if not header:
            header = [f.lower() for f in fields]
            cols = {h: [] for h in header}
            continue
        lines.append(number)
        for h, f in zip(header, fields, strict=True):
            cols[h].append(f)
    return header, lines, cols


def random_file(rng: random.Random, rows: int, plain: bool) -> str:
    """A random file; ``plain``: data rows of numbers and commas only (the fast path)."""
    out = ["\ufeff# source: random\n" if rng.random() < 0.5 else "# source: random\n"]
    out.append("T, u ,Omega,count,note\n")
    for k in range(rows):
        r = 1.0 if plain else rng.random()
        if r < 0.02:
            out.append("# a comment\n")
        elif r < 0.04:
            out.append("\n")
        t = f"{k * 0.025:.6g}"
        u = rng.choice(["0", "4.5", "-4.5", "4.50", ".5", "5.", "1e-3", "+2E+1"])
        omega = f"{rng.uniform(-9, 9):.6g}"
        count = str(rng.randrange(-(10**6), 10**6))
        sep = "," if plain else rng.choice([",", ",", ",", " , "])
        note = rng.choice(["a", "b", "12", "x y", '"q,1"' if sep == "," else "q"])
        if plain:
            note = rng.choice(["a", "b"])
        end = "\r\n" if rng.random() < 0.1 else "\n"
        out.append(sep.join((t, u, omega, count, note)) + end)
    return "".join(out)


@pytest.mark.parametrize("seed", range(10))
def test_streamed_columns_equal_the_plain_reading(tmp_path, monkeypatch, seed):
    rng = random.Random(seed)
    if seed % 2:  # tiny chunks and blocks: every boundary falls somewhere inside a line
        monkeypatch.setattr(csvread, "_CHUNK", rng.randrange(7, 200))
        monkeypatch.setattr(csvread, "_BLOCK", rng.randrange(1, 50))
    if seed % 4 == 2:  # more rows than one chunk, in a block of its own
        monkeypatch.setattr(csvread, "_CHUNK", 4096)
    text = random_file(rng, rows=rng.randrange(1, 3000), plain=seed >= 6)
    path = tmp_path / "f.csv"
    path.write_bytes(text.encode("utf-8"))
    got = read_csv(
        path,
        expected_header="t,u,omega",
        required={"t": "s", "u": "V", "omega": "rad/s"},
        numeric={"t": "s", "u": "V", "omega": "rad/s", "count": "counts"},
        max_rows=10**6,
        rows_are="test",
    )
    header, lines, cols = reference(text.lstrip("\ufeff"))
    assert got.header == header
    assert got.lines.tolist() == lines
    for name in ("t", "u", "omega", "count"):
        want = np.array([float(x) for x in cols[name]])
        np.testing.assert_array_equal(got.numbers(name), want)
    assert got.is_integer("count") and not got.is_integer("u")
    assert not got.is_numeric("note")
    assert got.texts("note").tolist() == cols["note"]
    assert got.metadata == {"source": "random"}


@pytest.mark.parametrize(
    "text", ["3_6", "nan", "inf", "-Infinity", "1e999", "0x1p3", "\u0663", "1-2", "", "1 2"]
)
def test_what_float_reads_but_a_lab_file_never_holds(tmp_path, text):
    assert NUMBER.match(text) is None or text == "1e999"
    path = tmp_path / "f.csv"
    path.write_text(f"t,u,omega\n0,0,0\n0.025,{text},1\n")
    with pytest.raises(InputError) as info:
        read_csv(
            path,
            expected_header="t,u,omega",
            required={"t": "s", "u": "V", "omega": "rad/s"},
            numeric={"t": "s", "u": "V", "omega": "rad/s"},
            max_rows=10,
            rows_are="test",
        )
    assert str(info.value).startswith(f"{path}:3: expected a number for u (V), got ")
