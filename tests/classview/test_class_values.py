"""The numbers of a row that are computable are shown, whatever else the session lacks."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.views.classview import QUANTITIES, judge, read_group
from minseg_tui.quantities import MISSING
from minseg_tui.report.class_content import table

from .build import LEVELS, group


def _table_without_currents(seed: int) -> dict[float, tuple[str, str, str]]:
    return {lv: (f"{lv - 0.45:.3f}", f"{1.99 * (lv - 0.45) - 0.3:.3f}", "") for lv in LEVELS}


def test_K_and_T_are_shown_when_only_i_ss_is_missing(tmp_path: Path) -> None:
    rows = _table_without_currents(3)
    complete = {lv: (u, w, "30.0 mA") for lv, (u, w, _) in rows.items()}
    full = read_group(group(tmp_path / "a", ["Full"], seed=3, rows=complete))
    bare = read_group(group(tmp_path / "b", ["No", "Amps"], seed=3, rows=rows))
    assert any("i_ss" in x for x in bare.lacks)  # it still says what it lacks
    for key in ("K", "T", "T_63"):  # they need neither i_ss nor R: the same numbers
        v = bare.value(key)
        assert v is not None and v == full.value(key), key
    assert bare.value("J") is None and bare.value("k_v") is None  # these need i_ss
    cells = dict(zip(table(judge([bare])).header, table(judge([bare])).rows[0], strict=True))
    labels = {q.key: q.shown_label for q in QUANTITIES}
    assert cells[labels["K"]] != MISSING and cells[labels["T"]] != MISSING
    assert cells[labels["J"]] == MISSING
