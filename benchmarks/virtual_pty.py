"""The virtual MinSeg at 1 kHz (P,1000: below the real board's 2000 us floor, allowed on
the virtual board) through a pty for 60 s (--seconds). The board runs in its own process;
the link in this one. Prints dropped and corrupt samples (goal 0) and the delay from a
sample's board timestamp to its arrival in the app (median, 99th percentile, max)."""

import argparse
import multiprocessing as mp
import threading
import time

import numpy as np

from minseg_tui.device.link import Link
from minseg_tui.device.samples import SampleBatch


def serve(conn, seconds: float) -> None:
    from minseg_tui.device.ptyserver import PtyServer

    server = PtyServer()
    conn.send(server.path)

    def report() -> None:
        seen = 0
        while True:
            if server.opens != seen:
                seen = server.opens
                # host monotonic time of the board's micros() == 0 (same system clock)
                conn.send(server.clock.t0 + server.board._boot_at)
            time.sleep(0.001)

    threading.Thread(target=report, daemon=True).start()
    threading.Timer(seconds + 10, server.stop).start()
    server.serve_forever()


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seconds", type=float, default=60.0)
    args = ap.parse_args()
    parent, child = mp.Pipe()
    proc = mp.Process(target=serve, args=(child, args.seconds), daemon=True)
    proc.start()
    path = parent.recv()
    link = Link(path)
    link.open()
    boot = parent.recv()
    assert link.set_period(0.001) == 0.001
    link.set_voltage(3.0)
    link.samples()
    batches, pulled = [], []
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        time.sleep(0.1)  # the app redraws ten times a second
        batch = link.samples()
        batches.append(batch)
        pulled.append(np.full(len(batch), time.monotonic()))
    link.close()
    proc.terminate()
    b = SampleBatch.concat(batches)
    assert set(b.epoch) == {0}
    delay_ms = (b.t_host - (boot + b.t_us / 1e6)) * 1e3
    gaps = np.diff(b.seq) - 1
    print(f"duration: {args.seconds:g} s at 1 kHz through {path}")
    print(f"samples received: {len(b)} ({len(b) / args.seconds:.1f}/s)")
    print(f"dropped (seq gaps): {link.stats.dropped} (in this window: {int(gaps.sum())})")
    print(f"corrupt lines: {link.stats.corrupt}")
    print(f"board period: median {np.median(np.diff(b.t_us)):.0f} us")
    app_ms = (np.concatenate(pulled) - (boot + b.t_us / 1e6)) * 1e3
    print(
        "delay timestamp -> app's 10 Hz pull: "
        f"median {np.median(app_ms):.1f} ms, p99 {np.percentile(app_ms, 99):.1f} ms"
    )
    print(
        "delay timestamp -> reader thread: "
        f"median {np.median(delay_ms):.2f} ms, p99 {np.percentile(delay_ms, 99):.2f} ms, "
        f"max {delay_ms.max():.2f} ms"
    )


if __name__ == "__main__":
    main()
