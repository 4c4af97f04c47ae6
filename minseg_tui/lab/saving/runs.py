"""Recorded runs: the stream written to disk while it arrives, then kept as a run log.

While a run records, raw samples (``seq, t_us, count, u_mV`` as the board sends them) are
appended to ``runs/<name>.partial`` in chunks, each chunk written and fsynced at most
:data:`FLUSH_INTERVAL` s after its first sample arrived: a crash or kill -9 loses at most
that much of the stream. When the run ends (or, after a crash, when the session is opened
again) the samples become ``runs/<name>.csv``, a run log in the shared format
(:mod:`minseg_tui.lab.saving.files`), written atomically, with the columns

    t (s, board time from the first sample), u (V: the voltage asked of the board, u_req;
    see below), omega (rad/s, mean speed over each sample interval from the count and the
    board's timestamps), u_req (V), omega_lab (rad/s, the manual's Euler derivative at the
    nominal period then the 20-tap average), theta (rad), count, t_us (board micros), seq.

Every column is what the board sent (u requested, counts, board time) or follows from it
alone, so a recording is written once and never again. The applied voltage u_A depends on
the table the group types (u_ss), so it is worked out when the run is read
(:func:`applied_log`, mapping u_req through the table's u_ss by
:func:`minseg_tui.model.identify.u_ss_at`: the same mapping Task 11 divides by). Runs
recorded before this (their u column held u_A as mapped when the table last changed) read
the same: their u_req column is mapped the same way. The header says ``# cpr: 720`` and
``# omega_over: interval`` so the model check need not detect them.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import json
import os
import stat
import threading
import time
from array import array
from collections import OrderedDict
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from minseg_tui.device.samples import SampleBatch
from minseg_tui.errors import InputError
from minseg_tui.lab.content.u_ss_says import u_ss_words
from minseg_tui.lab.saving.csvread import metadata_key
from minseg_tui.lab.saving.files import check_step, read_run_log, write_run_log
from minseg_tui.lab.saving.schema import PARTIAL_HEADER
from minseg_tui.lab.saving.store import RUNS_DIR, atomic_write_bytes, fsync_dir, read_regular
from minseg_tui.model.identify import u_ss_at
from minseg_tui.model.runlog import RunLog
from minseg_tui.signals import angle, lab_velocity, timestamp_velocity
from minseg_tui.units import COUNTS_PER_REV

FLUSH_INTERVAL: float = 0.5
"""Longest time (s) a received sample waits in memory before it is written and fsynced."""

PARTIAL_SUFFIX = ".partial"

MAX_PARTIAL_BYTES = 128 * 2**20
"""Largest partial file read back (2 million samples of at most 48 bytes each, and more)."""

PARTIAL_RANGES: tuple[tuple[int, int], ...] = (
    (0, 2**32 - 1),
    (0, 2**32 - 1),
    (-(2**31), 2**31 - 1),
    (-(2**31), 2**31 - 1),
)
"""What the board sends for seq, t_us (uint32), count and u_mV (int32): a partial file's
line outside these is damage, not a sample."""

OMEGA_OVER = "interval"
"""How a recorded run's ``omega`` is computed, for its ``# omega_over:`` header: over each
sample's real interval on the board's clock (:func:`minseg_tui.signals.timestamp_velocity`)."""
_HEADER = "seq,t_us,count,u_mV"

U_AS_SENT = (
    "u = u_req, the voltage asked of the board; the lab maps it to the applied voltage u_A "
    "through the table's u_ss when it reads the run"
)
"""The ``# u:`` header of a recording as written: its u column is what the board was asked."""


RESPONSE_KINDS: tuple[str, ...] = ("steps", "fast", "imported")
"""The kinds of run Tasks 11-15 can read the steps of."""

ENDED_BY: dict[str, str] = {
    "quit": "quit",
    "stopped": "stopped",
    "cable": "board lost (cable pulled?)",
    "watchdog": "board's watchdog",
    "restart": "board restarted",
    "link": "link error",
    "not started": "board did not start it",
    "crash": "crash",
}
"""What can interrupt a run (:attr:`RunInfo.ended_by`) -> its words in lists and the report."""


