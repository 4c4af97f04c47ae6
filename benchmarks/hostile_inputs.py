"""A battery of hostile inputs, per area: what was tried, how much came out clean, and how
much gave a traceback, a hang, a wrong answer given with confidence, or lost data.

- cli: the `minseg-tui` command as a process, on hostile arguments, files, FIFOs, devices,
  a closed or full stdout and a memory limit. Clean: the expected exit code (2 for bad
  input, 1 for a memory limit, 0 for an input that is fine) with at most one line on stderr
  and no traceback. Wrong-but-confident: exit 0 on an input that must be refused, or a
  claim no data can support (a step said to act further than a sample from its time).
  Data lost: a file that was there before is changed or gone. Hang: no exit in 60 s.
- link: the real Link on a pseudo-terminal, fed by a board that sends the true stream of
  a Task 10 run (300 samples, 25 ms) with altered lines among them, all with valid
  checksums unless the alteration is the checksum. Each altered stream is one try. Clean:
  every kept sample is a true one, no restart, every true line not altered is kept, and
  the counters (lost, bad) account for every altered line. Wrong-but-confident: a false
  or old sample kept, or a restart that was none. Data lost: a true line not altered and
  not kept. Hang: the stream's last sample never handed over.

Prints one table. Seeded; takes about two minutes on a loaded 2-core machine.
"""

from __future__ import annotations

import math
import os
import resource
import select
import subprocess
import sys
import tempfile
import threading
import time
import tty
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from minseg_tui.device import protocol as P
from minseg_tui.device.link import Link
from minseg_tui.device.samples import SampleBatch
from minseg_tui.lab.saving.files import write_run_log
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import make_log

OUTCOMES = ("clean", "traceback", "hang", "wrong-but-confident", "data lost")
TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,5.8,34\n4.5,4.05,7.8,37\n"


# -- the CLI --------------------------------------------------------------------------------


def _cli() -> list[str]:
    """The command, from the package this script imports (PYTHONPATH picks another tree)."""
    return [sys.executable, "-m", "minseg_tui"]


@dataclass
class Case:
    """One hostile command line: ``argv`` (``{d}`` is the scratch folder), the exit code
    expected, the files that must survive, how stdout is given, a memory limit (MiB), and
    a check of what the command said (True when it is supportable)."""

    name: str
    argv: list[str]
    code: int
    keep: tuple[str, ...] = ()
    stdout: str = "pipe"  # pipe, closed, full
    limit_mib: int = 0
    sane: Callable[[str], bool] | None = None


def _late_steps_sane(out: str) -> bool:
    """No step said to act further than a 25 ms sample from its sample time."""
    for word in out.split("acts about ")[1:]:
        ms = float(word.split(" ms", 1)[0])
        if abs(ms) > 25.1:
            return False
    return True


ORIGINALS = {
    "notes.txt": b"our notes\n",
    "session.json": b'{"kind": "minseg-session"}\n',
}
"""Files a case must leave as they are (``log.csv`` is added when it is written)."""


