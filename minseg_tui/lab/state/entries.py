"""What a group typed in each field, as the session keeps it: the :class:`Entry`.

:func:`read_entry` reads text typed in a field (:mod:`minseg_tui.lab.content.steps`) into an
entry, accepted with its SI value or refused with a one-line message; :func:`revise`
decides what is in effect after a new text, keeping the history and never letting a
refused text displace an accepted one. Pure functions: the session stores and saves.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import datetime
from typing import Any

from minseg_tui import quantities
from minseg_tui.errors import InputError
from minseg_tui.lab.content.answers import read_formula
from minseg_tui.lab.content.expr import formula_fault, parse_formula
from minseg_tui.lab.content.model_eq import ModelUnreadable, read_model
from minseg_tui.lab.content.steps import FIELDS, LEVELS, Field
from minseg_tui.quantities import EntryRefused, Parsed, lookup_unit, parse_quantity


@dataclass(frozen=True)
class Entry:
    """What was typed in one field, and what it was read as.

    key: the field's key; text: exactly as typed; ok: accepted; value: SI float for a
    quantity (or a formula without names), tuple of option indices for a choice, None
    otherwise; unit: the unit it was typed in; message: why it was refused, or a note on
    how it was read (``read as 47 mA``); warnings: plausibility warnings; source: ``typed``,
    ``capture`` or ``meter``; at: ISO time; history: earlier (text, at) pairs, oldest first;
    run: for an answer of Tasks 11-15, the run those tasks used when it was given (it is
    judged against the run in use now, which may be another); '' otherwise, or not known (a
    session of an older program); edited: for an entry whose stored value is not what its
    text reads as (session.json changed by hand: :func:`check_stored`), the one line saying
    so and what the file holds; the entry is then not in effect (``ok`` False, no value)
    until the field is typed again; older: for an entry whose stored value is what an older
    minseg-tui read its text as, under a reading rule changed since (:data:`OLDER_READINGS`),
    the one line saying so; the entry stays in effect with that value, as the group saw it
    judged. Neither is saved: the file keeps what it holds. meter: for a
    reading of Tasks 2, 4 and 5 typed on the virtual MinSeg, the values (SI, each once,
    ascending) its multimeter showed for that field while the group was on its step (the
    session's record, :meth:`~minseg_tui.lab.state.session.Session.note_meter`), which the
    reading is judged against; () on a real board, or when the meter had shown nothing yet.

    A refused text never displaces an accepted one: the accepted entry stays in effect and
    carries the refused attempt in ``refused`` (text, message, at) until something is
    accepted again, so neither what was typed last nor what was entered before is lost.
    """

    key: str
    text: str
    ok: bool
    value: float | tuple[int, ...] | None = None
    unit: str = ""
    message: str = ""
    warnings: tuple[str, ...] = ()
    source: str = "typed"
    at: str = ""
    history: tuple[tuple[str, str], ...] = ()
    refused: tuple[str, str, str] | None = None
    run: str = ""
    edited: str = ""
    older: str = ""
    meter: tuple[float, ...] = ()

    @property
    def typed(self) -> str:
        """What the field shows: the refused attempt if there is one, else the text in effect."""
        return self.refused[0] if self.refused else self.text

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict (the session file's form)."""
        out = {
            "text": self.text,
            "ok": self.ok,
            "value": list(self.value) if isinstance(self.value, tuple) else self.value,
            "unit": self.unit,
            "message": self.message,
            "warnings": list(self.warnings),
            "source": self.source,
            "at": self.at,
            "history": [list(h) for h in self.history],
        }
        if self.refused:
            out["refused"] = list(self.refused)
        if self.run:
            out["run"] = self.run
        if self.meter:
            out["meter"] = list(self.meter)
        return out

    @classmethod
    def from_json(cls, key: str, d: Mapping[str, Any]) -> Entry:
        """Inverse of :meth:`to_json`."""
        v = d.get("value")
        value: float | tuple[int, ...] | None = (
            tuple(int(x) for x in v)
            if isinstance(v, list)
            else (float(v) if isinstance(v, int | float) else None)
        )
        return cls(
            key=key,
            text=str(d["text"]),
            ok=bool(d["ok"]),
            value=value,
            unit=str(d.get("unit", "")),
            message=str(d.get("message", "")),
            warnings=tuple(str(w) for w in d.get("warnings", [])),
            source=str(d.get("source", "typed")),
            at=str(d.get("at", "")),
            history=tuple((str(h[0]), str(h[1])) for h in d.get("history", [])),
            refused=(str(d["refused"][0]), str(d["refused"][1]), str(d["refused"][2]))
            if d.get("refused")
            else None,
            run=str(d.get("run", "")),
            meter=tuple(float(x) for x in d.get("meter", [])),
        )


def parse_choice(text: str, n: int) -> tuple[int, ...]:
    """'b', 'B, c', '2', '2 3' -> option indices; ValueError if unreadable."""
    parts = [p for p in re.split(r"[\s,;]+", text.strip()) if p]
    out = []
    for p in parts:
        if len(p) == 1 and p.isalpha():
            k = ord(p.lower()) - ord("a")
        elif p.isdigit():
            k = int(p) - 1
        else:
            raise ValueError(p)
        if not 0 <= k < n:
            raise ValueError(p)
        out.append(k)
    if not out:
        raise ValueError(text)
    return tuple(sorted(set(out)))


def _arithmetic(fld: Field, text: str) -> str | None:
    """``text`` as a number and a unit when it is arithmetic on numbers with, perhaps, a
    unit after it (``0.65*0.49``, ``0.65 * 0.49 N m/A``, ``(5.0 - 5.2*0.03)/6.8``): the
    value written out with the unit, or None when it is no such thing."""
    stripped = text.strip()
    if not re.search(r"[-+*/^×·(]", stripped.lstrip("+-")):
        return None
    for cut in range(len(stripped), 0, -1):
        unit = stripped[cut:].strip()
        if unit and (not re.match(r"[A-Za-zµμΩ°%]", unit) or lookup_unit(unit) is None):
            continue
        try:
            formula = parse_formula(stripped[:cut])
        except InputError:
            continue
        return f"{formula.value({})!r} {unit}".strip()
    return None


def _arithmetic_fault(text: str) -> str | None:
    """What keeps ``text`` from being arithmetic on numbers, when it was meant as such (an
    operator or a parenthesis in it: '(4.05 - 2.05/60 mA' lacks its ')'), in one line
    (:func:`formula_fault`); None when it is no such thing or no fault is found."""
    stripped = text.strip()
    if not re.search(r"[-+*/^×·()]", stripped.lstrip("+-")):
        return None
    unit = re.search(r"\s*[A-Za-zµμΩ°][\w/ ·°]*$", stripped)
    if unit is not None and lookup_unit(unit.group().strip()) is not None:
        stripped = stripped[: unit.start()]
    return formula_fault(stripped)


def read_quantity(fld: Field, text: str) -> Parsed:
    """``text`` typed in the quantity field ``fld``, read by :func:`parse_quantity`; a text
    it refuses that is arithmetic on numbers (Task 8's ``0.65*0.49``), perhaps with a unit
    after it, is worked out and read as its value. EntryRefused (the plain reading's
    one line) when it is neither."""

    def read(t: str) -> Parsed:
        return parse_quantity(
            t,
            fld.unit,
            label=fld.label,
            allow_negative=fld.allow_negative,
            allow_zero=fld.allow_zero,
            within=None
            if fld.meter is None
            else (
                fld.meter.lo,
                fld.meter.hi,
                f"a multimeter {fld.meter.setting} shows, {fld.meter.words}",
            ),
        )

    try:
        return read(text)
    except InputError:
        worked = _arithmetic(fld, text)
        if worked is None:
            fault = _arithmetic_fault(text)
            if fault is None:
                raise
            raise EntryRefused(fld.label, None, fault) from None
    try:
        return read(worked)
    except EntryRefused as exc:  # said of what was typed, not of the worked-out value
        raise EntryRefused(
            exc.source, exc.line, exc.expected.replace(repr(worked), repr(text.strip()), 1)
        ) from None


def _echo(fld: Field, text: str, p: Parsed) -> str:
    """How ``text`` (accepted in the quantity field ``fld`` as ``p``) was read, in the one
    unit its quantity is shown in (:func:`~minseg_tui.quantities.shown_unit`: T in ms, f in
    mN m s/rad), when it is not written as the lab writes it, a number with a decimal point
    and perhaps that unit: a decimal comma, a unit spelt out, arithmetic ('5,3 ohm' is "read
    as 5.3 Ω"); a value typed in another unit says what was typed ('500 rpm' is "read as
    52.36 rad/s (typed 500 rpm)"); '' when it is written the lab's way."""
    shown = quantities.shown_unit(fld.unit)
    t = text.strip()
    plain = r"\+?(?:\d+\.?\d*|\.\d+)"  # the lab's way: no exponent ("1e3" is echoed)
    number = rf"{plain}(?:[eE][-+]?\d+)?"
    bare = re.fullmatch(number, t) is not None
    lab_way = re.fullmatch(plain, t) is not None
    if re.fullmatch(rf"{plain}\s*{re.escape(shown)}", t) or (lab_way and fld.unit == shown):
        return ""
    said = f"read as {quantities.format_reading(p.value, shown, typed=t)}"
    named = p.unit != fld.unit or not bare  # a unit was typed
    if named and p.unit != shown and not re.fullmatch(rf"{number}\s*{re.escape(fld.unit)}", t):
        said += f" (typed {t})"
    return said


def choice_words(fld: Field, chosen: Sequence[int]) -> str:
    """Options ``chosen`` (0-based) of choice field ``fld`` in their own words, quoted, as
    the screen and the report show them: "'the input amplitude' and 'the static gain'"."""
    words = [repr(fld.options[k]) for k in chosen if 0 <= k < len(fld.options)]
    return " and ".join(words) if len(words) < 3 else ", ".join(words[:-1]) + " and " + words[-1]


def _no_choice(fld: Field, text: str) -> str:
    """Why ``text`` names no answer of choice field ``fld``, in the answers' words (the
    letters are only how the session file keeps a choice)."""
    if not text.strip():
        return "no answer ticked" if fld.multiple else "no answer picked"
    return f"{text.strip()!r} names none of the answers: " + ", ".join(map(repr, fld.options))


MAX_TYPED = 200
"""Most characters read in a field that takes a value, a formula or a choice (the lab's
longest answer, Preparation 15's formula, has about 30): a longer text, pasted by mistake,
is refused at once without being read (s39 attack: 10 kB pasted into a formula field took
10 s to refuse, in the screen's thread, or ended in a RecursionError or a MemoryError)."""


def read_entry(fld: Field, text: str) -> Entry:
    """``text`` typed in field ``fld``, read: accepted with its value, unit, note and
    plausibility warnings, or refused with the one-line message (no time, source, history)."""
    if fld.kind != "text" and len(text.strip()) > MAX_TYPED:
        return Entry(
            fld.key,
            text,
            ok=False,
            message=f"{fld.label}: {len(text.strip())} characters, more than any answer here "
            f"(at most {MAX_TYPED}): pasted by mistake? Nothing was read from it",
        )
    if fld.kind == "text":
        if fld.compare == "model" and text.strip():
            # a model that cannot be read as an equation is refused, the text kept to mend
            # (walk 9, D7: 'T=34ms K=1.93' was stored and graded wrong); one that is read
            # but is no first-order model is an answer, judged wrong on Task 14
            try:
                read_model(text)
            except ModelUnreadable as exc:
                return Entry(fld.key, text, ok=False, message=str(exc))
            except InputError:
                pass
        return Entry(fld.key, text, ok=True)
    if not text.strip() and fld.optional:
        return Entry(fld.key, text, ok=True)
    try:
        if fld.kind == "quantity":
            p = read_quantity(fld, text)
            warnings = tuple(w for rule in fld.plausible for w in rule.warnings(p.value))
            return Entry(
                fld.key,
                text,
                ok=True,
                value=p.value,
                unit=p.unit,
                message=_echo(fld, text, p),
                warnings=warnings,
            )
        if fld.kind == "formula":
            f = read_formula(fld, text)
            value = f.value({}) if not fld.names else None
            return Entry(fld.key, text, ok=True, value=value)
        try:
            chosen = parse_choice(text, len(fld.options))
        except ValueError:
            raise InputError(fld.label, None, _no_choice(fld, text)) from None
        if len(chosen) > 1 and not fld.multiple:
            raise InputError(
                fld.label, None, f"pick one answer, not {len(chosen)}: {choice_words(fld, chosen)}"
            )
        return Entry(fld.key, text, ok=True, value=chosen)
    except InputError as exc:
        return Entry(fld.key, text, ok=False, message=str(exc))


def revise(old: Entry | None, read: Entry, source: str, at: str) -> Entry:
    """The entry in effect after ``read`` was typed (at ISO time ``at``) over ``old``.

    A refused text over an accepted entry is kept beside it (``refused``); otherwise the
    new entry takes effect and the old text (and a refused attempt) joins its history.
    """
    if not read.ok and old is not None and old.ok:
        return replace(old, refused=(read.text, read.message, at))
    history = (*old.history, (old.text, old.at)) if old is not None else ()
    if old is not None and old.refused:
        history = (*history, (old.refused[0], old.refused[2]))
    return Entry(
        key=read.key,
        text=read.text,
        ok=read.ok,
        value=read.value,
        unit=read.unit,
        message=read.message,
        warnings=read.warnings,
        source=source,
        at=at,
        history=history,
    )


NOT_AS_READ_WHY = "edited by hand, or saved by an older minseg-tui that read the text otherwise"
"""Why session.json can hold an entry whose value its text does not read as: both causes are
named, since a reading rule changed since that is not one of :data:`OLDER_READINGS` gives the same
disagreement as a hand edit, and every line saying it must be true of either."""

HAND_EDITED = f"session.json holds a value here that its text does not read as ({NOT_AS_READ_WHY})"
"""How :func:`check_stored`'s line begins: an entry this program would not have written."""

NOT_AS_READ = f"an entry whose value in session.json its text does not read as ({NOT_AS_READ_WHY})"
"""Such an entry named in a list (the class view's legend of what it marks '!'), in the same
words as :data:`HAND_EDITED`."""


@dataclass(frozen=True)
class OlderReading:
    """A reading rule an older minseg-tui had for the fields ``keys``, changed by ``commit``
    (committed at ``until``, ISO): ``read`` gives what that program read a text as (SI; None
    where the rule does not decide), ``how`` says the rule in words."""

    keys: tuple[str, ...]
    commit: str
    until: str
    how: str
    read: Callable[[Field, str], float | None]


def _bare_in(unit: str) -> Callable[[Field, str], float | None]:
    """A bare number (a decimal point or comma, an exponent) read in ``unit``."""

    def read(fld: Field, text: str) -> float | None:
        t = text.strip().replace(",", ".", 1)
        if quantities.NUMBER.match(t) is None:
            return None
        return float(t) * quantities.UNITS[unit].scale

    return read


def _without_range(fld: Field, text: str) -> float | None:
    """The text read as now, without the range of what a multimeter shows."""
    try:
        return parse_quantity(
            text,
            fld.unit,
            allow_negative=fld.allow_negative,
            allow_zero=fld.allow_zero,
        ).value
    except InputError:
        return None


OLDER_READINGS: tuple[OlderReading, ...] = (
    OlderReading(
        ("own.f",),
        "840d117",
        "2026-11-27T02:04:36+00:00",
        "a bare number was read in mN m s/rad, the field's unit",
        _bare_in("mN m s/rad"),
    ),
    OlderReading(
        ("own.T",),
        "0c668f1",
        "2026-11-27T17:30:34+00:00",
        "a bare number was read in s, the field's unit then",
        _bare_in("s"),
    ),
    OlderReading(
        ("R", *(f"{q}@{lv:g}" for q in ("u_ss", "i_ss") for lv in LEVELS)),
        "b092299",
        "2026-11-28T21:02:52+00:00",
        "a reading outside what a multimeter shows was taken, with a warning",
        _without_range,
    ),
)
"""The reading rules changed since a session could have been saved, by which a stored value
that disagrees with its text now is told from a hand edit: an older minseg-tui read
own.f typed bare as "0.00186" as 0.00186 mN m s/rad (it asks which unit now), own.T typed
bare as "0.057" as 0.057 s (it asks now: T is in ms), and an R of 1e9 Ω as 1e9 Ω (refused
now: no multimeter shows it). An instructor grading such a session sees what the group saw
judged, said as such."""


def _older(fld: Field, e: Entry, again: Entry) -> str:
    """The line saying that ``e``'s stored value is what an older program read its text as
    (``again``: how it reads now), or '' when no older rule gives that value at that time."""
    if not isinstance(e.value, float):
        return ""
    try:
        at = datetime.fromisoformat(e.at)
    except ValueError:
        return ""
    for rule in OLDER_READINGS:
        if e.key not in rule.keys or at.tzinfo is None:
            continue
        until = datetime.fromisoformat(rule.until)
        if at >= until:
            continue
        then = rule.read(fld, e.text)
        if then is None or not _agree(then, e.value):
            continue
        if again.ok:
            now = f"this one reads it as {_held(fld, again.value)}"
        else:
            now = f"this one refuses it ({again.message.removeprefix(f'{fld.label}: ')})"
        return (
            f"read by an older minseg-tui (before {until:%d %b %Y %H:%M} UTC) as {_held(fld, e.value)}: "
            f"{rule.how}, where {now}; kept as it was read then, until the field is typed again"
        )
    return ""


NOT_JUDGED_UNTIL_TYPED = "it counts for nothing until the field is typed again"
"""How :func:`check_stored`'s line ends: what becomes of the entry."""


def _held(fld: Field, value: float | tuple[int, ...] | None) -> str:
    """A stored value as the line of :func:`check_stored` says it: a quantity in the unit
    it is shown in, with every digit the file holds; a choice in its answers' words."""
    if value is None:
        return "no value"
    if isinstance(value, tuple):
        return choice_words(fld, value) or repr(list(value))
    if fld.kind == "quantity" and math.isfinite(value):
        return quantities.format_reading(value, quantities.shown_unit(fld.unit), digits=12)
    return repr(value)


def _agree(a: float | tuple[int, ...] | None, b: float | tuple[int, ...] | None) -> bool:
    """Whether a stored value and the one its text reads as are the same (floats to a
    relative 1e-9: rounding, not a change)."""
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=0.0)
    return a == b