@dataclass(frozen=True)
class RunInfo:
    """A recorded run as the session file keeps it.

    name: file stem (``runs/<name>.csv``); kind: ``steps`` (Task 10), ``fast`` or ``free``;
    ts: nominal sample period (s); samples: rows in the log; dropped: samples lost on the
    link (gaps in seq); started: ISO time; interrupted: the run ended before its plan did (stopped, board lost,
    program closed) or was recovered after a crash; ended_by: what interrupted it, a key of
    :data:`ENDED_BY` ("" when not known: a run kept before it was recorded);
    plan: the step plan as a dict (empty for a free run); sha256: the SHA-256 of the run's
    file as it was written, hex ("" for a run recorded by an older program, which kept
    none): :func:`changed_file` compares the file with it.
    """

    name: str
    file: str
    kind: str
    ts: float
    samples: int
    dropped: int
    started: str
    interrupted: bool = False
    plan: Mapping[str, float] = field(default_factory=dict)
    ended_by: str = ""
    sha256: str = ""

    @property
    def complete(self) -> bool:
        """The run went to the end of its plan."""
        return not self.interrupted

    @property
    def interruption(self) -> str:
        """What interrupted the run, in words ("" for a complete run)."""
        if not self.interrupted:
            return ""
        return ENDED_BY.get(self.ended_by, "cause not recorded")

    def to_json(self) -> dict[str, object]:
        """JSON-ready dict."""
        return {
            "name": self.name,
            "file": self.file,
            "kind": self.kind,
            "ts": self.ts,
            "samples": self.samples,
            "dropped": self.dropped,
            "started": self.started,
            "interrupted": self.interrupted,
            "plan": dict(self.plan),
            **({"ended_by": self.ended_by} if self.ended_by else {}),
            **({"sha256": self.sha256} if self.sha256 else {}),
        }

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> RunInfo:
        """Inverse of :meth:`to_json` (``d`` checked by :data:`minseg_tui.lab.saving.schema.RUN`)."""
        return cls(
            name=str(d["name"]),
            file=str(d["file"]),
            kind=str(d.get("kind", "free")),
            ts=float(d.get("ts", 0.025)),
            samples=int(d.get("samples", 0)),
            dropped=int(d.get("dropped", 0)),
            started=str(d.get("started", "")),
            interrupted=bool(d.get("interrupted", False)),
            plan={str(k): float(v) for k, v in dict(d.get("plan") or {}).items()},
            ended_by=str(d.get("ended_by", "")),
            sha256=str(d.get("sha256", "")),
        )


# -- the applied voltage -----------------------------------------------------------------------


def applied_voltage(
    u_req: np.ndarray, table: Sequence[tuple[float, float]]
) -> tuple[np.ndarray, str]:
    """u_A (V) for each requested u_req (V), mapped through the table's (u_req, u_ss) pairs
    by :func:`minseg_tui.model.identify.u_ss_at` (the mapping Task 11 divides by), and a
    sentence for the log's metadata saying what each level became and how.

    Zero stays zero (driver off); without pairs u_A = u_req.
    """
    u = np.asarray(u_req, dtype=float)
    if not table:
        return (
            u.copy(),
            "u = u_req: the table has no u_ss yet, so the driver's voltage loss is not known",
        )
    out = np.zeros_like(u)
    said = []
    for level in np.unique(u):
        if level == 0:
            continue
        v, how = u_ss_at(table, float(level))
        out[u == level] = v
        said.append(f"{level:g} V -> {v:.4g} V ({u_ss_words(how, [float(level)])})")
    mapped = "u = u_A mapped from u_req through the table's u_ss" + (
        ": " + "; ".join(said) if said else ""
    )
    return out, mapped + "; 0 V stays 0 V"


# -- partial files -----------------------------------------------------------------------------


