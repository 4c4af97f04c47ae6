"""The board check on the virtual MinSeg in real time (the board's clock is the host's, as
at the bench): every wiring fault and pair of faults, --repeat times each with another seed.
Prints what the check named for each, whether that is right, and the time per check
and with the port's open and handshake (what `minseg-tui board-check` adds); goal: under 3 s)."""

import argparse
import statistics
import time

import minseg_tui.device  # noqa: F401  (registers minseg://)
from minseg_tui.device.boardcheck import check_board
from minseg_tui.device.factory import open_device

# faults -> (ok, direction, wheel turned) the check must report
CASES: dict[str, tuple[bool, str, bool]] = {
    "": (True, "forward", True),
    "encoder-reversed": (True, "reversed", True),  # found, fixed, checked again
    "encoder-off": (False, "none", True),
    "motor-off": (False, "none", False),
    "encoder-off,motor-off": (False, "none", False),
    "encoder-reversed,motor-off": (False, "none", False),
}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    times: list[float] = []
    totals: list[float] = []
    wrong = 0
    print(f"{'faults':<28} {'seed':>4} {'named':<22} {'right':<5} {'time s':>7}")
    for faults, want in CASES.items():
        for seed in range(args.repeat):
            query = f"&fault={faults}" if faults else ""
            t_open = time.monotonic()
            link = open_device(f"minseg://?clock=real&seed={seed}{query}")
            try:
                t0 = time.monotonic()
                r = check_board(link)
                dt = time.monotonic() - t0
            finally:
                link.close()
            totals.append(time.monotonic() - t_open)
            got = (r.ok, r.direction, bool(r.wheel_turned))
            right = got == want
            wrong += not right
            times.append(dt)
            named = f"{'ok' if r.ok else 'fail'} {r.direction}" + (" fixed" if r.fixed else "")
            print(f"{faults or '(none)':<28} {seed:>4} {named:<22} {right!s:<5} {dt:7.2f}")
    print(
        f"\n{len(times)} checks, {wrong} named wrong; time per check: median "
        f"{statistics.median(times):.2f} s, max {max(times):.2f} s; with open and handshake: "
        f"median {statistics.median(totals):.2f} s, max {max(totals):.2f} s (goal < 3 s)"
    )


if __name__ == "__main__":
    main()
