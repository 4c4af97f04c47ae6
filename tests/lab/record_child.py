"""Child process for the kill -9 test: types entries, then streams a run at wall-clock pace.

Usage: python record_child.py SESSIONS_ROOT
Prints ``typed <key>`` after each entry returns, ``id <session id>`` once, and
``sent <seq> <t_us>`` after each sample is handed to the recorder. Never ends by itself.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import PlantParams, record

ENTRIES = [
    ("R", "5,3 Ω"),
    ("u_ss@2.5", "2.05 V"),
    ("i_ss@2.5", "0.047"),
    ("i_ss@2.5", "29 mA"),
    ("prep8.T", "a/b"),
    ("summary.unclear", "why the filter lags"),
]


def main() -> None:
    root = Path(sys.argv[1])
    s = Session.create(root, ["Kim", "Lee"], date="2026-11-22")
    print(f"id {s.id}", flush=True)
    for key, text in ENTRIES:
        s.enter(key, text)
        print(f"typed {key}", flush=True)
    s.go_to("task10")
    ts = 0.005
    n = 4000  # 20 s, more than the test waits
    u = np.where((np.arange(n) // 200) % 2 == 1, 4.5, 0.0)
    rec_data = record(PlantParams(), u, ts=ts, seed=7, jitter_us=500)
    rec = s.start_run("fast", ts=ts)
    start = time.monotonic()
    for k in range(n):
        delay = start + rec_data.t[k] - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        rec.append(
            int(rec_data.seq[k]),
            int(rec_data.t_us[k]),
            int(rec_data.count[k]),
            int(round(u[k] * 1000)),
        )
        print(f"sent {k} {int(rec_data.t_us[k])}", flush=True)
    time.sleep(60)


if __name__ == "__main__":
    main()