class Recorder:
    """Writes one run's samples to ``runs/<name>.partial`` as they arrive.

    Call :meth:`append` (or :meth:`extend`) for each sample, then ``Session.finish_run``.
    ``clock`` is the monotonic clock deciding when to flush (injectable for tests).

    Every sample also stays in memory (32 bytes each) until the run is kept, so a write
    that fails (a full disk, a drive pulled out) loses nothing: :attr:`problem` says why,
    the next flush tries again, and the run is built from memory when it ends. Only
    opening the partial file at the start may raise (OSError).
    """

    def __init__(
        self,
        path: Path,
        header: Mapping[str, object],
        flush_interval: float = FLUSH_INTERVAL,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.path = Path(path)
        self.header = dict(header)
        self.flush_interval = flush_interval
        self._clock = clock
        self._samples = array("q")  # seq, t_us, count, u_mV of every sample
        self._written = 0  # samples on disk
        self._torn = False  # a failed write may have left half a line
        self._first_unflushed: float | None = None
        self.problem: str | None = None
        """Why the last write failed (None while everything is on disk)."""
        self.closed = False
        fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_APPEND, 0o644)
        self._fd: int | None = fd
        try:
            self._write(f"# {json.dumps(self.header, sort_keys=True)}\n{_HEADER}\n")
        except OSError:
            os.close(fd)
            with contextlib.suppress(OSError):
                os.unlink(self.path)
            raise
        fsync_dir(self.path.parent)

    @property
    def name(self) -> str:
        """The run's name (file stem)."""
        return self.path.name[: -len(PARTIAL_SUFFIX)]

    @property
    def samples(self) -> int:
        """Samples received so far."""
        return len(self._samples) // 4

    @property
    def on_disk(self) -> bool:
        """True when every sample received is written and fsynced."""
        return self._written == self.samples and self.problem is None

    def _write(self, text: str) -> None:
        if self._fd is None:
            self._fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
        data = memoryview(text.encode("ascii"))
        while data:
            n = os.write(self._fd, data)
            data = data[n:]
        os.fsync(self._fd)

    def append(self, seq: int, t_us: int, count: int, u_mV: int) -> None:
        """One sample as the board sent it: sequence number, board time (us), encoder count,
        requested voltage (mV) in force from this sample on."""
        if self.closed:
            raise ValueError("the run is finished")
        self._samples.extend((int(seq), int(t_us), int(count), int(u_mV)))
        now = self._clock()
        if self._first_unflushed is None:
            self._first_unflushed = now
        if now - self._first_unflushed >= self.flush_interval:
            self.flush()

    def add(self, batch: SampleBatch) -> None:
        """Every sample of ``batch`` as the link hands it over (u_req in V is the board's mV
        over 1000, so it is kept in mV exactly, the whole batch at once)."""
        if self.closed:
            raise ValueError("the run is finished")
        if not len(batch):
            return
        rows = np.empty((len(batch), 4), dtype=np.int64)
        rows[:, 0], rows[:, 1], rows[:, 2] = batch.seq, batch.t_us, batch.count
        rows[:, 3] = np.rint(batch.u_req * 1000.0)
        self._samples.frombytes(rows.tobytes())
        now = self._clock()
        if self._first_unflushed is None:
            self._first_unflushed = now
        if now - self._first_unflushed >= self.flush_interval:
            self.flush()

    def extend(self, samples: Iterable[object]) -> None:
        """Append samples with attributes ``seq, t_us, count, u_mV`` (e.g. protocol SampleLine)."""
        for s in samples:
            self.append(s.seq, s.t_us, s.count, s.u_mV)  # type: ignore[attr-defined]

    def tick(self) -> None:
        """Flush if the oldest unwritten sample is older than the flush interval (call this
        from a timer when samples may stop arriving)."""
        if (
            self._first_unflushed is not None
            and self._clock() - self._first_unflushed >= self.flush_interval
        ):
            self.flush()

    def flush(self) -> bool:
        """Write and fsync every sample received so far; False (and :attr:`problem` set, the
        samples kept in memory, a retry after the flush interval) when the write fails."""
        n = self.samples
        if self._written == n and self.problem is None:
            self._first_unflushed = None
            return True
        rows = self._samples[4 * self._written : 4 * n]
        text = "".join(
            f"{rows[k]},{rows[k + 1]},{rows[k + 2]},{rows[k + 3]}\n" for k in range(0, len(rows), 4)
        )
        try:
            self._write(("\n" if self._torn else "") + text)
        except OSError as exc:
            self.problem = f"{exc.strerror or type(exc).__name__} ({self.path})"
            self._torn = True
            if self._fd is not None:
                with contextlib.suppress(OSError):
                    os.close(self._fd)
                self._fd = None
            self._first_unflushed = self._clock()
            return False
        self._written, self._torn, self.problem = n, False, None
        self._first_unflushed = None
        return True

    def close(self) -> None:
        """Flush (as far as it can) and close the file; the samples stay in memory and the
        partial file until the run is kept. Never raises."""
        if not self.closed:
            self.flush()
            if self._fd is not None:
                with contextlib.suppress(OSError):
                    os.close(self._fd)
                self._fd = None
            self.closed = True

    def raw(self) -> RawRun:
        """Every sample received, from memory, with the header."""
        arr = np.frombuffer(self._samples, dtype=np.int64).reshape(-1, 4).copy()
        return RawRun(
            header=self.header, seq=arr[:, 0], t_us=arr[:, 1], count=arr[:, 2], u_mV=arr[:, 3]
        )


