"""Seeded groups for the class view tests: real session folders written with the Session API."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from minseg_tui.lab.state.session import Session
from tests.seeded import Clock, record_square_wave

LEVELS = (2.5, 3.5, 4.5)


def group(
    root: Path,
    members: list[str],
    seed: int,
    *,
    R: str | None = None,
    rows: dict[float, tuple[str, str, str]] | None = None,
    run: bool = True,
    own_T: str | None = None,
    at: str = "task12",
) -> Path:
    """A group's session under ``root``: R, the table (u_ss, omega_ss, i_ss as typed, per
    level; defaults scattered by ``seed`` around the lab's motor), a recorded step run from
    the simulated motor (seeded), and the step the group is at. Returns the folder."""
    rng = np.random.default_rng(seed)
    s = Session.create(root, members, date="2026-11-22", clock=Clock())
    s.enter("R", R if R is not None else f"{5.2 + 0.1 * rng.standard_normal():.2f} Ω")
    for lv in LEVELS:
        if rows is not None and lv in rows:
            u, w, i = rows[lv]
        else:
            u_ss = lv - 0.45 + 0.02 * rng.standard_normal()
            w_ss = 1.99 * u_ss - 0.3 + 0.05 * rng.standard_normal()
            i = 26.0 + 2.5 * lv + 0.5 * rng.standard_normal()
            u, w, i = f"{u_ss:.3f}", f"{w_ss:.3f}", f"{i:.1f} mA"
        if u:
            s.enter(f"u_ss@{lv:g}", u)
        if w:
            s.enter(f"omega_ss@{lv:g}", w)
        if i:
            s.enter(f"i_ss@{lv:g}", i)
    if own_T is not None:
        s.enter("own.T", own_T)
    if run:
        record_square_wave(s, seed=seed)
    s.go_to(at)
    s.close()
    return s.folder
