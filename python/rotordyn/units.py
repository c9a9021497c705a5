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


# The suffix vocabulary of column names and fields (longest first): the unit each names.
SUFFIX_UNITS = (("_n_s_per_m", "N·s/m"), ("_n_per_m", "N/m"), ("_n_m_per_rad", "N·m/rad"), ("_nm_per_rad", "N·m/rad"),
                ("_kg_m3", "kg/m³"), ("_kg_m2", "kg·m²"), ("_1_per_s", "1/s"),
                ("_pa_s", "Pa·s"), ("_m3_s", "m³/s"), ("_rad_s", "rad/s"), ("_hz", "Hz"),
                ("_pa", "Pa"), ("_kg", "kg"), ("_deg", "deg"), ("_rad", "rad"), ("_n_m", "N·m"),
                ("_m_s", "m/s"), ("_m", "m"), ("_s", "s"), ("_n", "N"), ("_w", "W"))


def unit_of(name: str) -> str:
    """The unit a column or field name carries in its suffix (``bearing[0].clearance_m`` →
    ``m``); ``"1"`` for a name without a unit suffix (dimensionless)."""
    for suffix, unit in SUFFIX_UNITS:
        if name.endswith(suffix):
            return unit
    return "1"