@dataclass(frozen=True)
class RawRun:
    """Samples read back from a partial file (or a Recorder's memory), and its header (name,
    kind, ts, plan, started; checked against :data:`minseg_tui.lab.saving.schema.PARTIAL_HEADER`,
    broken fields left out and said in ``damage``)."""

    header: Mapping[str, object]
    seq: np.ndarray
    t_us: np.ndarray
    count: np.ndarray
    u_mV: np.ndarray
    damage: str | None = None


def _header(line: str) -> tuple[dict[str, object], str | None]:
    """The header of a partial file from its ``# {...}`` line: the sound fields, and what
    was wrong (None when nothing)."""
    try:
        value = json.loads(line[2:])
    except (ValueError, RecursionError):
        return {}, "its header is not readable JSON"
    if not isinstance(value, dict):
        return {}, "its header is not a JSON object"
    kept, broken = {}, []
    for name, node in PARTIAL_HEADER.optional.items():
        if name in value:
            why = node.check(value[name], name)
            if why:
                broken.append(why)
            else:
                kept[name] = value[name]
    return kept, ("its header has a broken " + "; ".join(broken)) if broken else None


def read_partial(path: Path) -> RawRun:
    """The samples of a partial file; a torn or malformed line (a crash mid-write) is
    skipped, a damaged header is left out field by field (see :class:`RawRun`)."""
    header: dict[str, object] = {}
    damage = None
    rows: list[tuple[int, int, int, int]] = []
    raw = read_regular(Path(path), MAX_PARTIAL_BYTES)
    if len(raw) > MAX_PARTIAL_BYTES:
        raise OSError(errno.EFBIG, f"larger than any recording ({MAX_PARTIAL_BYTES >> 20} MiB)")
    text = raw.decode("ascii", errors="replace")
    lines = text.split("\n")
    if not text.endswith("\n"):
        lines = lines[:-1]  # the last line was cut by the crash
    for line in lines:
        if line.startswith("# "):
            header, damage = _header(line)
            continue
        parts = line.split(",")
        if len(parts) != 4:
            continue
        try:
            row = (int(parts[0]), int(parts[1]), int(parts[2]), int(parts[3]))
        except ValueError:
            continue
        if all(lo <= v <= hi for v, (lo, hi) in zip(row, PARTIAL_RANGES, strict=True)):
            rows.append(row)  # else a line no board sent (a damaged file): skipped
    arr = np.array(rows, dtype=np.int64).reshape(-1, 4)
    return RawRun(
        header=header, seq=arr[:, 0], t_us=arr[:, 1], count=arr[:, 2], u_mV=arr[:, 3], damage=damage
    )


def ts_of(raw: RawRun) -> float:
    """The run's nominal sample period, s: its header's, else the median interval of its
    board times (rounded to 1 us), else 0.025 s."""
    ts = raw.header.get("ts")
    if isinstance(ts, int | float) and not isinstance(ts, bool) and ts > 0:
        return float(ts)
    steps = np.diff(_unwrap(raw.t_us))
    steps = steps[steps > 0]
    return round(float(np.median(steps)) / 1e6, 6) if steps.size else 0.025


def _unwrap(values: np.ndarray, bits: int = 32) -> np.ndarray:
    d = np.mod(np.diff(values.astype(np.int64)), 2**bits)
    return (
        np.concatenate(([0], np.cumsum(d))).astype(np.int64)
        if values.size
        else values.astype(np.int64)
    )


