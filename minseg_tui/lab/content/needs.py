"""What each derived value of the lab is computed from, and where the group enters it.

One table (:data:`NEEDS`) says which inputs each derived value (k_v of a row, the median
k_v, k_a, f, K, T, J, ...) is computed from; :func:`missing` follows it down to the
readings the group enters (:data:`INPUTS`: R in Task 2, u_ss and omega_ss in Task 4, ...)
and gives those not there yet, so a value that cannot be computed says what it waits for
("needs R (Task 2)") in the table, under F7, beside the group's own values and in the
report (walk 8, D7: with R left out, Tasks 6-9 showed "—" everywhere and never said why).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from minseg_tui.lab.content.keys import USE_RUN, key_name


@dataclass(frozen=True)
class Input:
    """A reading the group enters: its name as the lab writes it, and where it is entered."""

    name: str
    where: str


INPUTS: dict[str, Input] = {
    "R": Input("R", "Task 2"),
    "u_ss": Input("u_ss", "Task 4"),
    "omega_ss": Input("omega_ss", "Task 4"),
    "i_ss": Input("i_ss", "Task 5"),
    "row": Input("a row with u_ss, omega_ss and i_ss", "Tasks 4-5"),
    "run": Input("a step run", "Task 10"),
    "u_ss@steps": Input("u_ss at the steps' voltage", "Task 4"),
    "run.complete": Input(
        "a complete step run",
        f"Task 10; every run recorded was interrupted: {key_name('palette')} '{USE_RUN}' uses "
        "one all the same",
    ),
    "own.omega_step": Input("{whose} omega_ss in the steps", "Task 11"),
    "own.K": Input("{whose} K", "Task 11"),
    "own.T": Input("a T: {whose}, or a 63 % reading of the run", "Task 12"),
}
"""The readings derived values wait for. ``u_ss``, ``omega_ss`` and ``i_ss`` are those of
one row of the table; ``row``: at least one complete row; ``run``: the step run Tasks
11-15 use; ``u_ss@steps``: a u_ss in the table, which the run's requested voltage is mapped
through (the one at the steps' own voltage is used as it is; any other is carried over,
:func:`~minseg_tui.model.identify.steady.u_ss_at`); ``own.*``: the group's own values of Tasks 11-12 that values worked out the
group's way wait for (``{whose}``: "your" on the screen, "the group's" in the report;
``own.T`` is there when the group gave T or the program read T at 63 % of a rise;
``run.complete`` stands for ``run`` when runs were recorded but every one was interrupted,
and none chosen, so that the words are true of the session: not "no run", but what to do)."""

NEEDS: dict[str, tuple[str, ...]] = {
    "k_v@row": ("R", "u_ss", "omega_ss", "i_ss"),
    "k_v": ("R", "row"),
    "k_a": ("k_v",),
    "f": ("k_a", "row"),
    "f@row": ("omega_ss", "i_ss", "k_a"),
    "K": ("run", "u_ss@steps"),
    "T": ("run",),
    "omega_step": ("run",),
    "J": ("T", "R", "k_v", "k_a", "f"),
    "model": ("K", "T"),
    "omega_5": ("K",),
    "K@yours": ("own.omega_step", "run", "u_ss@steps"),
    "J@yours": ("own.T", "R", "k_v", "k_a", "f"),
    "model@yours": ("own.T",),
    "omega_5@yours": ("own.K",),
}
"""Each derived value and what it is computed from: inputs (:data:`INPUTS`) or other derived
values. ``k_v@row``, ``f@row``: a row's own (k_v = (u_ss - R i_ss) / omega_ss, f = k_a i_ss
/ omega_ss); ``k_v``, ``k_a``, ``f``: the final ones (medians over the complete rows); K
(Task 11) from the step run and the u_ss it ran at (neither R nor i_ss: walk 10, D4); T
and omega_ss in the steps (Tasks 11-12) from the run's speed alone (walk 18, D4); J (Task 13) from T and the table's constants, the model
(Task 14) and omega at 5 V (Task 15) from K and T. ``*@yours``: the same worked out the
group's way (K from their omega_ss in the steps, J and the model from their T or the 63 %
reading, omega at 5 V from their K), as Tasks 11-15 compare the group's values."""


def missing(value: str, have: Callable[[str], bool]) -> tuple[str, ...]:
    """The inputs (:data:`INPUTS` keys) derived value ``value`` waits for, first needed first,
    each once: those for which ``have`` is False. () when every input is there (a value still
    not computed then has another reason, which the caller says)."""
    out: list[str] = []

    def walk(name: str) -> None:
        if name in INPUTS:
            if not have(name) and name not in out:
                out.append(name)
            return
        for part in NEEDS[name]:
            walk(part)

    walk(value)
    return tuple(out)


def needs(inputs: Sequence[str], whose: str = "your") -> str:
    """What the missing ``inputs`` are and where to enter them, in words: 'needs R (Task 2)',
    'needs R (Task 2) and i_ss (Task 5)', 'needs your K (Task 11)' (``whose``: how the
    group's own values are named, "your" or "the group's"); '' for none."""
    said = [f"{INPUTS[k].name.format(whose=whose)} ({INPUTS[k].where})" for k in inputs]
    if not said:
        return ""
    if len(said) == 1:
        return f"needs {said[0]}"
    return "needs " + ", ".join(said[:-1]) + " and " + said[-1]


SHORT_WIDTH = 14
"""The most characters :func:`needs_short` writes: two such cells (k_v, f) beside the
table's four readings fit the pane at 80 columns (15 each put a scroll bar under it)."""


def needs_short(inputs: Sequence[str]) -> str:
    """The first of the missing ``inputs`` by name alone, for a narrow cell: 'needs R',
    'needs i_ss…' (the '…': more are missing, F7 gives them all; left out where it would
    make the text wider than :data:`SHORT_WIDTH`: 'needs omega_ss'); '' for none."""
    if not inputs:
        return ""
    first = INPUTS[inputs[0]].name.format(whose="your") if inputs[0] != "row" else "a row"
    said = f"needs {first}"
    return said + "…" if len(inputs) > 1 and len(said) < SHORT_WIDTH else said


__all__ = ["INPUTS", "NEEDS", "SHORT_WIDTH", "Input", "missing", "needs", "needs_short"]
