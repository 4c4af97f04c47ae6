"""`sim --seed` beyond its range names the largest seed it takes (s39 attack: the bound was
formatted as a float, so 2**63 - 1 read 9223372036854775808, and that very seed was refused
with 'expected an integer from 0 to 9223372036854775808'). Through main()."""

from __future__ import annotations

import pytest

from minseg_tui.cli import main


@pytest.mark.parametrize("seed", ["9223372036854775808", "-1"])
def test_a_seed_out_of_range_names_the_largest_it_takes(capsys, seed):
    try:
        code = main(["sim", "--seed", seed])
    except SystemExit as exc:
        code = int(exc.code or 0)
    err = capsys.readouterr().err
    assert code == 2
    assert err == (
        "minseg-tui sim: option seed: expected an integer from 0 to 9223372036854775807, "
        f"got '{seed}'\n"
    )
