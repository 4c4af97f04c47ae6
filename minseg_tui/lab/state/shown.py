"""What the session records of what the group was shown, and of the lab's policy, as facts.

The report says when the group saw a computed value of Tasks 11-15 against when it entered its
own; it can say only what was recorded while the group worked. :class:`Shown` is the first time
a computed value was put on the group's screen (by whom or what, and the group's answer then, if
any); :class:`PolicyRecord` is the instructor's policy (``lab.toml``) as it stood when the
session was opened or when it changed. The session keeps both in session.json (``shown``,
``shown_since``, ``policy``), saved the moment they happen; a session begun with an older
program has neither, and the report says that it does not know. Plain data, no I/O.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

AFTER_ANSWER = "answer"
"""Shown by Tasks 11-15 once the group had entered its own value."""
REVEAL = "reveal"
"""Shown by a lab assistant's reveal (Ctrl+R)."""
POLICY = "policy"
"""Shown at once by the lab's policy (``answers_first = false``)."""
MODEL_CHECK = "model_check"
"""Shown by the model check, whose first-order model gives T and K (and so the model)."""

BY: tuple[str, ...] = (AFTER_ANSWER, REVEAL, POLICY, MODEL_CHECK)
"""Every way a computed value reaches the group's screen."""

MODEL_CHECK_SHOWS: tuple[str, ...] = ("own.K", "own.T", "own.model")
"""The values of Tasks 11-15 the model check puts on the screen: it writes the first-order
model it fitted, with its T and K."""


@dataclass(frozen=True)
class Shown:
    """The first time the computed value of one field was on the group's screen: ``at`` (ISO
    time), ``by`` (one of :data:`BY`) and ``answer``, the group's accepted text in the field at
    that moment (None: not answered yet, so the value was revealed before answering)."""

    at: str
    by: str
    answer: str | None = None

    def to_json(self) -> dict[str, Any]:
        """The session file's form."""
        return {"at": self.at, "by": self.by, "answer": self.answer}

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> Shown:
        """Inverse of :meth:`to_json`."""
        answer = d.get("answer")
        return cls(str(d["at"]), str(d["by"]), None if answer is None else str(answer))


@dataclass(frozen=True)
class PolicyRecord:
    """The lab's policy as it stood from ``at`` (ISO time): ``answers_first``, and ``problem``,
    one line when the file could not be read (the default then held); ``file``: whether a
    ``lab.toml`` was there at all."""

    at: str
    answers_first: bool
    problem: str = ""
    file: bool = True

    def same_rule(self, other: PolicyRecord) -> bool:
        """The same policy (the time aside)."""
        return (self.answers_first, self.problem, self.file) == (
            other.answers_first,
            other.problem,
            other.file,
        )

    def to_json(self) -> dict[str, Any]:
        """The session file's form."""
        return {
            "at": self.at,
            "answers_first": self.answers_first,
            "problem": self.problem,
            "file": self.file,
        }

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> PolicyRecord:
        """Inverse of :meth:`to_json`."""
        return cls(
            str(d["at"]),
            bool(d["answers_first"]),
            str(d.get("problem", "")),
            bool(d.get("file", True)),
        )


__all__ = [
    "AFTER_ANSWER",
    "BY",
    "MODEL_CHECK",
    "MODEL_CHECK_SHOWS",
    "POLICY",
    "REVEAL",
    "PolicyRecord",
    "Shown",
]
