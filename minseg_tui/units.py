"""Constants of the MinSeg hardware and of the lab, with their units. (Units themselves, how
a value is read and how it is written: :mod:`minseg_tui.quantities`.)"""

from __future__ import annotations

import math

COUNTS_PER_REV: int = 720
"""Encoder counts per wheel revolution (x4 quadrature decoding, 48 x gear ratio 15)."""

RAD_PER_COUNT: float = 2.0 * math.pi / COUNTS_PER_REV
"""Wheel angle per encoder count, rad (the scaling gain of Preparation 10)."""

LAB_TS: float = 0.025
"""The manual's sample period, s."""

LAB_FIR_TAPS: int = 20
"""Length of the manual's moving-average velocity filter (coefficients 0.05), samples."""

KA_OVER_KV: float = 0.65
"""The manual's ratio k_a / k_v (equation 3.3)."""
