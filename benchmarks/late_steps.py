"""True late steps found by the model check, and late steps it reports on logs that hold none.

    .venv/bin/python benchmarks/late_steps.py [--seeds 11-18]

model.synth's late_step=True logs (every cause of model.synth, the given seeds): one command
of the log acts 0.3-0.7 of a sample late. A log counts as found when a late step is reported
at that edge's row; every other late step reported on it is extra. (The independent
generator issues no command late: benchmarks/model_check_independent.py counts its late steps
as false ones.)
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from minseg_tui.model.check import check  # noqa: E402
from minseg_tui.model.synth import CAUSES, make_log  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="11-18", help="first-last, inclusive")
    a = ap.parse_args()
    first, last = (int(x) for x in a.seeds.split("-"))
    found = extra = n = 0
    for cause in CAUSES:
        row = []
        for s in range(first, last + 1):
            log = make_log(cause, seed=s, late_step=True)
            r = check(log.t, log.u, log.omega)
            late = [x.row for x in r.anomalies if x.kind == "late_step"]
            hit = log.late_step_row in late
            found += hit
            extra += len(late) - hit
            n += 1
            row.append("x" if hit else ".")
        print(f"  {cause:>17}: {''.join(row)}", flush=True)
    print(f"true late steps found: {found} of {n}; extra late steps reported on them: {extra}")


if __name__ == "__main__":
    main()