def build_log(raw: RawRun, ts: float) -> tuple[RunLog, int]:
    """The run log of a raw run as the board sent it (its u column is u_req: see
    :func:`applied_log`), and the number of samples lost on the link.

    Samples whose (unwrapped) board time does not increase are dropped (a repeated line).
    """
    t_rel = _unwrap(raw.t_us)
    # keep only samples later than every sample before them (a repeated line is dropped)
    before = np.concatenate(([-1], np.maximum.accumulate(t_rel)[:-1])) if t_rel.size else t_rel
    keep = t_rel > before
    seq_u = _unwrap(raw.seq)[keep]
    t_rel = t_rel[keep]
    count = raw.count[keep].astype(np.int64)
    u_req = raw.u_mV[keep].astype(float) / 1000.0
    t = t_rel / 1e6
    dropped = int(np.sum(np.maximum(np.diff(seq_u) - 1, 0))) if seq_u.size > 1 else 0
    theta = angle(count)
    omega = timestamp_velocity(t, count)
    omega_lab = lab_velocity(count, ts)
    meta = {
        "source": "minseg-tui session recording",
        "ts": f"{ts:g}",
        "cpr": str(COUNTS_PER_REV),
        "u": U_AS_SENT,
        "omega": "mean speed over each sample interval, from the encoder count and the board's timestamps",
        "omega_over": OMEGA_OVER,
        "omega_lab": f"the manual's estimate: Euler derivative at the nominal Ts = {ts:g} s, then the 20-tap average",
        "dropped": str(dropped),
    }
    for k in ("kind", "started", "plan"):
        if k in raw.header:
            meta[k] = (
                json.dumps(raw.header[k])
                if not isinstance(raw.header[k], str)
                else str(raw.header[k])
            )
    log = RunLog(
        t=t,
        u=u_req.copy(),
        omega=omega,
        extra={
            "u_req": u_req,
            "omega_lab": omega_lab,
            "theta": theta,
            "count": count,
            "t_us": raw.t_us[keep].astype(np.int64),
            "seq": raw.seq[keep].astype(np.int64),
        },
        metadata=meta,
    )
    return log, dropped


def write_log_atomic(path: Path, log: RunLog) -> str:
    """Write ``log`` with :func:`minseg_tui.lab.saving.files.write_run_log`, atomically; the
    SHA-256 (hex) of the bytes written."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.build")
    try:
        write_run_log(tmp, log)
        data = tmp.read_bytes()
        atomic_write_bytes(path, data)
    finally:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
    return hashlib.sha256(data).hexdigest()


def applied_log(log: RunLog, table: Sequence[tuple[float, float]]) -> RunLog:
    """``log`` of a recorded run as the lab reads it: its u column u_A, mapped from its u_req
    through the table's (u_req, u_ss) pairs (:func:`applied_voltage`), the metadata saying
    how. A log without u_req (recorded elsewhere) is returned as it is."""
    if "u_req" not in log.extra:
        return log
    u, how = applied_voltage(np.asarray(log.extra["u_req"], dtype=float), table)
    meta = {**log.metadata, "u": how}
    meta.setdefault("cpr", str(COUNTS_PER_REV))  # runs recorded before these were written
    meta.setdefault("omega_over", OMEGA_OVER)
    return RunLog(t=log.t, u=u, omega=log.omega, extra=log.extra, metadata=meta)


def refuse_special(path: Path, expected: str) -> None:
    """InputError at once, without a read, when ``path`` is a FIFO, a device or a socket (a
    FIFO waited 10 s at every read: s37 attack; the palette's import of one froze the lab
    for those 10 s: s38); ``expected``: what it should have been, for the message. A path
    that cannot be looked at passes: the read says why."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return  # read_run_log says what is wrong (no such file, ...)
    if not stat.S_ISREG(mode) and not stat.S_ISDIR(mode):
        what = "a FIFO (a named pipe)" if stat.S_ISFIFO(mode) else "a device or a socket"
        raise InputError(str(path), None, f"expected {expected}; this is {what}, not read")


LOGS_HELD = 512 * 2**20
"""Most bytes of run logs (their columns as read) a :class:`LogCache` holds."""


def _identity(path: Path) -> tuple[int, ...] | None:
    """The identity of the file at ``path`` as it stands (device, inode, size, change
    times), None when it cannot be looked at."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns)


def _held_bytes(log: RunLog) -> int:
    """What ``log``'s columns (and lines) take in memory, bytes."""
    arrays = [log.t, log.u, log.omega, *log.extra.values()]
    if log.lines is not None:
        arrays.append(log.lines)
    return sum(int(np.asarray(a).nbytes) for a in arrays)


