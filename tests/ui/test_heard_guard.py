"""The hang guard of :class:`tests.ui.helpers.Heard`: a wait for something that never
comes fails, counted in the app's own messages, instead of blocking the suite for as long
as Textual's timers keep the app busy."""

import pytest

from tests.ui.conftest import board_url, real_app
from tests.ui.helpers import Heard, settle


async def test_a_wait_that_never_ends_fails_after_the_apps_own_messages(tmp_path):
    app = real_app(tmp_path / "sessions", board_url(seed=4))
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await settle(pilot, lambda: app.device is not None)
        own = heard.own
        with pytest.raises(AssertionError, match="not after 30 of the app's own messages"):
            await heard.until(pilot, lambda: False, most=30)
        assert heard.own - own >= 30  # the stream's messages, not Textual's, ended it
