"""Widgets of the lab: they render state handed to them and post messages; no math, no I/O."""
