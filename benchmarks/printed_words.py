"""Every sentence identify and analyze print on a corpus of run logs, as records to diff
before and after a change that must leave the printed text byte-identical (issue 19 item 3:
moving words out of the model).

The corpus:

- every CSV under ../shared/data (the real logs, the probes, the NXT logs);
- seeded logs of the project's plant (model/plant.record) and generator (model/synth.make_log),
  each angle source the analysis reads: a theta column, a count column, an Euler speed of
  counts over the nominal period, a speed over the real intervals, with and without t_us;
- hostile variants that meet each of a run log's refusals: too few rows, a speed that never
  changes, a t_us that does not keep time with t, a sample period out of range, a voltage
  out of size, a wheel whose angle never changes (count and theta), a command that only
  falls (no rising edge);
- hostile tables that meet each of identify's refusals of the steady-state readings: a
  speed, u_ss or current at 0, --R at 0, readings too small to give a finite k_v, a median
  k_v below 0.

For each log: ``identify TABLE --R 5 --step LOG`` as text and ``--json``, ``analyze LOG``
(``--json`` too with ``--json``): exit code, stdout and stderr, one record each; and, when
analyze does not refuse the log, what the lab's screen and the report tell a student of the
same check (the close-up's title, the lead, the details: issue 20's student words). Then the
refusals of :func:`minseg_tui.model.runlog.problem` and :func:`~minseg_tui.model.runlog.
clock_problem` on arrays the CSV reader would refuse first (unequal lengths, non-finite
values, a time that goes back), and :meth:`~minseg_tui.model.runlog.RunLog.angle`'s source,
in the words the program prints; and identify's refusals asked of the model directly (a row
not a number, a bad R, no rows, no rising edge), with the session's line for a row it leaves
out (:func:`minseg_tui.lab.state.results.compute`).

Run: ``.venv/bin/python benchmarks/printed_words.py OUT.txt`` (``--fast`` leaves analyze
out on the logs it does not refuse: the model check takes seconds a log), then ``diff``
two outputs. Seeded; the records are in a fixed order.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import math
import sys
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from minseg_tui.cli import main  # noqa: E402
from minseg_tui.cli.analyze import _sample_period  # noqa: E402
from minseg_tui.lab.saving.files import read_run_log, write_run_log  # noqa: E402
from minseg_tui.lab.views import check_words  # noqa: E402
from minseg_tui.model import runlog  # noqa: E402
from minseg_tui.model.check import check  # noqa: E402
from minseg_tui.model.motor import MotorParams  # noqa: E402
from minseg_tui.model.plant import PlantParams, record, square_wave  # noqa: E402
from minseg_tui.model.runlog import RunLog  # noqa: E402
from minseg_tui.model.synth import make_log  # noqa: E402
from minseg_tui.signals import timestamp_velocity  # noqa: E402

SHARED = ROOT.parent / "shared" / "data"
TABLE = "u_req,u_ss,omega_ss,i_ss\n2,1.55,20,40\n3,2.55,30,45\n4,3.55,40,50\n"
MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3)


def _said(what: object) -> str:
    """A refusal or an angle's source in the words the program prints: the model's answer
    as it is (words before the change), or its record worded by lab/content/log_says."""
    if what is None or isinstance(what, str):
        return repr(what)
    from minseg_tui.lab.content import log_says

    name = "angle_words" if type(what).__name__ == "AngleFrom" else "refusal_words"
    words: Callable[[object], str] = getattr(log_says, name)
    return repr(words(what))


def _refused(call: Callable[[], object]) -> str:
    """What the program says of a call to identify the model refuses: an InputError as it
    is (words before the change), or a refusal record worded by lab/content/identify_says."""
    from minseg_tui.errors import InputError

    try:
        call()
    except InputError as e:
        return repr(str(e))
    except Exception as e:
        if type(e).__name__ != "IdentifyRefused":
            raise
        from minseg_tui.lab.content import identify_says

        worded: Callable[[object], object] = identify_says.identify_refusal
        return repr(str(worded(e)))
    return "not refused"


def _run(argv: list[str]) -> str:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as e:  # argparse
            code = e.code if isinstance(e.code, int) else 2
    return f"exit {code}\n--- stdout\n{out.getvalue()}--- stderr\n{err.getvalue()}"


def _plant(d: Path) -> Iterator[tuple[str, Path]]:
    """Seeded plant recordings, one per angle source the analysis reads."""
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=0.45)
    for seed in (1, 2, 3):
        rec = record(params, square_wave(0.0, 4.0, 40, 3, lead=20), seed=seed, jitter_us=2000)
        omega = timestamp_velocity(rec.t, rec.count)
        q = 2 * np.pi / 720
        euler = np.concatenate(([0.0], np.diff(rec.count) * q / 0.025))
        kinds = {
            "count+t_us": (omega, {"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us}),
            "theta": (omega, {"u_req": rec.u_req, "theta": rec.count * q}),
            "euler": (euler, {"u_req": rec.u_req}),
            "mean-speed": (omega, {"u_req": rec.u_req, "t_us": rec.t_us}),
        }
        for kind, (w, extra) in kinds.items():
            p = d / f"plant-{seed}-{kind}.csv"
            write_run_log(p, RunLog(t=rec.t, u=rec.u_A, omega=w, extra=extra), {})
            yield p.stem, p


def _synth(d: Path) -> Iterator[tuple[str, Path]]:
    for cause, seed in (("none", 1), ("none", 4), ("coulomb_friction", 2)):
        g = make_log(cause, seed=seed, duration=6.0)
        p = d / f"synth-{cause}-{seed}.csv"
        write_run_log(p, RunLog(t=g.t, u=g.u, omega=g.omega), {})
        yield p.stem, p


def _hostile(d: Path) -> Iterator[tuple[str, Path]]:
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=0.45)
    rec = record(params, square_wave(0.0, 4.0, 40, 3, lead=20), seed=7, jitter_us=2000)
    omega = timestamp_velocity(rec.t, rec.count)
    base = {"u_req": rec.u_req, "count": rec.count, "t_us": rec.t_us}
    variants: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray, dict[str, np.ndarray]]] = {
        "few-rows": (
            rec.t[17:23],
            rec.u_A[17:23],
            omega[17:23],
            {k: v[17:23] for k, v in base.items()},
        ),
        "still-speed": (rec.t, rec.u_A, omega * 0 + 1.5, base),
        "clock-fast": (rec.t, rec.u_A, omega, {**base, "t_us": np.round(rec.t * 1e5)}),
        "clock-slow": (rec.t, rec.u_A, omega, {**base, "t_us": np.round(rec.t * 1e7)}),
        "period-us": (rec.t * 1e-3, rec.u_A, omega, {"u_req": rec.u_req, "count": rec.count}),
        "huge-u": (rec.t, rec.u_A * 1e7, omega, {"count": rec.count}),
        "count-still": (rec.t, rec.u_A, omega, {**base, "count": rec.count * 0}),
        "theta-still": (rec.t, rec.u_A, omega, {"u_req": rec.u_req, "theta": rec.t * 0 + 1.0}),
        "board-period": (rec.t, rec.u_A, omega, {**base, "t_us": np.round(rec.t * 1e2)}),
        "falls-only": (
            rec.t[:60],
            np.where(rec.t[:60] < rec.t[30], 4.0, 0.0),
            omega[:60],
            {"u_req": np.where(rec.t[:60] < rec.t[30], 4.5, 0.0), "count": rec.count[:60]},
        ),
    }
    for name, (t, u, w, extra) in variants.items():
        p = d / f"hostile-{name}.csv"
        ex = {k: (v.astype(np.int64) if k in ("t_us", "count") else v) for k, v in extra.items()}
        write_run_log(p, RunLog(t=t, u=u, omega=w, extra=ex), {})
        yield p.stem, p


TABLES: dict[str, tuple[str, str]] = {
    "omega_ss-zero": ("u_req,u_ss,omega_ss,i_ss\n2,1.55,20,40\n3,2.55,0,45\n", "5"),
    "u_ss-zero": ("u_req,u_ss,omega_ss,i_ss\n2,0,20,40\n", "5"),
    "i_ss-zero": ("u_req,u_ss,omega_ss,i_ss\n2,1.55,20,40\n3,2.55,30,0\n", "5"),
    "R-zero": (TABLE, "0"),
    "tiny-speed": ("u_req,u_ss,omega_ss,i_ss\n2,1.55,1e-320,40\n", "5"),
    "k_v-median-negative": ("u_req,u_ss,omega_ss,i_ss\n2.5,2,3,125\n1.5,1,1,375\n", "4"),
}
"""Tables identify refuses, each with the --R it is given."""


def _tables(d: Path) -> Iterator[tuple[str, str]]:
    for name, (text, R) in TABLES.items():
        p = d / f"table-{name}.csv"
        p.write_text(text)
        for label, extra in (("identify", []), ("identify --json", ["--json"])):
            said = _run(["identify", str(p), "--R", R, *extra]).replace(str(d), "TMP")
            yield f"table {name} | {label}", said


def _identify_direct() -> Iterator[tuple[str, str]]:
    """identify's refusals asked of the model directly, and the session's line for a row
    it leaves out."""
    from minseg_tui.lab.state.results import compute
    from minseg_tui.model.identify import Reading, identify

    good = [Reading(2, 1.55, 20, 40, line=2), Reading(3, 2.55, 30, 45, line=3)]
    rows = {
        "u_req-nan": Reading(math.nan, 3.55, 40, 50, line=4),
        "u_ss-inf": Reading(4, math.inf, 40, 50, line=4),
        "omega_ss-nan": Reading(4, 3.55, math.nan, 50, line=4),
        "i_ss-inf": Reading(4, 3.55, 40, -math.inf, line=4),
        "omega_ss-negative": Reading(4, 3.55, -40, 50, line=4),
        "u_ss-negative": Reading(4, -3.55, 40, 50, line=4),
        "i_ss-zero": Reading(4, 3.55, 40, 0.0, line=None),
        "tiny-speed": Reading(4, 3.55, 1e-320, 50, line=4),
    }
    for name, row in rows.items():
        yield f"identify row {name}", _refused(lambda row=row: identify([*good, row], 5.0))
        said = compute(None, [*good, row], None, Path("."))
        yield f"compute row {name}", repr(said.problems)
    for R in (0.0, -5.0, math.nan, math.inf):
        yield f"identify R {R}", _refused(lambda R=R: identify(good, R, source="t.csv"))
    yield "identify no rows", _refused(lambda: identify([], 5.0, source="t.csv"))
    negative = [Reading(2.5, 2.0, 3.0, 125.0, line=2), Reading(1.5, 1.0, 1.0, 375.0, line=3)]
    yield "identify k_v median", _refused(lambda: identify(negative, 4.0, source="t.csv"))
    said = compute(4.0, negative, None, Path("."))
    yield "compute k_v median", repr(said.problems)
    t = np.arange(60) * 0.025
    for name, u in (("falls", np.where(t < 0.5, 4.0, 0.0)), ("flat", t * 0 + 3.0)):
        log = RunLog(t=t, u=u, omega=np.zeros(60), source="down.csv", lines=np.arange(60) + 2)
        yield f"identify log {name}", _refused(lambda log=log: identify(good, 5.0, log))
    late = np.where(t > t[-3], 4.0, 0.0)  # a rise too near the end to be used
    log = RunLog(t=t, u=late, omega=np.zeros(60), source="late.csv", lines=np.arange(60) + 2)
    yield "identify log late rise", _refused(lambda: identify(good, 5.0, log))


def _direct() -> Iterator[tuple[str, str]]:
    """The refusals the CSV reader meets first, asked of the model directly."""
    t = np.arange(20) * 0.025
    u = np.where(t > 0.2, 4.0, 0.0)
    w = np.where(t > 0.2, 30.0, 0.0)
    nan = w.copy()
    nan[3] = np.nan
    back = t.copy()
    back[5] = back[4]
    asks = {
        "unequal": (t, u[:-1], w, None),
        "few": (t[:5], u[:5], w[:5], None),
        "nan-t": (np.where(t > 0.1, np.inf, t), u, w, None),
        "nan-u": (t, np.where(t > 0.1, np.nan, u), w, None),
        "nan-omega": (t, u, nan, None),
        "big-u": (t, u * 1e7, w, None),
        "big-omega": (t, u, -w * 1e7, None),
        "back": (back, u, w, None),
        "slow": (t * 100, u, w, None),
        "fast": (t * 1e-3, u, w, None),
        "ts-given": (t, u, w, 5.0),
        "still": (t, u, w * 0 + 2.5, None),
        "fine": (t, u, w, None),
    }
    for name, (tt, uu, ww, ts) in asks.items():
        yield f"problem {name}", _said(runlog.problem(tt, uu, ww, ts))
    for name, scale in (("same", 1e6), ("10x", 1e5), ("short", 1.02e6)):
        yield f"clock_problem {name}", _said(runlog.clock_problem(t, np.round(t * scale)))
    counts = np.round(np.cumsum(np.where(t > 0.2, 3, 0)))
    for name, extra in (
        ("theta", {"theta": counts * 0.01}),
        ("count", {"count": counts.astype(np.int64)}),
        ("euler", {}),
    ):
        om = np.concatenate(([0.0], np.diff(counts) * (2 * np.pi / 720) / 0.025))
        log = RunLog(t=t, u=u, omega=om, extra=extra)
        yield f"angle {name}", _said(log.angle()[1])
    rng = np.random.default_rng(3)
    log = RunLog(t=t + rng.uniform(0, 0.004, t.size), u=u, omega=w + rng.normal(0, 0.3, t.size))
    yield "angle mean speed", _said(log.angle()[1])


def _student(path: Path) -> str:
    """What the lab's screen and the report tell a student of the check of the log at
    ``path``: the lead (about the close-up, with the run's input) and the details, as
    :mod:`minseg_tui.lab.views.check_words` writes them (the same check ``analyze`` runs)."""
    log = read_run_log(path)
    ts = _sample_period(dict(log.metadata))
    r = check(log.t, log.u, log.omega, ts=ts, cpr=log.declared_cpr, omega_over=log.omega_over)
    told = check_words.details(r)
    return "\n".join(
        (
            "--- lead",
            check_words.close_up_title(r),
            *check_words.lead(r, log.u),
            "--- details",
            *told.lines(),
        )
    )


def main_(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", help="file to write the records to")
    ap.add_argument("--fast", action="store_true", help="analyze only the refused logs")
    args = ap.parse_args(argv)
    lines: list[str] = []
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        (d / "table.csv").write_text(TABLE)
        logs = [(str(p.relative_to(SHARED)), p) for p in sorted(SHARED.rglob("*.csv"))]
        logs += [*_plant(d), *_synth(d), *_hostile(d)]
        lines += [f"=== {k}\n{v}" for k, v in _tables(d)]
        for name, path in logs:
            print(name, file=sys.stderr, flush=True)
            base = ["identify", str(d / "table.csv"), "--R", "5", "--step", str(path)]
            for label, argv_ in (("identify", base), ("identify --json", [*base, "--json"])):
                said = _run(argv_).replace(str(d), "TMP").replace(str(SHARED), "SHARED")
                lines.append(f"=== {name} | {label}\n{said}")
            refused = _run(["identify", str(d / "table.csv"), "--step", str(path), "--R", "5"])
            if args.fast and refused.startswith("exit 0") and not name.startswith("hostile"):
                continue
            for label, argv_ in (("analyze", ["analyze", str(path)]),):
                said = _run(argv_).replace(str(d), "TMP").replace(str(SHARED), "SHARED")
                lines.append(f"=== {name} | {label}\n{said}")
            if said.startswith("exit 0"):
                lines.append(f"=== {name} | student\n{_student(path)}")
    lines += [f"=== {k}\n{v}" for k, v in _direct()]
    lines += [f"=== {k}\n{v}" for k, v in _identify_direct()]
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{len(lines)} records -> {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main_())
