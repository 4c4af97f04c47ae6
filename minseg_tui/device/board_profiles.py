"""The board profiles the firmware is built for, in the order of its table of pins
(firmware/minseg-fw/src/board/pins.def); the first is the firmware's default.

Made by firmware/tools/pins_table.py (--write) from that table; do not edit: make
host-test fails while it differs."""

PROFILES = (
    "MinSegMega",
    "M2V3",
    "M1V4",
)
DEFAULT_PROFILE = "MinSegMega"
