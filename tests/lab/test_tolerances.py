"""The grading tolerances as measured (benchmarks/grading_tolerances.py, 300 seeded
sessions): T read at 63 % on the sample nearest the level falls up to 27 % from the
program's interpolated reading, so 25 % marked an honest reading wrong; 30 % holds it, and a
T read a whole sample late past a fast rise (+40 %) is still wrong. On a real session
folder with a run of the seeded plant (tests/lab/test_compare.py's)."""

from __future__ import annotations

from minseg_tui.lab.state.compare import TOLERANCE
from minseg_tui.quantities import format_number
from tests.lab.test_compare import _lab


def _judged(s, key: str, step_id: str) -> bool | None:
    (c,) = [c for c in s.comparisons(step_id) if c.key == key]
    return c.right


def test_t_read_on_the_nearest_sample_is_right_and_a_sample_late_is_wrong(tmp_path):
    assert TOLERANCE["own.T"] == 0.30
    with _lab(tmp_path) as s:
        st = s.results().identification.step  # type: ignore[union-attr]
        for factor, right in ((1.27, True), (0.74, True), (1.40, False), (0.62, False)):
            assert s.enter("own.T", format_number(st.T_63 * factor * 1e3, 3) + " ms").ok
            assert _judged(s, "own.T", "task12") is right, factor
            assert s.step_status("task12") == ("done" if right else "wrong")
