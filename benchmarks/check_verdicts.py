"""The model check's verdict on every log of the benchmarks, to tell whether a change moved any.

    .venv/bin/python benchmarks/check_verdicts.py SET... [--out FILE] [--against FILE]

A change meant to make the check faster must leave every verdict as it was (issue 17 item 8):
this runs the logs of the benchmarks one by one and writes one line per log,

    <set> <cause(s)> <seed> | <verdict> | <hash> | <CPU s>

where the verdict is the causes named, the ambiguity (``finding.ambiguous_with``), every
parameter of the model chosen to 4 significant digits and the anomalies (kind, and time to
4 digits); the hash is of the whole result's repr (equal hashes: the same floats, so a change
that gives the same numbers by construction shows none differ); the CPU is check()'s own
(time.process_time, the log's generation left out).

SETS (the logs of each benchmark, the same seeds):
  tuning-pairs      model_check_independent.py --tuning --seeds 10: every pair, seeds 0-9;
  tuning2-pairs     model_check_independent.py --tuning2 --seeds 10: every pair, seeds
                    920000-920009;
  held-out-pairs    model_check_independent.py --seeds 5: every pair, seeds 900000-900004;
  held-out-singles  its singles (none and each cause), seeds 900500-900504;
  held-out-touches  its hands on the wheel, seeds 901000-901004 (logs with a touch);
  singles           model_check.py --seeds 10: the confusion matrix's logs (seeds 1000-1009)
                    and the clean logs of T's spread (none, seeds 2000-2009);
  synth-pairs       model_check_pairs.py --seeds 5 --touch-seeds 10: pairs of seeds
                    3000-3004 and hands of seeds 4000-4009.

--against FILE: an earlier run's lines (the tree before the change); each log whose verdict
differs is printed with both verdicts, then how many logs were compared, how many verdicts
and hashes differ, and CPU per log (median, max, total) of both runs. For CPU figures, run the
two trees side by side (two processes at once) so both see the same load.
"""

from __future__ import annotations

import argparse
import hashlib
import itertools
import json
import statistics
import sys
import time
from collections.abc import Callable, Iterator
from functools import partial
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from minseg_tui.lab.content.log_says import refusal_words  # noqa: E402
from minseg_tui.model.check import check  # noqa: E402
from minseg_tui.model.runlog import LogRefused  # noqa: E402
from minseg_tui.model.synth import CAUSES as SYNTH_CAUSES  # noqa: E402
from minseg_tui.model.synth import PARAM_RANGES, make_log  # noqa: E402
from tests.model import physics_gen as gen  # noqa: E402

SETS = (
    "tuning-pairs",
    "tuning2-pairs",
    "held-out-pairs",
    "held-out-singles",
    "held-out-touches",
    "singles",
    "synth-pairs",
)

Log = Any
"""A generated log with t (s), u (V), omega (rad/s) and, for a hand, touch."""


def logs(which: str) -> Iterator[tuple[str, Callable[[], Log]]]:
    """(key, a maker of the log) of every log of one set."""
    if which in ("tuning-pairs", "tuning2-pairs", "held-out-pairs"):
        base = {
            "tuning-pairs": gen.TUNING_SEEDS.start,
            "tuning2-pairs": gen.TUNING2_SEEDS.start,
        }.get(which, gen.HELD_OUT_SEEDS.start)
        n = 5 if which == "held-out-pairs" else 10
        for a, b in itertools.combinations(gen.CAUSES, 2):
            for s in range(base, base + n):
                yield f"{which} {a}+{b} {s}", partial(gen.make, s, (a, b))
    elif which in ("held-out-singles", "held-out-touches"):
        touch = which == "held-out-touches"
        first = gen.HELD_OUT_SEEDS.start + (1000 if touch else 500)
        for c in ("none", *gen.CAUSES):
            causes = () if c == "none" else (c,)
            for s in range(first, first + 5):
                yield f"{which} {c} {s}", partial(gen.make, s, causes, touch=touch)
    elif which == "singles":
        for c in SYNTH_CAUSES:
            for s in range(1000, 1010):
                yield f"{which} {c} {s}", partial(make_log, c, seed=s)
        for s in range(2000, 2010):
            yield f"{which} none {s}", partial(make_log, "none", seed=s)
    elif which == "synth-pairs":
        for a, b in itertools.combinations(list(PARAM_RANGES), 2):
            for s in range(3000, 3005):
                yield f"{which} {a}+{b} {s}", partial(make_log, a, seed=s, also=b)
        for c in SYNTH_CAUSES:
            for s in range(4000, 4010):
                yield f"{which} {c}-hand {s}", partial(make_log, c, seed=s, touch=True)
    else:
        raise ValueError(f"no set {which!r}: one of {', '.join(SETS)}")


