"""The one schema of session.json (and of a run's partial-file header), as data.

A schema is built from a few small node types (:class:`Text`, :class:`Number`,
:class:`Flag`, :class:`ListOf`, :class:`Pair`, :class:`MapOf`, :class:`Record`,
:class:`OneOf`, :class:`Exactly`); :func:`problem` says where and why a value breaks it
(``entries.R.history: expected a list, got 5``), or None. The check descends only as
deep as the schema, so no file, however deeply nested, can exhaust the stack here.

:data:`SESSION` is session.json as :class:`~minseg_tui.lab.state.session.Session` writes it;
:func:`salvage` keeps what is sound in a damaged one for a read-only look.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from minseg_tui.lab.content.steps import FIELDS, STEP_INDEX, STEPS

SCHEMA: int = 1
"""Version of session.json's layout; a file with another version is refused."""

KIND: str = "minseg-tui session"
"""The ``kind`` every session file carries."""


def _show(value: object) -> str:
    if isinstance(value, int) and value.bit_length() > 64:
        return f"a whole number of {_digits(value)} digits"
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _digits(value: int) -> int:
    """How many decimal digits ``value`` has, without writing it out (Python refuses to
    write out more than 4300)."""
    return max(1, int(abs(value).bit_length() * math.log10(2)) + 1)


COUNT_MAX = 2**53
"""The largest whole number a count in a session file may hold (beyond it a float can no
longer hold every count: no run, sample or capture comes near)."""


class Node:
    """A part of a schema: :meth:`check` says why ``value`` (at ``where``) breaks it."""

    def check(self, value: object, where: str) -> str | None:  # pragma: no cover - abstract
        raise NotImplementedError

    def default(self) -> object:
        """What stands in for a broken value when a damaged file is salvaged."""
        return None


@dataclass(frozen=True)
class Text(Node):
    """A string; ``pattern``: a regular expression it must match whole."""

    pattern: str = ""

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, str):
            return f"{where}: expected text, got {_show(value)}"
        if self.pattern and not re.fullmatch(self.pattern, value):
            return f"{where}: {_show(value)} is not of the form {self.pattern}"
        return None

    def default(self) -> object:
        return ""


@dataclass(frozen=True)
class Number(Node):
    """A finite JSON number (not true/false); ``integer``: a whole one; ``low``: the least
    value; ``positive``: above zero."""

    integer: bool = False
    low: float | None = None
    positive: bool = False

    def check(self, value: object, where: str) -> str | None:
        ok = isinstance(value, int) if self.integer else isinstance(value, int | float)
        if not ok or isinstance(value, bool):
            what = "a whole number" if self.integer else "a number"
            return f"{where}: expected {what}, got {_show(value)}"
        assert isinstance(value, int | float)
        if isinstance(value, int):
            # a long whole number is no float: math.isfinite would raise OverflowError
            top = COUNT_MAX if self.integer else sys.float_info.max
            if abs(value) > top:
                return f"{where}: expected a number below {top:.4g}, got {_show(value)}"
        elif not math.isfinite(value):
            return f"{where}: expected a finite number, got {_show(value)}"
        if self.low is not None and value < self.low:
            return f"{where}: expected at least {self.low:g}, got {value!r}"
        if self.positive and value <= 0:
            return f"{where}: expected a number above 0, got {value!r}"
        return None

    def default(self) -> object:
        return 0


@dataclass(frozen=True)
class Flag(Node):
    """true or false."""

    def check(self, value: object, where: str) -> str | None:
        return (
            None
            if isinstance(value, bool)
            else f"{where}: expected true or false, got {_show(value)}"
        )

    def default(self) -> object:
        return False


@dataclass(frozen=True)
class Exactly(Node):
    """This very value."""

    value: object

    def check(self, value: object, where: str) -> str | None:
        return (
            None if value == self.value else f"{where}: expected {self.value!r}, got {_show(value)}"
        )


@dataclass(frozen=True)
class ListOf(Node):
    """A list whose every item is ``item``."""

    item: Node

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, list):
            return f"{where}: expected a list, got {_show(value)}"
        for k, v in enumerate(value):
            why = self.item.check(v, f"{where}[{k}]")
            if why:
                return why
        return None

    def default(self) -> object:
        return []


@dataclass(frozen=True)
class Pair(Node):
    """A list of exactly these items, in this order (JSON has no tuples)."""

    items: tuple[Node, ...]

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, list) or len(value) != len(self.items):
            return f"{where}: expected a list of {len(self.items)}, got {_show(value)}"
        for k, (node, v) in enumerate(zip(self.items, value, strict=True)):
            why = node.check(v, f"{where}[{k}]")
            if why:
                return why
        return None


@dataclass(frozen=True)
class MapOf(Node):
    """An object whose every value is ``item`` (keys are free text)."""

    item: Node

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, dict):
            return f"{where}: expected an object, got {_show(value)}"
        for k, v in value.items():
            why = self.check_item(k, v, f"{where}.{k}" if where else str(k))
            if why:
                return why
        return None

    def check_item(self, key: str, value: object, where: str) -> str | None:
        """Why the value under ``key`` breaks the schema, or None."""
        return self.item.check(value, where)

    def default(self) -> object:
        return {}


