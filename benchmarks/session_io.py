"""Session I/O figures: autosave latency per entry, recorder throughput, results and report time.

Prints figures; not a test. Run: .venv/bin/python benchmarks/session_io.py
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import PlantParams, record
from minseg_tui.report.write import write_report


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        s = Session.create(Path(tmp), ["Bench"], date="2026-11-22")
        for lv, u, w, i in (
            (2.5, "2.05", "3.8", "29.8"),
            (3.5, "3.05", "5.8", "33.5"),
            (4.5, "4.05", "7.8", "37.2"),
        ):
            s.enter(f"u_ss@{lv:g}", u)
            s.enter(f"omega_ss@{lv:g}", w)
            s.enter(f"i_ss@{lv:g}", i)
        times = []
        for k in range(50):
            t0 = time.perf_counter()
            s.enter("R", f"{5 + k * 0.001:.3f}")
            times.append(time.perf_counter() - t0)
        print(
            f"enter() incl. atomic save + fsync: median {np.median(times) * 1e3:.2f} ms, max {max(times) * 1e3:.2f} ms"
        )

        plan = dict(step("task10").plans)["fast"]
        n = 20000
        u = np.where((np.arange(n) // 300) % 2 == 1, 4.5, 0.0)
        data = record(PlantParams(), u, ts=plan.ts, seed=1)
        rec = s.start_run("fast", plan)
        t0 = time.perf_counter()
        for k in range(n):
            rec.append(
                int(data.seq[k]), int(data.t_us[k]), int(data.count[k]), int(round(u[k] * 1000))
            )
        dt = time.perf_counter() - t0
        print(
            f"Recorder.append: {n / dt:,.0f} samples/s ({dt / n * 1e6:.1f} us each; the board sends at most 500/s)"
        )
        t0 = time.perf_counter()
        s.finish_run(rec)
        print(
            f"finish_run of {n} samples (run log written atomically): {(time.perf_counter() - t0) * 1e3:.0f} ms"
        )
        t0 = time.perf_counter()
        s.results()
        print(f"results() (identify, {n} samples): {(time.perf_counter() - t0) * 1e3:.0f} ms")
        t0 = time.perf_counter()
        s.model_check()
        print(f"model_check() ({n} samples): {(time.perf_counter() - t0) * 1e3:.0f} ms")
        t0 = time.perf_counter()
        w = write_report(s)
        print(
            f"write_report: {(time.perf_counter() - t0) * 1e3:.0f} ms, html {w.html.stat().st_size / 1e3:.0f} kB"
        )
        s.close()


if __name__ == "__main__":
    main()
