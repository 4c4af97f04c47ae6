"""Walk 7's key defects (D1, D2, D12, D5, D11, D3, D17): keys in bursts land where and when
they were typed; a step arrives with its values drawn."""

from __future__ import annotations

from textual.widgets import Input

from tests.ui.helpers import burst, settle, shown


async def test_names_typed_in_a_burst_with_backspaces_are_kept(quiet):
    """Walk 7 (D1): 'Kim Parkk' BSpace BSpace 'k' Enter in one burst created 'Kim Parkkk'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(pilot, *"Abcd", "backspace", "backspace", "x")
        assert app.screen.query_one("#members", Input).value == "Abx"
        await burst(pilot, *"yz")
        assert app.screen.query_one("#members", Input).value == "Abxyz"


async def test_a_group_typed_in_one_burst_with_backspaces_gets_its_names(quiet):
    """Walk 7 (D1): 'Lena Berg, Omra' BSpace x3 'mar Haddad' Enter created the session of
    'Lena Berg', 'Omrr Haddad' (the name in the session id, the report, the class view)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await burst(pilot, *"Lena Berg, Omra", *["backspace"] * 3, *"mar Haddad", "enter")
        await settle(pilot, lambda: shown(app))
        assert app.session is not None
        with app.session as s:
            assert list(s.members) == ["Lena Berg", "Omar Haddad"]
