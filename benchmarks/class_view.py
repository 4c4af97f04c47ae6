"""`minseg-tui class` on a class of 100 groups (goal: under 5 s).

Builds --groups seeded sessions in a temporary folder with the real Session API (R, the
table of Tasks 4-5 scattered around the lab's motor, a few of the manual's slips, and a
recorded step run of the simulated motor, each with its own seed), then runs the command
as a user does (a new process) and prints its wall time and CPU time (the process and its
workers):

- cold: nothing saved (the sessions keep no results, the cache is empty): every row
  computed, Tasks 6-15 and the model check per group;
- saved: the same sessions as the lab writes them: each opened, its results and model
  check computed as the lab's screens do, closed (the session file then keeps them,
  lab/saving/kept.py); the cache empty again. The rows take the kept results;
- warm: the same folder again, every row from the cache;
- one changed: one group typed a new R since, that row is read again (its kept results
  still hold: R changes neither the run nor the table's u_ss);
- warm with --out: also writing class.md, class.html and class.csv.

The output of cold, saved and warm must be the same, byte for byte.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.state.session import Session

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.seeded import Clock, record_square_wave  # the tests' seeded sessions


def make_group(root: Path, k: int) -> Path:
    """Group ``k``: seeded readings, every 17th with a slip, and a step run."""
    rng = np.random.default_rng(k)
    s = Session.create(
        root, [f"Student {2 * k}", f"Student {2 * k + 1}"], "2026-11-22", clock=Clock()
    )
    s.enter("R", "12 Ω" if k % 17 == 5 else f"{5.2 + 0.15 * rng.standard_normal():.2f} Ω")
    for lv in (2.5, 3.5, 4.5):
        u = lv - 0.45 + 0.03 * rng.standard_normal()
        w = 1.99 * u - 0.3 + 0.08 * rng.standard_normal()
        i = 26.0 + 2.5 * lv + 0.8 * rng.standard_normal()
        s.enter(f"u_ss@{lv:g}", f"{u:.3f}")
        s.enter(f"omega_ss@{lv:g}", f"{w / (2 * np.pi / 60):.1f}" if k % 17 == 9 else f"{w:.3f}")
        s.enter(f"i_ss@{lv:g}", f"{i / 1000:.4f} mA" if k % 17 == 13 else f"{i:.1f} mA")
    record_square_wave(s, seed=k)
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


def as_the_lab_does(folder: Path) -> None:
    """Open the session, compute what the lab's screens show of its run (Tasks 11-15 and
    the model check) and close it: the session file then keeps the results."""
    with Session.open(folder) as s:
        s.results()
        s.model_check()


def line(name: str, wall: float, cpu: float) -> None:
    """One run's figures; judged by CPU time, which the other programs on a shared machine
    do not inflate (on an idle machine the wall time is about the CPU time over the
    processes that share it)."""
    ok = "ok" if cpu < 5 else "over"
    load = os.getloadavg()[0]
    print(f"{name:<28} {wall:7.2f} {cpu:7.2f}  {ok} (load average {load:.1f})", flush=True)


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
        cache = Path(tmp) / "cache"
        env = {**os.environ, "MINSEG_TUI_CACHE": str(cache)}
        cmd = [exe, "class", "--sessions", str(root), "--json"]
        print(f"CPUs this process may use: {len(os.sched_getaffinity(0))}")
        print(f"{'run':<28} {'wall s':>7} {'CPU s':>7}  goal < 5 s of CPU")
        wall, cpu, out = timed(cmd, env)
        line("cold (nothing saved)", wall, cpu)
        flagged = sum(1 for g in json.loads(out)["groups"] if g["flags"])
        t0 = time.perf_counter()
        for f in folders:
            as_the_lab_does(f)
        print(f"  (the lab computed and kept the results in {time.perf_counter() - t0:.1f} s)")
        shutil.rmtree(cache)
        wall, cpu, saved = timed(cmd, env)
        line("saved (kept results)", wall, cpu)
        assert saved == out, "the rows from kept results differ from the computed ones"
        wall, cpu, warm = timed(cmd, env)
        line("warm (all cached)", wall, cpu)
        assert warm == out, "the cached rows differ from the computed ones"
        with Session.open(folders[3]) as s:
            s.enter("R", "5.05 Ω")
        wall, cpu, _ = timed(cmd, env)
        line("one group changed", wall, cpu)
        wall, cpu, _ = timed([*cmd[:-1], "--out", str(Path(tmp) / "out")], env)
        line("warm, with --out", wall, cpu)
        print(f"groups with something that stands out: {flagged} of {args.groups}")


if __name__ == "__main__":
    main()
