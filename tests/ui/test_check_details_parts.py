"""Issue 20, what stop 36 left (item 4 of /work/coord/B37-fix.md): the model check's Details
at 80x24. Its paragraphs ran together, one line under the other, and two causes were still
named as the specialist names them: "averaged speed (velocity filter)" and "coasting at
zero command" (with "the bridge lets the wheel coast … at zero command" in the evidence).
Each part is set apart by a blank line now, and the causes are said in everyday words
("averaged speed reading", "coasting at 0 V"); the CLI keeps its words."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from textual.widgets import Collapsible

from minseg_tui.lab.state.session import Session
from minseg_tui.model.synth import make_log
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import TABLE, goto, resume, settle

SPECIALIST = ("velocity filter", "zero command", "the bridge", "_")
"""What a second-year student should not meet in the Details (a contract name has '_'; a
parameter's symbol, T_coast, is the lab's notation: left out of the text searched)."""


def _coasting_log(path: Path) -> None:
    """The generator's log of a driver that lets the wheel coast at 0 V (seed 3), the check's
    next best explanation an averaged speed: both causes the words were about."""
    log = make_log("coast_on_zero", seed=3)
    rows = "\n".join(
        f"{t:.6f},{u:.4f},{w:.6f}" for t, u, w in zip(log.t, log.u, log.omega, strict=True)
    )
    path.write_text(f"# ts: {log.ts}\nt,u,omega\n{rows}\n", encoding="utf-8")


async def test_the_details_set_their_parts_apart_and_name_causes_in_everyday_words(quiet, tmp_path):
    """The model check of a coasting log at 80x24, Details opened: a blank line between its
    parts (the cause, each paragraph, each list with its heading), and no specialist's
    name of a cause in it."""
    _coasting_log(tmp_path / "coast.csv")
    with Session.create(tmp_path / "sessions", ["Ada", "Bo"], date="2024-04-16") as s:
        for key, text in TABLE.items():
            s.enter(key, text)
        info = s.import_run(tmp_path / "coast.csv")
        s.select_run(info.name)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        await goto(pilot, "model_check", focus=None)
        lines = app.screen.query_one("#check-lines", Prose)
        await settle(pilot, lambda: "cause:" in lines.text)
        fold = app.screen.query_one("#check-details", Collapsible)
        fold.collapsed = False
        await settle(pilot, lambda: lines.region.height > 0)
        text = lines.text
        parts = text.split("\n\n")
        assert parts[0] == "cause: coasting at 0 V", parts[0]
        assert len(parts) >= 6, parts  # the cause, the log, the simple model, the figure
        # that leads, the evidence, the extended model, ...: each a part of its own
        assert all(p.strip() and p == p.strip("\n") for p in parts), parts
        for part in parts[1:]:  # a paragraph is one line of text, a list its heading first
            assert "\n" not in part or part.split("\n")[1].startswith("- "), part
        assert "Why coasting at 0 V, over the whole run:" in text
        assert "The next best explanation, averaged speed reading," in text
        searched = text.replace("T_coast", "T coast")
        assert not [w for w in SPECIALIST if w in searched], searched
        # the lines as drawn at 80 columns: a blank one between two parts
        drawn = [s.text.strip() for s in lines.render_lines(lines.region.reset_offset)]
        assert drawn[1] == "", drawn[:3]
        assert np.count_nonzero([not line for line in drawn]) >= len(parts) - 1
