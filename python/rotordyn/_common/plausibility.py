"""Unit plausibility checks: warn (:class:`rotordyn.errors.UnitWarning`) when a value is far
outside its physical range in the way a unit slip puts it there, naming the field and the
likely slip. Used by the model's validation and by the command line.

The windows are chosen so that a real machine never triggers them and a slip by 10³ or 10⁹
does (a check is about units, not design: deliberate idealisations such as a rigid material
with E = 1e15 Pa or a near-massless one with ρ = 1e-3 kg/m³ pass silently):

* Young's modulus below 1e7 Pa: engineering metals lie in 45 GPa (magnesium) … 410 GPa
  (tungsten) — aluminium ≈ 70 GPa, brass ≈ 100 GPa, steel ≈ 210 GPa; polymers ≥ 0.5 GPa.
  A value in GPa (≈ 70 … 400) or MPa (7e4 … 4e5) typed as Pa lands below 1e7.
* Density in [0.1, 100) kg/m³: every solid is above 500 kg/m³; a value in g/cm³
  (aluminium 2.7, steel 7.85, brass 8.5) lands here.
* Diameters above 5 m, section lengths above 20 m: millimetres typed as metres.
* Radial clearance below 1e-4 or above 0.02 of the journal radius (plain bearings: about
  1e-3 … 3e-3 of R).
* Viscosity above 5 Pa·s (mPa·s typed as Pa·s: ISO VG 32 oil at 40 °C ≈ 28 mPa·s).
* Gravity above 100 m/s² (10 g): mm/s² typed as m/s² (9810 for 9.81).
* A housing offset ``config_a*_m`` larger than 50 clearances (the paper's rig: a_y = −1.85 mm
  = 6.2 c): millimetres typed as metres.
"""

from __future__ import annotations

import warnings

from rotordyn.errors import UnitWarning

METALS_E_PA = {"aluminium": 70e9, "brass": 100e9, "steel": 210e9}
MAX_DIAMETER_M = 5.0
MAX_SECTION_LENGTH_M = 20.0
CLEARANCE_RATIO = (1e-4, 0.02)
MAX_VISCOSITY_PA_S = 5.0
MAX_OFFSET_CLEARANCES = 50.0
MAX_GRAVITY_M_S2 = 100.0  # 10 g; the Earth's 9.81 m/s² typed in mm/s² is 9810


def _warn(message: str) -> None:
    warnings.warn(message, UnitWarning, stacklevel=3)


def young_modulus(field: str, value: float) -> None:
    """Warn when Young's modulus ``value`` (Pa) looks like GPa or MPa typed as Pa."""
    if 0 < value < 1e7:
        unit = "GPa" if value < 1e4 else "MPa"
        scale = 1e9 if unit == "GPa" else 1e6
        _warn(f"{field} = {value:g} Pa is far below any structural material (aluminium 70 GPa, "
              f"brass 100 GPa, steel 210 GPa): given in {unit}? ({value:g} {unit} = "
              f"{value * scale:.4g} Pa)")


def density(field: str, value: float) -> None:
    """Warn when a density (kg/m³) looks like g/cm³ typed as kg/m³."""
    if 0.1 <= value < 100.0:
        _warn(f"{field} = {value:g} kg/m³ is far below any solid (aluminium 2700, steel 7850 "
              f"kg/m³): given in g/cm³? ({value:g} g/cm³ = {value * 1e3:g} kg/m³)")


def length(field: str, value: float, limit: float = MAX_DIAMETER_M) -> None:
    """Warn when a length (m) exceeds ``limit``: millimetres typed as metres?"""
    if value > limit:
        _warn(f"{field} = {value:g} m is above {limit:g} m: given in millimetres? "
              f"({value:g} mm = {value * 1e-3:g} m)")


def clearance(field: str, clearance_m: float, diameter_m: float) -> None:
    """Warn when the radial clearance is implausible relative to the journal radius."""
    if clearance_m <= 0 or diameter_m <= 0:
        return
    ratio = clearance_m / (0.5 * diameter_m)
    lo, hi = CLEARANCE_RATIO
    if ratio < lo:
        _warn(f"{field} = {clearance_m:g} m is {ratio:.2g} of the journal radius "
              f"({0.5 * diameter_m:g} m; plain bearings: about 1e-3 to 3e-3): is the diameter "
              "in millimetres or the clearance in metres typed as micrometres?")
    elif ratio > hi:
        _warn(f"{field} = {clearance_m:g} m is {ratio:.2g} of the journal radius "
              f"({0.5 * diameter_m:g} m; plain bearings: about 1e-3 to 3e-3): given in "
              f"millimetres? ({clearance_m:g} mm = {clearance_m * 1e-3:g} m)")


def viscosity(field: str, value: float) -> None:
    """Warn when a dynamic viscosity (Pa·s) looks like mPa·s typed as Pa·s."""
    if value > MAX_VISCOSITY_PA_S:
        _warn(f"{field} = {value:g} Pa·s is above {MAX_VISCOSITY_PA_S:g} Pa·s (ISO VG 32 oil "
              f"at 40 °C: 0.028 Pa·s): given in mPa·s? ({value:g} mPa·s = {value * 1e-3:g} Pa·s)")


def gravity(field: str, value: float) -> None:
    """Warn when the gravitational acceleration (m/s²) looks like mm/s² typed as m/s²."""
    if value > MAX_GRAVITY_M_S2:
        _warn(f"{field} = {value:g} m/s² is above {MAX_GRAVITY_M_S2:g} m/s² (10 g; the Earth's "
              f"9.81 m/s²): given in mm/s²? ({value:g} mm/s² = {value * 1e-3:g} m/s²)")


def housing_offset(field: str, value, clearance_m: float) -> None:
    """Warn when a housing offset (m) is more than 50 clearances: millimetres typed as m?"""
    if value is None or clearance_m <= 0:
        return
    n = abs(float(value)) / clearance_m
    if n > MAX_OFFSET_CLEARANCES:
        _warn(f"{field} = {float(value):g} m is {n:.0f} times the radial clearance "
              f"({clearance_m:g} m): given in millimetres? ({float(value):g} mm = "
              f"{float(value) * 1e-3:g} m)")
