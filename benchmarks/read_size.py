"""Reading large run logs and tables: rows per second and peak memory.

Each read runs in a fresh process (peak resident memory is per process), on files written
here: session-style run logs (t,u,omega,u_req,omega_lab,theta,count,t_us,seq) of 100k,
1M and 2M rows (MAX_LOG_ROWS) and tables of 10M rows, which are refused at row
MAX_TABLE_ROWS + 1. Prints one line per file: rows, file size, seconds, rows/s, peak
resident memory and, for comparison, that of a process that only imports the reader.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.saving import files

CHILD = """
import json, resource, sys, time
from minseg_tui.errors import InputError
from minseg_tui.lab.saving.files import read_run_log, read_table
kind, path = sys.argv[1], sys.argv[2]
t0 = time.perf_counter()
rows, refused = 0, ""
if kind != "none":
    try:
        rows = len(read_run_log(path) if kind == "log" else read_table(path))
    except InputError as exc:
        refused = str(exc).split(": ", 1)[1]
dt = time.perf_counter() - t0
try:  # the peak of this program; ru_maxrss would also count the parent's pages before exec
    status = open("/proc/self/status").read().split("VmHWM:")[1]
    peak = int(status.split()[0]) / 1024
except (OSError, IndexError):
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({"rows": rows, "seconds": dt, "peak_mb": peak, "refused": refused}))
"""


def write_log(path: Path, n: int) -> None:
    rng = np.random.default_rng(0)
    k = np.arange(n)
    t = k * 0.002
    u_req = np.where((k // 500) % 2 == 1, 4.5, 0.0)
    u = np.where(u_req > 0, 4.05, 0.0)
    count = np.cumsum(np.where(u_req > 0, rng.integers(2, 6, n), rng.integers(0, 2, n)))
    omega = np.concatenate(([0.0], np.diff(count) * (2 * np.pi / 720) / 0.002))
    theta = count * (2 * np.pi / 720)
    t_us = (k * 2000) % 2**32
    with path.open("w") as fh:
        fh.write("# ts: 0.002\n# source: benchmarks/read_size.py\n")
        fh.write("t,u,omega,u_req,omega_lab,theta,count,t_us,seq\n")
        step = 200_000
        for a in range(0, n, step):
            b = min(n, a + step)
            fh.write(
                "".join(
                    f"{t[i]:.6f},{u[i]:g},{omega[i]:.6g},{u_req[i]:g},{omega[i]:.6g},"
                    f"{theta[i]:.8g},{count[i]},{t_us[i]},{i}\n"
                    for i in range(a, b)
                )
            )


def write_table(path: Path, n: int) -> None:
    with path.open("w") as fh:
        fh.write("u_req,u_ss,omega_ss,i_ss\n")
        row = "4.5,4.05,7.8,37\n"
        for _ in range(n // 100_000):
            fh.write(row * 100_000)


def measure(kind: str, path: Path) -> dict[str, object]:
    out = subprocess.run(
        [sys.executable, "-c", CHILD, kind, str(path)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return json.loads(out)


def main() -> None:
    base = measure("none", Path("/dev/null"))
    print(f"a process that imports the reader: peak {base['peak_mb']:.0f} MB")
    with tempfile.TemporaryDirectory() as tmp:
        cases = [("log", n) for n in (100_000, 1_000_000, files.MAX_LOG_ROWS)]
        cases += [("table", 10_000_000)]
        for kind, n in cases:
            path = Path(tmp) / f"{kind}-{n}.csv"
            t0 = time.perf_counter()
            (write_log if kind == "log" else write_table)(path, n)
            made = time.perf_counter() - t0
            r = measure(kind, path)
            size = path.stat().st_size / 2**20
            rate = r["rows"] / r["seconds"] if r["rows"] else 0.0
            what = f"read {r['rows']} rows" if not r["refused"] else f"refused: {r['refused']}"
            print(
                f"{kind} of {n} rows ({size:.0f} MB, written in {made:.1f} s): {what} in "
                f"{r['seconds']:.2f} s, {rate:,.0f} rows/s, peak {r['peak_mb']:.0f} MB"
            )
            path.unlink()


if __name__ == "__main__":
    main()
