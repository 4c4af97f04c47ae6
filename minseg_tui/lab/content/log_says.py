"""A run log's refusals in words, made from the model's records (:mod:`minseg_tui.model.
runlog`): the one place the reader of a log file (lab/saving/files.py) takes them from.

It sits in lab/content/, the lowest of lab/'s folders, beside identify_says.py and
u_ss_says.py, because the saving quotes it.
"""

from __future__ import annotations

from minseg_tui.model.runlog import MAX_CPR, BadHeader


def header_words(bad: BadHeader) -> str:
    """Why a header line ``# key: value`` cannot be taken, as the 'expected ...' part of an
    InputError: "expected # omega_over: interval or nominal, got 'sometimes'"."""
    if bad.key == "cpr":
        return (
            f"expected # cpr: a whole number of counts per revolution above 0 and at most "
            f"{MAX_CPR} (the MinSeg's encoder has 720), got '{bad.value}'"
        )
    return f"expected # omega_over: interval or nominal, got '{bad.value}'"


__all__ = ["header_words"]
