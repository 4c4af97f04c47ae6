"""`minseg-tui class` on a class of 100 groups (goal: under 5 s).

Builds --groups seeded sessions in a temporary folder with the real Session API (R, the
table of Tasks 4-5 scattered around the lab's motor, a few of the manual's slips, and a
recorded step run of the simulated motor, each with its own seed), then runs the command
as a user does (a new process) and prints its wall time and CPU time:

- cold: an empty cache, every row computed (Tasks 6-15 and the model check per group);
- warm: the same folder again, every row from the cache;
- one changed: one group typed a new R since, that row is computed again;
- warm with --out: also writing class.md, class.html and class.csv.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from datetime import UTC, datetime, timedelta
from pathlib import Path

import numpy as np

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import PlantParams, record


class _Clock:
    def __init__(self) -> None:
        self.t = datetime(2026, 11, 22, 10, 0, 0, tzinfo=UTC)

    def __call__(self) -> datetime:
        self.t += timedelta(seconds=1)
        return self.t


def make_group(root: Path, k: int) -> Path:
    """Group ``k``: seeded readings, every 17th with a slip, and a step run."""
    rng = np.random.default_rng(k)
    s = Session.create(
        root, [f"Student {2 * k}", f"Student {2 * k + 1}"], "2026-11-22", clock=_Clock()
    )
    s.enter("R", "12 Ω" if k % 17 == 5 else f"{5.2 + 0.15 * rng.standard_normal():.2f} Ω")
    for lv in (2.5, 3.5, 4.5):
        u = lv - 0.45 + 0.03 * rng.standard_normal()
        w = 1.99 * u - 0.3 + 0.08 * rng.standard_normal()
        i = 26.0 + 2.5 * lv + 0.8 * rng.standard_normal()
        s.enter(f"u_ss@{lv:g}", f"{u:.3f}")
        s.enter(f"omega_ss@{lv:g}", f"{w / (2 * np.pi / 60):.1f}" if k % 17 == 9 else f"{w:.3f}")
        s.enter(f"i_ss@{lv:g}", f"{i / 1000:.4f} mA" if k % 17 == 13 else f"{i:.1f} mA")
    plan = dict(step("task10").plans)["manual"]
    n = int(round(plan.duration / plan.ts))
    u_req = np.concatenate(
        (np.zeros(20), np.where((np.arange(n) * plan.ts // plan.half_period) % 2 == 0, 4.5, 0.0))
    )
    p = PlantParams()
    data = record(p, u_req, ts=plan.ts, seed=k, jitter_us=800)
    rec = s.start_run("steps", plan)
    for j in range(u_req.size):
        rec.append(
            int(data.seq[j]), int(data.t_us[j]), int(data.count[j]), int(round(u_req[j] * 1000))
        )
    s.finish_run(rec)
    s.go_to("task13")
    s.close()
    return s.folder


def timed(args: list[str], env: dict[str, str]) -> tuple[float, float, str]:
    """Wall time (s), CPU time of the process and its children (s), and stdout."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    out = subprocess.run(args, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if out.returncode != 0:
        sys.exit(f"minseg-tui class failed ({out.returncode}): {out.stderr.strip()}")
    return wall, cpu, out.stdout


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--groups", type=int, default=100)
    args = ap.parse_args()
    exe = str(Path(sys.executable).with_name("minseg-tui"))
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "sessions"
        t0 = time.perf_counter()
        folders = [make_group(root, k) for k in range(args.groups)]
        print(f"built {args.groups} sessions with step runs in {time.perf_counter() - t0:.1f} s")
        env = {**os.environ, "MINSEG_TUI_CACHE": str(Path(tmp) / "cache")}
        cmd = [exe, "class", "--sessions", str(root), "--json"]
        print(f"CPUs this process may use: {len(os.sched_getaffinity(0))}")
        print(f"{'run':<24} {'wall s':>7} {'CPU s':>7}  goal < 5 s")
        wall, cpu, out = timed(cmd, env)
        print(f"{'cold (empty cache)':<24} {wall:7.2f} {cpu:7.2f}  {'ok' if wall < 5 else 'over'}")
        flagged = sum(1 for g in json.loads(out)["groups"] if g["flags"])
        wall, cpu, warm = timed(cmd, env)
        print(f"{'warm (all cached)':<24} {wall:7.2f} {cpu:7.2f}  {'ok' if wall < 5 else 'over'}")
        assert warm == out, "the cached rows differ from the computed ones"
        with Session.open(folders[3]) as s:
            s.enter("R", "5.05 Ω")
        wall, cpu, _ = timed(cmd, env)
        print(f"{'one group changed':<24} {wall:7.2f} {cpu:7.2f}  {'ok' if wall < 5 else 'over'}")
        wall, cpu, _ = timed([*cmd[:-1], "--out", str(Path(tmp) / "out")], env)
        print(f"{'warm, with --out':<24} {wall:7.2f} {cpu:7.2f}  {'ok' if wall < 5 else 'over'}")
        print(f"groups with something that stands out: {flagged} of {args.groups}")


if __name__ == "__main__":
    main()
