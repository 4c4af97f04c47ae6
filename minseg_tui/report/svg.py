"""Line plots as self-contained SVG text (no scripts, no external files, no fonts to fetch).

:func:`plot` draws one panel (x/y axes with round ticks, lines, a legend); :func:`stack`
puts panels above one another with a shared x axis label. Long series are thinned to at
most :data:`MAX_POINTS` points per line by keeping each bucket's min and max, so steps
and spikes survive.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from html import escape

import numpy as np
from numpy.typing import ArrayLike

MAX_POINTS = 1600
COLORS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#555555")


@dataclass(frozen=True)
class Line:
    """One series: its legend ``label``, x and y values, and an optional colour and dash."""

    label: str
    x: ArrayLike
    y: ArrayLike
    color: str = ""
    dash: bool = False
    steps: bool = False


def nice_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    """About ``n`` round tick values covering [lo, hi]."""
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
        return [lo]
    raw = (hi - lo) / max(n, 1)
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw)
    first = math.ceil(lo / step - 1e-9) * step
    return [round(first + k * step, 12) for k in range(int((hi - first) / step + 1e-9) + 1)]


def _fmt(v: float) -> str:
    return f"{v:.4g}"


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


def plot(
    lines: Sequence[Line],
    *,
    title: str = "",
    xlabel: str = "",
    ylabel: str = "",
    width: int = 720,
    height: int = 240,
    show_xlabel: bool = True,
) -> str:
    """One panel as an ``<svg>`` element (text)."""
    ml, mr, mt, mb = 62, 14, 24 if title else 10, 40 if show_xlabel else 22
    pw, ph = width - ml - mr, height - mt - mb
    xs = [np.asarray(ln.x, dtype=float) for ln in lines]
    ys = [np.asarray(ln.y, dtype=float) for ln in lines]
    allx = np.concatenate([x[np.isfinite(x)] for x in xs]) if xs else np.zeros(0)
    ally = np.concatenate([y[np.isfinite(y)] for y in ys]) if ys else np.zeros(0)
    x0, x1 = (float(allx.min()), float(allx.max())) if allx.size else (0.0, 1.0)
    y0, y1 = (float(ally.min()), float(ally.max())) if ally.size else (0.0, 1.0)
    if x1 <= x0:
        x1 = x0 + 1.0
    if y1 <= y0:
        y0, y1 = y0 - 1.0, y1 + 1.0
    pad = 0.05 * (y1 - y0)
    y0, y1 = y0 - pad, y1 + pad

    def sx(v: np.ndarray | float) -> np.ndarray | float:
        return ml + (np.asarray(v) - x0) / (x1 - x0) * pw

    def sy(v: np.ndarray | float) -> np.ndarray | float:
        return mt + ph - (np.asarray(v) - y0) / (y1 - y0) * ph

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">'
    ]
    if title:
        out.append(
            f'<text x="{ml}" y="15" font-size="12" font-weight="bold">{escape(title)}</text>'
        )
    out.append(f'<rect x="{ml}" y="{mt}" width="{pw}" height="{ph}" fill="none" stroke="#999"/>')
    for v in nice_ticks(x0, x1, 8):
        px = float(sx(v))
        out.append(f'<line x1="{px:.1f}" y1="{mt}" x2="{px:.1f}" y2="{mt + ph}" stroke="#eee"/>')
        out.append(f'<text x="{px:.1f}" y="{mt + ph + 13}" text-anchor="middle">{_fmt(v)}</text>')
    for v in nice_ticks(y0, y1, 5):
        py = float(sy(v))
        out.append(f'<line x1="{ml}" y1="{py:.1f}" x2="{ml + pw}" y2="{py:.1f}" stroke="#eee"/>')
        out.append(f'<text x="{ml - 4}" y="{py + 4:.1f}" text-anchor="end">{_fmt(v)}</text>')
    if y0 < 0 < y1:
        py = float(sy(0.0))
        out.append(f'<line x1="{ml}" y1="{py:.1f}" x2="{ml + pw}" y2="{py:.1f}" stroke="#bbb"/>')
    if show_xlabel and xlabel:
        out.append(
            f'<text x="{ml + pw / 2}" y="{height - 6}" text-anchor="middle">{escape(xlabel)}</text>'
        )
    if ylabel:
        out.append(
            f'<text transform="translate(13,{mt + ph / 2}) rotate(-90)" text-anchor="middle">{escape(ylabel)}</text>'
        )
    for k, (ln, x, y) in enumerate(zip(lines, xs, ys, strict=True)):
        color = ln.color or COLORS[k % len(COLORS)]
        ok = np.isfinite(x) & np.isfinite(y)
        x, y = x[ok], y[ok]
        if ln.steps and x.size > 1:
            x = np.repeat(x, 2)[1:]
            y = np.repeat(y, 2)[:-1]
        x, y = thin(x, y)
        pts = " ".join(
            f"{a:.1f},{b:.1f}" for a, b in zip(np.asarray(sx(x)), np.asarray(sy(y)), strict=True)
        )
        dash = ' stroke-dasharray="5,3"' if ln.dash else ""
        out.append(
            f'<polyline fill="none" stroke="{color}" stroke-width="1.2"{dash} points="{pts}"/>'
        )
        lx = ml + 8 + 150 * k
        out.append(
            f'<line x1="{lx}" y1="{mt + 10}" x2="{lx + 18}" y2="{mt + 10}" stroke="{color}" stroke-width="2"{dash}/>'
        )
        out.append(f'<text x="{lx + 22}" y="{mt + 14}">{escape(ln.label)}</text>')
    out.append("</svg>")
    return "".join(out)


def stack(panels: Sequence[str]) -> str:
    """Panels (SVG texts) one above the other, in a ``<div>`` for HTML."""
    return "<div>" + "<br/>".join(panels) + "</div>"
