"""Task 14's model, as a group writes it, read into T and K and judged against the model
computed the group's way (issue 20's second walk: "w = 1,9 u" was ticked)."""

from __future__ import annotations

import pytest

from minseg_tui.lab.content.model_eq import read_model
from minseg_tui.lab.views import session as views
from tests.lab.test_compare import _lab

# -- (5) Task 14's model is judged ------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "T", "K"),
    [
        ("0.043 omega' = -omega + 1.9 u_A", 0.043, 1.9),
        ("0,043 ω' + ω = 1,9 u", 0.043, 1.9),
        ("omega' = -omega/0.043 + 1.9/0.043 u_A", 0.043, 1.9),
        ("0.043 dw/dt + w = 1.9 u", 0.043, 1.9),
        ("0.043*omega'(t) = 1.9*u_A(t) - omega(t)", 0.043, 1.9),
    ],
)
def test_a_model_is_read_in_the_forms_groups_write(text, T, K):
    m = read_model(text)
    assert m.T == pytest.approx(T) and m.K == pytest.approx(K)


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("w = 1,9 u", "no omega' term"),
        ("T omega' = -omega + K u_A", "numbers in for T and K"),
        ("0.043 w' = -w^2 + 1.9 u", "not linear"),
        ("-0.043 w' = -w + 1.9 u", "time constant is positive"),
        ("fast", "one '='"),
    ],
)
def test_what_is_no_model_is_said_in_one_line(text, says):
    with pytest.raises(Exception) as info:
        read_model(text)
    assert says in str(info.value) and "\n" not in str(info.value)


def test_task14_model_is_marked_right_or_wrong(tmp_path):
    with _lab(tmp_path) as s:
        st = s.results().identification.step  # type: ignore[union-attr]
        assert st is not None and st.T_63 is not None
        s.enter("own.model", "w = 1,9 u")
        assert s.step_status("task14") == "wrong"
        (c,) = s.comparisons("task14")
        assert c.right is False and "no omega' term" in c.verdict
        assert (
            "no omega' term"
            in dict((label, comp) for label, _, comp in views.comparisons(s, "task14"))[
                "your model"
            ]
        )
        s.enter("own.model", f"{st.T_63:.3g} omega' = -omega + {2 * st.K:.3g} u_A")
        assert s.step_status("task14") == "wrong"
        (c,) = s.comparisons("task14")
        assert c.right is False and c.verdict.startswith("wrong: K =")
        s.enter("own.model", f"{st.T_63:.3g} omega' = -omega + {st.K:.3g} u_A")
        (c,) = s.comparisons("task14")
        assert c.right is True and s.step_status("task14") == "done"
        # with the group's own T and K, the model is judged against those
        s.enter("own.T", f"{st.T_63 * 1.3 * 1e3:.3g} ms")
        assert s.step_status("task14") == "wrong"
        s.enter("own.model", f"{st.T_63 * 1.3:.3g} omega' = -omega + {st.K:.3g} u_A")
        (c,) = s.comparisons("task14")
        assert c.right is True  # consistent with their T, which is marked wrong: "!" (walk 7)
        assert s.step_status("task14") == ("warned" if c.caveat else "done")