@dataclass(frozen=True)
class EntryMap(MapOf):
    """The entries: each an :data:`ENTRY` whose value is of its field's kind (a number
    for a quantity or a formula, option indices for a choice, none for text). A key of no
    field here (a newer program's) is checked as an entry only."""

    def check_item(self, key: str, value: object, where: str) -> str | None:
        why = self.item.check(value, where)
        if why or not isinstance(value, dict) or value.get("value") is None:
            return why
        fld = FIELDS.get(key)
        if fld is None:
            return None
        v, at = value["value"], f"{where}.value"
        if fld.kind == "text":
            return f"{at}: expected no value (a text field), got {_show(v)}"
        if fld.kind == "choice":
            if not isinstance(v, list) or not v:
                return f"{at}: expected the chosen options (a list), got {_show(v)}"
            if any(k >= len(fld.options) for k in v):
                return f"{at}: expected options below {len(fld.options)}, got {_show(v)}"
            if len(v) > 1 and not fld.multiple:
                return f"{at}: expected one option (one answer), got {_show(v)}"
            return None
        if not isinstance(v, int | float) or isinstance(v, bool):
            return f"{at}: expected a number (a {fld.kind} field), got {_show(v)}"
        return None


@dataclass(frozen=True)
class StepName(Node):
    """The id of one of the lab's steps (:data:`minseg_tui.lab.content.steps.STEPS`)."""

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, str):
            return f"{where}: expected text, got {_show(value)}"
        if value not in STEP_INDEX:
            return f"{where}: names an unknown step {_show(value)}"
        return None

    def default(self) -> object:
        return STEPS[0].id


@dataclass(frozen=True)
class OneOf(Node):
    """Any of ``options`` (``None`` in them: JSON null)."""

    options: tuple[Node | None, ...]

    def check(self, value: object, where: str) -> str | None:
        if value is None and None in self.options:
            return None
        nodes = [n for n in self.options if n is not None]
        whys = [n.check(value, where) for n in nodes]
        if not all(whys):
            return None
        if isinstance(value, int | float) and not isinstance(value, bool):
            # a number that breaks the Number option: say why (too long, not finite)
            for n, why in zip(nodes, whys, strict=True):
                if isinstance(n, Number):
                    return why
        if all(whys):
            return whys[0] if len(whys) == 1 else f"{where}: unexpected {_show(value)}"
        return None


@dataclass(frozen=True)
class Memo(Node):
    """Anything: a part the program only keeps as a memo and reads itself, passing over
    what it cannot read (:mod:`minseg_tui.lab.saving.kept`); never a reason to refuse a file."""

    def check(self, value: object, where: str) -> str | None:
        return None


Rule = Callable[[Mapping[str, Any], str], str | None]


@dataclass(frozen=True)
class Record(Node):
    """An object with ``required`` and ``optional`` fields (others are allowed: a newer
    program may add fields) and ``rules`` across fields."""

    required: Mapping[str, Node]
    optional: Mapping[str, Node] = field(default_factory=dict)
    rules: tuple[Rule, ...] = ()

    def check(self, value: object, where: str) -> str | None:
        if not isinstance(value, dict):
            return f"{where}: expected an object, got {_show(value)}"
        for name, node in self.required.items():
            at = f"{where}.{name}" if where else name
            if name not in value:
                return f"{at}: missing"
            why = node.check(value[name], at)
            if why:
                return why
        for name, node in self.optional.items():
            if name in value:
                why = node.check(value[name], f"{where}.{name}" if where else name)
                if why:
                    return why
        for rule in self.rules:
            why = rule(value, where)
            if why:
                return why
        return None


def problem(value: object, node: Node) -> str | None:
    """Where and why ``value`` breaks ``node``, in one line; None when it does not."""
    return node.check(value, "")


# -- the session file ----------------------------------------------------------------------------


def _run_file(run: Mapping[str, Any], where: str) -> str | None:
    want = f"runs/{run['name']}.csv"
    if run["file"] != want:
        return f"{where}.file: expected {want!r} (a run's log stays in runs/), got {_show(run['file'])}"
    return None


RUN_NAME = r"[A-Za-z0-9][A-Za-z0-9_-]{0,63}"
"""What a run's name may be: it names files in runs/."""

ENTRY = Record(
    required={"text": Text(), "ok": Flag()},
    optional={
        "value": OneOf((None, Number(), ListOf(Number(integer=True, low=0)))),
        "unit": Text(),
        "message": Text(),
        "warnings": ListOf(Text()),
        "source": Text(),
        "at": Text(),
        "history": ListOf(Pair((Text(), Text()))),
        "refused": OneOf((None, Pair((Text(), Text(), Text())))),
        "run": Text(),
        "meter": ListOf(Number()),
    },
)
"""One entry (:meth:`minseg_tui.lab.state.entries.Entry.to_json`)."""

