"""minseg-tui: a terminal lab assistant for DC-motor identification on the MinSeg robot."""

__version__ = "0.1.0"