def verdict(r: Any) -> str:
    """The causes named, the ambiguity, the parameters (4 digits) and the anomalies, as JSON."""
    f = r.finding
    named = [f.cause, *(o.cause for o in f.others)]
    amb = [sorted(a) for a in (getattr(f, "ambiguous_with", None) or [])]
    params = {k: f"{v:.4g}" for k, v in sorted(r.extended.params.items())}
    notes = [[a.kind, None if a.t is None else f"{a.t:.4f}"] for a in r.anomalies]
    return json.dumps([named, amb, params, notes], sort_keys=True)


def line(key: str, log: Log) -> str:
    """One log's line (see the module docstring)."""
    t0 = time.process_time()
    try:
        r = check(log.t, log.u, log.omega)
    except LogRefused as e:  # refused (a wheel that never turns): that is its verdict
        return f"{key} | refused: {refusal_words(e.why)} | - | {time.process_time() - t0:.3f}"
    cpu = time.process_time() - t0
    digest = hashlib.sha1(repr(r).encode()).hexdigest()[:16]
    return f"{key} | {verdict(r)} | {digest} | {cpu:.3f}"


def read(path: Path) -> dict[str, tuple[str, str, float]]:
    """{key: (verdict, hash, CPU s)} of a file of lines."""
    out = {}
    for text in path.read_text().splitlines():
        parts = text.split(" | ")
        if len(parts) == 4:
            out[parts[0]] = (parts[1], parts[2], float(parts[3]))
    return out


def compare(
    before: dict[str, tuple[str, str, float]], after: dict[str, tuple[str, str, float]]
) -> None:
    """Print the logs whose verdict differs, then the counts and CPU per log of both."""
    keys = [k for k in after if k in before]
    moved = [k for k in keys if before[k][0] != after[k][0]]
    for k in moved:
        print(f"{k}\n  before {before[k][0]}\n  after  {after[k][0]}")
    floats = sum(1 for k in keys if before[k][1] != after[k][1])
    print(
        f"{len(keys)} logs compared: {len(moved)} verdicts differ, {floats} results differ in "
        "some float"
    )
    if keys:
        b = [before[k][2] for k in keys]
        a = [after[k][2] for k in keys]
        print(
            f"CPU per log (check only), before -> after: median {statistics.median(b):.3f} -> "
            f"{statistics.median(a):.3f} s, max {max(b):.2f} -> {max(a):.2f} s, total "
            f"{sum(b):.1f} -> {sum(a):.1f} s"
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", nargs="+", choices=SETS)
    ap.add_argument("--out", type=Path, help="also write the lines to this file")
    ap.add_argument("--against", type=Path, help="an earlier run's lines to compare with")
    a = ap.parse_args()
    lines = []
    sink = a.out.open("w") if a.out else None
    try:
        for which in a.sets:
            for key, make in logs(which):
                log = make()
                if which.endswith("touches") and log.touch is None:
                    continue  # the touch fell outside a settled stretch: no hand on this log
                text = line(key, log)
                lines.append(text)
                print(text, flush=True)
                if sink is not None:
                    sink.write(text + "\n")
                    sink.flush()
    finally:
        if sink is not None:
            sink.close()
    if a.against:
        after = {}
        for text in lines:
            key, v, h, cpu = text.split(" | ")
            after[key] = (v, h, float(cpu))
        compare(read(a.against), after)


if __name__ == "__main__":
    main()
