"""One unit per quantity, and every unit the program writes taken back in its entries: a
group copying a value from the screen ("1.855 mN m s/rad", "42.99 ms", "0.001384 kg m^2")
into an entry of that quantity has it read, in any field of the lab (real entries, no UI)."""

from __future__ import annotations

from minseg_tui.lab.content.steps import FIELDS
from minseg_tui.lab.state.entries import read_entry
from minseg_tui.quantities import DISPLAY_UNITS, UNITS, format_reading, shown_unit


def test_every_unit_the_program_writes_is_taken_in_every_field_of_its_quantity() -> None:
    refused = []
    for key, fld in FIELDS.items():
        if fld.kind != "quantity":
            continue
        quantity = UNITS[fld.unit].quantity
        for unit in DISPLAY_UNITS:
            if unit in UNITS and UNITS[unit].quantity == quantity:
                e = read_entry(fld, f"2 {unit}")
                if not e.ok:
                    refused.append((key, unit, e.message))
    assert not refused, refused


def test_a_value_in_another_unit_is_read_back_in_its_quantitys_one_unit() -> None:
    for key, text in (
        ("own.omega_step", "500 rpm"),
        ("i_ss@4.5", "0.0372 A"),
        ("own.T", "0.057 s"),
    ):
        fld = FIELDS[key]
        e = read_entry(fld, text)
        shown = shown_unit(fld.unit)
        assert e.ok and e.value is not None
        assert e.message.startswith(f"read as {format_reading(e.value, shown)}"), e.message
    assert read_entry(FIELDS["own.omega_step"], "500 rpm").message == (
        "read as 52.36 rad/s (typed 500 rpm)"
    )
    assert read_entry(FIELDS["own.T"], "57 ms").message == ""  # as the screen writes it
