"""The summary step: F8 writes the report; the files written."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static


class ReportPanel(Static):
    """Says how to write the report and lists the files ``exported`` (paths) so far."""

    exported: reactive[tuple[str, ...]] = reactive((), layout=True)

    def __init__(self) -> None:
        super().__init__("", classes="panel")

    def render(self) -> str:
        paths = self.exported
        return "F8 (or Ctrl+P → Export report) writes report.md, report.html and the runs' CSV." + (
            "\nwritten:\n" + "\n".join(f"  {p}" for p in paths) if paths else ""
        )
