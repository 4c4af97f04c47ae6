"""How u_ss was found, in words: the one place every screen, file, report and the CLI take
them from (issue 19 item 3), made from the model's codes (:data:`~minseg_tui.model.identify.
steady.UssHow`), and identify's refusal of a rise that ends at 0 V on the motor, which quotes
them.

It sits beside identify_says.py in lab/content/, the lowest of lab/'s folders: the saving
(a recorded run's metadata) quotes it, as the views, the report and the CLI do.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import MappingProxyType
from typing import Final

from minseg_tui.errors import InputError
from minseg_tui.model.identify import UssHow, ZeroVoltRefusal

U_SS_SAYS: Final[Mapping[UssHow, tuple[str, str]]] = MappingProxyType(
    {
        "off": ("the driver is off at 0 V", ""),
        "extrapolated": (
            "extrapolated from the table",
            "no table row at {levels}, the nearest row's driver drop",
        ),
        "requested": ("as requested", "the table has no u_ss yet"),
        "interpolated": ("interpolated between the table's rows", "no row at {levels}"),
        "row": ("the table's row", ""),
        "log": ("the log's applied voltage", "it has no u_req column"),
    }
)
"""Each way u_ss is found (:data:`~minseg_tui.model.identify.U_SS_HOW`) as the words every
screen, file and report uses, and the detail a report adds ({levels}: the levels), in the
model's order (a test checks that each has its words)."""

BELOW_THE_DROP: Final = "below the driver's drop in the table"
"""Why an extrapolated u_ss is 0 V: the step's level is below the nearest row's drop."""


def u_ss_words(how: UssHow, levels: Sequence[float] | None = None) -> str:
    """How u_ss was found in words: "extrapolated from the table"; given the ``levels`` (V)
    the steps requested (empty when the log has no u_req), its detail too: "extrapolated
    from the table: no table row at 4.5 V, the nearest row's driver drop"."""
    short, detail = U_SS_SAYS[how]
    if levels is None or not detail:
        return short
    at = " and ".join(f"{v:g} V" for v in sorted(set(levels))) or "that level"
    return f"{short}: {detail.format(levels=at)}"


def zero_volt_refusal(refused: ZeroVoltRefusal) -> InputError:
    """identify's refusal of a rise that ends at 0 V on the motor, as the one-line
    InputError the CLI, the session and the report show: where, which edge, and why its
    u_ss is 0 V."""
    rise = refused.rise
    why = BELOW_THE_DROP if rise.how == "extrapolated" else u_ss_words(rise.how)
    at = "" if rise.u_req is None else f"u_req = {rise.u_req:g} V, "
    return InputError(
        refused.source,
        refused.line,
        f"expected each rising edge to put a voltage on the motor; the edge at "
        f"t = {rise.t:.4g} s ends at {at}0 V on the motor ({why}), so K = "
        "omega_ss / u_ss cannot be computed: record steps that end above the driver's "
        "drop (steps that only go negative end at 0 V)",
    )


__all__ = ["BELOW_THE_DROP", "U_SS_SAYS", "u_ss_words", "zero_volt_refusal"]
