"""The summary step: F8 writes the report; the files written."""

from __future__ import annotations

from textual.content import Content
from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.ui.panels.view_panel import ViewPanel


class ReportPanel(Static):
    """Says how to write the report and lists the files ``exported`` (paths) so far."""

    exported: reactive[tuple[str, ...]] = reactive((), layout=True)

    def __init__(self) -> None:
        super().__init__("", classes="panel")

    def watch_exported(self) -> None:
        """The files listed above the summary's entries: the step keeps the entry the group
        types in in view (the list pushed it under the footer at 80x24)."""
        self.call_after_refresh(self.post_message, ViewPanel.Drawn())

    def render(self) -> Content:
        """Plain text: a file's or a port's name with brackets in it is shown as it is."""
        return Content(self._text())

    def _text(self) -> str:
        paths = self.exported
        return "F8 (or Ctrl+P → Export report) writes report.md, report.html and the runs' CSV." + (
            "\nwritten:\n" + "\n".join(f"  {p}" for p in paths) if paths else ""
        )
