"""Test doubles of the device layer shared by the CLI and UI tests."""


class RealBoardView:
    """The link to a virtual board seen as a real board is: no multimeter (the firmware
    answers METER with $ERR,UNKNOWN, which Link.meter turns into None) and no virtual board
    behind it. Everything else is the link's."""

    board = None

    def __init__(self, link) -> None:
        self._link = link

    def __getattr__(self, name):
        return getattr(self._link, name)

    def meter(self):
        return None