def check_stored(e: Entry) -> Entry:
    """``e`` as a session file holds it, its text read again by :func:`read_entry` (the
    reading the field gives what is typed in it): the same entry when its stored value is
    what the text reads as (or it was refused, or it is a text answer, or of no field
    here); the entry marked :attr:`Entry.older`, in effect with its value, when that value
    is what an older minseg-tui read the text as (:data:`OLDER_READINGS`, typed before the
    rule changed); else the entry marked :attr:`Entry.edited` with one line saying what the
    file holds, out of effect (``ok`` False, no value), so that nothing judges or computes
    with a value the group never typed. The text, the history and the time are kept."""
    fld = FIELDS.get(e.key)
    if fld is None or not e.ok or fld.kind == "text":
        return e
    again = read_entry(fld, e.text)
    if again.ok and _agree(again.value, e.value):
        return e
    older = _older(fld, e, again)
    if older:
        return replace(e, older=older)
    text = e.text.strip()
    if again.ok:
        reads = f"{text!r} reads as {_held(fld, again.value)}"
    else:
        reads = f"{text!r} does not read as a value ({again.message})"
    line = (
        f"{HAND_EDITED}: it holds the text {text!r} with the value {_held(fld, e.value)}, "
        f"but {reads}; {NOT_JUDGED_UNTIL_TYPED}"
    )
    return replace(e, ok=False, value=None, message=line, refused=None, edited=line)


def parsed_values(entries: Mapping[str, Entry]) -> dict[str, object]:
    """Accepted values by key, as checks use them (floats, Formulas, option tuples)."""
    out: dict[str, object] = {}
    for key, e in entries.items():
        if not e.ok or key not in FIELDS:
            continue
        fld = FIELDS[key]
        if fld.kind == "formula":
            try:
                out[key] = read_formula(fld, e.text)
            except InputError:
                continue
        elif e.value is not None:
            out[key] = e.value
    return out


__all__ = [
    "HAND_EDITED",
    "MAX_TYPED",
    "NOT_AS_READ",
    "NOT_AS_READ_WHY",
    "OLDER_READINGS",
    "Entry",
    "OlderReading",
    "check_stored",
    "parse_choice",
    "parsed_values",
    "read_entry",
    "read_quantity",
    "revise",
]