CAPTURE = Record(
    required={
        "omega_ss": Number(),
        "spread": Number(low=0),
        "t0": Number(),
        "t1": Number(),
        "n": Number(integer=True, low=0),
    },
    optional={"velocity": Text()},
)
"""One steady-state capture (:meth:`minseg_tui.lab.state.capture.Capture.to_json`)."""

PLAN = MapOf(Number())
"""A run's step plan: low, high, half_period, periods, ts."""

RUN = Record(
    required={"name": Text(RUN_NAME), "file": Text()},
    optional={
        "kind": Text(),
        "ts": Number(positive=True),
        "samples": Number(integer=True, low=0),
        "dropped": Number(integer=True, low=0),
        "started": Text(),
        "interrupted": Flag(),
        "plan": PLAN,
        "ended_by": Text(),
        "sha256": Text("[0-9a-f]{64}"),
    },
    rules=(_run_file,),
)
"""One recorded run (:meth:`minseg_tui.lab.saving.runs.RunInfo.to_json`)."""

BOARD_CHECK = Record(
    required={"ok": Flag(), "text": Text(), "at": Text()},
    optional={"counts": Number(integer=True)},
)
"""One board check's result (:meth:`minseg_tui.lab.state.session.Session.record_check`)."""

SHOWN = Record(
    required={"at": Text(), "by": Text()},
    optional={"answer": OneOf((None, Text()))},
)
"""The first showing of one computed value (:class:`minseg_tui.lab.state.shown.Shown`)."""

POLICY = Record(
    required={"at": Text(), "answers_first": Flag()},
    optional={"problem": Text(), "file": Flag()},
)
"""The lab's policy as recorded (:class:`minseg_tui.lab.state.shown.PolicyRecord`)."""

SESSION = Record(
    required={
        "kind": Exactly(KIND),
        "schema": Exactly(SCHEMA),
        "id": Text(),
        "members": ListOf(Text()),
        "date": Text(),
        "created": Text(),
        "modified": Text(),
        "current_step": StepName(),
        "entries": EntryMap(ENTRY),
        "captures": MapOf(CAPTURE),
        "runs": ListOf(RUN),
    },
    optional={
        "selected_run": OneOf((None, Text())),
        "check_run": OneOf((None, Text())),
        "revealed": ListOf(Text()),
        "kept": Memo(),
        "board_checks": MapOf(BOARD_CHECK),
        "shown": MapOf(SHOWN),
        "shown_since": Text(),
        "policy": ListOf(POLICY),
        "former_members": ListOf(Text()),
    },
)
"""session.json, whole (``revealed``: fields of Tasks 11-15 shown before the group
answered them; ``kept``: the run's results as last computed, which
:mod:`minseg_tui.lab.saving.kept` reads, and passes over when it cannot: a memo, never a
reason to refuse the file; ``board_checks``: the newest result of each board check, by key
of :data:`minseg_tui.lab.content.steps.BOARD_CHECKS`; ``shown``: the first time each computed
value of Tasks 11-15 was on the group's screen, recorded since ``shown_since``; ``policy``: the
lab's policy when the session was opened and whenever it changed; ``former_members``: the
names the group had before each correction, joined by ', '). Optional parts added since keep the
schema at 1: a file without them reads as before, and an older program ignores them."""

PARTIAL_HEADER = Record(
    required={},
    optional={
        "name": Text(),
        "kind": Text(),
        "ts": Number(positive=True),
        "started": Text(),
        "plan": PLAN,
    },
)
"""The header line of a run's partial file (:func:`minseg_tui.lab.saving.runs.run_header`)."""


def salvage(data: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
    """What is sound in a session file that breaks :data:`SESSION` (its kind and schema
    already right), for a read-only look, and a line for each part left out: a broken
    field takes its empty value; a broken entry, capture or run is left out."""
    out = dict(data)
    lost: list[str] = []
    for name, node in {**SESSION.required, **SESSION.optional}.items():
        value = data.get(name)
        if isinstance(node, MapOf) and isinstance(value, dict):
            keep = {}
            for k, v in value.items():
                why = node.check_item(k, v, f"{name}.{k}")
                if why:
                    lost.append(why)
                else:
                    keep[k] = v
            out[name] = keep
        elif isinstance(node, ListOf) and isinstance(value, list) and name == "runs":
            keep_runs = []
            for k, v in enumerate(value):
                why = node.item.check(v, f"{name}[{k}]")
                if why:
                    lost.append(why)
                else:
                    keep_runs.append(v)
            out[name] = keep_runs
        elif name in SESSION.required or name in data:
            why = node.check(value, name) if name in data else f"{name}: missing"
            if why:
                lost.append(why)
                out[name] = node.default()
    return out, lost


__all__ = [
    "BOARD_CHECK",
    "CAPTURE",
    "ENTRY",
    "KIND",
    "PARTIAL_HEADER",
    "POLICY",
    "RUN",
    "SCHEMA",
    "SESSION",
    "SHOWN",
    "problem",
    "salvage",
]
