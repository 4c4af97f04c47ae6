"""Line plots as self-contained SVG text (no scripts, no external files, no fonts to fetch).

:func:`plot` draws one panel: x/y axes with round ticks and a label (with its unit) on each,
lines (optionally as sample dots), shaded bands (a noise floor), reference marks (a level,
an instant) and a legend. The legend sits above the plot area, outside it, so it never
covers the data; entries wrap onto more rows when they do not fit. :func:`stack` puts
panels above one another into one ``<svg>`` a student can paste as one figure.

Long series are thinned to at most :data:`MAX_POINTS` points per line by keeping each
bucket's min and max, so steps and spikes survive.

The plot area is the ``<rect class="plot-area">``; the legend is the ``<g class="legend">``;
marks are ``<line class="mark">`` elements. Tests read them.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from html import escape

import numpy as np
from numpy.typing import ArrayLike

from minseg_tui.quantities import format_ticks

MAX_POINTS = 1600
COLORS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#555555")

FONT_SIZE = 11
"""Font size of tick labels, axis labels and the legend, px."""

CHAR_WIDTH = 6.2
"""A generous width of one character at :data:`FONT_SIZE` in a sans-serif font, px (to lay
out the legend without measuring text)."""

LEGEND_ROW = 15
"""Height of one row of the legend, px."""

DOTS_MAX = 250
"""A series with dots gets them up to this many samples (beyond, they would merge into a
thick line; the line alone shows the samples then)."""


@dataclass(frozen=True)
class Line:
    """One series: its legend ``label``, x and y values, a colour (default: the next of
    :data:`COLORS`), dashed, drawn as steps (a held value), or with a dot at every sample
    (up to :data:`DOTS_MAX` samples)."""

    label: str
    x: ArrayLike
    y: ArrayLike
    color: str = ""
    dash: bool = False
    steps: bool = False
    dots: bool = False


@dataclass(frozen=True)
class Band:
    """A shaded band from ``lo`` to ``hi`` over ``x`` (for instance a model +- the noise
    floor), with its legend ``label``."""

    label: str
    x: ArrayLike
    lo: ArrayLike
    hi: ArrayLike
    color: str = "#999999"


@dataclass(frozen=True)
class Mark:
    """A reference line across the plot area: horizontal at ``y`` or vertical at ``x`` (one
    of them), with its legend ``label``; ``dot`` puts a dot on it at (x, dot)."""

    label: str
    x: float | None = None
    y: float | None = None
    color: str = "#555555"
    dash: bool = True
    dot: float | None = None


def nice_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    """About ``n`` round tick values covering [lo, hi]."""
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
        return [lo]
    raw = (hi - lo) / max(n, 1)
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw)
    first = math.ceil(lo / step - 1e-9) * step
    return [round(first + k * step, 12) for k in range(int((hi - first) / step + 1e-9) + 1)]


def thin(
    x: np.ndarray, y: np.ndarray, max_points: int = MAX_POINTS
) -> tuple[np.ndarray, np.ndarray]:
    """At most about ``max_points`` points: per bucket the first, min and max (in order)."""
    n = x.size
    if n <= max_points:
        return x, y
    buckets = max_points // 3
    edges = np.linspace(0, n, buckets + 1).astype(int)
    keep: list[int] = []
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        if b <= a:
            continue
        seg = y[a:b]
        idx = (
            sorted({a, a + int(np.nanargmin(seg)), a + int(np.nanargmax(seg))})
            if np.isfinite(seg).any()
            else [a]
        )
        keep.extend(idx)
    keep.append(n - 1)
    k = np.array(sorted(set(keep)))
    return x[k], y[k]


@dataclass(frozen=True)
class _Entry:
    label: str
    color: str
    kind: str  # line, dashed, band, dots

    @property
    def width(self) -> float:
        return 22 + CHAR_WIDTH * len(self.label) + 14


def _legend_rows(entries: Sequence[_Entry], room: float) -> list[list[_Entry]]:
    rows: list[list[_Entry]] = []
    used = room + 1.0
    for e in entries:
        if used + e.width > room and (not rows or rows[-1]):
            rows.append([])
            used = 0.0
        rows[-1].append(e)
        used += e.width
    return rows


def _legend(rows: list[list[_Entry]], left: float, top: float) -> str:
    out = ['<g class="legend">']
    for r, row in enumerate(rows):
        y = top + r * LEGEND_ROW + LEGEND_ROW / 2
        x = left
        for e in row:
            if e.kind == "band":
                out.append(
                    f'<rect x="{x:.1f}" y="{y - 5:.1f}" width="18" height="10" fill="{e.color}" '
                    'fill-opacity="0.25" stroke="none"/>'
                )
            else:
                dash = ' stroke-dasharray="5,3"' if e.kind == "dashed" else ""
                out.append(
                    f'<line x1="{x:.1f}" y1="{y:.1f}" x2="{x + 18:.1f}" y2="{y:.1f}" '
                    f'stroke="{e.color}" stroke-width="2"{dash}/>'
                )
                if e.kind == "dots":
                    out.append(f'<circle cx="{x + 9:.1f}" cy="{y:.1f}" r="2.2" fill="{e.color}"/>')
            out.append(f'<text x="{x + 22:.1f}" y="{y + 4:.1f}">{escape(e.label)}</text>')
            x += e.width
    out.append("</g>")
    return "".join(out)


def _finite(values: Sequence[np.ndarray]) -> np.ndarray:
    kept = [v[np.isfinite(v)] for v in values]
    return np.concatenate(kept) if kept else np.zeros(0)


def plot(
    lines: Sequence[Line],
    *,
    bands: Sequence[Band] = (),
    marks: Sequence[Mark] = (),
    title: str = "",
    xlabel: str = "",
    ylabel: str = "",
    width: int = 720,
    height: int = 240,
    show_xlabel: bool = True,
) -> str:
    """One panel as an ``<svg>`` element (text): ``height`` is the plot's own height (the
    legend's rows are added above it). Axis labels should carry their units
    (:func:`~minseg_tui.quantities.axis_label`: "t [s]", as on screen)."""
    ml, mr = 62, 14
    pw = width - ml - mr
    xs = [np.asarray(ln.x, dtype=float) for ln in lines]
    ys = [np.asarray(ln.y, dtype=float) for ln in lines]
    bx = [np.asarray(b.x, dtype=float) for b in bands]
    blo = [np.asarray(b.lo, dtype=float) * np.ones_like(x) for b, x in zip(bands, bx, strict=True)]
    bhi = [np.asarray(b.hi, dtype=float) * np.ones_like(x) for b, x in zip(bands, bx, strict=True)]
    allx = _finite([*xs, *bx, np.array([m.x for m in marks if m.x is not None], dtype=float)])
    ally = _finite([*ys, *blo, *bhi, np.array([m.y for m in marks if m.y is not None], float)])
    x0, x1 = (float(allx.min()), float(allx.max())) if allx.size else (0.0, 1.0)
    y0, y1 = (float(ally.min()), float(ally.max())) if ally.size else (0.0, 1.0)
    if x1 <= x0:
        x1 = x0 + 1.0
    if y1 <= y0:
        y0, y1 = y0 - 1.0, y1 + 1.0
    pad = 0.05 * (y1 - y0)
    y0, y1 = y0 - pad, y1 + pad

    entries = []
    for k, ln in enumerate(lines):
        color = ln.color or COLORS[k % len(COLORS)]
        kind = "dots" if ln.dots else "dashed" if ln.dash else "line"
        if ln.label:
            entries.append(_Entry(ln.label, color, kind))
    entries += [_Entry(b.label, b.color, "band") for b in bands if b.label]
    entries += [_Entry(m.label, m.color, "dashed" if m.dash else "line") for m in marks if m.label]
    rows = _legend_rows(entries, pw)
    top = 22 if title else 6
    mt = top + len(rows) * LEGEND_ROW + 6
    mb = 40 if show_xlabel else 22
    ph = height - (24 if title else 10) - (40 if show_xlabel else 22)
    total = mt + ph + mb

    def sx(v: ArrayLike) -> np.ndarray:
        return np.asarray(ml + (np.asarray(v, dtype=float) - x0) / (x1 - x0) * pw)

    def sy(v: ArrayLike) -> np.ndarray:
        return np.asarray(mt + ph - (np.asarray(v, dtype=float) - y0) / (y1 - y0) * ph)

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{total}" '
        f'viewBox="0 0 {width} {total}" font-family="sans-serif" font-size="{FONT_SIZE}">',
        f'<rect width="{width}" height="{total}" fill="#ffffff"/>',
    ]
    if title:
        out.append(
            f'<text x="{ml}" y="15" font-size="12" font-weight="bold">{escape(title)}</text>'
        )
    out.append(_legend(rows, ml, top))
    out.append(
        f'<rect class="plot-area" x="{ml}" y="{mt}" width="{pw}" height="{ph}" fill="none" '
        'stroke="#999"/>'
    )
    xticks = nice_ticks(x0, x1, 8)
    for v, label in zip(xticks, format_ticks(xticks), strict=True):
        px = float(sx(v))
        out.append(f'<line x1="{px:.1f}" y1="{mt}" x2="{px:.1f}" y2="{mt + ph}" stroke="#eee"/>')
        out.append(
            f'<text class="xtick" x="{px:.1f}" y="{mt + ph + 13}" text-anchor="middle">'
            f"{label}</text>"
        )
    yticks = nice_ticks(y0, y1, 5)
    for v, label in zip(yticks, format_ticks(yticks), strict=True):
        py = float(sy(v))
        out.append(f'<line x1="{ml}" y1="{py:.1f}" x2="{ml + pw}" y2="{py:.1f}" stroke="#eee"/>')
        out.append(
            f'<text class="ytick" x="{ml - 4}" y="{py + 4:.1f}" text-anchor="end">{label}</text>'
        )
    if y0 < 0 < y1:
        py = float(sy(0.0))
        out.append(f'<line x1="{ml}" y1="{py:.1f}" x2="{ml + pw}" y2="{py:.1f}" stroke="#bbb"/>')
    if show_xlabel and xlabel:
        out.append(
            f'<text class="xlabel" x="{ml + pw / 2}" y="{total - 6}" text-anchor="middle">'
            f"{escape(xlabel)}</text>"
        )
    if ylabel:
        out.append(
            f'<text class="ylabel" transform="translate(13,{mt + ph / 2}) rotate(-90)" '
            f'text-anchor="middle">{escape(ylabel)}</text>'
        )
    for b, x, lo, hi in zip(bands, bx, blo, bhi, strict=True):
        ok = np.isfinite(x) & np.isfinite(lo) & np.isfinite(hi)
        if not np.any(ok):
            continue
        top_pts = [f"{a:.1f},{c:.1f}" for a, c in zip(sx(x[ok]), sy(hi[ok]), strict=True)]
        low_pts = [f"{a:.1f},{c:.1f}" for a, c in zip(sx(x[ok]), sy(lo[ok]), strict=True)]
        out.append(
            f'<polygon class="band" fill="{b.color}" fill-opacity="0.25" stroke="none" '
            f'points="{" ".join(top_pts + low_pts[::-1])}"/>'
        )
    # series with dots (the measured samples) are drawn last, on top of the models
    order = sorted(range(len(lines)), key=lambda k: lines[k].dots)
    for k in order:
        ln, x, y = lines[k], xs[k], ys[k]
        color = ln.color or COLORS[k % len(COLORS)]
        ok = np.isfinite(x) & np.isfinite(y)
        x, y = x[ok], y[ok]
        if ln.steps and x.size > 1:
            x = np.repeat(x, 2)[1:]
            y = np.repeat(y, 2)[:-1]
        x, y = thin(x, y)
        xy = list(zip(sx(x).tolist(), sy(y).tolist(), strict=True))
        pts = " ".join(f"{a:.1f},{b:.1f}" for a, b in xy)
        dash = ' stroke-dasharray="5,3"' if ln.dash else ""
        out.append(
            f'<polyline fill="none" stroke="{color}" stroke-width="{1.0 if ln.dots else 1.4}"'
            f'{dash} points="{pts}"/>'
        )
        if ln.dots and len(xy) <= DOTS_MAX:
            out.append(
                f'<g fill="{color}">'
                + "".join(f'<circle cx="{a:.1f}" cy="{b:.1f}" r="2"/>' for a, b in xy)
                + "</g>"
            )
    for m in marks:
        dash = ' stroke-dasharray="6,3"' if m.dash else ""
        if m.x is not None:
            px0 = float(sx(m.x))
            out.append(
                f'<line class="mark" x1="{px0:.2f}" y1="{mt}" x2="{px0:.2f}" y2="{mt + ph}" '
                f'stroke="{m.color}" stroke-width="1.5"{dash}/>'
            )
            if m.dot is not None:
                out.append(
                    f'<circle cx="{px0:.2f}" cy="{float(sy(m.dot)):.2f}" r="4" fill="none" '
                    f'stroke="{m.color}" stroke-width="2"/>'
                )
        elif m.y is not None:
            py0 = float(sy(m.y))
            out.append(
                f'<line class="mark" x1="{ml}" y1="{py0:.2f}" x2="{ml + pw}" y2="{py0:.2f}" '
                f'stroke="{m.color}" stroke-width="1.5"{dash}/>'
            )
    out.append("</svg>")
    return "".join(out)


_SIZE = re.compile(r'^<svg [^>]*?width="(\d+)" height="(\d+)"')


def stack(panels: Sequence[str]) -> str:
    """Panels (SVG texts from :func:`plot`) one above the other, as one ``<svg>``."""
    sizes = []
    for p in panels:
        m = _SIZE.match(p)
        if m is None:
            raise ValueError("expected a panel made by plot()")
        sizes.append((int(m.group(1)), int(m.group(2))))
    width = max(w for w, _ in sizes)
    height = sum(h for _, h in sizes)
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}">'
    ]
    y = 0
    for p, (_, h) in zip(panels, sizes, strict=True):
        out.append(p.replace('<svg xmlns="http://www.w3.org/2000/svg" ', f'<svg y="{y}" ', 1))
        y += h
    out.append("</svg>")
    return "".join(out)
