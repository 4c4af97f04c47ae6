"""Real-like logs the model check has never seen: seeded variants of the ten real logs.

    .venv/bin/python benchmarks/real_variants.py OUT_DIR [--seed N] [--analyze]

For each log in ../shared/data/real-motors (see its README and PROVENANCE.txt files) this
writes seven variants into OUT_DIR, each asking whether the check's sentences still hold on a
log it was not read against:

  cut-first   the first third of the rows dropped (a log that starts late; when the only
              step is in that third, the log starts on the step's response)
  cut-last    the last third dropped (a log cut short)
  coarse      every second row kept, the speed recomputed over the longer period from the
              angle (or the mean of two speeds where the log has no angle)
  second      a second step: after the log, the command drops to half its last level and the
              speed follows the log's own first rise, scaled and mirrored (what a linear motor
              does; a real motor with friction would settle lower)
  volts       the voltage column times 1.7 (a supply misread: K falls by 1.7, T is unchanged)
  gap         three rows removed at a seeded place after the first rise (a logging gap)
  reverse     u, omega and theta negated (the motor wired the other way)

Every variant keeps the log's own ``#`` header lines (``# ts:`` halved or doubled where the
period changes) and names itself in a ``# variant:`` line. With ``--analyze`` the check is
run on each variant and its text printed, for reading by eye (/work/coord/REAL37.md).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.shared_data import SHARED_DATA  # noqa: E402

REAL = SHARED_DATA / "real-motors"
VARIANTS = ("cut-first", "cut-last", "coarse", "second", "volts", "gap", "reverse")


def read(path: Path) -> tuple[list[str], list[str], np.ndarray]:
    """The header lines, the column names and the rows of a step log."""
    lines = path.read_text().splitlines()
    head = [x for x in lines if x.startswith("#")]
    body = [x for x in lines if x and not x.startswith("#")]
    cols = body[0].split(",")
    rows = np.array([[float(v) for v in x.split(",")] for x in body[1:]])
    return head, cols, rows


def write(path: Path, head: list[str], cols: list[str], rows: np.ndarray) -> None:
    text = "\n".join([*head, ",".join(cols), *(",".join(f"{v:.6g}" for v in r) for r in rows)])
    path.write_text(text + "\n")


def with_ts(head: list[str], factor: float) -> list[str]:
    out = []
    for h in head:
        if h.startswith("# ts:"):
            h = f"# ts: {float(h.split(':', 1)[1]) * factor:.6g}"
        out.append(h)
    return out


def variant(
    kind: str, head: list[str], cols: list[str], rows: np.ndarray, rng: np.random.Generator
) -> tuple[list[str], np.ndarray]:
    c = {n: i for i, n in enumerate(cols)}
    t, u, w = rows[:, c["t"]], rows[:, c["u"]], rows[:, c["omega"]]
    n = len(rows)
    if kind == "cut-first":
        return head, rows[n // 3 :]
    if kind == "cut-last":
        return head, rows[: n - n // 3]
    if kind == "coarse":
        keep = rows[1::2].copy()
        dt = np.diff(t[1::2], prepend=t[1] - 2 * (t[1] - t[0]))
        if "theta" in c:
            th = keep[:, c["theta"]]
            keep[1:, c["omega"]] = np.diff(th) / dt[1:]
            keep[0, c["omega"]] = rows[:2, c["omega"]].mean()
        else:
            keep[:, c["omega"]] = 0.5 * (w[0 : 2 * len(keep) : 2] + w[1::2])
        return with_ts(head, 2.0), keep
    if kind == "second":
        edges = np.flatnonzero(np.diff(u) != 0)
        a = int(edges[0]) + 1
        u1 = u[-1]
        # the levels as the means of the rows before the step and of the step's second half
        w0, w1 = float(np.mean(w[max(0, a - 10) : a])), float(np.mean(w[a + (n - a) // 2 :]))
        shape = (w[a:] - w0) / (w1 - w0) if w1 != w0 else np.ones(n - a)
        m = n - a
        ts = float(np.median(np.diff(t)))
        new = np.zeros((m, rows.shape[1]))
        new[:, c["t"]] = t[-1] + ts * np.arange(1, m + 1)
        new[:, c["u"]] = u1 / 2
        new[:, c["omega"]] = w1 - (w1 / 2) * shape
        if "theta" in c:
            new[:, c["theta"]] = rows[-1, c["theta"]] + np.cumsum(new[:, c["omega"]]) * ts
        for k in cols:
            if k not in ("t", "u", "omega", "theta"):
                new[:, c[k]] = rows[-1, c[k]]
        return head, np.vstack([rows, new])
    if kind == "volts":
        out = rows.copy()
        out[:, c["u"]] *= 1.7
        return head, out
    if kind == "gap":
        edges = np.flatnonzero(np.diff(u) != 0)
        lo = int(edges[0]) + 30 if edges.size else 10
        at = int(rng.integers(lo, max(lo + 1, n - 10)))
        return head, np.delete(rows, [at, at + 1, at + 2], axis=0)
    if kind == "reverse":
        out = rows.copy()
        for k in ("u", "omega", "theta"):
            if k in c:
                out[:, c[k]] *= -1
        return head, out
    raise ValueError(kind)


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", type=Path)
    p.add_argument("--seed", type=int, default=37)
    p.add_argument("--analyze", action="store_true")
    a = p.parse_args()
    a.out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(a.seed)
    made = []
    for log in sorted(REAL.glob("*/step.csv")):
        head, cols, rows = read(log)
        for kind in VARIANTS:
            h, r = variant(kind, head, cols, rows, rng)
            path = a.out / f"{log.parent.name}--{kind}.csv"
            write(path, [*h, f"# variant: {kind} of {log.parent.name} (seed {a.seed})"], cols, r)
            made.append(path)
    print(f"{len(made)} variants in {a.out}")
    if a.analyze:
        from minseg_tui.errors import InputError
        from minseg_tui.lab.saving.files import read_run_log
        from minseg_tui.lab.views.check_text import text
        from minseg_tui.model.check import check

        for path in made:
            try:
                lg = read_run_log(path)
            except InputError as e:
                print(f"=================== {path.name}\nrefused: {e}")
                continue
            ts = float(lg.metadata["ts"]) if "ts" in lg.metadata else None
            r = check(lg.t, lg.u, lg.omega, ts=ts, cpr=lg.declared_cpr, omega_over=lg.omega_over)
            print(f"=================== {path.name}\n{text(r)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
