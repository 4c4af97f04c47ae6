"""The class's middle and spread: median and MAD, so that one typo hides no other."""

from __future__ import annotations

import statistics
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.lab.views.classview import (
    MIN_GROUPS,
    THRESHOLD,
    Group,
    judge,
    outlier,
    spread,
    step_name,
)


def test_two_typos_are_both_found_where_mean_and_std_miss_one():
    rng = np.random.default_rng(21)
    honest = list(0.50 + 0.01 * rng.standard_normal(12))
    values = [*honest, 50.0, 0.9]  # k_v from i_ss in amperes, and a misread meter
    s = spread("k_v", values)
    assert s is not None and s.n == 14
    assert outlier(s, 50.0) is not None and outlier(s, 0.9) is not None
    assert all(outlier(s, v) is None for v in honest)
    # the mean and standard deviation: the big typo hides the smaller one
    m, sd = statistics.mean(values), statistics.stdev(values)
    assert abs(0.9 - m) < THRESHOLD * sd


def test_the_sentence_says_value_median_and_how_far():
    s = spread("R", [5.1, 5.2, 5.2, 5.3, 5.25])
    assert s is not None
    why = outlier(s, 12.0)
    assert why == (
        "R = 12 Ω is far above the class: 65 robust standard deviations from its median of 5.200 Ω."
    )


def test_alike_groups_are_not_called_far_for_a_few_per_cent():
    s = spread("T", [0.05] * 6)  # MAD 0: the floor of 2 % of the median holds
    assert s is not None and s.sigma > 0
    assert outlier(s, 0.052) is None and outlier(s, 0.08) is not None


def test_too_few_groups_have_no_class_median():
    assert spread("J", [1.0] * (MIN_GROUPS - 1)) is None
    assert spread("J", [1.0, float("nan"), 1.0, 1.0, 1.0]) is not None


def test_steps_are_named_as_the_lab_names_them():
    assert step_name("task13") == "Task 13" and step_name("table") == "Tasks 6-9"
    assert (
        step_name("prep3") == "Preparation 3" and step_name("summary") == "Summary and reflections"
    )


def _row(k: int, R: float, slipped: tuple[str, ...] = ()) -> Group:
    return Group(f"g{k}", Path(f"g{k}"), values={"R": R}, slipped=slipped)


def test_a_slipped_value_is_judged_but_never_moves_the_class_median_or_mad():
    honest = [5.2, 5.2, 5.2, 5.2, 5.21, 5.19]
    near = 5.8  # read on a warm motor, or a poor contact: 0.6 Ω from the rest
    typos = [52.0, 0.53, 12.0, 31.0, 1.4]  # the manual's slips, each flagged on its own
    groups = [_row(k, R) for k, R in enumerate([*honest, near])]
    groups += [_row(10 + k, R, slipped=("R",)) for k, R in enumerate(typos)]
    view = judge(groups)
    s = view.spreads["R"]
    assert s.n == len(honest) + 1 and s.median == pytest.approx(5.2)
    flagged = {g.id: g.flags for g in view.groups}
    assert flagged["g6"] and "far above the class" in flagged["g6"][0]
    assert all(flagged[f"g{10 + k}"] for k in range(len(typos)))  # still judged
    # had the typos fed the MAD, the spread would have hidden the group at 5.8 Ω
    wide = spread("R", [*honest, near, *typos])
    assert wide is not None and outlier(wide, near) is None