class LogCache:
    """Run logs as read from their files, by path, each under the file's identity as it was
    read (a file changed since is read again): a log is parsed once while it stays
    unchanged, not at every view, check and figure that reads it (an import of 1.9 million
    rows was parsed again by the model check, and its view a third time). The newest logs
    up to :data:`LOGS_HELD` bytes are held, the newest always. Threads may share it."""

    def __init__(self, most: int = LOGS_HELD) -> None:
        self.most = most
        self._lock = threading.Lock()
        self._logs: OrderedDict[str, tuple[tuple[int, ...], RunLog, int]] = OrderedDict()

    def read(self, path: Path) -> RunLog:
        """The log in the file at ``path``, parsed by :func:`read_run_log` (no step asked:
        :func:`~minseg_tui.lab.saving.files.check_step` says that) unless it is held
        unchanged. InputError as read_run_log says it."""
        ident = _identity(path)
        with self._lock:
            got = self._logs.get(str(path))
            if got is not None and ident is not None and got[0] == ident:
                self._logs.move_to_end(str(path))
                return got[1]
        log = read_run_log(path, require_step=False)
        if ident is not None and _identity(path) == ident:  # unchanged while it was read
            self.hold(path, log, ident)
        return log

    def drop(self, path: Path) -> None:
        """Hold nothing for the file at ``path`` any more (an import's copy removed)."""
        with self._lock:
            self._logs.pop(str(path), None)

    def hold(self, path: Path, log: RunLog, ident: tuple[int, ...] | None = None) -> None:
        """Hold ``log`` as what the file at ``path`` reads as while it has the identity
        ``ident`` (default: as it stands now)."""
        ident = ident if ident is not None else _identity(path)
        if ident is None:
            return
        size = _held_bytes(log)
        with self._lock:
            self._logs[str(path)] = (ident, log, size)
            self._logs.move_to_end(str(path))
            total = sum(v[2] for v in self._logs.values())
            while total > self.most and len(self._logs) > 1:
                total -= self._logs.popitem(last=False)[1][2]


def read_run(
    folder: Path,
    run: RunInfo,
    table: Sequence[tuple[float, float]],
    require_step: bool = False,
    logs: LogCache | None = None,
) -> RunLog:
    """Run ``run`` of the session in ``folder`` read back, its u column the applied voltage
    from ``table`` for a recorded run (:func:`applied_log`), as it stands for an imported
    one. InputError (file and line) when its file is damaged (or, with ``require_step``,
    holds no step); at once, without a read, when it is not a regular file (a FIFO put in
    its place waited 10 s at every read: s37 attack). ``logs``: where a log read before is
    held (the session's), so that an unchanged file is not parsed again."""
    path = folder / run.file
    refuse_special(path, "the run's log file")
    if logs is None:
        log = read_run_log(path, require_step=require_step)
    else:
        log = logs.read(path)
        if require_step:
            check_step(log)
    return log if run.kind == "imported" else applied_log(log, table)


# -- the runs of a session folder --------------------------------------------------------------


def new_name(folder: Path, kind: str, taken: Iterable[str]) -> str:
    """The first free ``<kind>-<k>`` among ``taken`` names and the files in ``folder/runs``."""
    names = set(taken) | {p.name.split(".")[0] for p in (folder / RUNS_DIR).iterdir()}
    k = 1
    while f"{kind}-{k}" in names:
        k += 1
    return f"{kind}-{k}"


def run_header(
    name: str, kind: str, ts: float, started: str, plan: Mapping[str, float] | None
) -> dict[str, object]:
    """The header line of a partial file: name, kind, ts (s), started (ISO) and the plan."""
    return {"name": name, "kind": kind, "ts": ts, "started": started, "plan": dict(plan or {})}


def keep_run(
    folder: Path,
    name: str,
    raw: RawRun,
    interrupted: bool,
    ended_by: str = "",
) -> RunInfo | None:
    """Write the samples of ``raw`` as ``runs/<name>.csv`` under ``folder`` (atomically) and
    return the run's record; None when it holds fewer than 2 samples. OSError when the log
    cannot be written."""
    if raw.seq.size < 2:
        return None
    ts = ts_of(raw)
    log, dropped = build_log(raw, ts)
    file = f"{RUNS_DIR}/{name}.csv"
    digest = write_log_atomic(folder / file, log)
    plan = raw.header.get("plan")
    return RunInfo(
        name=name,
        file=file,
        kind=str(raw.header.get("kind", "free")),
        ts=ts,
        samples=len(log),
        dropped=dropped,
        started=str(raw.header.get("started", "")),
        interrupted=interrupted,
        plan={str(k): float(v) for k, v in plan.items()} if isinstance(plan, dict) else {},
        ended_by=ended_by if interrupted else "",
        sha256=digest,
    )


def pasted_path(text: str) -> Path:
    """The file named by ``text`` as typed or pasted: a name in matching quotes (a terminal
    pastes a file dropped on it as '/home/ada/step log.csv') is taken without them, and
    ~ expanded, unless the quoted name itself exists."""
    path = Path(text)
    quoted = len(text) > 1 and text[0] == text[-1] and text[0] in "'\""
    if quoted and not os.path.lexists(path):
        return Path(text[1:-1]).expanduser()
    return path


