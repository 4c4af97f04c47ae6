"""Least-squares engines side by side: the same problems fitted by two or more source trees.

    .venv/bin/python benchmarks/lsq_engine.py [--trees main,WORK] [--seeds 16] [--check-seeds 10]
        [--cli-runs 5] [--real DIR] [--parts cli,identify,real,check]

``--trees main,s23-lsq-scipy,WORK`` adds the scipy candidate (branch s23-lsq-scipy: the same
call sites, the search done by scipy.optimize.least_squares) that this tree's search won over.

Each tree (a git ref, exported with ``git archive``, or WORK: this working tree) is measured
in a child process of its own (PYTHONPATH = the tree), on:

- identify on the project's synthetic logs (benchmarks/identify_peers.py's generator: tiers
  25ms, fast, 5ms; the command on the board's grid or right after the read; with and without
  the board's timestamps; seeds 1000 on): median and 90th percentile of |T error| (%), how often
  the 95 % interval holds the true T, CPU ms per ``identify``;
- identify on the real logs (DIR/*/step.csv, DIR/probes/*.csv; default
  /work/shared/data/real-motors): T (ms) and its 95 % interval per log, CPU ms per log;
- the model check on benchmarks/model_check.py's logs (one hidden cause each, seeds 1000 on):
  the share named right per cause, false alarms on clean logs, the median relative error of
  the named cause's parameter, CPU s per log;
- the work per fit in a count the machine's load does not change: the model evaluations per
  log (identify: the step fits' residual at one point; check: one simulated response);
- start-up along the CLI path: ``python -m minseg_tui identify TABLE --R 5.26 --step LOG`` (a
  25 ms synthetic log) and ``python -m minseg_tui analyze LOG`` (model_check.py's 20 s log
  with dry friction), wall and CPU time (the child's user + system) per run, median of
  ``--cli-runs``; and of ``python -c "import ..."`` for the fitting modules, numpy alone
  and scipy.optimize alone (the last two the same in every tree: what the import costs).

CPU time is the fair figure on a shared machine; wall time is printed beside it. The problems
come from minseg_tui.model.synth of each tree: the trees must hold the same synth.py (checked).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
REAL = Path("/work/shared/data/real-motors")
IMPORTS = "import minseg_tui.model.identify, minseg_tui.model.check"


# -- the child: one tree's figures ----------------------------------------------------------

CALLS = {"identify": 0, "check": 0}
"""Model evaluations so far: the fits' cost in a count that does not depend on the machine's
load (identify: the step fits' residual at one point; check: one simulated response)."""


def _count_calls() -> None:
    from minseg_tui.model.check import fit
    from minseg_tui.model.identify import wholelog, windowfit

    response = fit.response

    def counted(*args: Any, **kwargs: Any) -> Any:
        CALLS["check"] += 1
        return response(*args, **kwargs)

    fit.response = counted  # type: ignore[assignment]
    for module in (wholelog, windowfit):
        evaluate = module._Problem.evaluate

        def wrapped(self: Any, x: Any, evaluate: Any = evaluate) -> Any:
            CALLS["identify"] += 1
            return evaluate(self, x)

        module._Problem.evaluate = wrapped  # type: ignore[method-assign]


def _identify_synth(seeds: int) -> dict[str, Any]:
    import numpy as np

    sys.path.insert(0, str(ROOT / "benchmarks"))
    import identify_peers as peers

    out: dict[str, Any] = {}
    for tier in ("25ms", "fast", "5ms"):
        err, cover, cpu = [], [], []
        calls = CALLS["identify"]
        for timing in ("grid", "sample"):
            for stamped in (True, False):
                for s in range(seeds):
                    g = peers.make(tier, 1000 + s, stamped, timing)
                    t0 = time.process_time()
                    T, _, ci, _ = peers.project(g)
                    cpu.append(time.process_time() - t0)
                    err.append(abs(100.0 * (T / g.T - 1.0)))
                    cover.append(ci is not None and ci[0] <= g.T <= ci[1])
        out[tier] = {
            "logs": len(err),
            "T_med": float(np.median(err)),
            "T_p90": float(np.percentile(err, 90)),
            "cover": 100.0 * float(np.mean(cover)),
            "cpu_ms": 1e3 * float(np.median(cpu)),
            "evals": (CALLS["identify"] - calls) / len(err),
        }
    return out


def _identify_real(folder: Path) -> dict[str, Any]:
    from minseg_tui.lab.saving.files import read_run_log
    from minseg_tui.model.identify import Reading, identify
    from minseg_tui.model.runlog import command, find_edges

    out: dict[str, Any] = {}
    paths = sorted(folder.glob("*/step.csv")) + sorted(folder.glob("probes/*.csv"))
    for path in paths:
        log = read_run_log(path)
        cmd, _ = command(log)
        levels = sorted({abs(e.after) for e in find_edges(cmd) if e.rising and e.after})
        t0 = time.process_time()
        r = identify([Reading(v, v, 10.0, 50.0) for v in levels], 5.0, log)
        cpu = time.process_time() - t0
        s = r.step
        name = path.parent.name if path.name == "step.csv" else "probes/" + path.stem
        if s is None:
            out[name] = None
            continue
        out[name] = {"T": s.T, "ci": list(s.T_ci), "method": s.fit.method, "cpu_ms": 1e3 * cpu}
    return out


def _check(seeds: int) -> dict[str, Any]:
    import numpy as np

    from minseg_tui.model.check import check
    from minseg_tui.model.synth import CAUSES, PARAM_RANGES, make_log

    out: dict[str, Any] = {}
    cpu_all = []
    calls = CALLS["check"]
    for cause in CAUSES:
        right, rel = 0, []
        for s in range(seeds):
            log = make_log(cause, seed=1000 + s)
            t0 = time.process_time()
            r = check(log.t, log.u, log.omega)
            cpu_all.append(time.process_time() - t0)
            if r.finding.cause == cause:
                right += 1
                if cause != "none":
                    p = PARAM_RANGES[cause][0]
                    rel.append(abs(r.extended.params[p] / float(log.param) - 1.0))
        out[cause] = {
            "right": right,
            "of": seeds,
            "rel_med": 100.0 * float(np.median(rel)) if rel else math.nan,
        }
    out["cpu_s"] = float(np.median(cpu_all))
    out["evals"] = (CALLS["check"] - calls) / len(cpu_all)
    return out


def _run_timed(args: list[str], env: dict[str, str]) -> tuple[float, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, env=env, cwd=tempfile.gettempdir())
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def _cli(runs: int) -> dict[str, Any]:
    import numpy as np

    sys.path.insert(0, str(ROOT / "benchmarks"))
    import identify_peers as peers

    from minseg_tui.lab.saving.files import write_run_log
    from minseg_tui.model.runlog import RunLog
    from minseg_tui.model.synth import make_log

    env = dict(os.environ)
    out: dict[str, Any] = {}
    with tempfile.TemporaryDirectory() as d:
        step, table, log20 = Path(d) / "step.csv", Path(d) / "table.csv", Path(d) / "20s.csv"
        write_run_log(step, peers.make("25ms", 1000, True, "grid").log)
        table.write_text(
            "u_req,u_ss,omega_ss,i_ss\n"
            + "".join(f"{r.u_req},{r.u_ss},{r.omega_ss},{r.i_ss}\n" for r in peers.TABLE)
        )
        g = make_log("coulomb_friction", seed=5)
        write_run_log(log20, RunLog(t=g.t, u=g.u, omega=g.omega, extra={"count": g.count}))
        py = sys.executable
        cmds = {
            "identify": [py, "-m", "minseg_tui", "identify", str(table), "--R", "5.26"]
            + ["--step", str(step)],
            "analyze": [py, "-m", "minseg_tui", "analyze", str(log20)],
            "import": [py, "-c", IMPORTS],
            "numpy": [py, "-c", "import numpy"],
            "scipy": [py, "-c", "import scipy.optimize"],
        }
        for name, args in cmds.items():
            walls, cpus = zip(*(_run_timed(args, env) for _ in range(runs)), strict=True)
            out[name] = {"wall": float(np.median(walls)), "cpu": float(np.median(cpus))}
    return out


def child(a: argparse.Namespace) -> None:
    import minseg_tui

    synth = Path(minseg_tui.__file__).parent / "model" / "synth.py"
    _count_calls()
    parts = a.parts.split(",")
    res: dict[str, Any] = {
        "package": str(Path(minseg_tui.__file__).parent),
        "synth": hashlib.sha1(synth.read_bytes()).hexdigest(),
    }
    if "cli" in parts:
        res["cli"] = _cli(a.cli_runs)
    if "identify" in parts:
        res["identify"] = _identify_synth(a.seeds)
    if "real" in parts:
        res["real"] = _identify_real(Path(a.real))
    if "check" in parts:
        res["check"] = _check(a.check_seeds)
    print(json.dumps(res))


# -- the parent: the trees side by side -----------------------------------------------------


def _tree(ref: str, tmp: Path) -> Path:
    if ref == "WORK":
        return ROOT
    dest = tmp / ref.replace("/", "_")
    dest.mkdir()
    archive = subprocess.run(
        ["git", "-C", str(ROOT), "archive", ref], check=True, capture_output=True
    ).stdout
    subprocess.run(["tar", "-x", "-C", str(dest)], input=archive, check=True)
    return dest


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trees", default="main,WORK", help="git refs, or WORK for this tree")
    ap.add_argument("--seeds", type=int, default=16, help="seeds per identify row (x4 per tier)")
    ap.add_argument("--check-seeds", type=int, default=10, help="seeds per cause")
    ap.add_argument("--cli-runs", type=int, default=5)
    ap.add_argument("--real", default=str(REAL))
    ap.add_argument("--parts", default="cli,identify,real,check", help="what to measure")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.child:
        child(a)
        return
    refs = a.trees.split(",")
    res: dict[str, dict[str, Any]] = {}
    with tempfile.TemporaryDirectory() as d:
        for ref in refs:
            tree = _tree(ref, Path(d))
            env = dict(os.environ, PYTHONPATH=str(tree))
            args = [sys.executable, __file__, "--child", "--seeds", str(a.seeds)]
            args += ["--check-seeds", str(a.check_seeds), "--cli-runs", str(a.cli_runs)]
            args += ["--real", a.real, "--parts", a.parts]
            t0 = time.perf_counter()
            got = subprocess.run(args, check=True, capture_output=True, text=True, env=env)
            res[ref] = json.loads(got.stdout.strip().splitlines()[-1])
            print(f"{ref}: measured in {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    if len({r["synth"] for r in res.values()}) > 1:
        print("warning: the trees' synth.py differ; the problems are not the same")
    load = os.getloadavg()
    w = max(14, *(len(r) for r in refs))
    cols = "".join(f"{r:>{w}}" for r in refs)
    print(f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; columns: {', '.join(refs)}")
    parts = a.parts.split(",")
    if "cli" in parts:
        _print_cli(a, refs, res, w, cols)
    if "identify" in parts:
        _print_identify(a, refs, res, w, cols)
    if "real" in parts:
        _print_real(refs, res)
    if "check" in parts:
        _print_check(a, refs, res, w, cols)


def _print_cli(
    a: argparse.Namespace, refs: list[str], res: dict[str, Any], w: int, cols: str
) -> None:
    print(f"\nCLI path (median of {a.cli_runs} runs, Python start included): wall s / CPU s")
    print(f"{'':34}{cols}")
    for name in ("identify", "analyze", "import", "numpy", "scipy"):
        row = "".join(
            f"{res[r]['cli'][name]['wall']:>{w - 7}.2f} /{res[r]['cli'][name]['cpu']:5.2f}"
            for r in refs
        )
        label = {
            "import": "import identify+check",
            "numpy": "import numpy",
            "scipy": "import scipy.optimize",
        }.get(name, f"minseg-tui {name}")
        print(f"{label:34}{row}")


def _print_identify(
    a: argparse.Namespace, refs: list[str], res: dict[str, Any], w: int, cols: str
) -> None:
    print(
        f"\nidentify on synthetic logs ({a.seeds} seeds x grid/sample x t_us or not per tier): "
        "|T error| median / p90 %, 95 % interval coverage %, CPU ms per identify"
    )
    print(f"{'':34}{cols}")
    for tier in ("25ms", "fast", "5ms"):
        keys = (("T_med", ".3f"), ("T_p90", ".3f"), ("cover", ".1f"), ("cpu_ms", ".1f"))
        for key, fmt in (*keys, ("evals", ".1f")):
            row = "".join(f"{res[r]['identify'][tier][key]:>{w}{fmt}}" for r in refs)
            print(f"{tier + ' ' + key:34}{row}")


def _print_real(refs: list[str], res: dict[str, Any]) -> None:
    print("\nidentify on real logs: T ms [95 % interval] (method), CPU ms")
    names = list(res[refs[0]]["real"])
    for n in names:
        cells = []
        for r in refs:
            v = res[r]["real"].get(n)
            cells.append(
                "-"
                if v is None
                else f"{1e3 * v['T']:.2f} [{1e3 * v['ci'][0]:.2f}, {1e3 * v['ci'][1]:.2f}] "
                f"({v['method'][:5]}) {v['cpu_ms']:.0f} ms"
            )
        print(f"  {n:36}" + " | ".join(cells))


def _print_check(
    a: argparse.Namespace, refs: list[str], res: dict[str, Any], w: int, cols: str
) -> None:
    print(
        f"\nmodel check ({a.check_seeds} seeds per cause): named right, median relative error "
        "of its parameter %"
    )
    print(f"{'':34}{cols}")
    causes = [c for c in res[refs[0]]["check"] if c not in ("cpu_s", "evals")]
    for c in causes:
        row = "".join(
            f"{res[r]['check'][c]['right']:>{w - 9}d}/{res[r]['check'][c]['of']:<2d}"
            f"{res[r]['check'][c]['rel_med']:6.1f}"
            for r in refs
        )
        print(f"{c:34}{row}")
    for key, label, fmt in (
        ("cpu_s", "CPU s per log (median)", ".3f"),
        ("evals", "model evaluations per log", ".1f"),
    ):
        print(f"{label:34}" + "".join(f"{res[r]['check'][key]:>{w}{fmt}}" for r in refs))


if __name__ == "__main__":
    main()
