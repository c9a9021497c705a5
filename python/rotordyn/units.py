"""Unit conversions at the user boundary (everything inside is SI: m, s, kg, N, Pa, rad)."""

from __future__ import annotations

import math
import re

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
SUFFIX_UNITS = (("_n_m_s_per_rad", "N·m·s/rad"), ("_n_m_s_per_m", "N·m·s/m"),
                ("_n_s_per_rad", "N·s/rad"), ("_n_m_per_m", "N·m/m"), ("_n_per_rad", "N/rad"),
                ("_n_s_per_m", "N·s/m"), ("_n_per_m", "N/m"), ("_n_m_per_rad", "N·m/rad"),
                ("_nm_per_rad", "N·m/rad"),
                ("_j_per_kg_k", "J/(kg·K)"), ("_w_per_m_k", "W/(m·K)"), ("_w_m2k", "W/(m²·K)"),
                ("_kg_m3", "kg/m³"), ("_kg_m2", "kg·m²"), ("_1_per_s", "1/s"), ("_mm2_s", "mm²/s"),
                ("_pa_s", "Pa·s"), ("_m3_s", "m³/s"), ("_rad_s", "rad/s"), ("_hz", "Hz"),
                ("_pa", "Pa"), ("_kg", "kg"), ("_deg", "deg"), ("_rad", "rad"), ("_n_m", "N·m"),
                ("_m_s", "m/s"), ("_m", "m"), ("_s", "s"), ("_n", "N"), ("_w", "W"),
                ("_1_per_k", "1/K"), ("_k", "K"))

# Degrees Celsius: only a temperature's own name ends in _c (t1_c, t_ref_c, supply_temperature_c);
# other names ending in _c are in units of the clearance c (x_over_c, amplitude_c, disturbance_c)
_CELSIUS = re.compile(r"(?:^|[._])(?:[a-z_]*temperature|t(?:\d+|_ref|_min|_max)?)_c$")


def split_unit(name: str) -> tuple[str, str]:
    """(stem, unit) of a column or field name: ``thermal.supply_temperature_c`` →
    (``thermal.supply_temperature``, ``°C``); a name without a unit suffix is its own stem, unit
    ``"1"``."""
    if _CELSIUS.search(name):
        return name[:-2], "°C"
    for suffix, unit in SUFFIX_UNITS:
        if name.endswith(suffix):
            return (name[: -len(suffix)], unit) if unit != "1" else (name, unit)
    return name, "1"


def unit_of(name: str) -> str:
    """The unit a column or field name carries in its suffix (``bearing[0].clearance_m`` →
    ``m``); ``"1"`` for a name without a unit suffix (dimensionless)."""
    return split_unit(name)[1]


# A tilting film's 4×4 K, C over (x, y, θx, θy), ΔH = −K Δr − C Δṙ: the unit of entry (i, j)
# by its row block (0: the forces Fx, Fy; 1: the moments Mx, My) and column block (0: the
# translations x, y; 1: the rotations θx, θy), as the suffix stem of its column name
# (``k<i><j>_<stem>``, rotordyn.analysis.bearing_coefficients) — the one definition the
# coefficient frames, the report's tables and ``rotordyn bearing``'s 4×4 units are read from.
TILT_COORDINATES = ("x", "y", "theta_x", "theta_y")
TILT_UNIT_STEMS = {"k": (("n_per_m", "n_per_rad"), ("n_m_per_m", "n_m_per_rad")),
                   "c": (("n_s_per_m", "n_s_per_rad"), ("n_m_s_per_m", "n_m_s_per_rad"))}


def tilt_unit_stem(kind: str, i: int, j: int) -> str:
    """The unit stem of entry (i, j) of the 4×4 ``kind`` ("k" or "c") over
    :data:`TILT_COORDINATES` (``n_m_per_rad`` for K[2, 3])."""
    return TILT_UNIT_STEMS[kind][i // 2][j // 2]


def tilt_units(kind: str) -> list[list[str]]:
    """The 4×4 of units (``N/m`` … ``N·m/rad``) of ``kind`` ("k" or "c")."""
    return [[unit_of("_" + tilt_unit_stem(kind, i, j)) for j in range(4)] for i in range(4)]
