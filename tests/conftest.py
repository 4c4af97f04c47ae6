"""Tests that read ../shared/data carry the ``shared_data`` mark. Where that folder is absent
they are not run and the session ends with one line saying so; with CI=true they fail."""

import pytest

from tests.shared_data import absent_reason, required


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "shared_data: reads ../shared/data (real motor logs)")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The ``slow`` tests first (in their order; the rest keep theirs): under pytest-xdist
    each starts on a worker at once instead of ending the run on one worker alone."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)


def pytest_runtest_setup(item: pytest.Item) -> None:
    if item.get_closest_marker("shared_data") is None:
        return
    reason = absent_reason()
    if reason is None:
        return
    if required():
        pytest.fail(f"CI=true and {reason.removeprefix('not run: ')}", pytrace=False)
    pytest.skip(reason)


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    # counted from the reports, which also come back from pytest-xdist's workers
    not_run = [
        r
        for r in terminalreporter.stats.get("skipped", [])
        if "is not beside this clone" in str(getattr(r, "longrepr", ""))
    ]
    if not_run:
        terminalreporter.write_line(
            f"{len(not_run)} tests that read ../shared/data were not run: "
            "it is not beside this clone (CI always has it)"
        )
