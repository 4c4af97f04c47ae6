"""The model check's output on a fixed corpus, saved and compared bit for bit: the guard of a
refactor of the check (a change that must not change a single figure or word).

    .venv/bin/python benchmarks/check_corpus.py --save OUT.json [--quick]
    .venv/bin/python benchmarks/check_corpus.py --compare OUT.json [--quick]

The corpus: the real logs of ../shared/data/real-motors (each step.csv and the probes, read
as ``minseg-tui analyze`` reads them), logs of the independent generator
(tests/model/physics_gen.py) on its tuning seeds (every pair of causes, every single cause,
each with a hand on the wheel), and logs of model/synth.py's ``make_log`` as
benchmarks/model_check.py (single causes) and model_check_pairs.py (pairs, a hand) draw them.
For every log it keeps the JSON of ``analyze --json`` (floats written by repr, so bit for
bit), the text of ``analyze`` and a hash of the baseline's and the extended model's
predictions, and the CPU time of the check (s, process time, the check only; printed as a
total, never compared). ``--quick`` takes one seed of each tier instead of two.
"""

from __future__ import annotations

import argparse
import hashlib
import itertools
import json
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from minseg_tui.cli.analyze import _sample_period, in_words_text  # noqa: E402
from minseg_tui.lab.content.log_says import refusal_words  # noqa: E402
from minseg_tui.lab.saving.files import read_run_log  # noqa: E402
from minseg_tui.lab.views.check_says import as_json  # noqa: E402
from minseg_tui.model.check import CheckResult, check  # noqa: E402
from minseg_tui.model.runlog import LogRefused  # noqa: E402
from minseg_tui.model.synth import CAUSES as SYNTH_CAUSES  # noqa: E402
from minseg_tui.model.synth import PARAM_RANGES, make_log  # noqa: E402
from tests.model.physics_gen import CAUSES as PHYS_CAUSES  # noqa: E402
from tests.model.physics_gen import TUNING_SEEDS, make  # noqa: E402

REAL = ROOT.parent.parent / "shared" / "data" / "real-motors"
if not REAL.is_dir():
    REAL = Path("/work/shared/data/real-motors")

Run = Callable[[], CheckResult]


def _real() -> Iterator[tuple[str, Run]]:
    files = sorted(REAL.glob("*/step.csv")) + sorted((REAL / "probes").glob("*.csv"))
    for p in files:

        def run(p: Path = p) -> CheckResult:
            log = read_run_log(str(p))
            ts = _sample_period(dict(log.metadata))
            return check(
                log.t, log.u, log.omega, ts=ts, cpr=log.declared_cpr, omega_over=log.omega_over
            )

        yield f"real/{p.parent.name}/{p.name}", run


def _on(lg: Any) -> Run:
    """The check of a generated log (t s, u V, omega rad/s)."""
    return lambda: check(lg.t, lg.u, lg.omega)


def _independent(n: int) -> Iterator[tuple[str, Run]]:
    base = TUNING_SEEDS.start
    for a, b in itertools.combinations(PHYS_CAUSES, 2):
        for s in range(n):
            lg = make(base + s, (a, b))
            yield f"phys/pair/{a}+{b}/{base + s}", _on(lg)
    for cause in ("none", *PHYS_CAUSES):
        causes = () if cause == "none" else (cause,)
        for s in range(n):
            lg = make(base + 500 + s, causes)
            yield f"phys/single/{cause}/{base + 500 + s}", _on(lg)
            lg = make(base + 1000 + s, causes, touch=True)
            yield f"phys/touch/{cause}/{base + 1000 + s}", _on(lg)


def _synthetic(n: int) -> Iterator[tuple[str, Run]]:
    for cause in SYNTH_CAUSES:
        for s in range(n):
            lg = make_log(cause, seed=1000 + s)
            yield f"synth/single/{cause}/{1000 + s}", _on(lg)
            lg = make_log(cause, seed=4000 + s, touch=True)
            yield f"synth/touch/{cause}/{4000 + s}", _on(lg)
    for a, b in itertools.combinations(list(PARAM_RANGES), 2):
        for s in range(n):
            lg = make_log(a, seed=3000 + s, also=b)
            yield f"synth/pair/{a}+{b}/{3000 + s}", _on(lg)


def _digest(r: CheckResult) -> str:
    h = hashlib.sha256()
    for a in (r.baseline_pred, r.extended_pred):
        h.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    return h.hexdigest()


def collect(n: int) -> tuple[dict[str, object], float]:
    """{log name: its output} over the corpus (``n`` seeds a tier), and the check's CPU (s)."""
    out: dict[str, object] = {}
    cpu = 0.0
    for name, run in itertools.chain(_real(), _independent(n), _synthetic(n)):
        t0 = time.process_time()
        try:
            r = run()
        except LogRefused as e:  # the check refuses a log (a wheel that never turns)
            cpu += time.process_time() - t0
            out[name] = {"refused": refusal_words(e.why)}
            continue
        cpu += time.process_time() - t0
        out[name] = {"json": as_json(r), "text": in_words_text(r), "pred": _digest(r)}
    return out, cpu


def _diff(a: object, b: object, where: str, found: list[str]) -> None:
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                found.append(f"{where}/{k}: only in {'saved' if k in a else 'now'}")
            else:
                _diff(a[k], b[k], f"{where}/{k}", found)
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _diff(x, y, f"{where}[{i}]", found)
    elif a != b and not (a != a and b != b):  # NaN equals NaN here
        found.append(f"{where}: saved {a!r} now {b!r}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--save", metavar="OUT.json")
    g.add_argument("--compare", metavar="SAVED.json")
    ap.add_argument("--quick", action="store_true", help="one seed a tier, not two")
    a = ap.parse_args()
    out, cpu = collect(1 if a.quick else 2)
    print(f"{len(out)} logs, check CPU {cpu:.1f} s")
    if a.save:
        Path(a.save).write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
        return
    saved = json.loads(Path(a.compare).read_text())
    # a round trip through JSON, so that tuples and lists compare alike
    now = json.loads(json.dumps(out))
    found: list[str] = []
    _diff(saved, now, "", found)
    print("\n".join(found[:60]))
    print(f"{len(found)} differences" if found else "identical")
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
