"""The layer contract: model < signals < device < lab < ui|report < cli; no Textual below the UI."""

import ast
import subprocess
import sys
from pathlib import Path

from tests.prose import prose

ROOT = Path(__file__).resolve().parents[1]


def test_import_contracts_are_kept():
    lint = Path(sys.executable).with_name("lint-imports")
    out = subprocess.run([str(lint)], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "3 kept, 0 broken" in out.stdout  # the layers, lab/'s folders, Textual


def test_core_imports_without_textual():
    code = (
        "import sys, importlib, pkgutil, minseg_tui\n"
        "for m in pkgutil.walk_packages(minseg_tui.__path__, 'minseg_tui.'):\n"
        "    if m.name.split('.')[1] in ('ui', 'cli', '__main__'):\n"
        "        continue\n"
        "    importlib.import_module(m.name)\n"
        "assert not any(k == 'textual' or k.startswith('textual.') for k in sys.modules), 'textual imported'\n"
        "print('ok')\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120
    )
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr


def test_the_model_check_holds_no_words():
    """Issue 19 item 4: the check gives typed records and its words are made outside the
    model (lab/views/check_says.py, CONTRIBUTING's recipe for a cause)."""
    found = [
        f"{p.relative_to(ROOT)}:{line}: {text}"
        for p in sorted((ROOT / "minseg_tui" / "model" / "check").glob("*.py"))
        for line, text in prose(ast.parse(p.read_text(encoding="utf-8")))
    ]
    assert found == [], "\n".join(found)


IDENTIFY_KEEPS = {
    "a t quantile needs at least one degree of freedom",  # a programming error, not input
}
"""The words model/identify keeps besides its refusals ('expected ...'), and why. How u_ss
was found, and identify's refusal of a rise at 0 V on the motor that quotes it, are a code
and a record here (steady.UssHow, ZeroVoltRise), worded in lab/content/u_ss_says.py."""


IDENTIFY_REFUSALS = 10
"""How many refusals ('expected ...': a bad table, R or log) model/identify words itself, at
most: 21 prose strings there at 80a1f26, 11 now with the one of IDENTIFY_KEEPS (a wheel that
never turns is runlog.StillAngle since s35). A new one raises this on purpose, or is a record
worded above the model."""


def test_identify_holds_no_words_but_its_refusals():
    """Issue 19 item 4: identify gives typed records; what its numbers show, the 63 %
    reading's note, why T came from its fit, Task 14's model and how u_ss was found in
    words are written in lab/content/ (identify_says.py, u_ss_says.py). What stays is one
    of IDENTIFY_REFUSALS, or one of IDENTIFY_KEEPS."""
    said = [
        (f"{p.relative_to(ROOT)}:{line}: {text}", text)
        for p in sorted((ROOT / "minseg_tui" / "model" / "identify").glob("*.py"))
        for line, text in prose(ast.parse(p.read_text(encoding="utf-8")))
    ]
    found = [
        w for w, text in said if not text.startswith("expected") and text not in IDENTIFY_KEEPS
    ]
    refusals = [w for w, text in said if text.startswith("expected")]
    assert found == [], "\n".join(found)
    assert len(refusals) <= IDENTIFY_REFUSALS, "\n".join(refusals)


RUNLOG_KEEPS = {"columns differ in length from t ({}): {}"}  # a programming error, not input
"""The words model/runlog.py keeps, and why. A log's refusals are records there
(LogProblem, ClockApart, StillAngle, BadHeader) and so is where its angle came from
(AngleFrom), worded in lab/content/log_says.py."""


def test_a_run_log_holds_no_words():
    """Issue 19 items 3-4: a run log's refusals and its angle's source are records, worded
    above the model; only RUNLOG_KEEPS stays."""
    p = ROOT / "minseg_tui" / "model" / "runlog.py"
    found = [
        f"{line}: {text}"
        for line, text in prose(ast.parse(p.read_text(encoding="utf-8")))
        if text not in RUNLOG_KEEPS
    ]
    assert found == [], "\n".join(found)
