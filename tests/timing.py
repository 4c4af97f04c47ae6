"""Where the test run's time goes (`make test-times`, or ``pytest -p tests.timing``).

Each test process (each pytest-xdist worker, or pytest itself with ``-n 0``) writes one
line per test: its node id, its start and end (host time, s) and the CPU its process used
meanwhile (``time.process_time``: every thread of the test process, not the processes a
test starts). At the end the process that reports prints, from those lines:

- per worker: tests run, its last end and the time it then sat idle while another worker
  still ran (the tail);
- per folder: tests, wall and CPU seconds;
- the tests that used the most CPU (``--timing-top``, 60 unless told), with their wall time.

On a busy machine a test's wall time is mostly time spent waiting for a core; its CPU time
is what the test costs, and what shortening the suite has to cut.
"""

from __future__ import annotations

import json
import os
import tempfile
import time
from collections import defaultdict
from collections.abc import Iterator
from pathlib import Path

import pytest

_DIR_OPTION = "timing_dir"


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("timing", "where the test run's time goes (tests.timing)")
    group.addoption(
        "--timing-dir",
        dest=_DIR_OPTION,
        default=None,
        help="folder for the per-test lines (default: a new one in the temporary folder)",
    )
    group.addoption("--timing-top", type=int, default=60, help="how many tests to list by CPU (60)")


def _folder(config: pytest.Config) -> Path:
    given = config.getoption(_DIR_OPTION)
    if given is None:  # the controller picks the folder and hands it to its workers
        given = tempfile.mkdtemp(prefix="minseg-timing-")
        config.option.timing_dir = given
    path = Path(given)
    path.mkdir(parents=True, exist_ok=True)
    return path


def pytest_configure(config: pytest.Config) -> None:
    if not hasattr(config, "workerinput"):  # the controller, or pytest without xdist
        _folder(config)


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node: object) -> None:
    """pytest-xdist: hand the controller's folder to each worker."""
    config = node.config  # type: ignore[attr-defined]
    node.workerinput["timing_dir"] = config.getoption(_DIR_OPTION)  # type: ignore[attr-defined]


def _lines_path(config: pytest.Config) -> Path:
    workerinput = getattr(config, "workerinput", None)
    folder = Path(workerinput["timing_dir"]) if workerinput else _folder(config)
    return folder / f"{os.environ.get('PYTEST_XDIST_WORKER', 'main')}.jsonl"


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item) -> Iterator[None]:
    start, cpu = time.time(), time.process_time()
    yield
    line = [item.nodeid, start, time.time(), time.process_time() - cpu]
    with _lines_path(item.config).open("a") as f:
        f.write(json.dumps(line) + "\n")


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    config = terminalreporter.config
    if hasattr(config, "workerinput"):
        return
    rows = []
    for path in sorted(_folder(config).glob("*.jsonl")):
        for text in path.read_text().splitlines():
            nodeid, start, end, cpu = json.loads(text)
            rows.append((path.stem, nodeid, start, end, cpu))
    if not rows:
        return
    write = terminalreporter.write_line
    t0, t_end = min(r[2] for r in rows), max(r[3] for r in rows)
    terminalreporter.section("where the time went (tests.timing)")
    write(
        f"{len(rows)} tests, first start to last end {t_end - t0:.1f} s; lines in {_folder(config)}"
    )
    write("worker  tests  last end [s]  idle at the end [s]  CPU [s]")
    for worker in sorted({r[0] for r in rows}):
        mine = [r for r in rows if r[0] == worker]
        last = max(r[3] for r in mine)
        cpu = sum(r[4] for r in mine)
        write(f"{worker:6s}  {len(mine):5d}  {last - t0:12.1f}  {t_end - last:19.1f}  {cpu:7.1f}")
    folders: dict[str, list[float]] = defaultdict(lambda: [0, 0.0, 0.0])
    for _, nodeid, start, end, cpu in rows:
        parts = nodeid.split("::")[0].split("/")
        sums = folders["/".join(parts[:-1]) or "."]
        sums[0] += 1
        sums[1] += end - start
        sums[2] += cpu
    write("folder                     tests  wall [s]  CPU [s]")
    for name, (n, wall, cpu) in sorted(folders.items(), key=lambda kv: -kv[1][2]):
        write(f"{name:25s}  {int(n):5d}  {wall:8.1f}  {cpu:7.1f}")
    top = config.getoption("timing_top")
    write(f"the {top} tests that used the most CPU: CPU [s], wall [s], worker, node id")
    for worker, nodeid, start, end, cpu in sorted(rows, key=lambda r: -r[4])[:top]:
        write(f"{cpu:6.2f}  {end - start:6.2f}  {worker:6s}  {nodeid}")