_BOM = b"\xef\xbb\xbf"

IMPORTED_FROM = "imported_from"
"""The metadata key of an imported run's copy that names the file it was imported from."""

EARLIER_FROM = "earlier_imported_from"
"""What a log's own ``# imported_from:`` line is renamed to in its copy (a run imported once
more, from another session's runs/, say): the copy's ``imported_from`` names this import,
and the older source is kept as such, under this name."""

_PREAMBLE_MOST = 1 << 20
"""Most bytes of the lines before a log's header held back to look for its own
``# imported_from:`` line (a line longer than this is no metadata line anyone wrote)."""


def _line_text(line: bytes) -> str:
    return line.decode("utf-8", "replace").strip()


def _renamed(line: bytes) -> bytes:
    """``line`` with a log's own ``# imported_from:`` key renamed :data:`EARLIER_FROM` (as
    :func:`~minseg_tui.lab.saving.csvread.metadata_key` reads the key); any other line as it
    is."""
    if metadata_key(_line_text(line)) != IMPORTED_FROM:
        return line
    at = line.index(IMPORTED_FROM.encode())  # the key: only '#' and spaces stand before it
    return line[:at] + EARLIER_FROM.encode() + line[at + len(IMPORTED_FROM) :]


class _Preamble:
    """The bytes of a log as its copy is written: until the header row (the first line that
    is neither blank nor a comment), each line with a log's own ``# imported_from:`` renamed
    :data:`EARLIER_FROM`; from there on, the bytes as they are."""

    def __init__(self) -> None:
        self.open = True
        self._held = b""

    def feed(self, chunk: bytes) -> bytes:
        """What of ``chunk`` (and what was held back before it) goes into the copy now."""
        if not self.open:
            return chunk
        data, start, out = self._held + chunk, 0, []
        while self.open:
            nl = data.find(b"\n", start)
            if nl < 0:
                break
            line = data[start : nl + 1]
            text = _line_text(line)
            if text and not text.startswith("#"):
                self.open = False  # the header row: the rest as it is
                break
            out.append(_renamed(line))
            start = nl + 1
        self._held = data[start:]
        if not self.open or len(self._held) > _PREAMBLE_MOST:
            self.open = False
            out.append(self._held)
            self._held = b""
        return b"".join(out)

    def end(self) -> bytes:
        """What is still held back at the end of the log (a last line without a newline)."""
        held, self._held = self._held, b""
        return _renamed(held) if self.open else held


def import_log(
    folder: Path, path: Path, name: str, started: str, logs: LogCache | None = None
) -> RunInfo:
    """Copy the run log at ``path`` (checked by read_run_log; InputError with file and line
    if it is not one; at once for a FIFO or a device) into ``folder/runs/<name>.csv``; its
    record. OSError when the copy cannot be written (nothing is left behind).

    The copy is the very bytes read and checked, as they are read (s38 attack: a 227 MB log
    read in 39 s was then formatted and written again: 44 s more, 2.7 GB at the peak), after one
    ``# imported_from:`` line naming ``path`` (a BOM at its start is left out: it would stand
    mid-file; a log's own ``# imported_from:`` line before its header, a copy of a run
    imported before, is kept renamed :data:`EARLIER_FROM`, so that the copy names where this
    import came from); it is written to a temporary file and renamed into place, as the
    session's files are. The run's SHA-256 is of the bytes written. ``logs``: given the log
    as its copy reads (the same columns, its lines one further on, the metadata naming this
    import), so that what reads the run next does not parse it again."""
    refuse_special(Path(path), "a run log file")
    file = f"{RUNS_DIR}/{name}.csv"
    target = folder / file
    tmp = target.with_name(f".{target.name}.{os.getpid()}.build")
    digest = hashlib.sha256()
    first = True
    preamble = _Preamble()

    def put(data: bytes) -> None:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view) :]
        digest.update(data)

    def tee(chunk: bytes) -> None:
        nonlocal first
        if first and chunk.startswith(_BOM):
            chunk = chunk[len(_BOM) :]
        first = False
        put(preamble.feed(chunk))

    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_CLOEXEC, 0o644)
    except OSError as exc:  # named by the file meant, not by the temporary one
        raise type(exc)(exc.errno, exc.strerror, str(target)) from None
    try:
        try:
            source = " ".join(str(path).split())
            put(f"# {IMPORTED_FROM}: {source}\n".encode("utf-8", "replace"))
            log = read_run_log(Path(path), tee=tee)
            put(preamble.end())
            os.fsync(fd)
        finally:
            os.close(fd)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    fsync_dir(target.parent)
    written = source.encode("utf-8", "replace").decode("utf-8")  # as the copy's line reads
    if logs is not None and EARLIER_FROM not in log.metadata:
        logs.hold(target, _as_copied(log, target, written))
    return RunInfo(
        name=name,
        file=file,
        kind="imported",
        ts=log.ts,
        samples=len(log),
        dropped=0,
        started=started,
        sha256=digest.hexdigest(),
    )


