"""Errors that reach the user as one line, never as a traceback."""

from __future__ import annotations

from dataclasses import dataclass


class MinsegError(Exception):
    """Base class for every error the CLI and the TUI report as one line."""


@dataclass
class InputError(MinsegError):
    """Bad input: a file, a line in it (1-based, or None) and what was expected.

    str() gives the one-line message: ``table.csv:3: expected a number for i_ss (mA), got 'abc'``.
    """

    source: str
    line: int | None
    expected: str

    def __post_init__(self) -> None:
        super().__init__(str(self))

    def __str__(self) -> str:
        where = self.source if self.line is None else f"{self.source}:{self.line}"
        return f"{where}: {self.expected}" if where else self.expected


class DeviceError(MinsegError):
    """The board or its link failed in a way the user must act on (message says how)."""
