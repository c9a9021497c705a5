"""Unit conversions at the user boundary (everything inside is SI: m, s, kg, N, Pa, rad)."""

from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi


def hz_to_rad_s(f_hz):
    """Rotational speed or frequency, Hz → rad/s (works on scalars and numpy arrays)."""
    return f_hz * TWO_PI


def rad_s_to_hz(w_rad_s):
    """Angular frequency, rad/s → Hz."""
    return w_rad_s / TWO_PI


def rpm_to_rad_s(n_rpm):
    """Speed, rev/min → rad/s."""
    return n_rpm * TWO_PI / 60.0


def rad_s_to_rpm(w_rad_s):
    """Speed, rad/s → rev/min."""
    return w_rad_s * 60.0 / TWO_PI
