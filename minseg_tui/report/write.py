"""Write a session's report into its folder: report.md with its figures as SVG files beside
it (report-figure-1.svg, ...), and report.html, whole in one file (runs/*.csv are already
there); and the class's report (class.md, class.html, class.csv) into a folder."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from minseg_tui.lab.saving.store import atomic_write_text
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.classview import ClassView
from minseg_tui.report import class_content, content, html, markdown


@dataclass(frozen=True)
class Written:
    """Paths written: the Markdown and HTML reports and the CSV of every recorded run;
    ``figures``: the Markdown's figures (SVG files beside it)."""

    markdown: Path
    html: Path
    runs: tuple[Path, ...]
    figures: tuple[Path, ...] = ()

    @property
    def paths(self) -> tuple[Path, ...]:
        """Every file: the Markdown report, the HTML report, then the runs' CSV."""
        return (self.markdown, self.html, *self.runs)


FIGURE_PREFIX = "report-figure"
"""The Markdown report's figures are report-figure-1.svg, report-figure-2.svg, ... beside it."""


def write_report(session: Session) -> Written:
    """Build the report of ``session`` and write its figures, report.md and report.html
    atomically into its folder (figures of an earlier report that this one has not are
    removed); returns the paths (the run CSVs listed are the session's own files that are there). OSError
    when the folder cannot be written."""
    rep = content.build(session)
    md_path = session.folder / "report.md"
    html_path = session.folder / "report.html"
    figures = []
    for name, svg in markdown.figure_files(rep, FIGURE_PREFIX):
        figures.append(session.folder / name)
        atomic_write_text(figures[-1], svg)
    for old in session.folder.glob(f"{FIGURE_PREFIX}-*.svg"):  # an earlier report's extra ones
        if old not in figures:
            old.unlink(missing_ok=True)
    atomic_write_text(md_path, markdown.render(rep, FIGURE_PREFIX))
    atomic_write_text(html_path, html.render(rep))
    # only the run CSVs that are there: one deleted while the session was open is not named
    # as written (the report itself says it cannot be read)
    runs = tuple(p for p in (session.folder / r.file for r in session.runs) if p.is_file())
    return Written(md_path, html_path, runs, tuple(figures))


CLASS_FILES = ("class.md", "class.html", "class.csv")
"""The class's report, as :func:`write_class` names its files."""


def write_class(view: ClassView, out: Path) -> tuple[Path, ...]:
    """Write class.md, class.html (self-contained, fit to print) and class.csv of ``view``
    atomically into ``out`` (made if needed); returns their paths. OSError when ``out``
    cannot be made or written."""
    rep = class_content.build(view)
    bodies = (markdown.render(rep), html.render(rep), class_content.csv_text(view))
    out.mkdir(parents=True, exist_ok=True)
    paths = tuple(out / name for name in CLASS_FILES)
    for path, body in zip(paths, bodies, strict=True):
        atomic_write_text(path, body)
    return paths
