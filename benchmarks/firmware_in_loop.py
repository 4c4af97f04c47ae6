"""Firmware in the loop: the built firmware of every profile in simavr with a motor and
encoder model on each of its connectors in turn (firmware/sim/sim_fil.c).

Builds the ELFs and the harness with `make -C firmware`, runs Task 4's voltages (2.5,
3.5, 4.5 V), DIR REV on either side and a Task 10 step sequence (STEP,0,4500,1000,2)
through each, and prints per profile and connector: whether the speed's sign follows u
(and flips with DIR REV), the largest error of |omega_ss| against the motor model's K u
in %, the counts per wheel revolution (720 expected), the error at the end of the step's
high halves and over the first 200 ms of a rise (against the model's mean there), and
whether the open connector's bridge got the same mean voltage. Needs gcc-avr and
libsimavr; exit 1 when a run fails, 2 when they are missing.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from minseg_tui.device.flashing import PROFILES  # the profiles firmware/Makefile builds

FIRMWARE = Path(__file__).resolve().parents[1] / "firmware"
FIGURES = re.compile(
    r"^figures (?P<profile>\S+) (?P<conn>M\d) sign=(?P<sign>\S+) omega_err_pct=(?P<err>\S+) "
    r"counts_per_rev=(?P<cpr>\S+) dir_rev=(?P<dir>\S+) step_err_pct=(?P<step>\S+) "
    r"rise_err_pct=(?P<rise>\S+) alike=(?P<alike>\S+)$",
    re.M,
)


def make(*args: str) -> None:
    """Run make in firmware/ quietly; exit 2 with its output if it fails."""
    done = subprocess.run(
        ["make", "--no-print-directory", "-C", str(FIRMWARE), *args],
        capture_output=True,
        text=True,
        check=False,
    )
    if done.returncode != 0:
        sys.stderr.write(done.stdout + done.stderr)
        sys.stderr.write("firmware_in_loop: the build failed (needs gcc-avr and libsimavr)\n")
        sys.exit(2)


def main() -> int:
    make("all-profiles")
    make("build/host/sim_fil")
    harness = FIRMWARE / "build" / "host" / "sim_fil"
    print(
        f"{'profile':<11} {'conn':<4} {'sign':<5} {'omega_ss err %':>14} {'counts/rev':>10} "
        f"{'DIR REV':<7} {'step end %':>10} {'rise %':>7} {'alike':<5}"
    )
    failed = 0
    for profile in PROFILES:
        conns = subprocess.run(
            [str(harness), "--connectors", profile], capture_output=True, text=True, check=True
        ).stdout.split()
        elf = FIRMWARE / "build" / profile / "minseg-fw.elf"
        for conn in conns:
            run = subprocess.run(
                [str(harness), str(elf), profile, conn], capture_output=True, text=True, check=False
            )
            m = FIGURES.search(run.stdout)
            if run.returncode != 0 or m is None:
                failed += 1
                bad = [ln for ln in run.stdout.splitlines() if ln.startswith("FAIL")]
                print(f"{profile:<11} M{conn:<3} FAILED: {'; '.join(bad) or run.stderr.strip()}")
                if m is None:
                    continue
            print(
                f"{m['profile']:<11} {m['conn']:<4} {m['sign']:<5} {float(m['err']):>14.2f} "
                f"{float(m['cpr']):>10.2f} {m['dir']:<7} {float(m['step']):>10.2f} "
                f"{float(m['rise']):>7.2f} {m['alike']:<5}"
            )
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