def _as_copied(log: RunLog, target: Path, source: str) -> RunLog:
    """``log``, read from the file imported, as its copy at ``target`` reads: the line naming
    the import before the rest (every line one further on), its own ``# imported_from:``
    renamed :data:`EARLIER_FROM` (:class:`_Preamble`)."""
    meta = {IMPORTED_FROM: source}
    for key, value in log.metadata.items():
        meta[EARLIER_FROM if key == IMPORTED_FROM else key] = value
    lines = log.lines + 1 if log.lines is not None else None
    return replace(log, metadata=meta, source=str(target), lines=lines)


# -- a run's file changed after it was written ------------------------------------------------


def _file_digest(path: Path) -> tuple[tuple[int, ...], str] | None:
    """The identity of the regular file ``path`` (device, inode, size, change times) and the
    SHA-256 of its bytes; None when it cannot be read or is not a regular file."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError:
        return None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            return None
        ident = (st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns)
        h = hashlib.sha256()
        while chunk := os.read(fd, 1 << 20):
            h.update(chunk)
        return ident, h.hexdigest()
    except OSError:
        return None
    finally:
        os.close(fd)


@dataclass(frozen=True)
class ChangedFile:
    """What :func:`changed_file` says of a run's file: ``text``, one line, and ``edited``:
    the file is known to differ from what was written (False: it cannot be checked)."""

    text: str
    edited: bool


_said: dict[tuple[object, ...], ChangedFile | None] = {}
""":func:`changed_file`'s line by the file's identity and the run's record: the lab's views
ask again at every redraw, and a file unchanged on disk is not read again."""


def changed_file(folder: Path, run: RunInfo) -> ChangedFile | None:
    """The one rule for a run's file changed after it was written (s38 attack: the report
    said a row deleted by hand, the class view and the lab's Tasks 11-15 did not, and an
    edit that kept the number of rows was seen by none).

    A run records the SHA-256 of its file as written (:attr:`RunInfo.sha256`); a file whose
    bytes hash otherwise gives "run steps-1: its file runs/steps-1.csv was changed after the
    recording (edited by hand?): ...", with the samples it holds where they differ from those
    recorded. A run recorded by an older program has no SHA-256: a file whose samples differ
    in number says the same, else "... cannot be checked for edits ...". None when the file
    is as written, or cannot be read at all (the lines that read it say why). Reads the file
    once per change on disk."""
    path = Path(folder) / run.file
    got = _file_digest(path)
    if got is None:
        return None
    ident, digest = got
    key = (str(path), ident, run.sha256, run.samples, run.name, run.file)
    if key in _said:
        return _said[key]
    said: ChangedFile | None = None
    if not run.sha256 or digest != run.sha256:
        try:
            held = len(read_run_log(path, require_step=False))
        except InputError:
            held = None
        if held is None and run.sha256:  # cut short (a stick pulled out?) or spoiled
            how = "it no longer reads as a run log, so nothing is computed from it"
        elif held is not None and held != run.samples:
            how = f"it holds {held} samples where {run.samples} were recorded"
        elif run.sha256:
            how = f"it holds the {run.samples} samples recorded, but not the bytes written"
        else:
            how = ""
        uses = "" if held is None else "; what is computed from it uses the file as it is now"
        said = (
            ChangedFile(
                f"run {run.name}: its file {run.file} was changed after the recording (edited "
                f"by hand?): {how}{uses}",
                edited=True,
            )
            if how
            else ChangedFile(
                f"run {run.name}: its file {run.file} cannot be checked for edits by hand "
                "(an older minseg-tui wrote it and kept no checksum of it)",
                edited=False,
            )
        )
    _said[key] = said
    while len(_said) > 256:
        del _said[next(iter(_said))]
    return said
