"""Host pipeline: sample lines parsed, checked, unwrapped, batched and turned into
angle and velocity (board timestamps) on one core. Prints samples per second."""

import time

import numpy as np

from minseg_tui.device import protocol as P
from minseg_tui.device.link import Link
from minseg_tui.device.samples import motion

N = 200_000


def lines(n: int) -> list[bytes]:
    rng = np.random.default_rng(0)
    count = np.cumsum(rng.integers(0, 5, n))
    out = []
    for k in range(n):
        out.append(
            P.format_line(
                P.SampleLine(k, (k * 2000 + 4294000000) % 2**32, int(count[k]), 4500)
            ).encode()
        )
    return out


def main() -> None:
    data = lines(N)
    link = Link("bench://unused")  # never opened: only its line handling is timed
    t0 = time.perf_counter()
    for raw in data:
        link._on_line(raw)
    t1 = time.perf_counter()
    batch = link.samples()
    t2 = time.perf_counter()
    mo = motion(batch)
    t3 = time.perf_counter()
    assert len(batch) == N and link.stats.dropped == 0 and link.stats.corrupt == 0
    assert np.all(np.diff(batch.t_us) == 2000) and np.isfinite(mo.omega).all()
    total = t3 - t0
    print(f"samples: {N}")
    print(f"parse + check + unwrap: {N / (t1 - t0):,.0f} samples/s")
    print(f"batch to numpy:         {N / (t2 - t1):,.0f} samples/s")
    print(f"angle + velocity:       {N / (t3 - t2):,.0f} samples/s")
    print(f"whole pipeline:         {N / total:,.0f} samples/s (one core)")


if __name__ == "__main__":
    main()
