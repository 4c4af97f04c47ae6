"""Model-check benchmark on logs with two effects at once, and with a hand on the wheel.

    .venv/bin/python benchmarks/model_check_pairs.py [--seeds 20] [--touch-seeds 10]

Pairs: every pair of the causes (minseg_tui.model.synth, 20 s logs, parameters drawn from
their ranges). A log counts as right when exactly the two causes are named, T is within
15 % of the plant's, and each cause's parameter within 25 % (taps within one).

Hand on the wheel: every single cause (and none) with a touch of 0.15-0.3 s in a settled
driven stretch. Right when a disturbance is reported starting within 0.15 s of the touch
and the log's own cause (or none) is still named alone.
"""

from __future__ import annotations

import argparse
import itertools
import time

import numpy as np

from minseg_tui.model.check import check
from minseg_tui.model.synth import CAUSES, PARAM_RANGES, make_log, plant_with


def _named(r: object) -> list[str]:
    f = r.finding  # type: ignore[attr-defined]
    return [c for c in [f.cause, *(o.cause for o in f.others)] if c != "none"]


def _param_ok(cause: str, est: float, truth: float) -> bool:
    if cause == "velocity_filter":
        return abs(est - truth) <= 1.0
    return abs(est - truth) <= 0.25 * truth


def pairs(seeds: int) -> None:
    names = list(PARAM_RANGES)
    print(f"Two effects at once ({seeds} seeds per pair): named / T / params / all right")
    total = right_all = 0
    cpu = []
    wrong: dict[str, list[str]] = {}
    for a, b in itertools.combinations(names, 2):
        ok_named = ok_t = ok_p = ok_all = 0
        for s in range(seeds):
            log = make_log(a, seed=3000 + s, also=b)
            t0 = time.process_time()
            r = check(log.t, log.u, log.omega)
            cpu.append(time.process_time() - t0)
            named = _named(r)
            t_true = plant_with(log.effects).motor.T
            n_ok = sorted(named) == sorted((a, b))
            t_ok = abs(r.extended.params["T"] - t_true) <= 0.15 * t_true
            p_ok = n_ok and all(
                _param_ok(c, r.extended.params[PARAM_RANGES[c][0]], log.effects[c]) for c in (a, b)
            )
            ok_named += n_ok
            ok_t += t_ok
            ok_p += p_ok
            ok_all += n_ok and t_ok and p_ok
            if not (n_ok and t_ok and p_ok):
                wrong.setdefault(f"{a}+{b}", []).append(
                    f"seed {3000 + s}: named {named}, T {r.extended.params['T']:.4f} "
                    f"(true {t_true:.4f}), "
                    + ", ".join(
                        f"{PARAM_RANGES[c][0]} {r.extended.params.get(PARAM_RANGES[c][0], float('nan')):.4g}"
                        f" (true {log.effects[c]:.4g})"
                        for c in (a, b)
                    )
                )
        total += seeds
        right_all += ok_all
        print(
            f"  {a:>16} + {b:<16} {ok_named:3d} {ok_t:3d} {ok_p:3d} {ok_all:3d}  of {seeds}"
            f"  ({100 * ok_all / seeds:.0f} %)"
        )
    print(
        f"all pairs: {right_all} of {total} right ({100 * right_all / total:.1f} %); "
        f"CPU per log: median {np.median(cpu):.2f} s, max {max(cpu):.2f} s"
    )
    for k, v in wrong.items():
        for line in v[:3]:
            print(f"    wrong {k}: {line}")


def touches(seeds: int) -> None:
    print(f"\nA hand on the wheel ({seeds} seeds per cause): reported near its start / cause kept")
    total = ok_both = 0
    for cause in CAUSES:
        near = kept = both = 0
        for s in range(seeds):
            log = make_log(cause, seed=4000 + s, touch=True)
            r = check(log.t, log.u, log.omega)
            assert log.touch is not None
            starts = [a.t for a in r.anomalies if a.kind == "disturbance" and a.t is not None]
            n_ok = any(abs(t - log.touch[0]) <= 0.15 for t in starts)
            k_ok = _named(r) == ([] if cause == "none" else [cause])
            near += n_ok
            kept += k_ok
            both += n_ok and k_ok
            if not (n_ok and k_ok):
                print(
                    f"    wrong {cause} seed {4000 + s}: touch {log.touch[0]:.3f}-{log.touch[1]:.3f}"
                    f" s, reported {[round(x, 3) for x in starts]}, named {_named(r)}"
                )
        total += seeds
        ok_both += both
        print(f"  {cause:>17}: {near:3d} {kept:3d} {both:3d} of {seeds}")
    print(f"all: {ok_both} of {total} right ({100 * ok_both / total:.1f} %)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--touch-seeds", type=int, default=10)
    a = ap.parse_args()
    pairs(a.seeds)
    touches(a.touch_seeds)


if __name__ == "__main__":
    main()
