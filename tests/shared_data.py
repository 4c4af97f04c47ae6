"""Where the project's read-only material lies: ../shared beside the clone (real motor logs,
the lab manual). CI always has it; a fresh clone on a laptop may not, and then the tests
marked ``shared_data`` say in one line that they were not run (tests/conftest.py)."""

import os
from pathlib import Path

SHARED_DATA = Path(__file__).resolve().parents[2] / "shared" / "data"


def absent_reason() -> str | None:
    """Why the tests marked ``shared_data`` cannot run here, or None when they can."""
    if SHARED_DATA.is_dir():
        return None
    return f"not run: {SHARED_DATA} is not beside this clone (../shared; CI always has it)"


def required() -> bool:
    """True where an absent ../shared is a failure, not a reason to skip (CI=true)."""
    return os.environ.get("CI", "").lower() in {"1", "true", "yes"}