def _files(d: Path) -> None:
    (d / "table.csv").write_text(TABLE)
    for name, data in ORIGINALS.items():
        (d / name).write_bytes(data)
    (d / "folder").mkdir()
    log = make_log("none", param=0, seed=3)
    write_run_log(d / "log.csv", RunLog(t=log.t, u=log.u, omega=log.omega))
    ORIGINALS["log.csv"] = (d / "log.csv").read_bytes()
    rng = np.random.default_rng(1)
    noisy = np.round(log.u + rng.normal(0.0, 0.01, log.u.size), 2)
    write_run_log(d / "noisy_u.csv", RunLog(t=log.t, u=noisy, omega=log.omega))
    (d / "empty.csv").write_text("")
    (d / "garbage.csv").write_bytes(bytes(range(256)) * 40)
    (d / "header_only.csv").write_text("t,u,omega\n")
    (d / "nan.csv").write_text("t,u,omega\n0,0,nan\n0.025,2.5,1\n0.05,2.5,2\n")
    (d / "back.csv").write_text("t,u,omega\n0,0,0\n0.025,2.5,1\n0.01,2.5,2\n0.05,2.5,3\n")
    (d / "table_nan.csv").write_text("u_req,u_ss,omega_ss,i_ss\n2.5,nan,3.8,30\n")
    (d / "table_neg.csv").write_text("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,-3.8,30\n")
    (d / "long.csv").write_text("t,u,omega\n" + "1" * 200_000 + "\n")
    os.mkfifo(d / "fifo_out.csv")
    t = np.arange(2_000_000) * 0.001
    u = np.where((t // 1.5) % 2 == 0, 2.5, 0.0)
    with (d / "big.csv").open("w") as fh:
        fh.write("t,u,omega\n")
        np.savetxt(fh, np.column_stack([t, u, 2 * u]), fmt="%.3f", delimiter=",")


def cli_cases() -> list[Case]:
    """The hostile command lines."""
    L, T = "{d}/log.csv", "{d}/table.csv"
    cases = [
        Case("no such log", ["analyze", "{d}/missing.csv"], 2),
        Case("empty log", ["analyze", "{d}/empty.csv"], 2),
        Case("binary log", ["analyze", "{d}/garbage.csv"], 2),
        Case("header only", ["analyze", "{d}/header_only.csv"], 2),
        Case("nan speed", ["analyze", "{d}/nan.csv"], 2),
        Case("time going back", ["analyze", "{d}/back.csv"], 2),
        Case("a 200 kB line", ["analyze", "{d}/long.csv"], 2),
        Case("a folder as log", ["analyze", "{d}/folder"], 2),
        Case("/dev/zero as log", ["analyze", "/dev/zero"], 2),
        Case("predictions ''", ["analyze", L, "--predictions", ""], 2),
        Case("predictions onto the log", ["analyze", L, "--predictions", L], 2, keep=("log.csv",)),
        Case("predictions into a folder", ["analyze", L, "--predictions", "{d}/folder"], 2),
        Case("predictions, no folder", ["analyze", L, "--predictions", "{d}/no/p.csv"], 2),
        Case("predictions into a FIFO", ["analyze", L, "--predictions", "{d}/fifo_out.csv"], 2),
        Case("predictions into /dev/null", ["analyze", L, "--predictions", "/dev/null"], 2),
        Case("noisy u", ["analyze", "{d}/noisy_u.csv"], 0, sane=_late_steps_sane),
        Case("analyze, stdout closed", ["analyze", L], 2, stdout="closed"),
        Case("analyze, stdout full", ["analyze", L], 2, stdout="full"),
        Case("analyze 2M rows in 300 MiB", ["analyze", "{d}/big.csv"], 1, limit_mib=300),
        Case("identify --step ''", ["identify", T, "--R", "5.3", "--step", ""], 2),
        Case("identify --R 0", ["identify", T, "--R", "0"], 2),
        Case("identify --R nan", ["identify", T, "--R", "nan"], 2),
        Case("identify --R 1e999", ["identify", T, "--R", "1e999"], 2),
        Case("identify --R '5 ohm'", ["identify", T, "--R", "5 ohm"], 2),
        Case("identify, table with nan", ["identify", "{d}/table_nan.csv", "--R", "5.3"], 2),
        Case("identify, a log as table", ["identify", L, "--R", "5.3"], 2),
        Case(
            "identify, a binary step", ["identify", T, "--R", "5.3", "--step", "{d}/garbage.csv"], 2
        ),
        Case("identify, stdout closed", ["identify", T, "--R", "5.3"], 2, stdout="closed"),
        Case(
            "identify 2M rows in 500 MiB",
            ["identify", T, "--R", "5.3", "--step", "{d}/big.csv"],
            1,
            limit_mib=500,
        ),
        Case("ports, stdout closed", ["ports"], 2, stdout="closed"),
        Case("ports --json, stdout closed", ["ports", "--json"], 2, stdout="closed"),
        Case("--help, stdout closed", ["--help"], 2, stdout="closed"),
        Case("--help, stdout full", ["--help"], 2, stdout="full"),
        Case("sim --link notes.txt", ["sim", "--link", "{d}/notes.txt"], 2, keep=("notes.txt",)),
        Case(
            "sim --link session.json",
            ["sim", "--link", "{d}/session.json"],
            2,
            keep=("session.json",),
        ),
        Case("sim --link a folder", ["sim", "--link", "{d}/folder"], 2),
        Case("sim --link ''", ["sim", "--link", ""], 2),
        Case("sim --seed -1", ["sim", "--seed", "-1"], 2),
        Case("sim --garbage 5", ["sim", "--garbage", "5"], 2),
        Case("sim --R 1e999", ["sim", "--R", "1e999"], 2),
        Case("report of nothing", ["report", "{d}/missing"], 2),
        Case("report of a file", ["report", "{d}/notes.txt"], 2, keep=("notes.txt",)),
        Case("unknown command", ["fly"], 2),
        Case("unknown option", ["analyze", L, "--fast"], 2),
    ]
    return cases


def run_cli_case(case: Case, d: Path) -> str:
    """The outcome of one case (one of OUTCOMES)."""
    before = {k: ORIGINALS[k] for k in case.keep}
    for k, data in before.items():  # as made, whatever an earlier case did to it
        if os.path.lexists(d / k):
            os.unlink(d / k)
        (d / k).write_bytes(data)
    argv = [*_cli(), *(a.replace("{d}", str(d)) for a in case.argv)]
    limit = case.limit_mib * 2**20

    def prepare() -> None:
        if case.stdout == "closed":
            os.close(1)
        if limit:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    full = open("/dev/full", "w") if case.stdout == "full" else None
    try:
        proc = subprocess.run(
            argv,
            stdout=full if full is not None else subprocess.PIPE,
            stderr=subprocess.PIPE,
            stdin=subprocess.DEVNULL,
            text=True,
            timeout=60,
            preexec_fn=prepare,
        )
    except subprocess.TimeoutExpired:
        proc = None
    finally:
        if full is not None:
            full.close()
    for k, data in before.items():
        if os.path.islink(d / k) or not (d / k).exists() or (d / k).read_bytes() != data:
            return "data lost"
    if proc is None:
        return "hang"
    if "Traceback" in proc.stderr:
        return "traceback"
    if case.code != 0 and proc.returncode == 0:
        return "wrong-but-confident"
    if case.sane is not None and not case.sane(proc.stdout or ""):
        return "wrong-but-confident"
    if proc.returncode != case.code or (case.code != 0 and proc.stderr.count("\n") != 1):
        return f"other (exit {proc.returncode}: {proc.stderr.strip()[:80]})"
    return "clean"


# -- the link -------------------------------------------------------------------------------

PERIOD = 25_000  # us
SEQ0, T0 = 51_000, 1_300_000_000


def true_stream(n: int, rng: np.random.Generator) -> list[P.SampleLine]:
    """A Task 10 run as the board sends it (K = 2 rad/s/V, T = 45 ms, 0 / 2.5 V every 1.5 s)."""
    out, omega, theta = [], 0.0, 0.0
    for k in range(n):
        u = 2.5 if (k * PERIOD // 1_500_000) % 2 == 0 else 0.0
        new = 2.0 * u + (omega - 2.0 * u) * math.exp(-PERIOD / 1e6 / 0.045)
        theta += (omega + new) / 2 * PERIOD / 1e6
        omega = new
        t_us = T0 + k * PERIOD + int(rng.integers(0, 40))
        out.append(
            P.SampleLine(SEQ0 + k, t_us, round(theta * 720 / (2 * math.pi)), round(u * 1000))
        )
    return out


class Feeder:
    """A board on a pty: answers ID and commands, and sends the bytes it is given."""

    def __init__(self) -> None:
        master, slave = os.openpty()
        tty.setraw(slave)
        self.path = os.ttyname(slave)
        os.close(slave)
        self.master = master
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def send(self, data: bytes) -> None:
        with self._lock:
            view = memoryview(data)
            while view:
                view = view[os.write(self.master, view) :]

    def _serve(self) -> None:
        buf = b""
        while not self._stop.is_set():
            if not select.select([self.master], [], [], 0.02)[0]:
                continue
            try:
                buf += os.read(self.master, 4096)
            except OSError:
                time.sleep(0.01)
                continue
            *lines, buf = buf.split(b"\n")
            for raw in lines:
                try:
                    cmd = P.parse_command(raw)
                except P.ProtocolError:
                    continue
                if isinstance(cmd, P.Identify):
                    reply: P.Message = P.Ident(
                        "feeder", P.PROTOCOL_VERSION, "Feeder", 720, PERIOD, 12000, "BRAKE"
                    )
                else:
                    name = raw.strip().lstrip(b"$").split(b"*")[0].split(b",")[0].decode()
                    reply = P.Ok(name)
                self.send(P.encode(reply))

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2.0)
        os.close(self.master)


def _swap_digits(text: str, rng: np.random.Generator) -> str:
    if len(text) < 2:
        return text
    i = int(rng.integers(len(text) - 1))
    return text[:i] + text[i + 1] + text[i] + text[i + 2 :]


def altered(
    kind: str, true: list[P.SampleLine], rng: np.random.Generator
) -> tuple[list[bytes], int, set[int]]:
    """The wire (bytes per line) and how many lines were altered or added, for one kind."""
    wire: list[bytes] = [P.encode(s) for s in true]
    at = sorted(rng.choice(np.arange(30, len(true) - 5), 6, replace=False).tolist())
    n = 0
    if kind == "replayed block":
        for k in reversed(at):
            size = int(rng.integers(3, 31))
            end = max(k - int(rng.integers(0, 100)), size)
            wire[k + 1 : k + 1] = [P.encode(s) for s in true[end - size : end]]
            n += size
    elif kind == "replayed line":
        for k in reversed(at):
            wire[k + 1 : k + 1] = [P.encode(true[k - int(rng.integers(1, 20))])]
            n += 1
    elif kind == "repeated line":
        for k in reversed(at):
            wire[k + 1 : k + 1] = [P.encode(true[k])]
            n += 1
    else:
        for k in at:
            s = true[k]
            if kind == "seq +5":
                line = P.encode(P.SampleLine(s.seq + 5, s.t_us, s.count, s.u_mV))
            elif kind == "seq -40":
                line = P.encode(P.SampleLine(s.seq - 40, s.t_us, s.count, s.u_mV))
            elif kind == "seq far ahead":
                line = P.encode(P.SampleLine(s.seq + 245_867_300, s.t_us, s.count, s.u_mV))
            elif kind == "time +40 ms":
                line = P.encode(P.SampleLine(s.seq, s.t_us + 40_000, s.count, s.u_mV))
            elif kind == "time back 0.9 s":
                line = P.encode(P.SampleLine(s.seq, s.t_us - 900_000, s.count, s.u_mV))
            elif kind == "count +500":
                line = P.encode(P.SampleLine(s.seq, s.t_us, s.count + 500, s.u_mV))
            elif kind == "digits swapped":
                field = int(rng.integers(3))
                v = [s.seq, s.t_us, s.count][field]
                w = int(_swap_digits(str(v), rng))
                vals = [s.seq, s.t_us, s.count]
                vals[field] = w
                line = P.encode(P.SampleLine(vals[0], vals[1], vals[2], s.u_mV))
            elif kind == "bad checksum":
                raw = P.encode(s)
                line = raw[:-3] + (b"0" if raw[-3:-2] != b"0" else b"1") + raw[-2:]
            elif kind == "truncated":
                raw = P.encode(s)
                line = raw[: len(raw) // 2] + b"\n"
            else:
                raise ValueError(kind)
            wire[k] = line
            n += 1
    return (
        wire,
        n,
        set(at) if kind not in ("replayed block", "replayed line", "repeated line") else set(),
    )


LINK_KINDS = (
    "replayed block",
    "replayed line",
    "repeated line",
    "seq +5",
    "seq -40",
    "seq far ahead",
    "time +40 ms",
    "time back 0.9 s",
    "count +500",
    "digits swapped",
    "bad checksum",
    "truncated",
)


def run_link_case(kind: str, seed: int) -> tuple[str, int, str]:
    """The outcome of one altered stream, how many lines were altered, and what was wrong."""
    rng = np.random.default_rng(seed)
    true = true_stream(300, rng)
    wire, n_altered, replaced = altered(kind, true, rng)
    wire.append(P.encode(P.SampleLine(SEQ0 + 300, true[-1].t_us + PERIOD, true[-1].count, 0)))
    feeder = Feeder()
    link = Link(feeder.path, boot_wait_s=0.05, retry_s=0.02, reconnect=False)
    try:
        link.open()
        for i in range(0, len(wire), 50):
            feeder.send(b"".join(wire[i : i + 50]))
        got: list[SampleBatch] = []
        end = time.monotonic() + 20
        seen: tuple[int, ...] = ()
        still = 0
        while time.monotonic() < end:  # until every line is read and nothing more comes
            got.append(link.samples())
            st = link.stats
            now = (st.samples, st.corrupt, st.dropped)  # not lines: the PING replies go on
            still = still + 1 if now == seen else 0
            seen = now
            if st.lines >= len(wire) and still >= 20:
                break
            time.sleep(0.02)
        else:
            return "hang", n_altered, f"{link.stats.lines} of {len(wire)} lines read in 20 s"
        got.append(link.samples())
        batch = SampleBatch.concat(got)
        stats = link.stats
    finally:
        link.close()
        feeder.close()
    truth = {(s.seq, s.t_us, s.count) for s in true}
    truth.add((SEQ0 + 300, true[-1].t_us + PERIOD, true[-1].count))
    kept = list(
        zip(
            (batch.seq % 2**32).tolist(),
            (batch.t_us % 2**32).tolist(),
            batch.count.tolist(),
            strict=True,
        )
    )
    false = [k for k in kept if k not in truth]
    by_seq = {s.seq: s for s in true}
    if false:
        f = false[0]
        s = by_seq.get(f[0])
        was = f"(true: t_us {s.t_us}, count {s.count})" if s else "(no such seq)"
        return "wrong-but-confident", n_altered, f"kept seq {f[0]} t_us {f[1]} count {f[2]} {was}"
    if set(batch.epoch.tolist()) != {0} or len(set(kept)) != len(kept):
        return "wrong-but-confident", n_altered, "a restart that was none, or a sample twice"
    kept_seqs = {k[0] for k in kept}
    must = {s.seq for k, s in enumerate(true) if k not in replaced}
    if must - kept_seqs:
        return "data lost", n_altered, f"{len(must - kept_seqs)} true lines not kept"
    said = stats.corrupt + stats.dropped
    if said < n_altered or stats.dropped != len(replaced & set(range(300))) - sum(
        1 for k in replaced if true[k].seq in kept_seqs
    ):
        return "wrong-but-confident", n_altered, f"counters do not add up: {stats}"
    return "clean", n_altered, ""


# -- the table ------------------------------------------------------------------------------


def main() -> None:
    rows: list[tuple[str, Counter[str], str]] = []
    tracebacks: list[str] = []

    def hook(args: threading.ExceptHookArgs) -> None:
        tracebacks.append(f"{args.exc_type.__name__} in {args.thread.name if args.thread else '?'}")

    threading.excepthook = hook
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        _files(d)
        cli = Counter[str]()
        notes = []
        for case in cli_cases():
            outcome = run_cli_case(case, d)
            cli[outcome.split(" (")[0]] += 1
            if outcome != "clean":
                notes.append(f"  cli: {case.name}: {outcome}")
        rows.append(("cli", cli, f"{sum(cli.values())} command lines"))
    link = Counter[str]()
    lines = 0
    for kind in LINK_KINDS:
        per = Counter[str]()
        for seed in range(3):
            outcome, n, detail = run_link_case(kind, seed)
            lines += n
            per[outcome] += 1
            link[outcome] += 1
            if detail:
                notes.append(f"  link: {kind} (seed {seed}): {outcome}: {detail}")
    link["traceback"] += len(tracebacks)
    rows.append(("link", link, f"{sum(link.values())} altered streams, {lines} altered lines"))
    head = ["area", "tried", *OUTCOMES]
    print("  ".join(f"{h:>20}" if i > 1 else f"{h:<6}" for i, h in enumerate(head)))
    for area, counts, _what in rows:
        tried = sum(counts.values())
        cells = [area, str(tried), *(str(counts[o]) for o in OUTCOMES)]
        print("  ".join(f"{c:>20}" if i > 1 else f"{c:<6}" for i, c in enumerate(cells)))
    for area, counts, what in rows:
        other = sum(v for k, v in counts.items() if k not in OUTCOMES)
        print(f"{area}: {what}" + (f"; {other} other outcomes" if other else ""))
    for note in notes:
        print(note)
    for tb in tracebacks:
        print(f"  link: {tb}")


if __name__ == "__main__":
    main()
